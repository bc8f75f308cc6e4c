#pragma once
// The scene view (scene_view.h) of a scene and its model, for the film (a line a run) and for
// the live view (its one line) alike.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/inputs.h"
#include "core/line_model.h"
#include "core/vec.h"
#include "scene/scene_def.h"
#include "view/scene_view.h"

namespace cablefilm {

// The line of `model` (of `scene`, made from `sections`) named `label`: its stations' arc
// lengths, its sections (each named by its material when every one has a name; none named
// when `sections` is empty), its weights, its ends by role (fixed, moving, free), and its
// initial state: positions `initial_x` [m], tensions `initial_tension` [N].
LineView MakeLineView(const SceneDef& scene, const std::vector<SectionDef>& sections,
                      const LineModel& model, const Points& initial_x,
                      const Eigen::VectorXd& initial_tension, std::string label);

// The scene's title, `lines`, the reference's name (the scene's initial state: an equilibrium
// or the straight chord), from `model` the seabed, whether waves draw a surface and the current
// at the top of the water, and whether it is drawn in space (`space`: scene/film_view.h).
SceneView MakeSceneView(const SceneDef& scene, const LineModel& model, std::vector<LineView> lines,
                        bool space = false);

// The current of `water` at the top of the water [m/s]: at the still water level with waves,
// else at the top of its profile (a uniform current is the same at every elevation).
Vec TopCurrent(const LineModel& model, const Water& water);

}  // namespace cablefilm
