#pragma once
// The part of the world the cable panel shows: the lines' box, reaching down to the seabed and
// up to the wave crests, and the water surface sampled across it (and beyond, since the panel
// may be wider than the box).
#include "core/waves.h"
#include "view/scene_view.h"
#include "view/snapshot.h"

namespace cablefilm {

struct WorldBox {
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1;  // [m]
  double z_min = 0, z_max = 0;  // [m]: 0 in the plane
};

// `lines` (a box holding the lines) with the seabed in view and a strip of ground below it, and
// with waves (sea.surface) the surface of `wave` in view up to its crests and a strip of sky.
WorldBox ShownBox(WorldBox lines, const SeaView& sea, const Wave& wave);

// The surface of `wave` at the snapshot's time across the box and a box's width beyond it on
// either side, into snapshot->surface_x and surface_y (their storage reused).
void AddWaterSurface(const Wave& wave, const WorldBox& box, Snapshot* snapshot);

}  // namespace cablefilm
