#pragma once
// Every key a scene's schema asks for while reading, by its dotted name without indices
// (material.name, cable.section.length): what the loader accepts, for its documentation's test.
#include <set>
#include <string>

namespace cablefilm {

using KeyLog = std::set<std::string>;

}  // namespace cablefilm
