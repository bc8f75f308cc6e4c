#include "view/body_fit.h"

#include <Eigen/LU>
#include <Eigen/SVD>

#include "core/body.h"

namespace cablefilm {

BodyPlacement FitBodyPlacement(const std::vector<Vec>& local, const std::vector<Vec>& world,
                               const Mat& rest) {
  BodyPlacement out;
  out.R = rest;
  const std::size_t n = std::min(local.size(), world.size());
  if (n == 0) return out;
  Vec pc = Vec::Zero(), xc = Vec::Zero();
  for (std::size_t i = 0; i < n; ++i) pc += local[i] / n, xc += world[i] / n;
  Mat H = Mat::Zero();  // the local spread against the world's
  for (std::size_t i = 0; i < n; ++i) H += (local[i] - pc) * (world[i] - xc).transpose();
  const Eigen::JacobiSVD<Mat> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Vec s = svd.singularValues();
  // Spread in a plane at least: the second singular value (a squared length) well above
  // round-off of the first.
  if (n >= 3 && s[1] > 1e-9 * s[0] && s[0] > 0) {
    const Mat U = svd.matrixU(), V = svd.matrixV();
    Mat D = Mat::Identity();
    D(2, 2) = (V * U.transpose()).determinant() < 0 ? -1.0 : 1.0;  // a turn, not a mirror
    out.R = V * D * U.transpose();
  }
  out.r = xc - out.R * pc;
  return out;
}

std::vector<std::vector<std::array<Vec, 2>>> BodyBoxesNow(
    const SceneView& scene, const std::vector<LineSnapshot>& lines, double t) {
  std::vector<std::vector<std::array<Vec, 2>>> out(scene.bodies.size());
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const BodyView& body = scene.bodies[b];
    if (!body.has_box || body.local.size() != body.points.size()) continue;
    std::vector<Vec> local, world;
    for (std::size_t k = 0; k < body.points.size(); ++k) {
      const int q = body.points[k];
      if (q < 0 || static_cast<std::size_t>(q) >= scene.points.size()) continue;
      const PointView& pt = scene.points[q];
      if (pt.line < 0 || static_cast<std::size_t>(pt.line) >= lines.size()) continue;
      const LineSnapshot& l = lines[pt.line];
      const std::size_t j = static_cast<std::size_t>(pt.station);
      if (pt.station < 0 || j >= l.x.size() || j >= l.y.size()) continue;
      local.push_back(Vec(body.local[k][0], body.local[k][1], body.local[k][2]));
      world.push_back(Vec(l.x[j], l.y[j], j < l.z.size() ? l.z[j] : 0.0));
    }
    if (world.empty()) continue;
    // Too few points for the turn: the body's angles now (a driven body's), else at rest.
    const std::array<double, 3> a =
        body.angles_at ? body.angles_at(t) : body.rest_angles;
    const Vec rest(a[0], a[1], a[2]);
    const BodyPlacement at = FitBodyPlacement(local, world, BodyRotation(rest));
    const BoxEdges edges =
        BodyBoxEdges(at.r, at.R, Vec(body.box[0], body.box[1], body.box[2]),
                     Vec(body.box_center[0], body.box_center[1], body.box_center[2]));
    out[b].assign(edges.begin(), edges.end());
  }
  return out;
}

}  // namespace cablefilm
