#include "scene/moordyn_convert.h"

#include <cmath>
#include <filesystem>
#include <unordered_set>

#include "core/error.h"
#include "scene/moordyn_axes.h"
#include "scene/moordyn_checks.h"
#include "scene/moordyn_toml_out.h"
#include "scene/scene_limits.h"
#include "scene/text_escape.h"
#include "scene/toml_text.h"

namespace cablefilm {
namespace {

constexpr std::size_t kMaxTitleCharacters = 200;

std::string Row(const char* section, int row, int line) {
  return std::string(section) + " row " + std::to_string(row) + ", line " + std::to_string(line);
}

std::string Vector(const MoorDynVec& v) {
  return "[" + TomlNumber(v[0]) + ", " + TomlNumber(v[1]) + ", " + TomlNumber(v[2]) + "]";
}

std::string Triple(const MoorDynVec& v) {
  return "(" + FormatNumber(v[0]) + ", " + FormatNumber(v[1]) + ", " + FormatNumber(v[2]) + ")";
}

// The free text's first line, at most kMaxTitleCharacters (UTF-8 characters, not bytes); the
// file's name when there is none.
std::string Title(const MoorDynSystem& system) {
  if (system.title.empty()) return std::filesystem::path(system.file).stem().string();
  std::size_t characters = 0, end = 0;
  for (; end < system.title.size(); ++end)
    if ((static_cast<unsigned char>(system.title[end]) & 0xC0) != 0x80 &&
        ++characters > kMaxTitleCharacters)
      break;
  return system.title.substr(0, end);
}

// A system as ReadMoorDynFile returns it: at least one line, every reference defined (the
// conversion follows them). A system built otherwise is checked here.
void CheckSystem(const MoorDynSystem& system, const std::string& file) {
  if (system.lines.empty())
    throw Error(file + ": no lines; expected a MoorDyn system with at least one line");
  MoorDynSystem copy = system;
  CheckMoorDynReferences(file, &copy);
}

// Line type `index` (its row is index + 1). `used`: a line of LINES is of this type (what a
// type no line uses has does not matter).
void WriteMaterial(const MoorDynLineType& t, std::size_t index, bool used, MoorDynTomlOut* out) {
  const double area = M_PI * t.diameter * t.diameter / 4;  // m^2
  const std::string name = "LINE TYPES \"" + t.name + "\": ";
  out->text << "\n[[material]]                      # "
            << EscapeText("LINE TYPES \"" + t.name + "\", line " + std::to_string(t.line))
            << "\n";
  out->Table("material[" + std::to_string(index) + "]", t.line,
             "LINE TYPES row " + std::to_string(index + 1));
  out->Key("name", TomlString(t.name), "TypeName", "TypeName");
  out->Key("diameter", TomlNumber(t.diameter), "Diam, m: volume-equivalent (buoyancy, drag)",
           "Diam");
  out->Key("area", TomlNumber(area), "pi d^2 / 4, m^2: the volume-equivalent section", "Diam");
  out->Key("mass_per_length", TomlNumber(t.mass_per_length), "Mass/m, kg/m", "Mass/m");
  out->Key("youngs_modulus", TomlNumber(t.ea / area),
           name + "EA " + FormatNumber(t.ea) + " N / area, Pa", "EA");
  out->Key("drag_coefficient", TomlNumber(t.cd), "Cd, normal, on d l", "Cd");
  out->Key("added_mass_coefficient", TomlNumber(t.ca), "Ca, normal", "Ca");
  if (t.cd_ax != 0)
    out->Key("tangential_drag_coefficient", TomlNumber(t.cd_ax), "CdAx, along, on pi d l",
             "CdAx");
  if (t.ca_ax != 0)
    out->Key("tangential_added_mass_coefficient", TomlNumber(t.ca_ax), "CaAx, along", "CaAx");
  if (t.ba >= 0)
    out->Key("axial_damping", TomlNumber(t.ba / area),
             name + "BA " + FormatNumber(t.ba) + " N s / area, Pa s", "BA/-zeta");
  else
    out->Key("moordyn_axial_damping_ratio", TomlNumber(-t.ba),
             name + "BA/-zeta " + FormatNumber(t.ba) + ": BA = zeta l sqrt(EA mu), as MoorDyn",
             "BA/-zeta");
  if (!used) return;
  if (t.ei != 0)
    out->Warn(t.line, name + "EI " + FormatNumber(t.ei) + " N m^2: bending stiffness ignored");
  if (t.cl != 0)
    out->Warn(t.line,
              name + "Cl " + FormatNumber(t.cl) + ": vortex-induced vibration not modelled");
}

const char* AttachmentName(MoorDynAttachment a) {
  switch (a) {
    case MoorDynAttachment::kFixed: return "Fixed";
    case MoorDynAttachment::kFree: return "Free";
    case MoorDynAttachment::kCoupled: return "Coupled";
    case MoorDynAttachment::kBody: return "Body";
  }
  return "";
}

// Why a point not free is fixed where it is written.
std::string FixedReason(const MoorDynPoint& p) {
  if (p.attachment == MoorDynAttachment::kCoupled)
    return "Coupled: moved by MoorDyn's calling program; with no motion given it stays here";
  return "Fixed";
}

// A free point's mass, buoyancy, added mass and drag, only those that are not 0: MoorDyn's
// 0.5 rho CdA |u| u is cablefilm's per-axis rho/2 C S |u| u_i with C = 1, S = CdA on every
// axis, and its added mass rho Ca V an added volume Ca V on every axis.
void WriteFreePoint(const MoorDynPoint& p, MoorDynTomlOut* out) {
  if (p.mass > 0) out->Key("mass", TomlNumber(p.mass), "Mass, kg", "Mass");
  if (p.volume > 0) out->Key("volume", TomlNumber(p.volume), "Volume, m^3: buoyancy", "Volume");
  const double added = p.ca * p.volume;  // m^3
  if (added > 0)
    out->Key("added_volume", Vector({added, added, added}),
             "Ca " + FormatNumber(p.ca) + " x Volume, m^3", "Ca, Volume");
  if (p.cda > 0) {
    out->Key("drag_coefficient", "[1.0, 1.0, 1.0]", "with drag_area: CdA on every axis", "CdA");
    out->Key("drag_area", Vector({p.cda, p.cda, p.cda}), "CdA, m^2", "CdA");
  }
}

void WritePoint(const MoorDynSystem& system, const MoorDynPoint& p, MoorDynTomlOut* out) {
  const bool free = p.attachment == MoorDynAttachment::kFree;
  const MoorDynVec global = MoorDynPointPosition(system, p);
  out->text << "\n[[point]]                         # "
            << EscapeText(Row("POINTS", p.id, p.line)) << "\n";
  out->Table("point[" + std::to_string(p.id - 1) + "]", p.line,
             "POINTS row " + std::to_string(p.id));
  out->Key("name", TomlString(std::to_string(p.id)), "MoorDyn's point ID", "ID");
  if (p.attachment == MoorDynAttachment::kBody) {  // in the body's axes, moving with it
    const MoorDynBody& b = system.bodies[static_cast<std::size_t>(p.body - 1)];
    out->Key("body", TomlString(std::to_string(p.body)),
             "Body" + std::to_string(p.body) + " (" + AttachmentName(b.attachment) + ")",
             "Attachment");
    out->Key("position", Vector(MoorDynToCablefilm(p.position)),
             "MoorDyn's body frame " + Triple(p.position) + "; at rest " + Triple(global),
             "X, Y, Z");
    return;
  }
  out->Key("motion", TomlString(free ? "free" : "fixed"),
           free ? "Free" : FixedReason(p), "Attachment");
  out->Key("position", Vector(MoorDynToCablefilm(global)),
           "MoorDyn " + Triple(global) + (free ? ", a first guess" : ""), "X, Y, Z");
  if (free) WriteFreePoint(p, out);
}

void WriteLine(const MoorDynLine& l, MoorDynTomlOut* out) {
  out->text << "\n[[line]]                          # " << EscapeText(Row("LINES", l.id, l.line))
            << "\n";
  const std::string key = "line[" + std::to_string(l.id - 1) + "]";
  const std::string row = "LINES row " + std::to_string(l.id);
  out->Table(key, l.line, row);
  out->Key("name", TomlString(std::to_string(l.id)), "MoorDyn's line ID", "ID");
  out->Key("model", TomlString("elastic"));
  out->Key("start", TomlString(std::to_string(l.point_a)), "AttachA: node 0", "AttachA");
  out->Key("end", TomlString(std::to_string(l.point_b)), "AttachB", "AttachB");
  out->text << "\n[[line.section]]\n";
  out->Table(key + ".section[0]", l.line, row);
  out->Key("material", TomlString(l.type), "LineType", "LineType");
  out->Key("length", TomlNumber(l.length), "UnstrLen, m", "UnstrLen");
  out->Key("segments", std::to_string(l.segments), "NumSegs", "NumSegs");
}

std::string Header(const MoorDynSystem& system, const std::vector<std::string>& warnings) {
  std::ostringstream head;
  head << "# Converted from the MoorDyn v2 input file " << EscapeText(system.file)
       << " (docs/moordyn.md).\n"
       << "# MoorDyn's axes are z up, cablefilm's y up: a MoorDyn point (x, y, z) is written "
          "(x, z, -y).\n";
  if (!warnings.empty()) head << "#\n# Warnings:\n";
  for (const std::string& w : warnings) head << "#   " << w << "\n";  // escaped already
  head << "\ntitle = " << TomlString(Title(system)) << "\n";
  return head.str();
}

}  // namespace

std::string MoorDynToToml(const MoorDynSystem& system, std::vector<std::string>* warnings,
                          KeySources* sources) {
  MoorDynTomlOut out;
  out.file = EscapeText(system.file);
  CheckSystem(system, out.file);
  WriteMoorDynEnvironment(system, &out);
  std::unordered_set<std::string> used;  // the types lines have
  for (const MoorDynLine& l : system.lines) used.insert(l.type);
  for (std::size_t i = 0; i < system.line_types.size(); ++i) {
    const MoorDynLineType& t = system.line_types[i];
    WriteMaterial(t, i, used.count(t.name) > 0, &out);
  }
  WriteMoorDynBodies(system, MoorDynDensity(system), &out);
  for (const MoorDynPoint& p : system.points) WritePoint(system, p, &out);
  for (const MoorDynLine& l : system.lines) WriteLine(l, &out);
  std::vector<std::string> all = system.warnings;
  all.insert(all.end(), out.warnings.begin(), out.warnings.end());
  if (warnings) warnings->insert(warnings->end(), out.warnings.begin(), out.warnings.end());
  if (sources) *sources = std::move(out.sources);
  return Header(system, all) + out.text.str();
}

}  // namespace cablefilm
