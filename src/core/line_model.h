#pragma once
// The model of Polachek et al. (1963), const while it runs (MuJoCo's mjModel): the line (its
// stations j = 0..s carrying lumped masses, joined by weightless links j+1/2 stored at index
// j), the environment it lies in, and its ends (the boundary). Built once from a scene; what
// changes while it runs (the state, the schemes' memory) is in LineData (line_data.h), what a control
// changes (the current, the waves, the ends' motion) in Inputs (inputs.h).
#include <Eigen/Core>
#include <algorithm>
#include <limits>
#include <memory>
#include <vector>

#include "core/current_history.h"
#include "core/end_motion.h"
#include "core/vec.h"
#include "core/waves.h"

namespace cablefilm {

// A current that varies with elevation: speeds along the current's direction at elevations,
// linearly interpolated in y, constant beyond the first and the last point. Empty: no profile.
struct CurrentProfile {
  std::vector<double> y;      // elevations [m], strictly increasing
  std::vector<double> speed;  // the current there [m/s] along the current's direction

  bool empty() const { return y.empty(); }
  // c(y) [m/s] and dc/dy [1/s] (the slope of the piece holding y, the piece above at a point, 0
  // beyond the ends), with every speed multiplied by `scale` first (the equilibrium's
  // continuation in the current: the same arithmetic as a profile of scaled speeds).
  // Inline: they run for every link in every Newton iteration (7 % of a mooring system's
  // instructions as calls).
  double At(double elevation, double scale = 1.0) const {
    const int n = static_cast<int>(y.size());
    const int i = Piece(elevation);
    if (i < 0) return speed.front() * scale;
    if (i >= n - 1) return speed.back() * scale;
    const double f = (elevation - y[i]) / (y[i + 1] - y[i]);
    const double a = speed[i] * scale, b = speed[i + 1] * scale;
    return a + f * (b - a);
  }
  double Slope(double elevation, double scale = 1.0) const {
    const int i = Piece(elevation);
    if (i < 0 || i >= static_cast<int>(y.size()) - 1) return 0.0;
    return (speed[i + 1] * scale - speed[i] * scale) / (y[i + 1] - y[i]);
  }

 private:
  // The piece [y_i, y_{i+1}) holding `elevation`: i in 0..n-2, or -1 below the first point and
  // n-1 at or above the last.
  int Piece(double elevation) const {
    return static_cast<int>(std::upper_bound(y.begin(), y.end(), elevation) - y.begin()) - 1;
  }
};

// A flat seabed at elevation y: each station below it gets a normal reaction
//   N_j = k l_j p_j + clamp(-c_j v_y, -k l_j p_j, k l_j p_j),  p_j = y - y_j > 0 (penetration):
// a spring on the penetration and a dashpot on the normal velocity, the dashpot's force no
// larger than the spring's: the reaction never pulls the line down, and it starts from 0 when
// a falling station touches (a dashpot force c v from the first contact would be a jump that an
// implicit step cannot land on), so 0 <= N_j <= 2 k l_j p_j. Coulomb friction against the
// sliding velocity on the bed v_h = (v_x, 0, v_z), by one of two laws (FrictionModel). l_j is
// the station's share of the unstretched line (half of each adjoining link).
enum class FrictionModel {
  // Stick-slip (elastic-plastic, seabed_friction.h): a grounded station is held by a shear
  // spring K l_j and dashpot C_j to the point a_j where it last slid, F_h = -K l_j (x_h - a_j)
  // - C_j v_h, no larger than mu N_j; beyond it the station slides and a_j follows it. It holds
  // a station at rest under a pull below mu N_j (no creep).
  kStickSlip,
  // Regularised Coulomb: -mu N_j tanh(|v_h| / v_f) v_h / |v_h|, a function of the velocity
  // alone; a station held under a fraction r of mu N_j creeps at v_f atanh(r).
  kSmoothed,
};

struct SeabedSpec {
  bool present = false;
  double y = 0;                  // elevation [m]
  double stiffness = 3e7;        // k [N/m per m of line resting on it = N/m^2]; MoorDyn's kbot
                                 // [Pa/m] times the diameter
  double damping = -1;           // c [N s/m per m of line = N s/m^2]; MoorDyn's cbot [Pa s/m]
                                 // times the diameter; negative: critical damping of each
                                 // station on its bed spring, c_j = 2 sqrt(k l_j m_j)
  double friction = 0;           // mu, Coulomb coefficient along the seabed
  FrictionModel friction_model = FrictionModel::kStickSlip;
  double friction_velocity = 0.01;  // v_f [m/s], kSmoothed: friction is mu N tanh(|v_h| / v_f)
  double friction_stiffness = -1;   // K [N/m per m of line = N/m^2], kStickSlip: the bed's
                                    // shear stiffness under a sticking station (OrcaFlex's
                                    // "shear stiffness"); negative: equal to `stiffness`. Its
                                    // dashpot C_j is c_j sqrt(K / k): the normal one's ratio.
  double shear_stiffness() const {  // K [N/m^2]: friction_stiffness, or the normal stiffness
    return friction_stiffness > 0 ? friction_stiffness : stiffness;
  }
};

enum class LinkLaw {
  kElastic,       // Hooke's law, eq. (2); a compressed link is slack (T = 0)
  kInextensible,  // rest length kept exactly; tension from the constraint (reference [1])
};

// The line: what eq. (1) needs per link j+1/2 (size s) and per station j (size s+1).
struct Line {
  int links = 0;  // s: the number of links; stations are 0..s
  LinkLaw law = LinkLaw::kElastic;

  // Per link j+1/2 (size s).
  Eigen::VectorXd rest_length;    // l_{j+1/2} [m], unstretched
  Eigen::VectorXd axial_stiffness;  // sigma_{j+1/2} E_{j+1/2} [N]
  Eigen::VectorXd virtual_mass;   // e_{j+1/2} = rho k l sigma [kg], normal added mass of the link
  Eigen::VectorXd drag_factor;    // f^D_{j+1/2} = rho/2 C^D l d [kg/m]
  // Along the link (not in the paper; 0 unless the scene asks, MoorDyn's CaAx and CdAx):
  Eigen::VectorXd tangential_virtual_mass;  // e^t_{j+1/2} = rho k^t l sigma [kg], acting along t
  Eigen::VectorXd tangential_drag_factor;   // f^T_{j+1/2} = rho/2 C^T pi d l [kg/m], drag along t
  Eigen::VectorXd axial_damping;  // c_{j+1/2} [N s/m]: a taut link's tension gains c dL/dt
                                  // (not in the paper; 0 unless the scene asks for it)
  Eigen::VectorXd link_mass;      // mu_{j+1/2} l_{j+1/2} [kg]
  Eigen::VectorXd link_net_weight;  // mu l g - rho g l sigma [N], weight less buoyancy
  std::vector<int> link_section;  // the scene section each link belongs to
  Eigen::VectorXd breaking_load;  // MBL of the link's material [N]; 0 = not given (results
                                  // only: the utilisation T / MBL; no force depends on it)
  bool has_breaking_load() const { return breaking_load.size() > 0 && breaking_load.maxCoeff() > 0; }

  // Per station j (size s+1).
  Eigen::VectorXd arc_length;     // unstretched arc length from station 0 [m]
  Eigen::VectorXd cable_mass;     // m_j = (mu l)_{j-1/2}/2 + (mu l)_{j+1/2}/2 [kg]
  Points prism_mass;              // (m^x_j, m^y_j, m^z_j) = m*_j + rho (V^x_j, V^y_j, V^z_j) [kg]
  Eigen::VectorXd net_weight;     // W_j + W*_j [N], acting along -y
  Points prism_drag;              // (f^x_j, f^y_j, f^z_j) = rho/2 (C^x S^x, C^y S^y, C^z S^z)
                                  // [kg/m]
  Points prism_force;             // a constant force on the prism [N] (a point's thrust, not in
                                  // the paper; zero unless given)
  std::vector<int> weight_stations;  // stations carrying a prism

  std::vector<double> section_boundaries;  // interior section ends, unstretched arc length [m]

  // On a seabed (environment.seabed.present; empty otherwise), per station (size s+1):
  Eigen::VectorXd seabed_stiffness;  // k l_j [N/m]
  Eigen::VectorXd seabed_damping;    // c_j [N s/m]
  Eigen::VectorXd friction_stiffness;  // K l_j [N/m]: the stick-slip friction's shear spring
  Eigen::VectorXd friction_damping;    // C_j [N s/m]: its dashpot
  Eigen::VectorXd seabed_rest_depth; // |W_j| / (k l_j) [m]: the penetration at which the
                                     // station's net weight rests on the bed (at least 1e-9 m)
  Eigen::VectorXd seabed_landing_time;  // sqrt(m_j / (k l_j)) [s]: the time a bed damped at
                                     // least critically takes to stop a landing station
                                     // (without rebound); infinite on a bed damped less, whose
                                     // rebound is physics
  // In waves (environment.wave.spec.present; waves.h, wave_forces.h; empty otherwise):
  Eigen::VectorXd station_buoyancy;  // rho g (sigma l / 2 of each link + V*) [N] per station, the
                                     // buoyancy lost above the surface (size s+1)
  Eigen::VectorXd wet_band;          // l_j [m]: the station's share of line (half of each link),
                                     // the band of depth over which it goes from dry to wet
  Eigen::VectorXd link_fluid_mass;   // rho sigma l (1 + k) [kg] per link: Froude-Krylov plus
                                     // the normal added mass e, on the water's normal
                                     // acceleration (Morison's C_M = 1 + k)
  Eigen::VectorXd link_axial_fluid_mass;  // rho sigma l (1 + k^t) [kg] per link: Froude-Krylov
                                     // plus the tangential added mass e^t, on the water's
                                     // acceleration along the link (MoorDyn's 1 + CaAx); e^t
                                     // alone where the material leaves the Froude-Krylov
                                     // part along the line out (axial_froude_krylov false)
  Points prism_added_mass;           // rho (V^x, V^y, V^z) [kg] per station
  Points prism_fluid_mass;           // rho (V* + V^x, V* + V^y, V* + V^z) [kg] per station

  int stations() const { return links + 1; }
  double total_length() const { return arc_length[links]; }
};

// The fluid and the ground the line lies in, as the scene gives them.
// The largest utilisation T_j / MBL_j [1] over the links with a breaking load (MBL_j > 0) of
// `tension` [N], its link in `link`; NaN (link -1) when no link has one.
inline double MaxUtilisation(const Eigen::VectorXd& tension, const Eigen::VectorXd& breaking_load,
                             int* link = nullptr) {
  double best = std::numeric_limits<double>::quiet_NaN();
  int at = -1;
  for (Eigen::Index j = 0; j < breaking_load.size() && j < tension.size(); ++j) {
    if (!(breaking_load[j] > 0)) continue;
    const double u = tension[j] / breaking_load[j];
    if (at < 0 || u > best) best = u, at = static_cast<int>(j);
  }
  if (link) *link = at;
  return best;
}

// The line's one breaking load [N] when every link has the same (> 0), else NaN (none, or
// several materials' that differ): what a tension plot can draw as a line.
inline double SingleBreakingLoad(const Eigen::VectorXd& breaking_load) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (breaking_load.size() == 0 || !(breaking_load[0] > 0)) return nan;
  for (Eigen::Index j = 1; j < breaking_load.size(); ++j)
    if (breaking_load[j] != breaking_load[0]) return nan;
  return breaking_load[0];
}

struct Environment {
  double gravity = 9.80665;       // g [m/s^2]
  double fluid_density = 0;       // rho [kg/m^3]
  double current = 0;             // c [m/s] along current_direction, uniform
  CurrentProfile current_profile; // added to c: the current at y is c + profile(y) [m/s]
  Vec current_direction = Vec(1.0, 0.0, 0.0);  // horizontal unit vector the current flows along
  // The current over time: scales and turns the current above (null: steady).
  std::shared_ptr<const CurrentHistory> current_history;
  SeabedSpec seabed;              // seabed.present: contact on the stations below seabed.y
  Wave wave;                      // wave.spec.present: regular waves with a free surface
};

// How the ends move: station 0 (start) and station s (end).
struct Ends {
  EndMotion start;
  EndMotion end;
};

struct LineModel {
  Line line;
  Environment env;
  Ends ends;

  int stations() const { return line.stations(); }
  // The first and last station whose motion is computed (free ends included).
  int first_free() const { return ends.start.prescribed() ? 1 : 0; }
  int last_free() const { return ends.end.prescribed() ? line.links - 1 : line.links; }
  const EndMotion& end_motion(int j) const { return j == 0 ? ends.start : ends.end; }
  bool prescribed(int j) const {
    return (j == 0 && ends.start.prescribed()) || (j == line.links && ends.end.prescribed());
  }
  bool has_waves() const { return env.wave.spec.present; }
  // min(m^x_j, m^y_j) [kg] in any state: without the prism's added mass when waves can lift it
  // out of the water.
  double SmallestPrismMass(int j) const {
    return has_waves() ? (line.prism_mass.col(j) - line.prism_added_mass.col(j)).minCoeff()
                       : line.prism_mass.col(j).minCoeff();
  }
};

// One uniform section of cable, as the model builder takes it.
struct SectionSpec {
  double length = 0;                 // unstretched [m]
  int segments = 0;                  // links
  double diameter = 0;               // d [m]
  double area = 0;                   // sigma [m^2]
  double mass_per_length = 0;        // mu [kg/m]
  double youngs_modulus = 0;         // E [Pa]
  double drag_coefficient = 0;       // C^D
  double added_mass_coefficient = 0; // k
  double axial_damping = 0;          // BA [Pa s]: c = BA sigma / l
  double axial_damping_ratio = 0;    // zeta: c = 2 zeta sqrt((sigma E / l) m_ab), m_ab the
                                     // reduced mass of the link's two stations
  double moordyn_axial_damping_ratio = 0;  // zeta as MoorDyn's BA/-zeta defines it: c = zeta
                                           // sqrt(sigma E mu) [N s/m] on every link (BA = zeta
                                           // l sqrt(EA mu) [N s], EA's critical value for the
                                           // line's own mass per length, any link length)
  double minimum_breaking_load = 0;  // MBL [N], for the utilisation T / MBL; 0 = not given
  double tangential_drag_coefficient = 0;       // C^T, on pi d l (MoorDyn's CdAx)
  double tangential_added_mass_coefficient = 0; // k^t, on sigma l along the link (CaAx)
  bool axial_froude_krylov = true;   // in waves, the Froude-Krylov force along the link too,
                                     // rho sigma l (t . A) (MoorDyn's); false: across it only
};

struct PrismSpec {
  int station = 0;
  double mass = 0;                   // m* [kg]
  double volume = 0;                 // V* [m^3]
  Vec added_volume = Vec::Zero();    // (V^x, V^y, V^z) [m^3]
  Vec drag_coefficient = Vec::Zero();  // (C^x, C^y, C^z)
  Vec drag_area = Vec::Zero();       // (S^x, S^y, S^z) [m^2]
  Vec force = Vec::Zero();           // a constant external force [N] (a thrust, a steady wind)
};

struct EnvironmentSpec {
  double gravity = 9.80665;    // g [m/s^2]
  double fluid_density = 0;    // rho [kg/m^3]
  double current = 0;          // c [m/s] along current_direction
  CurrentProfile current_profile;  // added to c (empty: uniform)
  Vec current_direction = Vec(1.0, 0.0, 0.0);  // horizontal unit vector
  std::shared_ptr<const CurrentHistory> current_history;  // over time (null: steady)
  SeabedSpec seabed;           // none unless present
  WaveSpec waves;              // none unless present
};

// Assembles the per-link and per-station quantities of eq. (1). Sections must be valid
// (the scene loader checks them); throws Error on a prism at a station that does not exist.
LineModel MakeLineModel(const std::vector<SectionSpec>& sections, const std::vector<PrismSpec>& prisms,
                const EnvironmentSpec& env, EndMotion start, EndMotion end, LinkLaw law);

}  // namespace cablefilm
