#include "live/live_physics.h"

#include "live/live_simulation.h"
#include "live/live_system_simulation.h"

namespace cablefilm {

std::unique_ptr<LivePhysics> MakeLivePhysics(const SceneDef& scene) {
  if (scene.is_system()) return std::make_unique<LiveSystemSimulation>(scene);
  return std::make_unique<LiveSimulation>(scene);
}

}  // namespace cablefilm
