#include "core/model.h"

#include <algorithm>

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

// Point p as its body puts it: fixed to a held body, moving with a driven one, placed by a
// free one's pose.
Point OnBody(const PointSpec& p, const BodySpec& body) {
  const Vec x = BodyPoint(RestPose(body), p.local);
  Point point{p.name, PointKind::kFixed, EndMotion::Fixed(x), {}, -1, p.on_body, p.local};
  if (body.kind == BodyKind::kFree) point.kind = PointKind::kBody;
  if (body.kind == BodyKind::kDriven) {
    point.motion = body.motion.WithRest(x);
    if (body.turn.moves()) point.motion = point.motion.WithTurn(body.turn, p.local);
    point.kind = KindOf(point.motion);
  }
  return point;
}

}  // namespace

Model MakeModel(const std::vector<LineSpec>& lines, const std::vector<PointSpec>& points,
                       const EnvironmentSpec& env, const std::vector<BodySpec>& bodies) {
  Model sys;
  sys.env = env;
  sys.bodies = bodies;
  sys.line_specs = lines;
  sys.point_specs = points;
  const int np = static_cast<int>(points.size());
  const int nb = static_cast<int>(bodies.size());
  for (const PointSpec& p : points) {
    if (p.on_body >= nb)
      throw Error("point \"" + p.name + "\": on body " + std::to_string(p.on_body) +
                  ", which does not exist");
    if (p.on_body >= 0)
      sys.points.push_back(OnBody(p, bodies[p.on_body]));
    else
      sys.points.push_back({p.name, KindOf(p.motion), p.motion, {}, -1, -1, Vec::Zero()});
  }
  for (int b = 0; b < nb; ++b) {
    sys.body_poses.push_back(RestPose(bodies[b]));
    if (bodies[b].kind != BodyKind::kFree) continue;
    sys.free_bodies.push_back(b);
  }
  for (int i = 0; i < static_cast<int>(lines.size()); ++i) {
    const LineSpec& l = lines[i];
    for (int p : {l.start_point, l.end_point})
      if (p < 0 || p >= np)
        throw Error(LineName(l, i) + ": attached to point " + std::to_string(p) +
                    ", which does not exist");
    sys.points[l.start_point].ends.push_back({i, 0});
    sys.points[l.end_point].ends.push_back({i, Links(l)});
  }
  for (int b : sys.free_bodies) {
    bool held = false;
    for (const Point& p : sys.points) held = held || (p.on_body == b && !p.ends.empty());
    if (!held)
      throw Error("body \"" + bodies[b].name + "\" is free but no line ends at a point on it");
  }
  for (int p = 0; p < np; ++p) {
    Point& point = sys.points[p];
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
    EndMotion ends[2] = {sys.points[l.start_point].motion, sys.points[l.end_point].motion};
    const int at[2] = {l.start_point, l.end_point};
    const int links = Links(l);
    for (int e = 0; e < 2; ++e) {
      const Point& point = sys.points[at[e]];
      if (point.kind == PointKind::kBody) {  // a free station that follows its body
        ends[e] = EndMotion::Free(point.motion.rest());
        continue;
      }
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
    auto loose = [&](int e) {
      const Point& p = sys.points[at[e]];
      return !ends[e].prescribed() && p.shared < 0 && p.kind != PointKind::kBody;
    };
    if (loose(0) && loose(1))
      throw Error(LineName(l, i) +
                  ": both its ends are free points that hold no other line: nothing holds it");
    sys.lines.push_back(MakeLineModel(l.sections, prisms, env, ends[0], ends[1], l.law));
    sys.line_names.push_back(l.name);
    sys.line_points.push_back({l.start_point, l.end_point});
  }
  return sys;
}

void PlaceBodyEnds(const Model& sys, int b, const Vec6& pose, int line, LineModel& model) {
  for (int e = 0; e < 2; ++e) {
    const Point& p = sys.points[sys.line_points[line][e]];
    if (p.on_body != b) continue;
    (e == 0 ? model.ends.start : model.ends.end) = EndMotion::Fixed(BodyPoint(pose, p.local));
  }
}

void PlaceBody(Model& sys, int b, const Vec6& pose) {
  BodySpec& body = sys.bodies[b];
  sys.body_poses[b] = pose;
  if (body.kind != BodyKind::kFree) {
    body.motion = body.motion.WithRest(pose.head<3>());
    body.angles = pose.tail<3>();
    body.turn = body.turn.WithRest(body.angles);
  }
  // A turning point's turn is about the new rest angles.
  auto place = [&](const EndMotion& m, const Vec& local) {
    const EndMotion moved = m.WithRest(BodyPoint(pose, local));
    return m.turns() ? moved.WithTurn(body.turn, local) : moved;
  };
  for (Point& p : sys.points)
    if (p.on_body == b) p.motion = place(p.motion, p.local);
  for (int i = 0; i < static_cast<int>(sys.lines.size()); ++i)
    for (int e = 0; e < 2; ++e) {
      const Point& p = sys.points[sys.line_points[i][e]];
      if (p.on_body != b) continue;
      EndMotion& end = e == 0 ? sys.lines[i].ends.start : sys.lines[i].ends.end;
      end = place(end, p.local);
    }
}

Model HoldBody(const Model& sys, int b, const Vec6& pose) {
  Model held = sys;
  held.bodies[b].kind = BodyKind::kHeld;
  held.bodies[b].motion = EndMotion::Fixed(pose.head<3>());
  held.bodies[b].turn = EndMotion::Fixed(pose.tail<3>());
  for (Point& p : held.points)
    if (p.on_body == b) {
      p.kind = PointKind::kFixed;
      p.motion = EndMotion::Fixed(p.motion.rest());
    }
  held.free_bodies.erase(std::remove(held.free_bodies.begin(), held.free_bodies.end(), b),
                         held.free_bodies.end());
  for (int i = 0; i < static_cast<int>(held.lines.size()); ++i)
    for (int e = 0; e < 2; ++e)
      if (held.points[held.line_points[i][e]].on_body == b)
        (e == 0 ? held.lines[i].ends.start : held.lines[i].ends.end) = EndMotion::Fixed(Vec::Zero());
  PlaceBody(held, b, pose);
  return held;
}

}  // namespace cablefilm
