#pragma once
// A MoorDyn system written as the equivalent cablefilm scene (TOML, the system format of
// docs/moordyn.md: [[material]], [[point]], [[line]]), each value commented with where it came
// from. MoorDyn's axes (z up) become cablefilm's (y up): (x, y, z) -> (x, z, -y).
#include <string>
#include <vector>

#include "scene/key_source.h"
#include "scene/moordyn_file.h"

namespace cablefilm {

// The scene's text. What the scene leaves out or changes (bending stiffness, tangential drag,
// options cablefilm ignores, a seabed lowered to the deepest point, ...) is appended to
// `warnings` (may be null) as "file:line: ..." and also listed in the text's header comment,
// with the reader's warnings (system.warnings). Throws Error "file:line: ..." for what has no
// equivalent yet: a free body. `sources` (may be null): the row and column of the file each key
// came from, for messages about the scene.
std::string MoorDynToToml(const MoorDynSystem& system, std::vector<std::string>* warnings,
                          KeySources* sources = nullptr);

}  // namespace cablefilm
