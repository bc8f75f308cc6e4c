#include "view/camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace cablefilm {
namespace {

constexpr double kDegree = M_PI / 180;
constexpr double kFitMargin = 1.04;  // around the fitted box: markers and tubes have width

// The eight corners of a box.
void Corners(const WorldBox& b, Vec out[8]) {
  for (int i = 0; i < 8; ++i)
    out[i] = Vec(i & 1 ? b.x_max : b.x_min, i & 2 ? b.y_max : b.y_min, i & 4 ? b.z_max : b.z_min);
}

}  // namespace

OrbitCamera ClampCamera(const OrbitCamera& c) {
  const OrbitCamera fallback;
  OrbitCamera out;
  out.azimuth = std::isfinite(c.azimuth) ? std::remainder(c.azimuth, 360.0) : fallback.azimuth;
  if (out.azimuth <= -180) out.azimuth += 360;
  out.elevation = std::isfinite(c.elevation)
                      ? std::clamp(c.elevation, -kMaxElevation, kMaxElevation)
                      : fallback.elevation;
  out.zoom = std::isfinite(c.zoom) ? std::clamp(c.zoom, kMinZoom, kMaxZoom) : fallback.zoom;
  return out;
}

OrbitCamera DefaultCamera(const SceneView& scene) {
  OrbitCamera camera;
  double heading = 0;  // of the line's chord [deg]
  if (!scene.lines.empty()) {
    const LineState& r = scene.lines.front().reference;
    const std::size_t n = r.x.size();
    if (n >= 2 && r.z.size() == n) {
      const double dx = r.x[n - 1] - r.x[0], dz = r.z[n - 1] - r.z[0];
      if (std::hypot(dx, dz) > 0) heading = std::atan2(dz, dx) / kDegree;
    }
  }
  // Broadside (heading + 90) puts the start on the left; turning 35 degrees towards the end
  // shows the line's depth without hiding one end behind the other.
  camera.azimuth = heading + 90 - 35;
  // A system's spread reads from higher up: its lines apart in plan, not behind each other.
  camera.elevation = scene.lines_alike && scene.lines.size() > 1 ? 35 : 22;
  return ClampCamera(camera);
}

bool ViewProjection::ToPixel(const Vec& p, Vec2f* pixel) const {
  const Eigen::Vector4d c = matrix * Eigen::Vector4d(p.x(), p.y(), p.z(), 1.0);
  if (!(c.w() > 1e-12)) return false;
  const double x = c.x() / c.w(), y = c.y() / c.w();
  pixel->x = static_cast<float>(viewport.x0 + (x + 1) / 2 * viewport.width());
  pixel->y = static_cast<float>(viewport.y0 + (1 - y) / 2 * viewport.height());
  return true;
}

void ViewProjection::Fill(Scene3* scene) const {
  for (int i = 0; i < 16; ++i) scene->view_projection[i] = static_cast<float>(matrix.data()[i]);
  scene->eye = {static_cast<float>(eye.x()), static_cast<float>(eye.y()),
                static_cast<float>(eye.z())};
  scene->corner0 = {viewport.x0, viewport.y0};
  scene->corner1 = {viewport.x1, viewport.y1};
}

ViewProjection MakeViewProjection(const OrbitCamera& camera, const WorldBox& fit,
                                  const WorldBox& extent, const PixelRect& viewport,
                                  double fov_y) {
  const OrbitCamera c = ClampCamera(camera);
  const double az = c.azimuth * kDegree, el = c.elevation * kDegree;
  // `back` points from the target to the eye; the view looks along -back.
  const Vec back(std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az));
  const Vec right = Vec::UnitY().cross(back).normalized();
  const Vec up = back.cross(right);
  ViewProjection v;
  v.target = Vec(0.5 * (fit.x_min + fit.x_max), 0.5 * (fit.y_min + fit.y_max),
                 0.5 * (fit.z_min + fit.z_max));
  v.right = right;
  v.up = up;
  v.viewport = viewport;
  const double aspect = std::max(1e-6, static_cast<double>(viewport.width())) /
                        std::max(1e-6, static_cast<double>(viewport.height()));
  const double ty = std::tan(0.5 * fov_y * kDegree), tx = aspect * ty;
  // The nearest distance at which every corner is inside the view: |x| <= (d - z) tan, for each
  // corner at x, y across and z towards the eye from the target. Seen from above, the box's
  // near corners spread wider than its far ones: the target then moves across the view to the
  // middle of what the corners cover, and the fit is made again about it, so that the box
  // fills the view rather than leaving a band empty.
  Vec corners[8];
  Corners(fit, corners);
  double fit_distance = 1e-3;
  for (int pass = 0; pass < 2; ++pass) {
    fit_distance = 1e-3;
    for (const Vec& p : corners) {
      const Vec rel = p - v.target;
      const double x = rel.dot(right), y = rel.dot(up), z = rel.dot(back);
      fit_distance = std::max({fit_distance, z + std::fabs(x) / tx, z + std::fabs(y) / ty});
    }
    if (pass == 1) break;
    double lo_x = 1, hi_x = -1, lo_y = 1, hi_y = -1;  // the corners' extent [tan units]
    for (const Vec& p : corners) {
      const Vec rel = p - v.target;
      const double depth = fit_distance - rel.dot(back);  // > 0: the fit keeps them in front
      lo_x = std::min(lo_x, rel.dot(right) / depth);
      hi_x = std::max(hi_x, rel.dot(right) / depth);
      lo_y = std::min(lo_y, rel.dot(up) / depth);
      hi_y = std::max(hi_y, rel.dot(up) / depth);
    }
    v.target += fit_distance * (0.5 * (lo_x + hi_x) * right + 0.5 * (lo_y + hi_y) * up);
  }
  const double distance = kFitMargin * fit_distance / c.zoom;
  v.eye = v.target + distance * back;
  v.pixels_per_metre = viewport.height() / (2 * distance * ty);
  // Near and far planes around what is drawn, the near one never at the eye.
  Corners(extent, corners);
  double nearest = distance, farthest = distance;
  for (const Vec& p : corners) {
    const double depth = (v.eye - p).dot(back);
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
  }
  const double z_far = 1.05 * farthest;
  const double z_near = std::max(0.9 * nearest, 1e-3 * z_far);
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.block<1, 3>(0, 0) = right.transpose();
  view.block<1, 3>(1, 0) = up.transpose();
  view.block<1, 3>(2, 0) = back.transpose();
  view(0, 3) = -right.dot(v.eye);
  view(1, 3) = -up.dot(v.eye);
  view(2, 3) = -back.dot(v.eye);
  Eigen::Matrix4d projection = Eigen::Matrix4d::Zero();
  projection(0, 0) = 1 / tx;
  projection(1, 1) = 1 / ty;
  projection(2, 2) = (z_far + z_near) / (z_near - z_far);
  projection(2, 3) = 2 * z_far * z_near / (z_near - z_far);
  projection(3, 2) = -1;
  v.matrix = projection * view;
  return v;
}

}  // namespace cablefilm
