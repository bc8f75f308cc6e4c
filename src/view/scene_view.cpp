#include "view/scene_view.h"

#include "core/error.h"

namespace cablefilm {
namespace {

void CheckStations(const std::string& line, const char* what, const std::vector<int>& stations,
                   std::size_t n) {
  for (int j : stations)
    if (j < 0 || static_cast<std::size_t>(j) >= n)
      throw Error("frame: " + line + ": " + what + " " + std::to_string(j) +
                  " is not a station (0.." + std::to_string(n - 1) + ")");
}

}  // namespace

std::string LineName(const SceneView& scene, std::size_t line) {
  if (line < scene.lines.size() && !scene.lines[line].label.empty())
    return scene.lines[line].label;
  return "line " + std::to_string(line + 1);
}

std::string ReferenceName(const SceneView& scene) {
  return scene.reference_label.empty() ? "equilibrium" : scene.reference_label;
}

bool OverlaysNamed(const SceneView& scene) {
  for (std::size_t i = 1; i < scene.lines.size(); ++i)
    if (scene.lines[i].label.empty()) return false;
  return true;
}

void CheckSceneView(const SceneView& scene) {
  if (scene.lines.empty()) throw Error("frame: the scene has no line to draw");
  for (std::size_t i = 0; i < scene.lines.size(); ++i) {
    const LineView& l = scene.lines[i];
    const std::string name = "line " + std::to_string(i + 1);
    const std::size_t n = l.arc_length.size();
    if (n < 2)
      throw Error("frame: " + name + " needs at least 2 stations, got " + std::to_string(n));
    if (!l.section_names.empty() && l.section_names.size() != l.section_boundaries.size() + 1)
      throw Error("frame: " + name + ": " + std::to_string(l.section_names.size()) +
                  " section names for " + std::to_string(l.section_boundaries.size() + 1) +
                  " sections");
    CheckStations(name, "weight station", l.marks.weights, n);
    CheckStations(name, "fixed end", l.marks.fixed_ends, n);
    CheckStations(name, "moving end", l.marks.moving_ends, n);
    CheckStations(name, "free end", l.marks.free_ends, n);
    const LineState& r = l.reference;
    const bool positions = !r.x.empty() || !r.y.empty() || !r.z.empty();
    if ((positions && (r.x.size() != n || r.y.size() != n || (!r.z.empty() && r.z.size() != n))) ||
        (!r.tension.empty() && r.tension.size() + 1 != n) || (!positions && !r.tension.empty()))
      throw Error("frame: " + name + ": the reference has " + std::to_string(r.x.size()) + " x, " +
                  std::to_string(r.y.size()) + " y, " + std::to_string(r.z.size()) + " z and " +
                  std::to_string(r.tension.size()) + " tensions; the line has " +
                  std::to_string(n) + " stations and " + std::to_string(n - 1) + " links");
  }
  for (const PointView& p : scene.points) {
    if (p.line < 0 || static_cast<std::size_t>(p.line) >= scene.lines.size())
      throw Error("frame: point \"" + p.name + "\" is on line " + std::to_string(p.line + 1) +
                  " of " + std::to_string(scene.lines.size()));
    CheckStations("point \"" + p.name + "\"", "station", {p.station},
                  scene.lines[p.line].arc_length.size());
  }
  for (const BodyView& b : scene.bodies) {
    if (!b.local.empty() && b.local.size() != b.points.size())
      throw Error("frame: body \"" + b.name + "\" has " + std::to_string(b.local.size()) +
                  " local positions for " + std::to_string(b.points.size()) + " points");
    for (int q : b.points)
      if (q < 0 || static_cast<std::size_t>(q) >= scene.points.size())
        throw Error("frame: body \"" + b.name + "\" has point " + std::to_string(q + 1) +
                    " of " + std::to_string(scene.points.size()));
  }
}

}  // namespace cablefilm
