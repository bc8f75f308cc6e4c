#include "view/plane_views.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "view/body_fit.h"
#include "view/cable_panel.h"

namespace cablefilm {
namespace {

constexpr double kDegree = M_PI / 180;

// A state seen in plan (x across, z) or in the plane (distance along it, y); tensions as they
// are. `out`'s storage is reused.
void Project(const LineState& in, bool plan, const ElevationPlane& e, LineState* out) {
  const std::size_t n = in.x.size();
  out->x.resize(n);
  out->y.resize(n);
  out->z.clear();
  out->tension = in.tension;
  for (std::size_t j = 0; j < n; ++j) {
    const double z = in.z.empty() ? 0 : in.z[j];
    out->x[j] = plan ? in.x[j] : e.Along(in.x[j], z);
    out->y[j] = plan ? z : in.y[j];
  }
}

Vec3f ProjectPoint(const Vec3f& q, bool plan, const ElevationPlane& e) {
  if (plan) return {q.x, q.z, 0};
  return {static_cast<float>(e.Along(q.x, q.z)), q.y, 0};
}

// An arrow of `length` pixels centred on `centre` along the unit vector `dir`.
void DrawArrow(Painter& p, Vec2f centre, Vec2f dir, float length, Rgba c) {
  const float k = p.k(), head = 11 * k, half = 0.5f * length;
  const Vec2f tail{centre.x - dir.x * half, centre.y - dir.y * half};
  const Vec2f tip{centre.x + dir.x * half, centre.y + dir.y * half};
  const Vec2f base{tip.x - dir.x * head, tip.y - dir.y * head};
  const Vec2f side{-dir.y * 0.45f * head, dir.x * 0.45f * head};
  p.Line(tail, base, 2.2f * k, c);
  p.Triangle(tip, {base.x + side.x, base.y + side.y}, {base.x - side.x, base.y - side.y}, c);
}

// Distance from q to the segment a-b [px].
float SegmentDistance(Vec2f q, Vec2f a, Vec2f b) {
  const float dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  const float h = len2 > 0 ? std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy) / len2, 0.0f, 1.0f) : 0;
  return std::hypot(q.x - a.x - h * dx, q.y - a.y - h * dy);
}

// The current and the waves' heading, as arrows with their values, in the corner of the plan
// farthest from the first line's chord.
void DrawFlowArrows(Painter& p, const PlotMapping& plan, const PlaneViewsInput& in,
                    const Theme& th) {
  struct Row {
    Vec2f dir;
    std::string label;
    Rgba color;
  };
  std::vector<Row> rows;
  const Vec& c = in.now->current;
  const double speed = std::hypot(c.x(), c.z());
  if (speed > 1e-9) {
    std::string label = "current " + FormatValue("%.2f", speed) + " m/s";
    if (in.scene->sea.current_profile) label += " at the top";
    rows.push_back({{static_cast<float>(c.x() / speed), static_cast<float>(c.z() / speed)},
                    label, th.current});
  }
  const Wave& w = in.now->wave;
  if (w.spec.present && w.spec.height > 0)
    rows.push_back({{static_cast<float>(w.direction.x()), static_cast<float>(w.direction.z())},
                    "waves " + FormatValue("%.1f", w.spec.height) + " m, " +
                        FormatValue("%.3g", w.spec.period) + " s",
                    th.water});
  if (rows.empty()) return;
  const float k = p.k();
  const PixelRect& r = plan.rect;
  const float row_h = 40 * k, arrow = 40 * k, inset = 10 * k;
  float label_w = 0;
  for (const Row& row : rows) label_w = std::max(label_w, EstimateTextWidth(row.label, 14 * k));
  const float block_w = arrow + 14 * k + label_w, block_h = row_h * rows.size();
  // The corner farthest from the chord (a line rarely crosses its plan's corners).
  Vec2f a = plan.ToPixel(0, 0), b = a;
  const LineState& ref = in.scene->lines.front().reference;
  if (ref.x.size() >= 2) {
    const std::size_t n = ref.x.size();
    a = plan.ToPixel(ref.x[0], ref.z.empty() ? 0 : ref.z[0]);
    b = plan.ToPixel(ref.x[n - 1], ref.z.empty() ? 0 : ref.z[n - 1]);
  }
  float best = -1, x0 = r.x0 + inset, y0 = r.y0 + inset;
  for (int corner = 0; corner < 4; ++corner) {
    const float bx = corner & 1 ? r.x1 - inset - block_w : r.x0 + inset;
    const float by = corner & 2 ? r.y1 - inset - block_h : r.y0 + inset;
    const float d = SegmentDistance({bx + block_w / 2, by + block_h / 2}, a, b);
    if (d > best) {
      best = d;
      x0 = bx;
      y0 = by;
    }
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const float y = y0 + (i + 0.5f) * row_h;
    // Plan pixels grow with x across and with z down: a world (x, z) direction as it is.
    DrawArrow(p, {x0 + arrow / 2, y}, rows[i].dir, arrow, rows[i].color);
    p.Text(rows[i].label, {x0 + arrow + 14 * k, y}, 14 * k, th.text_dim, HAlign::kLeft,
           VAlign::kMiddle);
  }
}

// One of the two views into its panel.
void DrawView(Painter& p, const FrameLayout& L, bool plan, const PlaneViewsInput& in,
              const Colormap& colormap, const Theme& th) {
  const SceneView& scene = *in.scene;
  const ElevationPlane& e = in.plane;
  std::vector<LineView> lines(scene.lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i) {
    lines[i].label = scene.lines[i].label;
    lines[i].marks = scene.lines[i].marks;
    if (!scene.lines[i].reference.x.empty())
      Project(scene.lines[i].reference, plan, e, &lines[i].reference);
  }
  std::vector<LineSnapshot> now(in.now->lines.size());
  for (std::size_t i = 0; i < now.size(); ++i) Project(in.now->lines[i], plan, e, &now[i]);
  std::vector<EndPath> paths = in.history->end_paths();
  for (EndPath& path : paths)
    for (auto& piece : path.pieces)
      for (Vec3f& q : piece) q = ProjectPoint(q, plan, e);

  CablePanelInput c;
  c.panel = plan ? L.plan_panel : L.elevation_panel;
  c.world = plan ? L.plan : L.elevation;
  c.cable_width = L.cable_width;
  c.overlay_width = L.overlay_width;
  c.head = plan ? PlanHead() : ElevationHead(e);
  c.tension_min = in.tension_min;
  c.tension_max = in.tension_max;
  c.lines = &lines;
  c.now = &now;
  c.end_paths = &paths;
  c.alike = scene.lines_alike;
  if (plan) c.points = &scene.points;  // the plan shows the spread: the points apart
  // The bodies' boxes in both views (the elevation draws no outlines: its points overlap).
  std::vector<std::vector<PanelEdge>> boxes;
  for (const auto& edges : BodyBoxesNow(scene, in.now->lines, in.now->t)) {
    boxes.emplace_back();
    for (const auto& edge : edges) {  // as ProjectPoint, in double
      const Vec &a = edge[0], &b = edge[1];
      if (plan)
        boxes.back().push_back({a.x(), a.z(), b.x(), b.z()});
      else
        boxes.back().push_back({e.Along(a.x(), a.z()), a.y(), e.Along(b.x(), b.z()), b.y()});
    }
  }
  c.bodies = &scene.bodies;
  c.body_boxes = &boxes;
  c.x_label = plan ? "x [m]" : "horizontal distance from the start [m]";
  c.y_label = plan ? "z [m]" : "y [m]";
  std::vector<double> sx, sy;
  if (!plan) {
    if (scene.sea.seabed) c.seabed_y = &scene.sea.seabed_y;
    const Wave& w = in.now->wave;
    if (w.spec.present && w.k > 0) {  // the surface cut along the plane, 24 points a wave length
      const double lo = std::min(c.world.x_lo, c.world.x_hi), hi = std::max(c.world.x_lo, c.world.x_hi);
      const int n = std::clamp(static_cast<int>(std::ceil(24 * (hi - lo) / w.length())), 64, 4096);
      for (int i = 0; i <= n; ++i) {
        const double u = lo + (hi - lo) * i / n;
        sx.push_back(u);
        sy.push_back(SurfaceAt(w, Vec(e.x0 + u * e.ex, 0.0, e.z0 + u * e.ez), in.now->t));
      }
      c.surface_x = &sx;
      c.surface_y = &sy;
    }
  }
  DrawCablePanel(p, c, colormap, th);
  if (plan) DrawFlowArrows(p, c.world, in, th);
}

}  // namespace

double ElevationPlane::heading() const { return std::atan2(ez, ex) / kDegree; }

ElevationPlane MakeElevationPlane(const SceneView& scene) {
  ElevationPlane e;
  if (scene.lines.empty()) return e;
  const LineState& r = scene.lines.front().reference;
  const std::size_t n = r.x.size();
  if (n < 2) return e;
  const double z0 = r.z.empty() ? 0 : r.z[0], z1 = r.z.empty() ? 0 : r.z[n - 1];
  e.x0 = r.x[0];
  e.z0 = z0;
  const double dx = r.x[n - 1] - r.x[0], dz = z1 - z0, d = std::hypot(dx, dz);
  // Ends above each other (closer than a millionth of the line's height) have no plane of
  // their own: the x-y plane through them.
  const double dy = std::fabs(r.y[n - 1] - r.y[0]);
  if (d > 1e-6 * std::max(dy, 1e-9)) {
    e.ex = dx / d;
    e.ez = dz / d;
  }
  return e;
}

void SetPlaneBoxes(const WorldBox& b, const ElevationPlane& e, SpaceLayoutRequest* r) {
  r->x_min = b.x_min;
  r->x_max = b.x_max;
  r->z_min = b.z_min;
  r->z_max = b.z_max;
  r->y_min = b.y_min;
  r->y_max = b.y_max;
  // The box's corners along the plane: its horizontal extent seen edge on.
  r->s_min = r->s_max = e.Along(b.x_min, b.z_min);
  for (double x : {b.x_min, b.x_max})
    for (double z : {b.z_min, b.z_max}) {
      r->s_min = std::min(r->s_min, e.Along(x, z));
      r->s_max = std::max(r->s_max, e.Along(x, z));
    }
}

PanelHead PlanHead() { return PanelHead{"Plan (from above)", {}, false}; }

PanelHead ElevationHead(const ElevationPlane& e) {
  return PanelHead{"Elevation: vertical plane through the ends, along " +
                       FormatValue("%.0f", e.heading()) + "\u00b0",
                   {}, false};
}

void DrawPlaneViews(Painter& p, const FrameLayout& L, const PlaneViewsInput& in,
                    const Colormap& colormap, const Theme& th) {
  DrawView(p, L, true, in, colormap, th);
  DrawView(p, L, false, in, colormap, th);
}

}  // namespace cablefilm
