#include "core/system.h"

#include "core/error.h"

namespace cablefilm {
namespace {

PointKind KindOf(const EndMotion& motion) {
  if (!motion.prescribed()) return PointKind::kFree;
  return motion.moves() ? PointKind::kMoved : PointKind::kFixed;
}

std::string LineName(const LineSpec& line, int i) {
  return "line " + (line.name.empty() ? std::to_string(i + 1) : "\"" + line.name + "\"");
}

int Links(const LineSpec& line) {
  int links = 0;
  for (const SectionSpec& sec : line.sections) links += sec.segments;
  return links;
}

}  // namespace

SystemModel MakeSystem(const std::vector<LineSpec>& lines, const std::vector<PointSpec>& points,
                       const EnvironmentSpec& env) {
  SystemModel sys;
  sys.env = env;
  const int np = static_cast<int>(points.size());
  for (const PointSpec& p : points)
    sys.points.push_back({p.name, KindOf(p.motion), p.motion, {}, -1});
  for (int i = 0; i < static_cast<int>(lines.size()); ++i) {
    const LineSpec& l = lines[i];
    for (int p : {l.start_point, l.end_point})
      if (p < 0 || p >= np)
        throw Error(LineName(l, i) + ": attached to point " + std::to_string(p) +
                    ", which does not exist");
    sys.points[l.start_point].ends.push_back({i, 0});
    sys.points[l.end_point].ends.push_back({i, Links(l)});
  }
  for (int p = 0; p < np; ++p) {
    SystemPoint& point = sys.points[p];
    if (point.kind != PointKind::kFree) continue;
    if (point.ends.empty())
      throw Error("point \"" + point.name + "\" is free but no line is attached to it");
    if (point.ends.size() >= 2) {
      point.shared = sys.shared_count();
      sys.shared_points.push_back(p);
    }
  }
  for (int i = 0; i < static_cast<int>(lines.size()); ++i) {
    const LineSpec& l = lines[i];
    if (l.law != LinkLaw::kElastic)  // the system's step is the elastic line's
      throw Error(LineName(l, i) + ": the lines of a system are elastic");
    std::vector<PrismSpec> prisms = l.prisms;
    EndMotion ends[2] = {points[l.start_point].motion, points[l.end_point].motion};
    const int at[2] = {l.start_point, l.end_point};
    const int links = Links(l);
    for (int e = 0; e < 2; ++e) {
      const SystemPoint& point = sys.points[at[e]];
      if (point.kind != PointKind::kFree) continue;
      ends[e] = EndMotion::Free(points[at[e]].motion.rest());
      const LineEnd& owner = point.ends.front();
      const int station = e == 0 ? 0 : links;
      if (owner.line == i && owner.station == station) {  // the point's own terms, once
        PrismSpec body = points[at[e]].body;
        body.station = station;
        prisms.push_back(body);
      }
    }
    if (!ends[0].prescribed() && !ends[1].prescribed() &&
        sys.points[at[0]].shared < 0 && sys.points[at[1]].shared < 0)
      throw Error(LineName(l, i) +
                  ": both its ends are free points that hold no other line: nothing holds it");
    sys.lines.push_back(MakeModel(l.sections, prisms, env, ends[0], ends[1], l.law));
    sys.line_names.push_back(l.name);
    sys.line_points.push_back({l.start_point, l.end_point});
  }
  return sys;
}

}  // namespace cablefilm
