// BODIES of a MoorDyn file as [[body]] tables: a Fixed or Coupled body (with no motion given,
// it stays where the file puts it) is held; a Free body is free, with its mass, centre of
// gravity, inertia, buoyancy, added mass and drag mapped to cablefilm's axes.
#include <cmath>

#include "scene/moordyn_axes.h"
#include "scene/moordyn_toml_out.h"
#include "scene/scene_limits.h"
#include "scene/text_escape.h"
#include "scene/toml_text.h"

namespace cablefilm {
namespace {

std::string Array(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + TomlNumber(v[i]);
  return s + "]";
}

void WriteFreeBody(const MoorDynBody& b, double rho, MoorDynTomlOut* out) {
  const MoorDynVec cg = MoorDynToCablefilm(b.cg);
  out->Key("mass", TomlNumber(b.mass), "Mass, kg", "Mass");
  out->Key("center_of_gravity", Array({cg[0], cg[1], cg[2]}), "CG, in the body's axes", "CG");
  // About MoorDyn's x, y, z: cablefilm's x, -z, y.
  out->Key("inertia", Array({b.inertia[0], b.inertia[2], b.inertia[1]}),
           "I: Ixx, Izz, Iyy of MoorDyn's axes, kg m^2", "I");
  out->Key("volume", TomlNumber(b.volume), "Volume, m^3: buoyancy at the reference point",
           "Volume");
  // MoorDyn's added mass rho Ca V per translation (x, y, z: cablefilm's x, z, y).
  out->Key("added_mass",
           Array({rho * b.ca[0] * b.volume, rho * b.ca[2] * b.volume, rho * b.ca[1] * b.volume,
                  0.0, 0.0, 0.0}),
           "rho Ca V, kg", "Ca, Volume");
  // MoorDyn's drag 0.5 rho CdA |u_k| u_k per axis on the water's velocity relative to the
  // body: cablefilm's quadratic damping is that law.
  const double h = 0.5 * rho;
  out->Key("quadratic_damping",
           Array({h * b.cda[0], h * b.cda[2], h * b.cda[1], h * b.cda[3], h * b.cda[5],
                  h * b.cda[4]}),
           "0.5 rho CdA", "CdA");
}

}  // namespace

void WriteMoorDynBodies(const MoorDynSystem& system, double rho, MoorDynTomlOut* out) {
  for (const MoorDynBody& b : system.bodies) {
    const bool free = b.attachment == MoorDynAttachment::kFree;
    out->text << "\n[[body]]                          # "
              << EscapeText("BODIES row " + std::to_string(b.id) + ", line " +
                            std::to_string(b.line))
              << "\n";
    out->Table("body[" + std::to_string(b.id - 1) + "]", b.line,
               "BODIES row " + std::to_string(b.id));
    out->Key("name", TomlString(std::to_string(b.id)), "MoorDyn's body ID", "ID");
    out->Key("motion", TomlString(free ? "free" : "fixed"),
             free ? "Free"
                  : b.attachment == MoorDynAttachment::kCoupled
                        ? "Coupled: moved by MoorDyn's calling program; with no motion given it "
                          "stays here"
                        : "Fixed",
             "Attachment");
    const MoorDynVec x = MoorDynToCablefilm(b.position);
    out->Key("position", Array({x[0], x[1], x[2]}),
             "X0 Y0 Z0 (" + FormatNumber(b.position[0]) + ", " + FormatNumber(b.position[1]) +
                 ", " + FormatNumber(b.position[2]) + ")" + (free ? ", a first guess" : ""),
             "X0, Y0, Z0");
    const MoorDynVec a = MoorDynAnglesToCablefilm(b.rotation);
    out->Key("orientation", Array({a[0], a[1], a[2]}),
             "r0 p0 y0 (" + FormatNumber(b.rotation[0]) + ", " + FormatNumber(b.rotation[1]) +
                 ", " + FormatNumber(b.rotation[2]) + ") deg, the same turn in cablefilm's axes",
             "r0, p0, y0");
    if (free) WriteFreeBody(b, rho, out);
  }
}

}  // namespace cablefilm
