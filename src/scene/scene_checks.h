#pragma once
// The rules of a scene's file that involve several keys, each error naming the key most likely
// at fault (the parser's; what needs the built model is CheckModelLimits, scene_limits.h).
#include <string>

#include "scene/scene_def.h"
#include "scene/toml_reader.h"

namespace cablefilm {

// The seabed must not be above a prescribed end (an anchor in the bed, a fairlead dipping into
// it): an error naming seabed.y.
void CheckSeabed(const toml::table& root, const SceneDef& scene, const std::string& file);

// The output rows and fixed time steps a run makes: within the stated limits.
void CheckRunCounts(const toml::table& root, const SceneDef& scene, const std::string& file,
                    bool interval_given);

// With the equilibrium start, no line too long for the statics' bound (kMostLineStaticsWork,
// line_equilibrium.h): an error naming its longest section's segments, before its model is made.
void CheckStaticsSize(const toml::table& root, const SceneDef& scene, const std::string& file);

// Why an inextensible line's ends, at points given in the world's axes (not free, not on a
// body), are too far apart for it: as far as or further than its length ("" when they are
// not, or the line is elastic).
std::string LineReachProblem(const LineDef& line, const SceneDef& scene);

}  // namespace cablefilm
