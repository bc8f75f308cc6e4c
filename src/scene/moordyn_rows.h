#pragma once
// Each MoorDyn table's row read into its struct, column by column, with the checks that need
// only the row: every column present, numbers finite and in range, IDs sequential, the
// attachment words MoorDyn knows (MoorDyn2.cpp: "Fixed"/"Fix"/"Anchor", "Coupled"/"Vessel"/
// "Ves"/"Cpld"/"Fairlead", "Free"/"Point"/"Connect"/"Con", "Body#"), and what cablefilm
// cannot use refused with the reason (viscoelastic EA, a line on a rod end).
#include <string>
#include <vector>

#include "scene/moordyn_file.h"
#include "scene/moordyn_row.h"

namespace cablefilm {

// Column names as messages show them; `*_required` of them must be present.
extern const std::vector<std::string> kMoorDynLineTypeColumns;
extern const std::vector<std::string> kMoorDynBodyColumns;
extern const std::vector<std::string> kMoorDynPointColumns;       // the v2 form, 9 columns
extern const std::vector<std::string> kMoorDynPointForceColumns;  // the older form, 12 columns
extern const std::vector<std::string> kMoorDynLineColumns;

MoorDynLineType ReadMoorDynLineType(const MoorDynRow& row);
MoorDynBody ReadMoorDynBody(const MoorDynRow& row, int id);
MoorDynPoint ReadMoorDynPoint(const MoorDynRow& row, int id, std::vector<std::string>* warnings);
MoorDynLine ReadMoorDynLine(const MoorDynRow& row, int id);

}  // namespace cablefilm
