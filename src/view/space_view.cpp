#include "view/space_view.h"

#include <algorithm>
#include <cmath>

#include "view/body_fit.h"
#include "view/body_outline.h"
#include "view/cable_panel.h"
#include "view/name_tag.h"
#include "view/plot_layout.h"

namespace cablefilm {
namespace {

constexpr float kTubeWidth = 1.7f;    // a tube's diameter over the plane views' line width
constexpr double kSheetPad = 0.08;    // the seabed and the water beyond the box, of its width
constexpr int kMaxSheetSide = 96;     // water vertices along a side (bounded cost)

Vec3f F(const Vec& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

Vec StationOf(const LineState& l, std::size_t j) {
  return Vec(l.x[j], l.y[j], l.z.empty() ? 0.0 : l.z[j]);
}

Rgba WithAlpha(Rgba c, float a) {
  c.a = a;
  return c;
}

// A line's stations as a tube, a colour a link on the map (or `uniform` when given).
Tube LineTube(const LineState& l, float radius, const Colormap& map, double lo, double hi) {
  Tube t;
  t.radius = radius;
  for (std::size_t j = 0; j < l.x.size(); ++j) t.points.push_back(F(StationOf(l, j)));
  for (std::size_t j = 0; j + 1 < l.x.size() && j < l.tension.size(); ++j)
    t.colors.push_back(map.Map(l.tension[j], lo, hi));
  if (t.colors.size() + 1 != t.points.size()) t.colors.assign(1, map.At(0));
  return t;
}

Tube PlainTube(std::vector<Vec3f> points, float radius, Rgba c) {
  Tube t;
  t.points = std::move(points);
  t.colors = {c};
  t.radius = radius;
  return t;
}

double Horizontal(const WorldBox& b) { return std::max({b.x_max - b.x_min, b.z_max - b.z_min, 1e-6}); }

// Where the current's arrow goes: the horizontal corner of the box farthest from the first
// line's chord (seen from above), drawn in a bit.
Vec ArrowCentre(const WorldBox& b, const LineState& ref, double y) {
  const double inset = 0.14 * Horizontal(b);
  Vec2f a{0, 0}, c{0, 0};
  if (ref.x.size() >= 2) {
    const std::size_t n = ref.x.size();
    a = {static_cast<float>(ref.x[0]), static_cast<float>(ref.z.empty() ? 0 : ref.z[0])};
    c = {static_cast<float>(ref.x[n - 1]), static_cast<float>(ref.z.empty() ? 0 : ref.z[n - 1])};
  }
  Vec best(b.x_min, y, b.z_min);
  double farthest = -1;
  for (int corner = 0; corner < 4; ++corner) {
    const double x = corner & 1 ? b.x_max - inset : b.x_min + inset;
    const double z = corner & 2 ? b.z_max - inset : b.z_min + inset;
    const double dx = c.x - a.x, dz = c.y - a.y, len2 = dx * dx + dz * dz;
    const double h = len2 > 0 ? std::clamp(((x - a.x) * dx + (z - a.y) * dz) / len2, 0.0, 1.0) : 0;
    const double d = std::hypot(x - a.x - h * dx, z - a.y - h * dz);
    if (d > farthest) {
      farthest = d;
      best = Vec(x, y, z);
    }
  }
  return best;
}

// Distance from q to the segment a-b [px].
float ScreenDistance(Vec2f q, Vec2f a, Vec2f b) {
  const float dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  const float h = len2 > 0 ? std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy) / len2, 0.0f, 1.0f) : 0;
  return std::hypot(q.x - a.x - h * dx, q.y - a.y - h * dy);
}

// The axes' directions on screen, bottom left of the view: where x, y and z point.
void DrawTriad(Painter& p, const ViewProjection& v, const PixelRect& view) {
  const float k = p.k(), length = 26 * k;
  const Vec2f o{view.x0 + 40 * k, view.y1 - 40 * k};
  const struct {
    Vec axis;
    const char* name;
    Rgba color;
  } axes[] = {{Vec::UnitX(), "x", Hex(0xf06a6a)},
              {Vec::UnitY(), "y", Hex(0x6fd67a)},
              {Vec::UnitZ(), "z", Hex(0x5aa2f0)}};
  for (const auto& a : axes) {
    const Vec2f d{static_cast<float>(a.axis.dot(v.right)), static_cast<float>(-a.axis.dot(v.up))};
    const Vec2f tip{o.x + d.x * length, o.y + d.y * length};
    p.Line(o, tip, 2 * k, a.color);
    p.Text(a.name, {o.x + d.x * (length + 9 * k), o.y + d.y * (length + 9 * k)}, 13 * k, a.color,
           HAlign::kCenter, VAlign::kMiddle, false, true);
  }
  p.Disc(o, 2.5f * k, Hex(0xd0d7e1));
}

}  // namespace

PanelHead SpaceViewHead(const SceneView& scene, const std::string& path_label, Rgba swatch,
                        const Theme& th) {
  PanelHead head;
  head.title = scene.lines.size() > 1 ? "Lines in space (perspective)" : "Line in space (perspective)";
  if (scene.lines.size() > 1 && !scene.lines_alike) {  // alike: named on the picture
    LegendGroup names{{LegendEntry::kCable, swatch, LineName(scene, 0) + " (thick)"}};
    for (std::size_t i = 1; i < scene.lines.size(); ++i)
      names.push_back({LegendEntry::kLine, swatch, LineName(scene, i) + " (thin)"});
    head.groups.push_back(names);
  }
  bool weights = false;
  for (const LineView& line : scene.lines) weights = weights || !line.marks.weights.empty();
  const StationMarks first = LegendMarks(scene);
  const EndNames ends = EndLabels(scene);
  LegendGroup marks;
  if (weights) marks.push_back({LegendEntry::kDiamond, th.marker_edge, "weight"});
  if (!first.fixed_ends.empty())
    marks.push_back({LegendEntry::kSquare, th.marker_edge, ends.fixed});
  if (!first.moving_ends.empty()) {
    marks.push_back({LegendEntry::kRing, th.accent, ends.moving});
    marks.push_back({LegendEntry::kLine, EndPathColor(th), path_label});
  }
  if (!first.free_ends.empty()) marks.push_back({LegendEntry::kRing, th.marker_edge, ends.free});
  marks.push_back({LegendEntry::kLine, th.equilibrium, ReferenceName(scene)});
  head.groups.push_back(marks);
  LegendGroup sea;
  const auto& c = scene.sea.current;
  if (std::hypot(c[0], c[2]) > 0 || scene.sea.current_profile)
    sea.push_back({LegendEntry::kLine, th.current, "current"});
  if (scene.sea.surface) sea.push_back({LegendEntry::kLine, th.water, "water surface"});
  if (scene.sea.seabed) sea.push_back({LegendEntry::kLine, th.seabed, "seabed"});
  if (!sea.empty()) head.groups.push_back(sea);
  return head;
}

ViewProjection DrawSpaceView(Painter& p, const SpaceViewInput& in, const Colormap& map,
                             const Theme& th) {
  const float k = p.k();
  const SceneView& scene = *in.scene;
  const Snapshot& now = *in.now;
  const double lo = in.tension_min, hi = in.tension_max;
  DrawPanelHead(p, in.panel, in.head, in.view.y0, th);

  // The seabed and the water reach beyond the box, so that the box's edges are not the sea's.
  WorldBox sheet = in.box;
  const double pad = kSheetPad * Horizontal(in.box);
  sheet.x_min -= pad;
  sheet.x_max += pad;
  sheet.z_min -= pad;
  sheet.z_max += pad;
  const ViewProjection v = MakeViewProjection(in.camera, in.box, sheet, in.view);
  Scene3& s = p.Scene3D();
  v.Fill(&s);
  s.background = Mix(th.water, th.panel, 0.06f);  // a hint of deep water
  const Vec back = (v.eye - v.target).normalized();
  // The key light from above, over the viewer's left shoulder: lit sides face the viewer.
  s.light = F((-0.45 * v.right + 0.8 * v.up + 0.55 * back).normalized());
  const double mpp = 1 / v.pixels_per_metre;  // metres per pixel at the box's middle
  auto px = [&](float pixels) { return static_cast<float>(pixels * k * mpp); };
  const float radius = static_cast<float>(0.5 * kTubeWidth * in.cable_width * mpp);

  const SeaView& sea = scene.sea;
  if (sea.seabed) {
    Sheet bed;
    bed.origin = {static_cast<float>(sheet.x_min), static_cast<float>(sea.seabed_y),
                  static_cast<float>(sheet.z_min)};
    bed.du = {static_cast<float>(sheet.x_max - sheet.x_min), 0, 0};
    bed.dv = {0, 0, static_cast<float>(sheet.z_max - sheet.z_min)};
    bed.color = Mix(th.seabed, th.panel, 0.32f);
    bed.grid = static_cast<float>(NiceNum(Horizontal(in.box) / 8, true));
    bed.shine = 0.05f;
    s.sheets.push_back(bed);
  }
  const Wave& wave = now.wave;
  if (sea.surface && wave.spec.present) {
    Sheet water;
    const double wx = sheet.x_max - sheet.x_min, wz = sheet.z_max - sheet.z_min;
    // About 12 vertices a wave length, within bounds: the crests stay round.
    const double step = wave.k > 0 ? wave.length() / 12 : std::max(wx, wz);
    water.nu = std::clamp(static_cast<int>(std::ceil(wx / step)) + 1, 8, kMaxSheetSide);
    water.nv = std::clamp(static_cast<int>(std::ceil(wz / step)) + 1, 8, kMaxSheetSide);
    const double y0 = wave.spec.surface_y;
    water.origin = {static_cast<float>(sheet.x_min), static_cast<float>(y0),
                    static_cast<float>(sheet.z_min)};
    water.du = {static_cast<float>(wx / (water.nu - 1)), 0, 0};
    water.dv = {0, 0, static_cast<float>(wz / (water.nv - 1))};
    water.height.resize(static_cast<std::size_t>(water.nu) * water.nv);
    for (int j = 0; j < water.nv; ++j)
      for (int i = 0; i < water.nu; ++i) {
        const Vec at(sheet.x_min + i * wx / (water.nu - 1), y0, sheet.z_min + j * wz / (water.nv - 1));
        water.height[i + static_cast<std::size_t>(water.nu) * j] =
            static_cast<float>(SurfaceAt(wave, at, now.t) - y0);
      }
    water.color = WithAlpha(th.water, 0.2f);
    water.shine = 0.7f;
    s.sheets.push_back(water);
  }

  const LineState& reference = scene.lines.front().reference;
  if (sea.seabed) {  // each line's shadow straight down on the bed: where it hangs over it
    for (const LineSnapshot& l : now.lines) {
      std::vector<Vec3f> shadow;
      for (std::size_t j = 0; j < l.x.size(); ++j) {
        Vec3f q = F(StationOf(l, j));
        q.y = static_cast<float>(sea.seabed_y) + 0.3f * radius;
        shadow.push_back(q);
      }
      s.tubes.push_back(PlainTube(std::move(shadow), radius, Rgba{0, 0, 0, 0.28f}));
    }
  }
  // Drawn in full, with their ghosts, paths and ends: the first line, or all alike.
  const std::size_t full = scene.lines_alike ? now.lines.size() : 1;
  for (std::size_t i = 0; i < full && i < scene.lines.size(); ++i) {
    const LineState& ref = scene.lines[i].reference;
    if (ref.x.size() != now.lines[i].x.size()) continue;
    std::vector<Vec3f> ghost;
    for (std::size_t j = 0; j < ref.x.size(); ++j) ghost.push_back(F(StationOf(ref, j)));
    s.tubes.push_back(PlainTube(std::move(ghost), 0.45f * radius, WithAlpha(th.equilibrium, 0.5f)));
  }
  if (in.end_paths)
    for (const EndPath& path : *in.end_paths) {
      // An overlay's end goes where the first line's does.
      if (path.line < 0 || static_cast<std::size_t>(path.line) >= full) continue;
      for (const auto& piece : path.pieces)
        if (piece.size() >= 2) s.tubes.push_back(PlainTube(piece, 0.3f * radius, EndPathColor(th)));
    }
  const std::vector<std::vector<std::array<Vec, 2>>> boxes = BodyBoxesNow(scene, now.lines, now.t);
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {  // its box, else its outline
    const BodyView& body = scene.bodies[b];
    if (!boxes[b].empty()) {
      for (const auto& edge : boxes[b])
        s.tubes.push_back(PlainTube({F(edge[0]), F(edge[1])}, 0.8f * radius, th.text_dim));
      continue;
    }
    std::vector<Vec3f> at;
    for (int q : body.points) {
      const PointView& pt = scene.points[q];
      if (pt.line >= 0 && static_cast<std::size_t>(pt.line) < now.lines.size() && pt.station >= 0 &&
          static_cast<std::size_t>(pt.station) < now.lines[pt.line].x.size())
        at.push_back(F(StationOf(now.lines[pt.line], pt.station)));
    }
    std::vector<Vec3f> outline = BodyOutline(std::move(at));
    if (!outline.empty()) s.tubes.push_back(PlainTube(std::move(outline), 0.8f * radius, th.text_dim));
  }
  for (std::size_t i = full; i < now.lines.size(); ++i)  // thinner: the first shows through them
    s.tubes.push_back(LineTube(now.lines[i], radius * in.overlay_width / in.cable_width, map, lo, hi));
  for (std::size_t i = 0; i < full; ++i)
    s.tubes.push_back(LineTube(now.lines[i], radius, map, lo, hi));

  auto solid = [&](SolidKind kind, const Vec& at, float size, Rgba c) {
    s.solids.push_back({kind, F(at), {}, size, c});
  };
  for (std::size_t i = 0; i < now.lines.size() && i < scene.lines.size(); ++i)
    for (int w : scene.lines[i].marks.weights)
      if (w >= 0 && static_cast<std::size_t>(w) < now.lines[i].x.size())
        solid(SolidKind::kOctahedron, StationOf(now.lines[i], w), px(i < full ? 10 : 7),
              th.marker_edge);
  for (std::size_t i = 0; i < full && i < scene.lines.size(); ++i) {
    const LineSnapshot& l = now.lines[i];
    const StationMarks& marks = scene.lines[i].marks;
    auto inside = [&](int j) { return j >= 0 && static_cast<std::size_t>(j) < l.x.size(); };
    for (int e : marks.fixed_ends)
      if (inside(e)) solid(SolidKind::kBox, StationOf(l, e), px(6.5f), th.marker_edge);
    for (int e : marks.moving_ends)
      if (inside(e)) solid(SolidKind::kSphere, StationOf(l, e), px(8), th.accent);
    for (int e : marks.free_ends)
      if (inside(e)) solid(SolidKind::kSphere, StationOf(l, e), px(7), th.marker_edge);
  }

  // The current: an arrow near the top of the water, its speed beside its tip.
  const Vec current = HorizontalPart(now.current);
  const double speed = current.norm();
  Vec2f label_at;
  bool label = false, label_right = true;
  if (speed > 1e-9) {
    const double top = sea.surface ? wave.spec.surface_y : in.box.y_max;
    const double bottom = sea.seabed ? sea.seabed_y : in.box.y_min;
    const Vec centre = ArrowCentre(in.box, reference, top - 0.12 * std::max(top - bottom, 0.0));
    const Vec axis = 0.16 * Horizontal(in.box) / speed * current;
    s.solids.push_back({SolidKind::kArrow, F(centre - 0.5 * axis), F(axis), px(2.6f), th.current});
    // The label at whichever end of the arrow is farther from the line on screen, written away
    // from the arrow, so that it does not cross the line.
    Vec2f tip, tail, a, b;
    const std::size_t n = reference.x.size();
    if (v.ToPixel(centre + 0.5 * axis, &tip) && v.ToPixel(centre - 0.5 * axis, &tail)) {
      const bool chord = n >= 2 && v.ToPixel(StationOf(reference, 0), &a) &&
                         v.ToPixel(StationOf(reference, n - 1), &b);
      const bool at_tip = !chord || ScreenDistance(tip, a, b) >= ScreenDistance(tail, a, b);
      label_at = at_tip ? tip : tail;
      label_right = at_tip ? tip.x >= tail.x : tail.x > tip.x;
      label = true;
    }
  }

  // Over the scene: the labels and the axes' triad.
  if (label && in.view.Contains(label_at)) {
    std::string text = "current " + FormatValue("%.2f", speed) + " m/s";
    if (sea.current_profile) text += " at the top";
    // Kept inside the view: written from its left edge rightwards, whichever side it is on.
    const float width = EstimateTextWidth(text, 14 * k), gap = 10 * k;
    const float x = std::clamp(label_right ? label_at.x + gap : label_at.x - gap - width,
                               in.view.x0 + gap, std::max(in.view.x0 + gap, in.view.x1 - gap - width));
    p.Text(text, {x, label_at.y}, 14 * k, th.text, HAlign::kLeft, VAlign::kMiddle);
  }
  if (sea.seabed && !s.sheets.empty())
    p.Text("seabed grid " + FormatValue("%g", s.sheets.front().grid) + " m",
           {in.view.x1 - 10 * k, in.view.y1 - 10 * k}, 13 * k, th.text_dim, HAlign::kRight,
           VAlign::kBottom);
  if (scene.lines_alike) {  // the names over the scene, none over another: points by their
    NameTags tags(in.view);  // markers, then lines beside them
    std::vector<std::vector<Vec2f>> shapes(now.lines.size());
    for (std::size_t i = 0; i < now.lines.size(); ++i) {
      Vec2f q;
      for (std::size_t j = 0; j < now.lines[i].x.size(); ++j)
        if (v.ToPixel(StationOf(now.lines[i], j), &q)) shapes[i].push_back(q);
      tags.Avoid(shapes[i], kTubeWidth * in.cable_width);
    }
    for (const PointView& pt : scene.points) {
      if (pt.line < 0 || static_cast<std::size_t>(pt.line) >= now.lines.size()) continue;
      const LineSnapshot& l = now.lines[pt.line];
      Vec2f q;
      if (pt.station < 0 || static_cast<std::size_t>(pt.station) >= l.x.size() ||
          !v.ToPixel(StationOf(l, pt.station), &q))
        continue;
      tags.AddPointName(p, pt.name, q, 0.5f * (in.view.x0 + in.view.x1), th.text_dim, th);
    }
    for (std::size_t i = 0; i < now.lines.size() && i < scene.lines.size(); ++i)
      tags.AddLineName(p, scene.lines[i].label, shapes[i], LineColor(th, i), th);
  }
  DrawTriad(p, v, in.view);
  return v;
}

}  // namespace cablefilm
