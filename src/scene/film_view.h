#pragma once
// Whether a scene is drawn in the paper's plane (2D: x across, y up) or in space (3D: a
// perspective view beside the plan and the elevation): film.view = "auto" draws a scene in
// space unless every position, motion, current and wave of it stays in the plane z = 0.
#include <string>
#include <vector>

#include "scene/scene_def.h"

namespace cablefilm {

// "auto", "2d", "3d": the values of film.view and --view.
const std::vector<std::string>& FilmViewNames();

// Every end's rest position and motion (trochoid, table, wave response), the current and the
// waves keep z = 0, so the line stays in that plane; a system's every point likewise (and no
// point's force pushes across it).
bool SceneIsPlanar(const SceneDef& scene);

// The 3D picture for `view` ("auto", "2d", "3d"; anything else throws Error) of the scene.
bool DrawsInSpace(const SceneDef& scene, const std::string& view);

}  // namespace cablefilm
