#pragma once
// The scene as read from its TOML file: plain data with defaults and units, no behaviour.
// Field names follow scene-format.md; symbols in brackets are those of Polachek et al. (1963).
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/line_model.h"
#include "core/sea_components.h"
#include "scene/key_source.h"
#include "scene/rao_table.h"

namespace cablefilm {

struct EnvironmentDef {
  double gravity = 9.80665;       // g [m/s^2]
  double fluid_density = 1025.0;  // rho [kg/m^3]; 0 = vacuum
  double current = 0.0;           // c [m/s], uniform, along current_direction
  // Or a profile: speeds [m/s] at elevations y [m], y strictly increasing, linearly
  // interpolated, constant beyond the ends (current is then 0). Empty: uniform.
  CurrentProfile current_profile;
  // The horizontal direction the current (uniform and profile) flows along: +x unless
  // current_heading [deg from +x towards +z] or the vector form [u, w] says otherwise.
  Vec current_direction = Vec(1.0, 0.0, 0.0);
  // Or over time: current_file's rows t,speed,heading (a uniform current of that speed) or
  // t,scale,heading (the current above scaled), each turned to the heading (deg in the file,
  // rad here). Null: steady.
  std::string current_file;
  std::shared_ptr<const CurrentHistory> current_history;
};

// [seabed]: a flat seabed (optional), as the core takes it (core/line_model.h).
using SeabedDef = SeabedSpec;

// [waves]: what sea: the regular wave, a spectrum's components, or a recorded elevation's.
enum class SeaKind { kRegular, kJonswap, kPiersonMoskowitz, kTable, kRecord };

struct WavesDef {                  // [waves]: linear (Airy) waves (optional)
  bool present = false;
  SeaKind sea = SeaKind::kRegular; // `spectrum`
  double height = 0;               // H [m], crest to trough (0: still water with a surface);
                                   // an irregular sea's Hs (given, or 4 sqrt(m0) of its table
                                   // or record)
  double period = 0;               // T [s]; an irregular sea's Tp (given, or its table's or
                                   // record's peak)
  double depth = 0;                // h [m], still water level to the bed; default
                                   // surface_y - seabed.y with a [seabed]
  double surface_y = 0;            // the still water level's elevation [m]
  double phase = 0;                // [deg]: the phase of the surface at x = 0, t = 0 (0: a crest)
  double heading = 0;              // [deg]: the direction they travel, from +x towards +z
  double ramp_rate = 0;            // nu [1/s] of eq. (3)'s ramp R(t); default 4 / T
  WaveKinematics kinematics = WaveKinematics::kWheeler;  // where the Airy formulas are
                                   // evaluated (core/waves.h): "wheeler", "linear", "extrapolated"
  // An irregular sea (sea != kRegular):
  double gamma = 0;                // JONSWAP's peak enhancement (given, or DNV's rule)
  std::string file;                // resolved path of its table ("omega,S") or record ("t,eta")
  std::vector<double> table_omega, table_density;  // [rad/s], [m^2 s/rad]
  std::vector<double> record_t, record_eta;        // [s], [m]
  std::array<double, 2> record_point{};  // (x, z) [m] where the record was measured
  std::uint64_t seed = 1;          // a spectrum's random phases, frequencies and directions
  int components = 200;            // a spectrum's components
  std::array<double, 2> band{};    // a spectrum's band [rad/s]; 0, 0: its own
  double spreading = 0;            // s of cos-2s; 0: long-crested
  std::shared_ptr<const SeaComponents> components_made;  // what the loader made of the above
};

struct MaterialDef {
  std::string name;
  double diameter = 0;                 // d [m], for drag
  double area = 0;                     // sigma [m^2], for stiffness and buoyancy
  double mass_per_length = 0;          // mu [kg/m]
  double youngs_modulus = 0;           // E [Pa]
  double drag_coefficient = 1.2;       // C^D, normal drag
  double added_mass_coefficient = 1.0; // k, normal virtual inertia
  double axial_damping = 0;            // internal axial damping BA [Pa s]: stress BA x strain rate
  double axial_damping_ratio = 0;      // or zeta, of critical for each link's axial mode
  double moordyn_axial_damping_ratio = 0;  // or zeta as MoorDyn's negative BA: c = zeta sqrt(EA mu)
  double minimum_breaking_load = 0;    // MBL [N]: utilisation = tension / MBL; 0 = not given
  double tangential_drag_coefficient = 0;       // C^T, along the link on pi d l (MoorDyn's CdAx)
  double tangential_added_mass_coefficient = 0; // k^t, along the link (MoorDyn's CaAx)
  bool axial_froude_krylov = true;     // in waves, the Froude-Krylov force along the line too
};

struct SectionDef {
  int material = 0;     // index into SceneDef::materials
  double length = 0;    // unstretched [m]
  int segments = 0;     // links in this section
};

struct WeightDef {                      // a suspended prism at a station
  double at = 0;                        // unstretched arc length from station 0 [m]
  double mass = 0;                      // m* [kg]
  double volume = 0;                    // V* [m^3], buoyancy
  // [x, y, z]; two values [x, y] mean [x, y, x]: the same across both horizontal axes.
  std::array<double, 3> added_volume{};      // [V^x, V^y, V^z] [m^3]
  std::array<double, 3> drag_coefficient{};  // [C^x, C^y, C^z]
  std::array<double, 3> drag_area{};         // [S^x, S^y, S^z] [m^2]
};

enum class EndMotionKind { kFixed, kFree, kTrochoid, kTable };

struct EndDef {
  EndMotionKind motion = EndMotionKind::kFixed;
  std::array<double, 3> position{};       // rest position [x^0, y^0, z^0] [m] (z^0 = 0 in 2D)
  std::array<double, 2> x_amplitudes{};   // [a, b] [m], eq. (3)
  std::array<double, 2> y_amplitudes{};   // [c, d] [m], eq. (3)
  std::array<double, 2> z_amplitudes{};   // [e, f] [m], eq. (3) in 3D
  double period = 0;                      // 2 pi / omega [s]
  double ramp_rate = 0;                   // nu [1/s]
  // A body's angles, about x, y and z [deg]: eq. (3)'s [cos, sin] amplitudes (same period and
  // ramp as the offsets), added to its orientation.
  std::array<double, 2> rx_amplitudes{};
  std::array<double, 2> ry_amplitudes{};
  std::array<double, 2> rz_amplitudes{};
  // motion = "table": the table's; motion = "wave": the table added to the waves' motion (a
  // drift or a recorded motion; `drift_file`), empty if none.
  std::string table_file;                 // resolved path of the CSV (t, x, y[, z[, rx, ry, rz]])
  // Rows (t [s], dx, dy, dz [m], drx, dry, drz [deg]); the angles (a body's only) 0 unless the
  // table gives them.
  std::vector<std::array<double, 7>> table;
  TableInterpolation interpolation = TableInterpolation::kSpline;  // how the rows are joined
  // motion = "wave": the end follows the wave at its rest x through these response amplitude
  // operators, [ratio of the wave's amplitude (m/m), phase lead (deg)]; the loader turns them
  // into the trochoid of eq. (3) above (amplitudes, the wave's period and ramp).
  bool follows_wave = false;
  std::array<double, 2> x_rao{};
  std::array<double, 2> y_rao{};
  std::array<double, 2> z_rao{};
  // A body's angles about x, y, z: [deg per m of the wave's amplitude, phase lead (deg)].
  std::array<double, 2> rx_rao{};
  std::array<double, 2> ry_rao{};
  std::array<double, 2> rz_rao{};
  // Or the RAOs by heading and frequency from a file (rao_table.h): its resolved path and rows.
  std::string rao_file;
  std::shared_ptr<const RaoTable> rao_table;
  // Following an irregular sea: the harmonics the loader made of its components through the
  // RAOs, each [omega rad/s, then (cos, sin) amplitudes of x, y, z [m] and rx, ry, rz [deg]],
  // in place of the one above (empty: the regular wave's trochoid).
  std::vector<std::array<double, 13>> harmonics;
};

// Where lines end: a [[point]] (a mooring's anchors, fairleads, clump weights, buoys,
// junctions), or an end of [ends] (the one line of a [cable] scene ends at two points, "start"
// and "end"). Its motion as an end's (EndDef); a free point's own physics as a weight's.
struct PointDef {
  std::string name;                       // unique; the lines name it
  std::string key;                        // its keys' table in messages: "point[2]", "ends.start"
  std::string label;                      // how messages name it: point "anchor1", start end
  EndDef motion;                          // position and motion: fixed, free, trochoid, ...
  double mass = 0;                        // free: m* [kg]
  double volume = 0;                      // free: V* [m^3], buoyancy
  std::array<double, 3> added_volume{};   // free: [V^x, V^y, V^z] [m^3]
  std::array<double, 3> drag_coefficient{};  // free: [C^x, C^y, C^z]
  std::array<double, 3> drag_area{};      // free: [S^x, S^y, S^z] [m^2]
  std::array<double, 3> force{};          // free: a constant force [F_x, F_y, F_z] [N]
  int body = -1;                          // on a [[body]] (index into SceneDef::bodies): the
                                          // motion's position is then local, in its axes
};

// [[body]]: a rigid body of a system carrying points (a platform, a ship): held, driven (its
// reference point moves as an end does) or free (where its loads balance: statics only).
struct BodyDef {
  std::string name;
  EndDef motion;                          // the reference point's position and motion
  bool free = false;                      // motion = "free"
  std::array<double, 3> orientation{};    // [about x, y, z] [deg], turned in that order
  // Drawn only: its hull as a box of these sizes along its x, y, z axes [m] about box_center
  // (in its axes, from its reference point [m]); has_box false: the outline through its points.
  bool has_box = false;
  std::array<double, 3> box{};
  std::array<double, 3> box_center{};
  double mass = 0;                        // free: [kg]
  std::array<double, 3> center_of_gravity{};   // free: local [m]
  double volume = 0;                      // free: displaced at rest [m^3]
  std::array<double, 3> center_of_buoyancy{};  // free: local [m]
  double waterplane_area = 0;             // free: [m^2]
  std::array<double, 2> waterplane_inertia{};  // free: about its x and z axes [m^4]
  std::array<double, 3> force{};          // free: constant [N]
  std::array<double, 3> moment{};         // free: constant, about the reference point [N m]
  std::array<double, 3> inertia{};        // free: about the centre of gravity [kg m^2]
  std::array<double, 6> added_mass{};     // free: [kg] x3, [kg m^2] x3
  std::array<double, 6> linear_damping{};     // free: [N s/m] x3, [N m s] x3
  std::array<double, 6> quadratic_damping{};  // free: [N s^2/m^2] x3, [N m s^2] x3
  std::array<double, 6> initial_offset{};     // free: from its equilibrium at t = 0, [m] x3,
                                              // [deg] x3 (a decay test)
};

enum class CableModelKind { kElastic, kInextensible };

// A line between two points: a [[line]], or the [cable] of a scene of one line.
struct LineDef {
  std::string name;                 // unique; its results' folder is lines/<name> (a [cable]:
                                    // "cable")
  std::string key;                  // its keys' table in messages: "line[1]", "cable"
  CableModelKind model = CableModelKind::kElastic;
  std::vector<SectionDef> sections;
  std::vector<WeightDef> weights;
  int start = 0;                    // index into SceneDef::points: station 0's point
  int end = 0;                      // station s's point
};
enum class InitialStateKind { kEquilibrium, kStraight };

enum class IntegratorChoice { kExplicit, kImplicit };

struct SimulationDef {
  IntegratorChoice integrator = IntegratorChoice::kImplicit;
  double rho_infinity = 0.5;     // implicit: spectral radius at infinite frequency, [0, 1]
  double duration = 60.0;        // [s]
  double time_step = 0.0;        // [s]; 0 = "auto" (from the stability limit)
  double tolerance = 0;          // implicit, auto step: local position error per step [m];
                                 // 0 = 1e-6 of the cable's length
  double safety_factor = 0.8;    // fraction of the stability limit used by "auto" (and by
                                 // the implicit scheme's explicit steps through snaps)
  bool explicit_snaps = true;    // implicit, auto step: snaps it would jump over stepped
                                 // explicitly (snap_steps = "explicit" or "implicit")
  // Implicit, auto step: the tolerance while the motion starts [m] (0 = tolerance / 20) and how
  // long the start lasts [s] (negative = "auto": the ramps of eq. (3) and of the waves).
  double start_tolerance = 0;
  double start_duration = -1;
};

struct OutputDef {
  double interval = 0.0;         // [s] between timeseries rows; 0 = one row per film frame
  bool film = true;
  bool frames = false;
};

struct FilmWindow {              // which span of the run a film shows (film.window)
  double peak_width = 0;         // > 0: this many seconds around the run's peak [s]
  double start = 0, end = -1;    // else from start to end [s]; end < 0: the whole run
  bool whole() const { return peak_width <= 0 && end < 0; }
};

struct FilmDef {                 // [film]: how the film looks (all optional)
  int width = 1920;
  int height = 1080;
  double fps = 30.0;             // frames per second of film
  double speed = 1.0;            // simulated seconds per second of film
  int crf = 20;                  // H.264 quality (lower is better)
  std::string colormap = "viridis";
  double tension_min = -1;       // colour range [N]; negative = from the run
  double tension_max = -1;
  std::string view = "auto";     // "2d", "3d", or "auto": 3D unless all of it stays in z = 0
  FilmWindow window;             // the whole run unless given
};

struct SceneDef {
  std::string path;              // the scene file, as given
  std::string name;              // its stem: the default output folder name
  std::string title;
  std::vector<std::string> warnings;  // what reading it left out (a MoorDyn file's EI, ...)
  bool from_moordyn = false;     // read from a MoorDyn input file (through the scene it converts
                                 // to): advice naming scene keys is not the file's to take
  KeySources sources;            // a MoorDyn file's: the row and column of each key's value
  EnvironmentDef environment;
  SeabedDef seabed;
  WavesDef waves;
  std::vector<MaterialDef> materials;
  // The lines between points, and the bodies points may be on: a [cable] and its [ends] are
  // read as one line between two points, [[line]], [[point]] and [[body]] as they are.
  std::vector<PointDef> points;
  std::vector<LineDef> lines;
  std::vector<BodyDef> bodies;
  InitialStateKind initial = InitialStateKind::kEquilibrium;
  SimulationDef simulation;
  OutputDef output;
  FilmDef film;
};

// How messages name a point's motion: an end of [ends] by its table ("ends.start"), a
// [[point]] by its name (point "anchor1").
inline std::string PointTitle(const PointDef& p) {
  return p.key.rfind("ends.", 0) == 0 ? p.key : p.label;
}

}  // namespace cablefilm
