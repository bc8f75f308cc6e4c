#include "scene/moordyn_options.h"

#include <map>

#include "core/error.h"
#include "scene/moordyn_row.h"
#include "scene/scene_limits.h"
#include "scene/text_escape.h"

namespace cablefilm {
namespace {

struct Range {
  double lo, hi;
  const char* what;  // the expectation in words, with the unit
};

// The ranges: those of the scene keys each option becomes (scene_limits.h), or, for the
// bottom's pressures, the seabed's per metre of line over a diameter of 1 m.
Range RangeOf(MoorDynOptionKind kind) {
  switch (kind) {
    case MoorDynOptionKind::kTimeStep: return {1e-12, kMaxTime, "a number > 0 in s, at most 1e9"};
    case MoorDynOptionKind::kGravity: return {0, kMaxGravity, "a number from 0 to 1000 in m/s^2"};
    case MoorDynOptionKind::kDensity:
      return {0, kMaxFluidDensity, "a number from 0 to 1e5 in kg/m^3"};
    case MoorDynOptionKind::kDepth: return {0, kMaxLength, "a number from 0 to 1e6 in m"};
    case MoorDynOptionKind::kBottomStiffness:
      return {0, kMaxSeabedStiffness, "a number from 0 to 1e12 in Pa/m"};
    case MoorDynOptionKind::kBottomDamping:
      return {0, kMaxSeabedDamping, "a number from 0 to 1e12 in Pa s/m"};
    case MoorDynOptionKind::kFriction: return {0, kMaxFriction, "a number from 0 to 10"};
    case MoorDynOptionKind::kWaveKin:
    case MoorDynOptionKind::kCurrents: return {0, 100, "a whole number from 0 to 100"};
    default: break;
  }
  return {0, 0, ""};
}

}  // namespace

MoorDynOptionKind MoorDynOptionKindOf(const std::string& name) {
  static const std::map<std::string, MoorDynOptionKind> kNames = {
      {"dtM", MoorDynOptionKind::kTimeStep}, {"DT", MoorDynOptionKind::kTimeStep},
      {"g", MoorDynOptionKind::kGravity}, {"gravity", MoorDynOptionKind::kGravity},
      {"rho", MoorDynOptionKind::kDensity}, {"Rho", MoorDynOptionKind::kDensity},
      {"WtrDnsty", MoorDynOptionKind::kDensity}, {"rhoW", MoorDynOptionKind::kDensity},
      {"WtrDpth", MoorDynOptionKind::kDepth},
      {"kBot", MoorDynOptionKind::kBottomStiffness}, {"kb", MoorDynOptionKind::kBottomStiffness},
      {"cBot", MoorDynOptionKind::kBottomDamping}, {"cb", MoorDynOptionKind::kBottomDamping},
      {"FrictionCoefficient", MoorDynOptionKind::kFriction},
      {"dtIC", MoorDynOptionKind::kInitialCondition},
      {"ICdt", MoorDynOptionKind::kInitialCondition},
      {"TmaxIC", MoorDynOptionKind::kInitialCondition},
      {"ICTmax", MoorDynOptionKind::kInitialCondition},
      {"CdScaleIC", MoorDynOptionKind::kInitialCondition},
      {"ICDfac", MoorDynOptionKind::kInitialCondition},
      {"threshIC", MoorDynOptionKind::kInitialCondition},
      {"ICthresh", MoorDynOptionKind::kInitialCondition},
      {"WaveKin", MoorDynOptionKind::kWaveKin}, {"Currents", MoorDynOptionKind::kCurrents},
  };
  const auto it = kNames.find(name);
  return it == kNames.end() ? MoorDynOptionKind::kOther : it->second;
}

const MoorDynOption* FindMoorDynOption(const MoorDynSystem& system, MoorDynOptionKind kind,
                                       std::string* name) {
  const MoorDynOption* last = nullptr;
  for (const auto& [key, option] : system.options)
    if (MoorDynOptionKindOf(key) == kind && (!last || option.line > last->line)) {
      last = &option;
      if (name) *name = key;
    }
  return last;
}

double MoorDynOptionValue(const MoorDynOption& option) {
  double v = 0;
  ParseMoorDynNumber(option.text, &v);
  return v;
}

void CheckMoorDynOption(const std::string& file, const std::string& name,
                        const MoorDynOption& option) {
  const MoorDynOptionKind kind = MoorDynOptionKindOf(name);
  if (kind == MoorDynOptionKind::kInitialCondition || kind == MoorDynOptionKind::kOther) return;
  const Range range = RangeOf(kind);
  double v = 0;
  const bool whole = kind == MoorDynOptionKind::kWaveKin || kind == MoorDynOptionKind::kCurrents;
  int w = 0;
  const bool ok = whole ? ParseMoorDynWhole(option.text, &w) && w <= range.hi
                        : ParseMoorDynNumber(option.text, &v) && v >= range.lo && v <= range.hi;
  if (ok) return;
  throw Error(file + ":" + std::to_string(option.line) + ": OPTIONS " + EscapeText(name) +
              ": expected " + range.what + ", got " + QuoteText(option.text));
}

}  // namespace cablefilm
