// OPTIONS -> [environment] and [seabed], each value's source in its comment; the options
// cablefilm does not map listed as comments (hints, the initial-condition solver's settings)
// or warnings (the rest).
#include <algorithm>
#include <map>

#include "scene/moordyn_axes.h"
#include "scene/moordyn_options.h"
#include "scene/moordyn_toml_out.h"
#include "scene/scene_limits.h"
#include "scene/toml_text.h"

namespace cablefilm {
namespace {

// MoorDyn v2's defaults, from its documentation ("Input Files", Options; v2.7.1). Older
// MoorDyn-C sources set g = 9.80665 (v2.0) or 9.8 (the v2 alphas); the documented value is
// taken, and written out, so the scene does not depend on cablefilm's own default.
constexpr double kDefaultGravity = 9.81;    // m/s^2
constexpr double kDefaultDensity = 1025.0;  // kg/m^3
constexpr double kDefaultDepth = 0.0;       // m (raised to the deepest point, see SeabedDepth)
constexpr double kDefaultKBot = 3.0e6;      // Pa/m
constexpr double kDefaultCBot = 3.0e5;      // Pa s/m
constexpr double kDefaultFriction = 0.0;

struct Sourced {
  double value;
  std::string source;  // for the comment
  int line;            // 0: MoorDyn's default
  std::string place;   // "OPTIONS name" (a default: "")
};

Sourced OptionOr(const MoorDynSystem& system, MoorDynOptionKind kind, double fallback,
                 const std::string& default_name) {
  std::string name;
  if (const MoorDynOption* option = FindMoorDynOption(system, kind, &name))
    return {MoorDynOptionValue(*option),
            "OPTIONS " + name + ", line " + std::to_string(option->line), option->line,
            "OPTIONS " + name};
  return {fallback, "MoorDyn's default " + default_name, 0, ""};
}

// MoorDyn's seabed: flat at z = -WtrDpth, WtrDpth raised to the deepest point's depth when a
// point lies below it (MoorDyn2.cpp, reading POINTS: "make default water depth at least the
// depth of the lowest node"; here every point's global position, Body#N points through their
// body's pose).
Sourced SeabedDepth(const MoorDynSystem& system, MoorDynTomlOut* out) {
  Sourced depth = OptionOr(system, MoorDynOptionKind::kDepth, kDefaultDepth, "WtrDpth 0 m");
  const MoorDynPoint* deepest = nullptr;
  double lowest = -depth.value;  // m, z of the deepest point below the seabed
  for (const MoorDynPoint& p : system.points) {
    const double z = MoorDynPointPosition(system, p)[2];
    if (z < lowest) lowest = z, deepest = &p;
  }
  if (!deepest) return depth;
  const double z = lowest;
  if (depth.line > 0)
    out->Warn(deepest->line, "point " + std::to_string(deepest->id) + " lies below the seabed "
              "of WtrDpth " + FormatNumber(depth.value) + " m (z = " + FormatNumber(z) +
              " m): the seabed is lowered to it, as MoorDyn does");
  return {-z, depth.source + ", the seabed lowered to point " + std::to_string(deepest->id) +
                  " as MoorDyn does", depth.line, depth.place};
}

// The diameter the seabed's pressures act on: cablefilm's stiffness and damping are per metre
// of line, MoorDyn's kBot and cBot per unit of d l. One scene-wide value: the longest line's.
const MoorDynLineType& SeabedLineType(const MoorDynSystem& system, MoorDynTomlOut* out) {
  const MoorDynLine& longest = *std::max_element(
      system.lines.begin(), system.lines.end(),
      [](const MoorDynLine& a, const MoorDynLine& b) { return a.length < b.length; });
  const auto types = MoorDynLineTypeIndex(system);
  const MoorDynLineType& type = system.line_types[types.at(longest.type)];
  std::map<std::string, double> others;
  for (const MoorDynLine& line : system.lines) {
    const MoorDynLineType& t = system.line_types[types.at(line.type)];
    if (t.diameter != type.diameter) others[t.name] = t.diameter;
  }
  std::string names;
  for (const auto& [name, d] : others)
    names += (names.empty() ? "" : ", ") + ("\"" + name + "\" (d " + FormatNumber(d) + " m)");
  if (!names.empty())
    out->Warn(type.line, "the seabed's stiffness and damping are kBot and cBot times the "
              "diameter of \"" + type.name + "\" (" + FormatNumber(type.diameter) + " m), the "
              "longest line's (line " + std::to_string(longest.id) + "); also applied per metre "
              "to the line types of other diameters: " + names);
  return type;
}

// Returns g [m/s^2] and its source.
Sourced WriteEnvironment(const MoorDynSystem& system, MoorDynTomlOut* out) {
  const Sourced g = OptionOr(system, MoorDynOptionKind::kGravity, kDefaultGravity, "g");
  const Sourced rho = OptionOr(system, MoorDynOptionKind::kDensity, kDefaultDensity, "rho");
  out->text << "\n[environment]\n";
  out->Table("environment", 0, "");
  out->Key("gravity", TomlNumber(g.value), "m/s^2; " + g.source);
  out->Source("gravity", g.line, g.place);
  out->Key("fluid_density", TomlNumber(rho.value), "kg/m^3; " + rho.source);
  out->Source("fluid_density", rho.line, rho.place);
  return g;
}

// Returns the seabed's depth below the still water level [m] (-1 without a seabed) and its
// source.
Sourced WriteSeabed(const MoorDynSystem& system, MoorDynTomlOut* out) {
  const Sourced k = OptionOr(system, MoorDynOptionKind::kBottomStiffness, kDefaultKBot, "kBot");
  const Sourced c = OptionOr(system, MoorDynOptionKind::kBottomDamping, kDefaultCBot, "cBot");
  const Sourced mu =
      OptionOr(system, MoorDynOptionKind::kFriction, kDefaultFriction, "FrictionCoefficient");
  if (k.value == 0) {
    out->Warn(k.line, "kBot 0: MoorDyn's seabed has no stiffness; the scene has no seabed");
    out->text << "\n";
    out->Comment("No [seabed]: " + k.source + " is 0.");
    return {-1.0, k.source, k.line, k.place};
  }
  const Sourced depth = SeabedDepth(system, out);
  const MoorDynLineType& type = SeabedLineType(system, out);
  const std::string d = " x d " + FormatNumber(type.diameter) + " m of \"" + type.name + "\"";
  out->text << "\n[seabed]                          # MoorDyn's: flat, at z = -WtrDpth\n";
  out->Table("seabed", 0, "");
  out->Key("y", TomlNumber(-depth.value), "m, -WtrDpth; " + depth.source);
  out->Source("y", depth.line, depth.place);
  out->Key("stiffness", TomlNumber(k.value * type.diameter),
           "N/m per m: kBot " + FormatNumber(k.value) + " Pa/m" + d + "; " + k.source);
  out->Source("stiffness", k.line, k.place);
  out->Key("damping", TomlNumber(c.value * type.diameter),
           "N s/m per m: cBot " + FormatNumber(c.value) + " Pa s/m" + d + "; " + c.source);
  out->Source("damping", c.line, c.place);
  out->Key("friction", TomlNumber(mu.value), mu.source);
  out->Source("friction", mu.line, mu.place);
  return depth;
}

// Where MoorDyn takes its wave kinematics (WaveKin): its own waves (2, 3 from a grid, 7 at the
// nodes; 0, none, alike) are stretched to the instantaneous surface and held at the surface's
// above it, Wheeler's stretching (Waves.cpp, SpectrumKin.cpp); externally driven waves (1) are
// the calling program's as it gives them at each node, stretched by nothing: the formulas at
// the node's own elevation.
void WriteKinematics(const MoorDynSystem& system, MoorDynTomlOut* out) {
  std::string name;
  const MoorDynOption* wavekin = FindMoorDynOption(system, MoorDynOptionKind::kWaveKin, &name);
  if (wavekin && MoorDynOptionValue(*wavekin) == 1) {
    out->Key("kinematics", TomlString("linear"),
             "OPTIONS " + name + " = 1: MoorDyn stretches no kinematics it is given");
    out->Source("kinematics", wavekin->line, "OPTIONS " + name);
    return;
  }
  out->Key("kinematics", TomlString("wheeler"),
           "MoorDyn's own waves are stretched to the instantaneous surface");
  if (wavekin) out->Source("kinematics", wavekin->line, "OPTIONS " + name);
}

// MoorDyn's still water surface at z = 0: a line's segments above it have no buoyancy, drag or
// added mass (Line.cpp, the submerged fraction of each segment, waves or not). In cablefilm a
// surface comes with [waves]; height 0 is still water. Without it the fluid would fill all
// space and a float at the surface would rise out of the water with its full buoyancy.
void WriteStillSurface(const MoorDynSystem& system, const Sourced& gravity, double rho,
                       const Sourced& seabed, MoorDynTomlOut* out) {
  constexpr double kSomePeriod = 10.0;  // s: any; still water has none
  if (rho == 0) return;  // vacuum: no fluid to have a surface
  if (!(gravity.value > 0)) {
    out->Warn(gravity.line, "g = 0: the scene has no water surface (cablefilm's needs gravity): the fluid "
                 "fills all space, above z = 0 too");
    return;
  }
  if (seabed.value >= 0 && seabed.value < 1e-3) {
    out->Warn(seabed.line, "the seabed is at the still water level (z = 0): the scene has no water "
                 "surface, the fluid fills all space");
    return;
  }
  out->text << "\n[waves]                           # MoorDyn's still water surface at z = 0\n";
  out->Table("waves", 0, "");
  out->Key("height", "0.0", "m: still water; above the surface a line has no buoyancy, drag "
                            "or added mass, as MoorDyn's");
  out->Key("period", TomlNumber(kSomePeriod), "s: none in still water (a period is required)");
  if (seabed.value < 0) {  // no seabed: the waves' depth alone (any: still water)
    double depth = 1.0;
    for (const MoorDynPoint& p : system.points)
      depth = std::max(depth, -MoorDynPointPosition(system, p)[2]);
    out->Key("depth", TomlNumber(depth), "m: no seabed; the deepest point's depth");
  }
  WriteKinematics(system, out);
}

// TmaxIC (ICTmax) = 0: MoorDyn makes no initial-condition solve and starts from the file's
// positions.
bool StartsAsGiven(const std::string& name, const MoorDynOption& option) {
  return (name == "TmaxIC" || name == "ICTmax") && MoorDynOptionValue(option) == 0;
}

void WriteInitialState(const MoorDynSystem& system, MoorDynTomlOut* out) {
  for (const auto& [name, option] : system.options) {
    if (!StartsAsGiven(name, option)) continue;
    out->text << "\n[initial]                         # OPTIONS " << name << " = " << option.text
              << ", line " << option.line << ": no statics, as MoorDyn\n";
    out->Table("initial", 0, "");
    out->Key("state", "\"straight\"",
             "points and bodies where the file puts them, lines straight between them");
    out->Source("state", option.line, "OPTIONS " + name);
    return;
  }
}

// The options not mapped above: a comment (returned) for the hints and the initial-condition
// solver's settings, a warning for what changes the physics or is unknown.
std::string NoteOption(const std::string& name, const MoorDynOption& option,
                       MoorDynTomlOut* out) {
  const std::string given = "OPTIONS " + name + " = " + option.text;
  const std::string at = " (line " + std::to_string(option.line) + ")";
  switch (MoorDynOptionKindOf(name)) {
    case MoorDynOptionKind::kTimeStep:
      return given + " s" + at + ": MoorDyn's time step, a hint only; cablefilm chooses its "
             "own (simulation.time_step)";
    case MoorDynOptionKind::kInitialCondition:
      if (StartsAsGiven(name, option)) return "";  // mapped: [initial]
      return given + at + ": MoorDyn's initial-condition settings, ignored: cablefilm solves "
             "the statics by Newton";
    case MoorDynOptionKind::kWaveKin:
    case MoorDynOptionKind::kCurrents: {
      const bool waves = MoorDynOptionKindOf(name) == MoorDynOptionKind::kWaveKin;
      if (MoorDynOptionValue(option) != 0)
        out->Warn(option.line, given + ": " + (waves ? "waves" : "currents") +
                                   " are not imported (MoorDyn takes them from its files or "
                                   "its calling program): the scene's water is still");
      return "";
    }
    case MoorDynOptionKind::kOther: out->Warn(option.line, given + ": ignored"); return "";
    default: return "";  // mapped
  }
}

void NoteOptions(const MoorDynSystem& system, MoorDynTomlOut* out) {
  std::vector<std::pair<std::string, const MoorDynOption*>> in_order;
  for (const auto& [name, option] : system.options) in_order.push_back({name, &option});
  std::sort(in_order.begin(), in_order.end(),
            [](const auto& a, const auto& b) { return a.second->line < b.second->line; });
  std::vector<std::string> comments;
  for (const auto& [name, option] : in_order) {
    const std::string comment = NoteOption(name, *option, out);
    if (!comment.empty()) comments.push_back(comment);
  }
  if (!comments.empty()) out->text << "\n";
  for (const std::string& comment : comments) out->Comment(comment);
}

}  // namespace

double MoorDynDensity(const MoorDynSystem& system) {
  return OptionOr(system, MoorDynOptionKind::kDensity, kDefaultDensity, "rho").value;
}

void WriteMoorDynEnvironment(const MoorDynSystem& system, MoorDynTomlOut* out) {
  const Sourced gravity = WriteEnvironment(system, out);
  const Sourced seabed = WriteSeabed(system, out);
  WriteStillSurface(system, gravity, MoorDynDensity(system), seabed, out);
  WriteInitialState(system, out);
  NoteOptions(system, out);
}

}  // namespace cablefilm
