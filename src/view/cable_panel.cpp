#include "view/cable_panel.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "view/body_outline.h"
#include "view/cable_style.h"
#include "view/name_tag.h"
#include "view/plot_axes.h"

namespace cablefilm {
namespace {

Rgba PathColor(const Theme& th) { return EndPathColor(th); }

bool Inside(int j, std::size_t n) { return j >= 0 && static_cast<std::size_t>(j) < n; }

}  // namespace

EndNames EndLabels(const SceneView& scene) {
  if (scene.lines_alike) return {"fixed point", "moved point", "free point"};
  return {"fixed end", "moving end", "free end"};
}

StationMarks LegendMarks(const SceneView& scene) {
  StationMarks all = scene.lines.front().marks;
  for (std::size_t i = 1; scene.lines_alike && i < scene.lines.size(); ++i) {
    const StationMarks& m = scene.lines[i].marks;
    all.fixed_ends.insert(all.fixed_ends.end(), m.fixed_ends.begin(), m.fixed_ends.end());
    all.moving_ends.insert(all.moving_ends.end(), m.moving_ends.begin(), m.moving_ends.end());
    all.free_ends.insert(all.free_ends.end(), m.free_ends.begin(), m.free_ends.end());
  }
  return all;
}

PanelHead CablePanelHead(const SceneView& scene, const std::string& path_label, Rgba swatch,
                         const Theme& th) {
  PanelHead head;
  head.title = scene.lines_alike ? "Lines (to scale)" : "Cable shape (to scale)";
  // The names first, on a row of their own when space is short (alike: on the picture).
  if (scene.lines.size() > 1 && !scene.lines_alike) {
    LegendGroup names{{LegendEntry::kCable, swatch, LineName(scene, 0)}};
    for (std::size_t i = 1; i < scene.lines.size(); ++i)
      names.push_back({LegendEntry::kOverlay, swatch, LineName(scene, i)});
    head.groups.push_back(names);
  }
  bool weights = false;
  for (const LineView& line : scene.lines) weights = weights || !line.marks.weights.empty();
  const StationMarks first = LegendMarks(scene);
  const EndNames ends = EndLabels(scene);
  LegendGroup marks_row;
  if (weights) marks_row.push_back({LegendEntry::kDiamond, th.marker_fill, "weight"});
  if (!first.fixed_ends.empty())
    marks_row.push_back({LegendEntry::kSquare, th.marker_fill, ends.fixed});
  if (!first.moving_ends.empty()) {
    marks_row.push_back({LegendEntry::kRing, th.accent, ends.moving});
    marks_row.push_back({LegendEntry::kLine, PathColor(th), path_label});
  }
  if (!first.free_ends.empty())
    marks_row.push_back({LegendEntry::kRing, th.marker_edge, ends.free});
  marks_row.push_back({LegendEntry::kDash, th.equilibrium, ReferenceName(scene)});
  if (scene.sea.surface) marks_row.push_back({LegendEntry::kLine, th.water, "water surface"});
  if (scene.sea.seabed) marks_row.push_back({LegendEntry::kLine, th.seabed, "seabed"});
  head.groups.push_back(marks_row);
  return head;
}

Rgba EndPathColor(const Theme& th) { return Mix(th.accent, th.panel, 0.45f); }

void DrawCablePanel(Painter& p, const CablePanelInput& in, const Colormap& colormap,
                    const Theme& th) {
  const float k = p.k();
  const std::vector<LineView>& lines = *in.lines;
  const std::vector<LineSnapshot>& now = *in.now;
  const double lo = in.tension_min, hi = in.tension_max;
  DrawPanelHead(p, in.panel, in.head, in.world.rect.y0, th);
  DrawAxes(p, in.world, in.x_label, in.y_label, th, 10, 5);

  auto world = [&](double x, double y) { return in.world.ToPixel(x, y); };
  if (in.seabed_y && std::isfinite(*in.seabed_y)) {  // beneath everything: the ground, its line
    const PixelRect& r = in.world.rect;
    const float y = std::clamp(in.world.PixelY(*in.seabed_y), r.y0, r.y1);
    if (y < r.y1) p.Rect({r.x0, y, r.x1, r.y1}, Mix(th.seabed, th.panel, 0.22f));
    p.Line({r.x0, y}, {r.x1, y}, 2 * k, th.seabed);
  }
  if (in.surface_x && in.surface_y && in.surface_x->size() == in.surface_y->size() &&
      in.surface_x->size() > 1) {  // the water: a wash from the surface down, then its line
    const PixelRect& r = in.world.rect;
    const float bottom =
        in.seabed_y && std::isfinite(*in.seabed_y)
            ? std::clamp(in.world.PixelY(*in.seabed_y), r.y0, r.y1)
            : r.y1;
    // The samples (x increasing) clipped to the plot's x range, which the layout may widen
    // beyond the cable's box.
    const std::vector<double>&sx = *in.surface_x, &sy = *in.surface_y;
    const double x_lo = std::min(in.world.x_lo, in.world.x_hi);
    const double x_hi = std::max(in.world.x_lo, in.world.x_hi);
    auto at = [&](std::size_t i, double x) {  // the segment i-1..i at x
      const double f = (x - sx[i - 1]) / (sx[i] - sx[i - 1]);
      return world(x, sy[i - 1] + f * (sy[i] - sy[i - 1]));
    };
    std::vector<Vec2f> line;
    line.reserve(sx.size());
    for (std::size_t i = 1; i < sx.size(); ++i) {
      if (!(sx[i] > sx[i - 1]) || sx[i] < x_lo || sx[i - 1] > x_hi) continue;
      if (line.empty())
        line.push_back(sx[i - 1] < x_lo ? at(i, x_lo) : world(sx[i - 1], sy[i - 1]));
      line.push_back(sx[i] > x_hi ? at(i, x_hi) : world(sx[i], sy[i]));
    }
    const Rgba wash{th.water.r, th.water.g, th.water.b, 0.10f};
    for (std::size_t i = 1; i < line.size(); ++i) {
      const Vec2f a = line[i - 1], b = line[i];
      if (a.y >= bottom && b.y >= bottom) continue;
      const Vec2f a1{a.x, std::min(a.y, bottom)}, b1{b.x, std::min(b.y, bottom)};
      p.Triangle(a1, b1, {b.x, bottom}, wash);
      p.Triangle(a1, {b.x, bottom}, {a.x, bottom}, wash);
    }
    p.Polyline(line, 2 * k, th.water);
  }
  // Beneath the lines: each body's box, its 12 edges, else its outline through its points,
  // faintly filled; named inside.
  for (std::size_t b = 0; in.bodies && b < in.bodies->size(); ++b) {
    const BodyView& body = (*in.bodies)[b];
    if (in.body_boxes && b < in.body_boxes->size() && !(*in.body_boxes)[b].empty()) {
      const std::vector<PanelEdge>& edges = (*in.body_boxes)[b];
      Vec2f c{0, 0};
      float x0 = std::numeric_limits<float>::max(), x1 = -x0;
      for (const PanelEdge& e : edges) {
        const Vec2f a = world(e.x0, e.y0), z = world(e.x1, e.y1);
        p.Line(a, z, 2.5f * k, th.text_dim);
        c.x += (a.x + z.x) / (2 * edges.size()), c.y += (a.y + z.y) / (2 * edges.size());
        x0 = std::min({x0, a.x, z.x}), x1 = std::max({x1, a.x, z.x});
      }
      if (x1 - x0 > EstimateTextWidth(body.name, 12 * k) + 16 * k)
        p.Text(body.name, c, 12 * k, th.text, HAlign::kCenter, VAlign::kMiddle);
      continue;
    }
    if (!in.points) continue;
    std::vector<Vec2f> at;
    for (int q : body.points) {
      const PointView& pt = (*in.points)[q];
      if (pt.line >= 0 && static_cast<std::size_t>(pt.line) < now.size() &&
          Inside(pt.station, now[pt.line].x.size()))
        at.push_back(world(now[pt.line].x[pt.station], now[pt.line].y[pt.station]));
    }
    const std::vector<Vec2f> outline = BodyOutline(at);
    if (outline.empty()) continue;
    Vec2f c{0, 0};
    for (const Vec2f& q : at) c.x += q.x / at.size(), c.y += q.y / at.size();
    const Rgba fill = Mix(th.text_dim, th.panel, 0.8f);
    for (std::size_t i = 1; i < outline.size(); ++i) p.Triangle(c, outline[i - 1], outline[i], fill);
    p.Polyline(outline, 2.5f * k, th.text_dim);
    float x0 = c.x, x1 = c.x;
    for (const Vec2f& q : at) x0 = std::min(x0, q.x), x1 = std::max(x1, q.x);
    // Named inside when it is wide enough to hold its name; a small one is named by its points.
    if (x1 - x0 > EstimateTextWidth(body.name, 12 * k) + 16 * k)
      p.Text(body.name, c, 12 * k, th.text, HAlign::kCenter, VAlign::kMiddle);
  }
  // Drawn in full, with their marks, references and paths: the first line, or all alike.
  const std::size_t full = in.alike ? now.size() : 1;
  for (std::size_t i = 0; i < full && i < lines.size(); ++i) {
    const LineState& ref = lines[i].reference;
    if (ref.x.size() != now[i].x.size() || ref.y.size() != now[i].x.size()) continue;
    std::vector<Vec2f> eq;
    for (std::size_t j = 0; j < ref.x.size(); ++j) eq.push_back(world(ref.x[j], ref.y[j]));
    p.Dashed(eq, 1.6f * k, th.equilibrium, 8 * k, 6 * k);
  }
  if (in.end_paths)
    for (const EndPath& path : *in.end_paths) {
      // An overlay's end goes where the first line's does.
      if (path.line < 0 || static_cast<std::size_t>(path.line) >= full) continue;
      for (const auto& piece : path.pieces) {
        std::vector<Vec2f> px;
        px.reserve(piece.size());
        for (const Vec3f& q : piece) px.push_back(world(q.x, q.y));
        for (std::size_t i = 1; i < px.size(); ++i) p.Line(px[i - 1], px[i], 2 * k, PathColor(th));
      }
    }
  const float cw = in.cable_width;
  for (std::size_t i = full; i < now.size(); ++i) {  // beneath the first line; each dotted rim
    const LineSnapshot& o = now[i];                   // shows where the lines coincide
    std::vector<Vec2f> c;
    for (std::size_t j = 0; j < o.x.size(); ++j) c.push_back(world(o.x[j], o.y[j]));
    DrawOverlayRim(p, c, cw + 7 * k, th);
    for (std::size_t j = 0; j < o.tension.size() && j + 1 < c.size(); ++j)
      p.Line(c[j], c[j + 1], in.overlay_width, colormap.Map(o.tension[j], lo, hi));
  }
  // The last drawn on top: the first line over the others.
  for (std::size_t i = full; i-- > 0;) {
    const LineSnapshot& l = now[i];
    const std::size_t n = std::min(l.tension.size() + 1, l.x.size());
    for (std::size_t j = 0; j + 1 < n; ++j)  // a thin rim keeps the dark end of the map visible
      p.Line(world(l.x[j], l.y[j]), world(l.x[j + 1], l.y[j + 1]), cw + 2.5f * k, th.halo);
    for (std::size_t j = 0; j + 1 < n; ++j)
      p.Line(world(l.x[j], l.y[j]), world(l.x[j + 1], l.y[j + 1]), cw,
             colormap.Map(l.tension[j], lo, hi));
  }
  for (std::size_t i = full; i < now.size() && i < lines.size(); ++i)  // the overlays' weights,
    for (int w : lines[i].marks.weights) {  // smaller: hidden by the first's where they coincide
      if (!Inside(w, now[i].x.size())) continue;
      const Vec2f c = world(now[i].x[w], now[i].y[w]);
      p.Diamond(c, 8.5f * k, th.overlay_rim);
      p.Diamond(c, 6 * k, th.marker_fill);
    }
  for (std::size_t i = 0; i < full && i < lines.size(); ++i) {
    const LineSnapshot& l = now[i];
    const StationMarks& m = lines[i].marks;
    for (int w : m.weights) {
      if (!Inside(w, l.x.size())) continue;
      const Vec2f c = world(l.x[w], l.y[w]);
      p.Diamond(c, 11 * k, th.marker_edge);
      p.Diamond(c, 8 * k, th.marker_fill);
    }
    for (int e : m.fixed_ends) {
      if (!Inside(e, l.x.size())) continue;
      const Vec2f c = world(l.x[e], l.y[e]);
      p.Square(c, 8 * k, th.marker_edge);
      p.Square(c, 5.5f * k, th.marker_fill);
    }
    for (int e : m.moving_ends) {
      if (!Inside(e, l.x.size())) continue;
      const Vec2f c = world(l.x[e], l.y[e]);
      p.Disc(c, 9 * k, th.accent);
      p.Disc(c, 4.5f * k, th.panel);
    }
    for (int e : m.free_ends) {
      if (!Inside(e, l.x.size())) continue;
      const Vec2f c = world(l.x[e], l.y[e]);
      p.Disc(c, 8.5f * k, th.marker_edge);
      p.Disc(c, 7 * k, th.marker_fill);
      p.Disc(c, 3.5f * k, th.panel);
    }
  }
  if (!in.alike) return;
  // The names over everything, none over another: each point's by its marker, then each
  // line's beside it.
  NameTags tags(in.world.rect);
  std::vector<std::vector<Vec2f>> shapes(now.size());
  for (std::size_t i = 0; i < now.size(); ++i) {
    for (std::size_t j = 0; j < now[i].x.size(); ++j)
      shapes[i].push_back(world(now[i].x[j], now[i].y[j]));
    tags.Avoid(shapes[i], cw + 2.5f * k);
  }
  for (std::size_t q = 0; in.points && q < in.points->size(); ++q) {
    const PointView& pt = (*in.points)[q];
    if (pt.line < 0 || static_cast<std::size_t>(pt.line) >= now.size() ||
        !Inside(pt.station, now[pt.line].x.size()))
      continue;
    const LineSnapshot& l = now[pt.line];
    tags.AddPointName(p, pt.name, world(l.x[pt.station], l.y[pt.station]),
                      0.5f * (in.world.rect.x0 + in.world.rect.x1), th.text_dim, th);
  }
  for (std::size_t i = 0; i < now.size() && i < lines.size(); ++i)
    tags.AddLineName(p, lines[i].label, shapes[i], LineColor(th, i), th);
}

}  // namespace cablefilm
