#include "core/body.h"

#include <Eigen/Geometry>

namespace cablefilm {

Mat BodyRotation(const Vec& angles) {
  using Eigen::AngleAxisd;
  return (AngleAxisd(angles[2], Vec::UnitZ()) * AngleAxisd(angles[1], Vec::UnitY()) *
          AngleAxisd(angles[0], Vec::UnitX()))
      .toRotationMatrix();
}

Mat BodyPointTurn(const Vec& angles, const Vec& local) {
  using Eigen::AngleAxisd;
  const Mat Rx = AngleAxisd(angles[0], Vec::UnitX()).toRotationMatrix();
  const Mat Ry = AngleAxisd(angles[1], Vec::UnitY()).toRotationMatrix();
  const Mat Rz = AngleAxisd(angles[2], Vec::UnitZ()).toRotationMatrix();
  auto cross = [](const Vec& axis) {  // [axis]x: d/dtheta of a turn about axis, at the turn
    Mat c;
    c << 0, -axis[2], axis[1], axis[2], 0, -axis[0], -axis[1], axis[0], 0;
    return c;
  };
  Mat turn;
  turn.col(0) = Rz * Ry * cross(Vec::UnitX()) * Rx * local;
  turn.col(1) = Rz * cross(Vec::UnitY()) * Ry * Rx * local;
  turn.col(2) = cross(Vec::UnitZ()) * Rz * Ry * Rx * local;
  return turn;
}

Eigen::Matrix<double, 3, 6> BodyPointJacobian(const Vec6& pose, const Vec& local) {
  Eigen::Matrix<double, 3, 6> T;
  T << Mat::Identity(), BodyPointTurn(pose.tail<3>(), local);
  return T;
}

Mat6 BodyMassMatrix(const BodySpec& body, const Vec6& pose) {
  const Mat R = BodyRotation(pose.tail<3>());
  const Vec c = R * body.center_of_gravity;
  Mat C;  // [c]x
  C << 0, -c[2], c[1], c[2], 0, -c[0], -c[1], c[0], 0;
  const double m = body.mass;
  Mat6 M;
  M << m * Mat::Identity(), -m * C, m * C,
      R * body.inertia.asDiagonal() * R.transpose() - m * C * C;
  Mat6 P = Mat6::Identity();
  P.bottomRightCorner<3, 3>() = BodyTurnRates(pose.tail<3>());
  Mat6 Mq = P.transpose() * M * P;
  Mq.diagonal() += body.added_mass;
  return Mq;
}

Mat BodyTurnRates(const Vec& angles) {
  using Eigen::AngleAxisd;
  const Mat Ry = AngleAxisd(angles[1], Vec::UnitY()).toRotationMatrix();
  const Mat Rz = AngleAxisd(angles[2], Vec::UnitZ()).toRotationMatrix();
  Mat E;
  E << Rz * Ry * Vec::UnitX(), Rz * Vec::UnitY(), Vec::UnitZ();
  return E;
}

Vec6 GeneralizedLoad(const Vec6& pose, const Vec6& load) {
  Vec6 q;
  q << load.head<3>(), BodyTurnRates(pose.tail<3>()).transpose() * load.tail<3>();
  return q;
}

namespace {
// The water's velocity relative to the body per degree of freedom (no flow turns).
Vec6 RelativeFlow(const Vec6& rate, const Vec& flow) {
  Vec6 u = -rate;
  u.head<3>() += flow;
  return u;
}
}  // namespace

Vec6 BodyDampingLoad(const BodySpec& body, const Vec6& rate, const Vec& flow) {
  const Vec6 u = RelativeFlow(rate, flow);
  return body.quadratic_damping.cwiseProduct(u.cwiseAbs().cwiseProduct(u)) -
         body.linear_damping.cwiseProduct(rate);
}

Vec6 BodyDampingSlope(const BodySpec& body, const Vec6& rate, const Vec& flow) {
  return -(body.linear_damping +
           2.0 * body.quadratic_damping.cwiseProduct(RelativeFlow(rate, flow).cwiseAbs()));
}

Vec6 RestPose(const BodySpec& body) {
  Vec6 pose;
  pose << body.motion.rest(), body.angles;
  return pose;
}

Vec BodyPoint(const Vec6& pose, const Vec& local) {
  return pose.head<3>() + BodyRotation(pose.tail<3>()) * local;
}

Vec6 LoadAbout(const Vec& r, const Vec& x, const Vec& f) {
  Vec6 load;
  load << f, (x - r).cross(f);
  return load;
}

Vec6 BodyOwnLoads(const BodySpec& body, const Vec6& pose, double rho, double g) {
  const Vec r = pose.head<3>();
  const Vec up = Vec::UnitY();
  Vec6 load = LoadAbout(r, BodyPoint(pose, body.center_of_gravity), -body.mass * g * up);
  load += LoadAbout(r, BodyPoint(pose, body.center_of_buoyancy), rho * body.volume * g * up);
  const Vec6 rest = RestPose(body);
  // The waterplane: the displaced volume's change in heave, its metacentric part in roll and
  // pitch (linear: small motions about the rest pose, as hydrostatic stiffness is given).
  load[1] -= rho * g * body.waterplane_area * (pose[1] - rest[1]);
  load[3] -= rho * g * body.waterplane_inertia_x * (pose[3] - rest[3]);
  load[5] -= rho * g * body.waterplane_inertia_z * (pose[5] - rest[5]);
  load.head<3>() += body.force;
  load.tail<3>() += body.moment;
  return load;
}

}  // namespace cablefilm
