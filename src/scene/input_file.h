#pragma once
// The text of an input file (a scene, a MoorDyn file), at most kMaxSceneBytes, checked while
// reading (/dev/zero is refused). `what` names the kind of file in messages ("scene file").
#include <string>

namespace cablefilm {

std::string ReadInputFile(const std::string& path, const std::string& what,
                          const std::string& expected);

}  // namespace cablefilm
