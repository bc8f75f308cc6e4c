#pragma once
// A rigid body of a mooring system (a platform, a ship, a buoy hull): six degrees of freedom
// that carry the points its lines end at. Its pose is the position r of its reference point
// [m] and three angles theta [rad]: the body is turned about x by theta_x, then about y by
// theta_y, then about z by theta_z (fixed axes; y is up, so with x forward theta_x is roll,
// theta_y yaw and theta_z pitch). A point fixed to it at local position p (in the body's axes,
// from its reference point) is at r + R(theta) p.
//
// A held body stays at its pose; a driven body's reference point moves as an end does
// (end_motion.h: eq. (3), a table, the waves) and its angles as `turn` says (the same kinds of
// motion over the three angles; none: its rest orientation), each of its points at
// r(t) + R(theta(t)) p with exact velocity and acceleration (rotation_rates.h); a free body is where
// the loads on it balance: its lines', its weight at its centre of gravity, its buoyancy at
// its centre of buoyancy, the waterplane's restoring terms and a constant force and moment
// (a steady wind, a thrust).
#include <Eigen/Core>
#include <string>

#include "core/end_motion.h"
#include "core/vec.h"

namespace cablefilm {

using Vec6 = Eigen::Matrix<double, 6, 1>;  // (x, y, z [m], theta_x, theta_y, theta_z [rad])
using Mat6 = Eigen::Matrix<double, 6, 6>;

enum class BodyKind { kHeld, kDriven, kFree };

struct BodySpec {
  std::string name;
  BodyKind kind = BodyKind::kHeld;
  // The reference point's motion (its rest position: the pose's r at rest; a free body's first
  // guess) and the rest angles theta [rad].
  EndMotion motion = EndMotion::Fixed(Vec::Zero());
  Vec angles = Vec::Zero();
  // A driven body's angles in time [rad]: a trochoid or a table over the three angles about
  // x, y, z, its rest() `angles`; fixed (the default): it keeps its rest orientation.
  EndMotion turn = EndMotion::Fixed(Vec::Zero());
  // A free body's own loads.
  double mass = 0;                           // [kg]
  Vec center_of_gravity = Vec::Zero();       // local [m]
  double volume = 0;                         // displaced at rest [m^3]
  Vec center_of_buoyancy = Vec::Zero();      // local [m]
  double waterplane_area = 0;                // A_wp [m^2]: heave restoring rho g A_wp
  // The waterplane's second moments about the body's x and z axes [m^4]: the roll and pitch
  // restoring rho g I (the metacentre's part; the weight's and buoyancy's parts follow from
  // the centres of gravity and buoyancy as they turn).
  double waterplane_inertia_x = 0, waterplane_inertia_z = 0;
  Vec force = Vec::Zero();                   // constant, in the world's axes [N]
  Vec moment = Vec::Zero();                  // constant, about the reference point [N m]
  // A free body's motion in time: its moments of inertia about its centre of gravity, in its
  // axes [kg m^2]; added mass, linear and quadratic damping per degree of freedom (x, y, z:
  // [kg], [N s/m], [N s^2/m^2]; the turns: [kg m^2], [N m s], [N m s^2]): the linear on its own
  // velocity, the quadratic on the water's relative to it (BodyDampingLoad).
  Vec inertia = Vec::Zero();
  Vec6 added_mass = Vec6::Zero();
  Vec6 linear_damping = Vec6::Zero();
  Vec6 quadratic_damping = Vec6::Zero();
  // Where a free body starts a run, from its equilibrium [m, rad] (the lines in equilibrium
  // with it held there): a decay test.
  Vec6 initial_offset = Vec6::Zero();
};

// R(theta): about x, then y, then z.
Mat BodyRotation(const Vec& angles);

// d(R(theta) p)/d(theta): column k the motion of local point p per radian of theta_k [m].
Mat BodyPointTurn(const Vec& angles, const Vec& local);

// The 3x6 map from a change of pose (dr, dtheta) to the change of local point p's position.
Eigen::Matrix<double, 3, 6> BodyPointJacobian(const Vec6& pose, const Vec& local);

// E(theta): the angular velocity per rate of each angle [rad/s per rad/s] (omega = E dtheta/dt):
// columns Rz Ry e_x, Rz e_y, e_z.
Mat BodyTurnRates(const Vec& angles);

// A load in the world's axes (force, moment about the reference point) as the generalized
// force of the pose's coordinates: (f, E^T m).
Vec6 GeneralizedLoad(const Vec6& pose, const Vec6& load);

// The body's mass matrix in the pose's coordinates about its reference point, with its added
// mass [kg, kg m, kg m^2]: P^T M P with P = diag(I, E) and M the rigid body's in the world's
// axes. The velocity-squared (gyroscopic) terms are left out: slow turns.
Mat6 BodyMassMatrix(const BodySpec& body, const Vec6& pose);

// Its damping load at velocity `rate` (d(pose)/dt) in water moving at `flow` [m/s] at its
// reference point (the current, the waves) [N, N m]: the linear part -B_1 v on its own
// velocity (a radiation damping's); the quadratic part B_2 u abs(u) on the water's velocity
// relative to it, u = flow - v in translation and -v in the turns (a drag, MoorDyn's
// 0.5 rho CdA: a body held in a current is pushed along it).
Vec6 BodyDampingLoad(const BodySpec& body, const Vec6& rate, const Vec& flow);
// Its derivative with respect to `rate`: diagonal, -(B_1 + 2 B_2 abs(u)).
Vec6 BodyDampingSlope(const BodySpec& body, const Vec6& rate, const Vec& flow);

// The pose at rest: the reference point's rest position and the rest angles.
Vec6 RestPose(const BodySpec& body);

// Where local point p of a body at `pose` is [m].
Vec BodyPoint(const Vec6& pose, const Vec& local);

// A force f [N] at world point x [m] as a load on a body whose reference point is at r: the
// force and its moment about r, (f, (x - r) x f).
Vec6 LoadAbout(const Vec& r, const Vec& x, const Vec& f);

// The static loads of a free body's own at `pose` [N, N m about the reference point]: weight
// at the centre of gravity, the rest buoyancy at the centre of buoyancy, the waterplane's
// restoring (heave from the rest elevation, roll and pitch from the rest angles), the constant
// force and moment. rho [kg/m^3], g [m/s^2].
Vec6 BodyOwnLoads(const BodySpec& body, const Vec6& pose, double rho, double g);

}  // namespace cablefilm
