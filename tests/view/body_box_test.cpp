// A body's box (view/body_box.h) and its pose from where its points are (view/body_fit.h):
// the corners against a turn worked by hand, the edges' lengths, and the fit recovering a
// known pose. Tolerances: 1e-12 m on sizes of about 10 m is round-off of a few operations
// in double (the SVD of the fit included: it is exact for rigidly placed points).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/body.h"
#include "view/body_box.h"
#include "view/body_fit.h"

namespace cablefilm {
namespace {

constexpr double kTol = 1e-12;  // [m]

// The sign of corner i along each axis: bit 0 x, bit 1 y, bit 2 z (BoxCorners' order).
Vec Signs(int i) { return Vec((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1); }

TEST(BodyBox, CornersOfAYawedBoxByHand) {
  // Turned 90 degrees about y (up; yaw): the body's x is the world's -z, its z the world's x,
  // so a local (a, b, c) is at r + (c, b, -a). Box 4 x 2 x 6 about local (1, 0, 0), at
  // r = (1, 2, 3): local corner (1 + 2 sx, sy, 3 sz) is at (1 + 3 sz, 2 + sy, 3 - 1 - 2 sx).
  const Vec6 pose = (Vec6() << 1, 2, 3, 0, M_PI / 2, 0).finished();
  const Vec size(4, 2, 6), center(1, 0, 0);
  const std::array<Vec, 8> c =
      BoxCorners(pose.head<3>(), BodyRotation(pose.tail<3>()), size, center);
  for (int i = 0; i < 8; ++i) {
    const Vec s = Signs(i);
    const Vec hand(1 + 3 * s.z(), 2 + s.y(), 2 - 2 * s.x());
    EXPECT_LT((c[i] - hand).norm(), kTol) << "corner " << i;
  }
  // Each edge's ends are two of those corners.
  for (const auto& e : BodyBoxEdges(pose, size, center))
    for (const Vec& end : e)
      EXPECT_TRUE(std::any_of(c.begin(), c.end(), [&](const Vec& q) { return (q - end).norm() < kTol; }));
}

TEST(BodyBox, AnyPoseCornersAreTheBodysPointsAndEdgesItsSizes) {
  // Turned about all three axes: each corner is where the body's local point
  // centre + size/2 * signs is (core/body.h's BodyPoint, r + R(theta) p), and the 12 edges are
  // four of each size, each along one body axis, every corner the end of three.
  const Vec6 pose = (Vec6() << -5, 7, 11, 0.3, -1.1, 0.7).finished();
  const Vec size(40, 20, 30), center(2, -5, 1);
  const BoxEdges edges = BodyBoxEdges(pose, size, center);
  const std::array<Vec, 8> c =
      BoxCorners(pose.head<3>(), BodyRotation(pose.tail<3>()), size, center);
  for (int i = 0; i < 8; ++i)
    EXPECT_LT((c[i] - BodyPoint(pose, center + 0.5 * size.cwiseProduct(Signs(i)))).norm(), kTol)
        << "corner " << i;
  int count[3] = {0, 0, 0};
  const Mat R = BodyRotation(pose.tail<3>());
  for (const auto& e : edges) {
    const Vec d = R.transpose() * (e[1] - e[0]);  // in the body's axes
    int axis = 0;
    d.cwiseAbs().maxCoeff(&axis);
    ++count[axis];
    EXPECT_NEAR(d.norm(), size[axis], kTol);
    EXPECT_NEAR(d[axis], size[axis], kTol);  // along the axis, from - to +
  }
  EXPECT_EQ(count[0], 4);
  EXPECT_EQ(count[1], 4);
  EXPECT_EQ(count[2], 4);
  for (const Vec& q : c) {
    int ends = 0;
    for (const auto& e : edges) ends += (e[0] - q).norm() < kTol || (e[1] - q).norm() < kTol;
    EXPECT_EQ(ends, 3);
  }
}

TEST(BodyBox, AZeroSizeIsAPoint) {
  const Vec6 pose = (Vec6() << 1, 2, 3, 0.1, 0.2, 0.3).finished();
  for (const auto& e : BodyBoxEdges(pose, Vec::Zero(), Vec(1, 0, 0)))
    EXPECT_LT((e[0] - BodyPoint(pose, Vec(1, 0, 0))).norm(), kTol);
}

TEST(BodyFit, ThreeFairleadsGiveThePose) {
  // Three fairleads 120 degrees apart (floating_platform's), placed by a known pose: the fit
  // recovers r and R(theta) (to round-off), whatever the rest angles it is given.
  const std::vector<Vec> local = {Vec(20, -10, 0), Vec(-10, -10, 17.321), Vec(-10, -10, -17.321)};
  const Vec6 pose = (Vec6() << 26, -0.4, 3, 0.05, 0.3, -0.02).finished();
  std::vector<Vec> world;
  for (const Vec& p : local) world.push_back(BodyPoint(pose, p));
  const BodyPlacement at = FitBodyPlacement(local, world, Mat::Identity());
  EXPECT_LT((at.r - pose.head<3>()).norm(), 1e-10);  // m: the SVD's round-off on 20 m
  EXPECT_LT((at.R - BodyRotation(pose.tail<3>())).norm(), 1e-12);
}

TEST(BodyFit, FewerOrCollinearPointsKeepTheRestTurn) {
  // Two points (one line): its place from their centre at its rest turn.
  const Mat rest = BodyRotation(Vec(0, M_PI / 2, 0));
  const std::vector<Vec> local = {Vec(0, 0, -6), Vec(0, 0, 6)};
  const Vec r(20, 1, 6);
  const std::vector<Vec> world = {r + rest * local[0], r + rest * local[1]};
  const BodyPlacement at = FitBodyPlacement(local, world, rest);
  EXPECT_LT((at.r - r).norm(), kTol);
  EXPECT_LT((at.R - rest).norm(), kTol);
  // One point: the same.
  const BodyPlacement one = FitBodyPlacement({Vec(1, 2, 3)}, {r + rest * Vec(1, 2, 3)}, rest);
  EXPECT_LT((one.r - r).norm(), kTol);
}

// A scene view of one line whose end is the point "fairlead" (at (11, 5, 7) in OneSnapshot),
// the point of a body with a 2 m cube at local (1, 0, 0).
SceneView OneLineScene() {
  SceneView scene;
  LineView l;
  l.arc_length = {0, 1};
  scene.lines.push_back(l);
  scene.points.push_back({"fairlead", 0, 1});
  return scene;
}

BodyView CubeOnThePoint() {
  BodyView b;
  b.points = {0};
  b.local = {{1, 0, 0}};
  b.has_box = true;
  b.box = {2, 2, 2};
  return b;
}

LineSnapshot OneSnapshot() {
  LineSnapshot now;
  now.x = {0, 11};
  now.y = {0, 5};
  now.z = {0, 7};
  return now;
}

TEST(BodyFit, BoxesNowFollowThePointsOfABodyWithABox) {
  // The box follows the body's point, and a body without a box gets none.
  SceneView scene = OneLineScene();
  BodyView b = CubeOnThePoint();
  b.name = "buoy";
  scene.bodies.push_back(b);
  b.has_box = false;
  scene.bodies.push_back(b);
  const auto boxes = BodyBoxesNow(scene, {OneSnapshot()});
  ASSERT_EQ(boxes.size(), 2u);
  ASSERT_EQ(boxes[0].size(), 12u);
  EXPECT_TRUE(boxes[1].empty());
  // Its reference point at (10, 5, 7): the box from (9, 4, 6) to (11, 6, 8).
  Vec lo = boxes[0][0][0], hi = lo;
  for (const auto& e : boxes[0])
    for (const Vec& q : e) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  EXPECT_LT((lo - Vec(9, 4, 6)).norm(), kTol);
  EXPECT_LT((hi - Vec(11, 6, 8)).norm(), kTol);
}

// A driven body that turns (issue 20), with one point: too few for the fit, so the box takes
// the body's angles at the snapshot's time from its motion.
TEST(BodyFit, ABoxOfTooFewPointsTurnsWithItsDrivenAngles) {
  SceneView scene = OneLineScene();
  BodyView b = CubeOnThePoint();
  b.angles_at = [](double t) { return std::array<double, 3>{0.0, 0.25 * t, 0.0}; };  // [rad]
  scene.bodies.push_back(b);
  const auto boxes = BodyBoxesNow(scene, {OneSnapshot()}, 2.0);  // at t = 2 s: a yaw of 0.5 rad
  ASSERT_EQ(boxes[0].size(), 12u);
  // Its corners at r + R p, R the yaw of 0.5 rad, r where the point puts it: every corner of
  // the box (+-1, +-1, +-1) is one of the edges' ends.
  const Mat R = BodyRotation(Vec(0, 0.5, 0));
  const Vec r = Vec(11, 5, 7) - R * Vec(1, 0, 0);
  for (int c = 0; c < 8; ++c) {
    const Vec corner = r + R * Vec(c & 1 ? 1 : -1, c & 2 ? 1 : -1, c & 4 ? 1 : -1);
    double nearest = 1e300;
    for (const auto& e : boxes[0])
      for (const Vec& q : e) nearest = std::min(nearest, (q - corner).norm());
    EXPECT_LT(nearest, kTol) << c;
  }
}

}  // namespace
}  // namespace cablefilm
