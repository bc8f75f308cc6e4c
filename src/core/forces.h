#pragma once
// The right-hand side of eq. (1): link tensions (eq. 2), weight and buoyancy, normal drag on the
// links with the current (and tangential drag along them when the material has it), the
// prisms' drag, and the inertia tensor (I, J, K) of each station.
// Every function is O(s) and allocates nothing once the Workspace is sized.
#include <Eigen/Core>
#include <cmath>

#include "core/inputs.h"
#include "core/line_model.h"

namespace cablefilm {

// The water at each station at one time (waves only: wave_forces.h fills it; empty otherwise).
struct SeaState {
  double t = 0;                       // the time it is for [s]
  Points velocity;          // water particle velocity [m/s] (kDim x s+1)
  Points acceleration;      // its local acceleration [m/s^2] (kDim x s+1)
  Gradients velocity_gradient;     // d(velocity)/d(x, y, z) [1/s], column-major kDim x kDim per station
  Gradients acceleration_gradient; // d(du/dt, dw/dt)/d(x, y) [1/s^2], likewise
  Eigen::VectorXd wet;                // phi_j in [0, 1]: the station's wet fraction
  Points wet_gradient;      // d phi_j / d(x_j, y_j) [1/m]
  // A still sea (no wave running) whose surface no station's band reaches: the water at rest
  // and every station wholly wet (as the arrays above then say), the forces those without a
  // surface. A converted MoorDyn file's still water over a mooring below it took three times
  // the time of the same mooring without the surface through the sea's general forces.
  bool still_under = false;
  // Still water (no wave running): the water at rest (velocity, acceleration and their
  // gradients zero), only the wet fractions computed.
  bool still = false;
  // An irregular sea's last exact evaluation at each station (its base, ComputeSea): the sea
  // scale then, each station's time [s] and position [m] then, how far in time [s] and space
  // [m] it is carried (its reach over the highest frequency and wave number it sums), and there
  // the surface's elevation [m], its rate [m/s] and gradient, the water's velocity,
  // acceleration, their gradients (as above) and the acceleration's rate [m/s^3]. Empty until
  // the first.
  bool base_valid = false;
  double base_scale = 1;
  Eigen::VectorXd base_t, base_reach_t, base_reach_x;
  Points base_x, base_velocity, base_acceleration, base_jerk, base_eta_gradient;
  Gradients base_velocity_gradient, base_acceleration_gradient;
  Eigen::VectorXd base_eta, base_eta_rate;
  long exact_evaluations = 0;  // stations evaluated exactly (for the tests and bench)
};

// psi_k, link k's wet fraction: the mean of its two stations' (wave_forces.h).
inline double LinkWet(const SeaState& sea, int k) { return 0.5 * (sea.wet[k] + sea.wet[k + 1]); }

struct LinkGeometry {
  Eigen::VectorXd length;    // L_{j+1/2} = |x_{j+1} - x_j| [m] (size s)
  Points tangent;  // unit t_{j+1/2}, (cos theta, sin theta, 0) in the plane (kDim x s); zero for a zero-length link
  Eigen::VectorXd elevation;  // y_j of the stations [m] (size s+1): the seabed, the current
                              // profile
  SeaState sea;               // the waves' water at the stations (only with waves)
  // The stick-slip friction (seabed_friction.h; empty without it, and in statics):
  Points friction_anchor;  // a_j, where station j last slid on the bed [m] (kDim x s+1, y 0):
                           // state, not geometry, carried here so that every force
                           // evaluation of a LineData sees it; moved only when a step is accepted
  Points stick;            // x_h - a_j [m], the shear spring's stretch (kDim x s+1)
};

struct ForceWorkspace {
  LinkGeometry geometry;
  Eigen::VectorXd tension;   // T_{j+1/2} [N] (size s)
  Points force;    // right-hand side of eq. (1) per station (X + tension terms) [N]

  ForceWorkspace() = default;
  explicit ForceWorkspace(int links) { Resize(links); }
  void Resize(int links);
};

void ComputeGeometry(const Points& x, LinkGeometry& g);
// The same, and with waves the sea of `water` at time t [s] (wave_forces.h): what the forces of
// a simulation at time t need. Without waves it is the one above.
void ComputeGeometry(const LineModel& m, const Water& water, double t, const Points& x,
                     LinkGeometry& g);

// Whether the forces of geometry g go through the sea's (wave_forces.h): with waves, unless
// the sea is still and over every station (SeaState::still_under).
inline bool UsesSea(const LineModel& m, const LinkGeometry& g) {
  return m.has_waves() && !g.sea.still_under;
}

// d w_n / d d for w_n = (I - t t^T) w, the part of a vector w across a link d = x_{k+1} - x_k
// of direction t = d / |d| and length L = |d| [m] (w held fixed): -((t . w) P + t w_n^T) / L,
// P = I - t t^T. The Jacobians' normal drag and added mass terms.
inline Mat NormalPartDerivative(const Vec& t, double L, const Vec& w, const Vec& w_n) {
  const Mat P = Mat::Identity() - t * t.transpose();
  return -(t.dot(w) * P + t * w_n.transpose()) / L;
}
// d(|u| u) / du at u = w_n: |u| I + u u^T / |u| (0 at u = 0): the quadratic drag's.
inline Mat NormalDragDerivative(const Vec& w_n) {
  const double speed = w_n.norm();
  if (!(speed > 0)) return Mat::Zero();
  return speed * Mat::Identity() + w_n * (w_n.transpose() / speed);
}

// Eq. (2), with a compressed link slack: T = max(0, sigma E (L/l - 1)).
void ComputeHookeTensions(const LineModel& m, const LinkGeometry& g, Eigen::VectorXd& tension);

// Internal axial damping (Kelvin-Voigt, not in the paper): a taut link's tension gains
// c_{j+1/2} dL/dt, dL/dt = t . (v_{j+1} - v_j), and stays >= 0 (a cable cannot push); a slack
// link has none. No-op when the model has no damping.
void AddAxialDamping(const LineModel& m, const LinkGeometry& g, const Points& v,
                     Eigen::VectorXd& tension);
// The tension of the dynamics: Hooke's law plus the axial damping.
void ComputeTensions(const LineModel& m, const LinkGeometry& g, const Points& v,
                     Eigen::VectorXd& tension);

// The seabed's normal reaction N on station j at penetration p > 0 with vertical velocity vy
// (cable_model.h, SeabedSpec), and its derivatives; N = 0 with no derivative where it would pull.
// tanh(u) through one exponential, the friction's shape (mu N tanh(v_x / v_f)) on every
// grounded station at every Newton iteration: glibc's tanh goes through expm1 and took twice
// the time. Within 3e-17 of tanh (absolute), which is all a force needs.
inline double FrictionShape(double u) {
  const double e = std::exp(-2.0 * std::abs(u));
  return std::copysign((1.0 - e) / (1.0 + e), u);
}

// The seabed's normal reaction N on station j at penetration p > 0 with vertical velocity vy
// (line_model.h, SeabedSpec), and its derivatives; N = 0 with no derivative where it would pull.
struct SeabedReaction {
  double N = 0;       // [N]
  double dN_dp = 0;   // [N/m]
  double dN_dvy = 0;  // [N s/m]
};
SeabedReaction SeabedNormal(const LineModel& m, int j, double p, double vy);

// The smoothed friction's (FrictionModel::kSmoothed) direction and size without mu N:
// tanh(|v_h| / v_f) v_h / |v_h| for the sliding velocity v_h = (v_x, 0, v_z) of a station on
// the bed (0 when it is at rest).
inline Vec SlidingDirection(const Vec& v, const SeabedSpec& bed) {
  const Vec vh = HorizontalPart(v);
  const double speed = vh.norm();  // [m/s]
  if (!(speed > 0)) return Vec::Zero();
  return (FrictionShape(speed / bed.friction_velocity) / speed) * vh;
}

// force_j = T_{j+1/2} t_{j+1/2} - T_{j-1/2} t_{j-1/2} + (X_j, Y_j), for every station.
// v: station velocities; the current (of `water`) enters through the relative velocity.
void ComputeStationForces(const LineModel& m, const Water& water, const LinkGeometry& g,
                          const Eigen::VectorXd& tension, const Points& v, Points& force);

// The external part (X_j, Y_j) only: drag (normal, and tangential when given), prism drag,
// weight and buoyancy, and the seabed's
// reaction and friction (SeabedSpec) on the stations below it. With waves also the water's
// velocity in the drag, its acceleration (Morison inertia) and the surface (wave_forces.h);
// g.sea must then be filled (ComputeGeometry with the model and the time).
void AddExternalForces(const LineModel& m, const Water& water, const LinkGeometry& g,
                       const Points& v, Points& force);

// The inertia tensor of eq. (1) at station j ([[I_j, -K_j], [-K_j, J_j]] in the plane) [kg],
// with half of each adjoining link's tangential added mass along it when given. With waves the
// added masses are those of the wet part (g.sea.wet; all wet if g.sea is empty).
Mat StationInertia(const LineModel& m, const LinkGeometry& g, int j);
// block += scale StationInertia(m, g, j), entry by entry (the Newton matrix's diagonal blocks).
void AddStationInertia(const LineModel& m, const LinkGeometry& g, int j, double scale, Mat& block);
// StationInertia(m, g, j) * a without the matrix (the implicit scheme's residual, every
// station every Newton iteration) [N].
Vec StationInertiaTimes(const LineModel& m, const LinkGeometry& g, int j, const Vec& a);

// Accelerations of the stations whose motion is computed (free stations) in `water`; prescribed
// ends get their exact acceleration (as the inputs move them). Fills ws.geometry, ws.tension and
// ws.force along the way.
void ComputeAccelerations(const LineModel& m, const Inputs& in, const Water& water, double t,
                          const Points& x, const Points& v, ForceWorkspace& ws, Points& a);

// Energies for conservation checks [J]: kinetic (with the normal added mass), elastic strain
// energy of the links, and potential of the net weight (y = 0 datum) plus the strain energy of
// the seabed's springs (k l_j p_j^2 / 2 for the stations below it) and, with waves, of the
// buoyancy lost above the still water level (SurfaceBuoyancyEnergy).
double KineticEnergy(const LineModel& m, const LinkGeometry& g, const Points& v);
double ElasticEnergy(const LineModel& m, const LinkGeometry& g);
double PotentialEnergy(const LineModel& m, const Points& x);
double SeabedEnergy(const LineModel& m, const Points& x);  // the springs only

}  // namespace cablefilm
