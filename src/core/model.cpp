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

// A point's own terms that are all zero (a junction of no mass, a free end of a line alone):
// no prism on its station.
bool IsEmpty(const PrismSpec& p) {
  return p.mass == 0 && p.volume == 0 && p.added_volume.isZero() && p.drag_coefficient.isZero() &&
         p.drag_area.isZero() && p.force.isZero();
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
  if (lines.empty()) throw Error("a model needs at least one line");
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
      if (owner.line == i && owner.station == station && !IsEmpty(points[at[e]].body)) {
        PrismSpec body = points[at[e]].body;  // the point's own terms, once
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
    sys.line_prisms.push_back(prisms);
    sys.line_names.push_back(l.name);
    sys.line_points.push_back({l.start_point, l.end_point});
  }
  FindIslands(sys);
  return sys;
}

void FindIslands(Model& model) {
  const int nl = static_cast<int>(model.lines.size());
  // Union-find over the lines: joined where they share a point or a free body.
  std::vector<int> root(nl);
  for (int i = 0; i < nl; ++i) root[i] = i;
  auto find = [&](int i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  auto join = [&](int a, int b) { root[find(a)] = find(b); };
  for (int p : model.shared_points)
    for (const LineEnd& e : model.points[p].ends) join(e.line, model.owner(p).line);
  for (int b : model.free_bodies) {
    int first = -1;
    for (const Point& p : model.points) {
      if (p.on_body != b) continue;
      for (const LineEnd& e : p.ends) {
        if (first < 0) first = e.line;
        join(e.line, first);
      }
    }
  }
  model.islands.clear();
  model.line_island.assign(nl, -1);
  std::vector<int> island_of_root(nl, -1);
  for (int i = 0; i < nl; ++i) {
    int& k = island_of_root[find(i)];
    if (k < 0) {
      k = static_cast<int>(model.islands.size());
      model.islands.emplace_back();
    }
    model.islands[k].lines.push_back(i);
    model.line_island[i] = k;
  }
  for (int p : model.shared_points)
    model.islands[model.line_island[model.owner(p).line]].shared_points.push_back(p);
  for (int b : model.free_bodies)
    for (const Point& p : model.points)
      if (p.on_body == b && !p.ends.empty()) {
        model.islands[model.line_island[p.ends.front().line]].free_bodies.push_back(b);
        break;
      }
  for (const Island& island : model.islands) {
    if (!island.coupled()) continue;
    for (int i : island.lines)
      if (model.lines[i].line.law != LinkLaw::kElastic)  // the coupled step is the elastic one
        throw Error("line \"" + model.line_names[i] + "\": an inextensible line cannot be "
                    "joined to other lines or to a free body (the coupled step is the elastic "
                    "lines'); it may end at fixed or moving points, or at a free end of its own");
  }
}

Model IslandModel(const Model& model, int k, std::vector<int>* lines, std::vector<int>* points,
                  std::vector<int>* bodies) {
  const Island& island = model.islands.at(k);
  std::vector<int> line_of(island.lines), point_new(model.points.size(), -1),
      body_new(model.bodies.size(), -1);
  std::vector<int> point_of, body_of;
  for (int i : island.lines)
    for (int p : model.line_points[i]) point_new[p] = 0;
  for (std::size_t p = 0; p < model.points.size(); ++p) {
    if (point_new[p] < 0) continue;
    point_new[p] = static_cast<int>(point_of.size());
    point_of.push_back(static_cast<int>(p));
    const int b = model.points[p].on_body;
    if (b >= 0) body_new[b] = 0;
  }
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (body_new[b] < 0) continue;
    body_new[b] = static_cast<int>(body_of.size());
    body_of.push_back(static_cast<int>(b));
  }
  std::vector<int> line_new(model.lines.size(), -1);
  for (std::size_t i = 0; i < line_of.size(); ++i) line_new[line_of[i]] = static_cast<int>(i);
  Model m;
  m.env = model.env;
  for (int i : line_of) {
    m.lines.push_back(model.lines[i]);
    m.line_names.push_back(model.line_names[i]);
    m.line_points.push_back({point_new[model.line_points[i][0]], point_new[model.line_points[i][1]]});
    LineSpec spec = model.line_specs[i];
    spec.start_point = m.line_points.back()[0];
    spec.end_point = m.line_points.back()[1];
    m.line_specs.push_back(spec);
    m.line_prisms.push_back(model.line_prisms[i]);
  }
  for (int p : point_of) {
    Point point = model.points[p];
    std::vector<LineEnd> ends;
    for (const LineEnd& e : point.ends)
      if (line_new[e.line] >= 0) ends.push_back({line_new[e.line], e.station});
    point.ends = ends;
    if (point.on_body >= 0) point.on_body = body_new[point.on_body];
    point.shared = -1;
    if (point.kind == PointKind::kFree && point.ends.size() >= 2) {
      point.shared = m.shared_count();
      m.shared_points.push_back(static_cast<int>(m.points.size()));
    }
    m.points.push_back(point);
    PointSpec spec = model.point_specs[p];
    if (spec.on_body >= 0) spec.on_body = body_new[spec.on_body];
    m.point_specs.push_back(spec);
  }
  for (int b : body_of) {
    m.bodies.push_back(model.bodies[b]);
    m.body_poses.push_back(model.body_poses[b]);
    if (model.bodies[b].kind == BodyKind::kFree) m.free_bodies.push_back(body_new[b]);
  }
  FindIslands(m);
  if (lines) *lines = line_of;
  if (points) *points = point_of;
  if (bodies) *bodies = body_of;
  return m;
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
  FindIslands(held);
  return held;
}

}  // namespace cablefilm
