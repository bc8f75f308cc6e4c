#include "live/live_physics.h"

#include "live/live_simulation.h"
#include "live/sea_ramps.h"
#include "live/live_system_simulation.h"

namespace cablefilm {

double LivePhysics::current_now() const { return inputs().current.ValueAt(t()); }
double LivePhysics::current_heading_now() const {
  return inputs().current_heading.ValueAt(t()) / kDegree;
}
double LivePhysics::wave_heading_now() const {
  return inputs().wave_heading.ValueAt(t()) / kDegree;
}

std::unique_ptr<LivePhysics> MakeLivePhysics(const SceneDef& scene, const CancelFlag* stop) {
  if (scene.is_system()) return std::make_unique<LiveSystemSimulation>(scene, stop);
  return std::make_unique<LiveSimulation>(scene, stop);
}

}  // namespace cablefilm
