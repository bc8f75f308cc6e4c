#include "core/body_statics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "core/error.h"

namespace cablefilm {

Vec6 EquilibriumPose(const Model& sys, int b, const EquilibriumOptions& options) {
  EquilibriumReport report;
  SolveEquilibrium(sys, &report, options);
  return report.body_poses[b];
}

MooringLoad LoadAtPose(const Model& sys, int b, const Vec6& pose,
                       const EquilibriumOptions& options) {
  const Model held = HoldBody(sys, b, pose);
  MooringLoad out;
  out.states = SolveEquilibrium(held, nullptr, options);
  out.load = LinesLoadOnBody(held, out.states, b, pose);
  out.end_tension.assign(held.lines.size(), std::numeric_limits<double>::quiet_NaN());
  for (const Point& p : held.points) {
    if (p.on_body != b) continue;
    for (const LineEnd& e : p.ends)
      out.end_tension[e.line] =
          StaticStationForce(held.lines[e.line], out.states[e.line], e.station).norm();
  }
  return out;
}

double BodySize(const Model& sys, int b) {
  double size = 1;
  for (const Point& p : sys.points)
    if (p.on_body == b && !p.ends.empty()) size = std::max(size, p.local.norm());
  return size;
}

Mat6 MooringStiffness(const Model& sys, int b, const Vec6& pose, double step,
                      const EquilibriumOptions& options) {
  Mat6 K;
  const double size = BodySize(sys, b);
  for (int k = 0; k < 6; ++k) {
    const double h = k < 3 ? step : step / size;
    Vec6 d = Vec6::Zero();
    d[k] = h;
    const Vec6 plus = LoadAtPose(sys, b, pose + d, options).load;
    const Vec6 minus = LoadAtPose(sys, b, pose - d, options).load;
    K.col(k) = (minus - plus) / (2 * h);  // (not -(plus - minus): no -0 where they are equal)
  }
  return K;
}

std::vector<OffsetPoint> OffsetCurve(const Model& sys, int b, const Vec6& pose,
                                     double heading, const std::vector<double>& offsets,
                                     const EquilibriumOptions& options) {
  if (!(std::abs(heading) <= kMaxHeading)) {
    char what[128];
    std::snprintf(what, sizeof what, "heading: expected an angle from %g to %g degrees, got %.6g",
                  -kMaxHeading, kMaxHeading, heading);
    throw Error(what);
  }
  const Vec e = Horizontal(heading * M_PI / 180);
  std::vector<OffsetPoint> curve;
  for (double d : offsets) {
    Vec6 at = pose;
    at.head<3>() += d * e;
    OffsetPoint p;
    p.offset = d;
    p.load = LoadAtPose(sys, b, at, options);
    p.restoring = -p.load.load.head<3>().dot(e);
    curve.push_back(std::move(p));
  }
  return curve;
}

double ShortestLineOn(const Model& sys, int b) {
  double shortest = INFINITY;
  for (const Point& p : sys.points)
    if (p.on_body == b)
      for (const LineEnd& e : p.ends)
        shortest = std::min(shortest, sys.lines[e.line].line.total_length());
  if (!std::isfinite(shortest))
    throw Error("body \"" + sys.bodies[b].name + "\": no line ends on it");
  return shortest;
}

}  // namespace cablefilm
