#include "view/world_box.h"

#include <algorithm>

namespace cablefilm {
namespace {

// How far the box reaches beyond the seabed or the crests, for a box `height` tall [m]: the
// lines' box often ends on them (an anchor on the bed, a buoy at the surface).
double Margin(double height) { return 0.04 * height; }

}  // namespace

WorldBox ShownBox(WorldBox box, const SeaView& sea, const Wave& wave) {
  if (sea.seabed) box.y_min = std::min(box.y_min, sea.seabed_y - Margin(box.y_max - box.y_min));
  if (sea.surface) {
    const double crest = wave.spec.surface_y + wave.amplitude;  // [m]
    box.y_max = std::max(box.y_max, crest + Margin(crest - box.y_min));
  }
  return box;
}

void AddWaterSurface(const Wave& wave, const WorldBox& box, Snapshot* snapshot) {
  SurfaceProfile(wave, snapshot->t, 2 * box.x_min - box.x_max, 2 * box.x_max - box.x_min,
                 snapshot->surface_x, snapshot->surface_y);
}

}  // namespace cablefilm
