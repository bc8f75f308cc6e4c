#pragma once
// The discrete cable of Polachek et al. (1963): stations j = 0..s carrying lumped masses, joined
// by weightless links j+1/2 (stored at index j). Built once from a scene; const while it runs.
#include <Eigen/Core>
#include <vector>

#include "core/end_motion.h"

namespace cablefilm {

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
  double current = 0;             // c [m/s] along +x
  LinkLaw law = LinkLaw::kElastic;

  EndMotion start;                // station 0
  EndMotion end;                  // station s

  int stations() const { return links + 1; }
  double total_length() const { return arc_length[links]; }
  // The first and last station whose motion is computed (free ends included).
  int first_free() const { return start.prescribed() ? 1 : 0; }
  int last_free() const { return end.prescribed() ? links - 1 : links; }
  const EndMotion& end_motion(int j) const { return j == 0 ? start : end; }
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
};

// Assembles the per-link and per-station quantities of eq. (1). Sections must be valid
// (the scene loader checks them); throws Error on a prism at a station that does not exist.
CableModel BuildCableModel(const std::vector<SectionSpec>& sections,
                           const std::vector<PrismSpec>& prisms, const EnvironmentSpec& env,
                           EndMotion start, EndMotion end, LinkLaw law);

}  // namespace cablefilm
