#pragma once
// The checks of a MoorDyn file that span its sections, once every row is read: each line's
// type is a LINE TYPES name, its two attachments defined points, each Body#N point's body a
// defined body. Errors name the row and column that refers; a point that no line uses is a
// warning (MoorDyn lets it be, but it is likely a mistake).
#include <string>

#include "scene/moordyn_file.h"

namespace cablefilm {

// `file`: the name as messages show it. Throws Error; adds to system->warnings.
void CheckMoorDynReferences(const std::string& file, MoorDynSystem* system);

}  // namespace cablefilm
