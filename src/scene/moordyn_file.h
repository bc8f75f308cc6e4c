#pragma once
// A MoorDyn v2 input file read as it is into plain structs (MoorDyn's axes: z up, the still
// water surface at z = 0): its line types, bodies, points, lines and options, each remembering
// the line of the file it came from so that later steps (the conversion to a cablefilm scene)
// can name it. Every problem of the file is an Error "file:line: SECTION row n, column C:
// expected ..., got "..."". What MoorDyn would accept but cablefilm cannot use (rods,
// viscoelastic EA, a line on a rod end) is refused here with the reason; what cablefilm
// ignores is left to the conversion's warnings. docs/moordyn.md describes both.
#include <array>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

namespace cablefilm {

// A row of LINE TYPES: MoorDyn's cross-section and hydrodynamic coefficients.
struct MoorDynLineType {
  int line = 0;              // of the file, 1-based
  std::string name;          // TypeName
  double diameter = 0;       // Diam [m], volume-equivalent: sets buoyancy and drag
  double mass_per_length = 0;  // Mass/m [kg/m] in air
  double ea = 0;             // EA [N]
  double ba = 0;             // BA/-zeta: BA [N s] when >= 0, else -zeta (fraction of critical)
  double ei = 0;             // EI [N m^2]
  double cd = 0, ca = 0;     // normal drag (on d l) and added mass coefficients [-]
  double cd_ax = 0, ca_ax = 0;  // tangential drag (on pi d l) and added mass coefficients [-]
  double cl = 0;             // optional VIV lift coefficient [-] (0: no VIV)
};

// How a body or a point is held: by nothing (Fixed), by MoorDyn's dynamics (Free), by the
// calling program (Coupled, also "Vessel"), or, for a point, by a body (Body#N).
enum class MoorDynAttachment { kFixed, kFree, kCoupled, kBody };

// A row of BODIES.
struct MoorDynBody {
  int line = 0;
  int id = 0;
  MoorDynAttachment attachment = MoorDynAttachment::kFixed;  // kFixed, kFree or kCoupled
  std::array<double, 3> position{};   // X0, Y0, Z0 [m]
  std::array<double, 3> rotation{};   // r0, p0, y0 [deg]: roll, pitch, yaw
  double mass = 0;                    // [kg]
  std::array<double, 3> cg{};         // [m], body frame (one value in the file: along z)
  std::array<double, 3> inertia{};    // Ixx, Iyy, Izz [kg m^2]
  double volume = 0;                  // [m^3]
  std::array<double, 6> cda{};        // [m^2]: three translations, three rotations
  std::array<double, 3> ca{};         // [-]
};

// A row of POINTS.
struct MoorDynPoint {
  int line = 0;
  int id = 0;
  MoorDynAttachment attachment = MoorDynAttachment::kFixed;
  int body = 0;                       // the body's ID for kBody, else 0
  std::array<double, 3> position{};   // X, Y, Z [m]: global, or the body frame for kBody
  double mass = 0;                    // [kg]
  double volume = 0;                  // [m^3]
  std::array<double, 3> force{};      // FX, FY, FZ [N] (the older 12-column form only)
  double cda = 0;                     // drag coefficient times area [m^2], all directions
  double ca = 0;                      // added mass coefficient on the volume [-]
};

// A row of LINES.
struct MoorDynLine {
  int line = 0;
  int id = 0;
  std::string type;        // a LINE TYPES name
  int point_a = 0;         // AttachA: node 0's point ID
  int point_b = 0;         // AttachB: the last node's point ID
  double length = 0;       // UnstrLen [m]
  int segments = 0;        // NumSegs
};

// A row of OPTIONS: "value name [description]", the value kept as written.
struct MoorDynOption {
  int line = 0;
  std::string text;
};

struct MoorDynSystem {
  std::string file;        // the name messages use
  int last_line = 0;       // the file's number of lines
  std::string title;       // the first non-empty line of the free text at the top
  std::vector<MoorDynLineType> line_types;
  std::vector<MoorDynBody> bodies;   // bodies[i].id == i + 1
  std::vector<MoorDynPoint> points;  // points[i].id == i + 1
  std::vector<MoorDynLine> lines;    // lines[i].id == i + 1
  std::map<std::string, MoorDynOption> options;  // by the name as written (the last one given)
  std::vector<std::string> warnings;  // "file:line: ..." for what is skipped; file text escaped
};

// Reads the file at `path` (at most 16 MiB). Throws Error.
MoorDynSystem ReadMoorDynFile(const std::string& path);

// The same from the file's text; `file` names it in messages.
MoorDynSystem ReadMoorDynText(const std::string& text, const std::string& file);

// Each line type's name to its index in line_types: a lookup per line that does not scan.
std::unordered_map<std::string, std::size_t> MoorDynLineTypeIndex(const MoorDynSystem& system);

// A MoorDyn number ("1.5", "-3e6", "+2", "384.243E6"): finite, nothing else in the text.
bool ParseMoorDynNumber(const std::string& text, double* value);

}  // namespace cablefilm
