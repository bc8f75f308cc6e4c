#pragma once
// The discrete cable of Polachek et al. (1963): stations j = 0..s carrying lumped masses, joined
// by weightless links j+1/2 (stored at index j). Built once from a scene; const while it runs.
#include <Eigen/Core>
#include <vector>

#include "core/end_motion.h"
#include "core/waves.h"

namespace cablefilm {

// A current that varies with elevation: speeds along +x at elevations, linearly interpolated in
// y, constant beyond the first and the last point. Empty: no profile.
struct CurrentProfile {
  std::vector<double> y;      // elevations [m], strictly increasing
  std::vector<double> speed;  // the current there [m/s] along +x

  bool empty() const { return y.empty(); }
  double At(double elevation) const;     // c(y) [m/s]
  // dc/dy [1/s]: the slope of the piece holding y (the piece above at a point), 0 beyond the
  // ends.
  double Slope(double elevation) const;
};

// A flat seabed at elevation y: each station below it gets a normal reaction
//   N_j = k l_j p_j + clamp(-c_j v_y, -k l_j p_j, k l_j p_j),  p_j = y - y_j > 0 (penetration):
// a spring on the penetration and a dashpot on the normal velocity, the dashpot's force no
// larger than the spring's: the reaction never pulls the line down (as MoorDyn's), and it
// starts from 0 when a falling station touches (a dashpot force c v from the first contact
// would be a jump that an implicit step cannot land on), so 0 <= N_j <= 2 k l_j p_j. Coulomb
// friction along x regularised by a velocity, -mu N_j tanh(v_x / v_f). l_j is the station's
// share of the unstretched line (half of each adjoining link).
struct SeabedSpec {
  bool present = false;
  double y = 0;                  // elevation [m]
  double stiffness = 3e7;        // k [N/m per m of line resting on it = N/m^2]; MoorDyn's kbot
                                 // [Pa/m] times the diameter
  double damping = -1;           // c [N s/m per m of line = N s/m^2]; MoorDyn's cbot [Pa s/m]
                                 // times the diameter; negative: critical damping of each
                                 // station on its bed spring, c_j = 2 sqrt(k l_j m_j)
  double friction = 0;           // mu, Coulomb coefficient along the seabed
  double friction_velocity = 0.01;  // v_f [m/s]: friction is mu N tanh(v_x / v_f)
};

enum class LinkLaw {
  kElastic,       // Hooke's law, eq. (2); a compressed link is slack (T = 0)
  kInextensible,  // rest length kept exactly; tension from the constraint (reference [1])
};

struct CableModel {
  int links = 0;  // s: the number of links; stations are 0..s

  // Per link j+1/2 (size s).
  Eigen::VectorXd rest_length;    // l_{j+1/2} [m], unstretched
  Eigen::VectorXd axial_stiffness;  // sigma_{j+1/2} E_{j+1/2} [N]
  Eigen::VectorXd virtual_mass;   // e_{j+1/2} = rho k l sigma [kg], normal added mass of the link
  Eigen::VectorXd drag_factor;    // f^D_{j+1/2} = rho/2 C^D l d [kg/m]
  Eigen::VectorXd axial_damping;  // c_{j+1/2} [N s/m]: a taut link's tension gains c dL/dt
                                  // (not in the paper; 0 unless the scene asks for it)
  Eigen::VectorXd link_mass;      // mu_{j+1/2} l_{j+1/2} [kg]
  Eigen::VectorXd link_net_weight;  // mu l g - rho g l sigma [N], weight less buoyancy
  std::vector<int> link_section;  // the scene section each link belongs to

  // Per station j (size s+1).
  Eigen::VectorXd arc_length;     // unstretched arc length from station 0 [m]
  Eigen::VectorXd cable_mass;     // m_j = (mu l)_{j-1/2}/2 + (mu l)_{j+1/2}/2 [kg]
  Eigen::Matrix2Xd prism_mass;    // (m^x_j, m^y_j) = m*_j + rho (V^x_j, V^y_j) [kg]
  Eigen::VectorXd net_weight;     // W_j + W*_j [N], acting along -y
  Eigen::Matrix2Xd prism_drag;    // (f^x_j, f^y_j) = rho/2 (C^x S^x, C^y S^y) [kg/m]
  std::vector<int> weight_stations;  // stations carrying a prism

  std::vector<double> section_boundaries;  // interior section ends, unstretched arc length [m]

  double gravity = 9.80665;       // g [m/s^2]
  double fluid_density = 0;       // rho [kg/m^3]
  double current = 0;             // c [m/s] along +x, uniform
  CurrentProfile current_profile; // added to c: the current at y is c + profile(y) [m/s]
  SeabedSpec seabed;              // seabed.present: contact on the stations below seabed.y
  Eigen::VectorXd seabed_stiffness;  // k l_j [N/m] per station (size s+1; empty: no seabed)
  Eigen::VectorXd seabed_damping;    // c_j [N s/m] per station (size s+1; empty: no seabed)
  Eigen::VectorXd seabed_rest_depth; // |W_j| / (k l_j) [m]: the penetration at which the
                                     // station's net weight rests on the bed (at least 1e-9 m;
                                     // size s+1; empty: no seabed)
  Eigen::VectorXd seabed_landing_time;  // sqrt(m_j / (k l_j)) [s]: the time a bed damped at
                                     // least critically takes to stop a landing station
                                     // (without rebound); infinite on a bed damped less, whose
                                     // rebound is physics (size s+1; empty: no seabed)
  // Waves (wave.spec.present; waves.h, wave_forces.h): the arrays below are sized only then.
  Wave wave;
  Eigen::VectorXd station_buoyancy;  // rho g (sigma l / 2 of each link + V*) [N] per station, the
                                     // buoyancy lost above the surface (size s+1)
  Eigen::VectorXd wet_band;          // l_j [m]: the station's share of line (half of each link),
                                     // the band of depth over which it goes from dry to wet
  Eigen::VectorXd link_fluid_mass;   // rho sigma l (1 + k) [kg] per link: Froude-Krylov plus
                                     // the normal added mass e, on the water's normal
                                     // acceleration (Morison's C_M = 1 + k)
  Eigen::Matrix2Xd prism_added_mass; // rho (V^x, V^y) [kg] per station
  Eigen::Matrix2Xd prism_fluid_mass; // rho (V* + V^x, V* + V^y) [kg] per station
  LinkLaw law = LinkLaw::kElastic;

  EndMotion start;                // station 0
  EndMotion end;                  // station s

  int stations() const { return links + 1; }
  double total_length() const { return arc_length[links]; }
  // The first and last station whose motion is computed (free ends included).
  int first_free() const { return start.prescribed() ? 1 : 0; }
  int last_free() const { return end.prescribed() ? links - 1 : links; }
  const EndMotion& end_motion(int j) const { return j == 0 ? start : end; }
  // The current at elevation y [m/s] and its y-derivative [1/s].
  double CurrentAt(double y) const {
    return current_profile.empty() ? current : current + current_profile.At(y);
  }
  double CurrentSlope(double y) const {
    return current_profile.empty() ? 0.0 : current_profile.Slope(y);
  }
  bool has_waves() const { return wave.spec.present; }
  bool has_current() const;  // anywhere non-zero
  double max_current() const;  // the largest |c(y)| over all y [m/s]
  // min(m^x_j, m^y_j) [kg] in any state: without the prism's added mass when waves can lift it
  // out of the water.
  double SmallestPrismMass(int j) const {
    return has_waves() ? (prism_mass.col(j) - prism_added_mass.col(j)).minCoeff()
                       : prism_mass.col(j).minCoeff();
  }
  bool prescribed(int j) const {
    return (j == 0 && start.prescribed()) || (j == links && end.prescribed());
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
};

struct PrismSpec {
  int station = 0;
  double mass = 0;                   // m* [kg]
  double volume = 0;                 // V* [m^3]
  Eigen::Vector2d added_volume = Eigen::Vector2d::Zero();  // (V^x, V^y) [m^3]
  Eigen::Vector2d drag_coefficient = Eigen::Vector2d::Zero();  // (C^x, C^y)
  Eigen::Vector2d drag_area = Eigen::Vector2d::Zero();   // (S^x, S^y) [m^2]
};

struct EnvironmentSpec {
  double gravity = 9.80665;    // g [m/s^2]
  double fluid_density = 0;    // rho [kg/m^3]
  double current = 0;          // c [m/s]
  CurrentProfile current_profile;  // added to c (empty: uniform)
  SeabedSpec seabed;           // none unless present
  WaveSpec waves;              // none unless present
};

// The model with its current (uniform and profile) multiplied by `factor`: the continuation of
// the static equilibrium in the current.
CableModel ScaleCurrent(const CableModel& m, double factor);

// Assembles the per-link and per-station quantities of eq. (1). Sections must be valid
// (the scene loader checks them); throws Error on a prism at a station that does not exist.
CableModel BuildCableModel(const std::vector<SectionSpec>& sections,
                           const std::vector<PrismSpec>& prisms, const EnvironmentSpec& env,
                           EndMotion start, EndMotion end, LinkLaw law);

}  // namespace cablefilm
