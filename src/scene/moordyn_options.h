#pragma once
// The OPTIONS of a MoorDyn file that cablefilm maps or must know of, by the names MoorDyn
// reads them under (MoorDyn2.cpp, readOptionsLine: case-sensitive, with its aliases; "rhoW"
// is MoorDyn-F's), and the range each value must be in.
#include <string>

#include "scene/moordyn_file.h"

namespace cablefilm {

enum class MoorDynOptionKind {
  kTimeStep,          // dtM, DT [s]
  kGravity,           // g, gravity [m/s^2]
  kDensity,           // rho, Rho, WtrDnsty, rhoW [kg/m^3]
  kDepth,             // WtrDpth [m]
  kBottomStiffness,   // kBot, kb [Pa/m]
  kBottomDamping,     // cBot, cb [Pa s/m]
  kFriction,          // FrictionCoefficient [-]
  kInitialCondition,  // dtIC, TmaxIC, CdScaleIC, threshIC and their older names
  kWaveKin,           // WaveKin (0: no waves)
  kCurrents,          // Currents (0: no current)
  kOther,
};

MoorDynOptionKind MoorDynOptionKindOf(const std::string& name);

// The option of that kind given last (MoorDyn keeps the last value it reads), or nullptr;
// `name` (optional) receives the name it was given under.
const MoorDynOption* FindMoorDynOption(const MoorDynSystem& system, MoorDynOptionKind kind,
                                       std::string* name = nullptr);

// The value of a checked option of a numeric kind (all but kInitialCondition and kOther).
double MoorDynOptionValue(const MoorDynOption& option);

// Checks the value of an option of a numeric kind against its range: Error
// "file:line: OPTIONS name: expected ..., got "..."". `file` as messages show it.
void CheckMoorDynOption(const std::string& file, const std::string& name,
                        const MoorDynOption& option);

}  // namespace cablefilm
