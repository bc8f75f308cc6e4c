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

// The output rows, fixed time steps and film frames a run makes: within the stated limits.
void CheckRunCounts(const toml::table& root, const SceneDef& scene, const std::string& file,
                    bool interval_given);

// An inextensible cable's ends less than its length apart (`ends`: the [ends] table, `r` its
// reader).
void CheckEndsReach(const toml::table* ends, const TableReader& r, const SceneDef& scene);

}  // namespace cablefilm
