#pragma once
// The model (MuJoCo's mjModel), const while it runs: lines, points and bodies in one
// environment. Each line is the lumped-mass line of line_model.h between two points; a single
// line is a line between two points. A point is fixed (an anchor), moved (a fairlead on a
// ship: the end motions of end_motion.h) or free (a clump weight, a buoy, a junction of
// lines), with its own mass, buoyancy, added mass, drag and a constant force. A free point
// carried by one line is that line's free end with the point as its prism; a free point where
// several line ends meet is a shared station: each line keeps its own copy of it, and the
// coupled step (coupled_step.h) solves the lines together through the Schur complement on the
// shared stations. Its equation of motion is the sum of the rows of its copies: the point's
// own terms are on the copy of the line that owns it (the first end attached), and each line
// adds its end station's lumped share (half of its end link's mass, weight, drag), as MoorDyn
// lumps them.
//
// A point may be fixed to a rigid body (body.h) at a local position instead: a held body's
// points are fixed, a driven body's move with its reference point, and a free body's (kind
// kBody) are where the body's pose puts them; the statics find a free body's pose.
//
// Lines joined through shared points or free bodies form an island (Box2D's islands, MuJoCo's
// trees), stepped on its own (step.h): an island of one line between points that hold it
// (fixed, moved, or a free end of its own) takes the line's schemes (explicit, implicit,
// inextensible); a coupled island the coupled step.
#include <array>
#include <string>
#include <vector>

#include "core/body.h"
#include "core/line_model.h"

namespace cablefilm {

enum class PointKind { kFixed, kMoved, kFree, kBody };

struct PointSpec {
  std::string name;
  EndMotion motion = EndMotion::Fixed(Vec::Zero());  // Free(): the first guess of a free point
  // A free point's own physics, as a suspended weight's (PrismSpec): mass m* [kg], volume V*
  // [m^3], added volumes [m^3], drag coefficients and areas [m^2], a constant force [N].
  PrismSpec body;
  // On a body: its index, and the point's position in the body's axes from its reference
  // point [m] (the motion above is then unused).
  int on_body = -1;
  Vec local = Vec::Zero();
};

struct LineSpec {
  std::string name;
  std::vector<SectionSpec> sections;
  std::vector<PrismSpec> prisms;
  LinkLaw law = LinkLaw::kElastic;
  int start_point = 0;  // the point station 0 is attached to (index into the points)
  int end_point = 0;    // the point station s is attached to
};

// A line end at a point: line `line`, station 0 or s.
struct LineEnd {
  int line = 0;
  int station = 0;
};

struct Point {
  std::string name;
  PointKind kind = PointKind::kFixed;
  EndMotion motion = EndMotion::Fixed(Vec::Zero());  // as given (a free point: its first guess)
  std::vector<LineEnd> ends;  // the line ends attached to it (the first: its owner)
  int shared = -1;            // index among the shared points (a free point with several
                              // line ends), -1 otherwise
  int on_body = -1;           // the body it is fixed to, -1 for none
  Vec local = Vec::Zero();    // its position in that body's axes [m]
};

// A connected part of the model: its lines, the shared points and free bodies that join them
// (model indices, in the model's order).
struct Island {
  std::vector<int> lines;
  std::vector<int> shared_points;
  std::vector<int> free_bodies;
  // Several lines, or a line whose end is on a free body: the coupled step's.
  bool coupled() const { return !shared_points.empty() || !free_bodies.empty(); }
};

struct Model {
  std::vector<LineModel> lines;  // each line's model: a shared end is a free station there
  std::vector<std::string> line_names;
  std::vector<std::array<int, 2>> line_points;  // per line: the points of station 0 and s
  std::vector<Point> points;
  std::vector<int> shared_points;  // indices of the points that are shared stations
  EnvironmentSpec env;             // as built (the lines' environments are made from it)
  std::vector<BodySpec> bodies;
  std::vector<int> free_bodies;    // indices of the free bodies (the statics' unknowns)
  // Each body's pose at the start [m, rad]: its rest pose, or where PlaceBody put it (a free
  // body's equilibrium). A free body's waterplane keeps its scene's rest as its reference.
  std::vector<Vec6> body_poses;
  // What it was made from (chain_guess.h solves a chain of lines as one line from them).
  std::vector<LineSpec> line_specs;
  std::vector<PointSpec> point_specs;
  std::vector<std::vector<PrismSpec>> line_prisms;  // per line: the prisms its model was made
                                                    // with (its own, and its free end's point's)
  std::vector<Island> islands;     // the connected parts (FindIslands)
  std::vector<int> line_island;    // per line: its island

  int shared_count() const { return static_cast<int>(shared_points.size()); }
  // The line end that owns point p (its first).
  const LineEnd& owner(int p) const { return points[p].ends.front(); }
  // The index among the shared points of line i's end at station 0 (e = 0) or s (e = 1); -1
  // when that end is not at a shared point.
  int shared_end(int i, int e) const { return points[line_points[i][e]].shared; }
};

// Builds the model, its islands found; throws Error on no line, a free point no line is
// attached to, a line end at a point that does not exist, a line whose ends are both loose,
// an inextensible line in a coupled island (the coupled step is the elastic lines'), a point
// on a body that does not exist, or a free body that no line holds.
Model MakeModel(const std::vector<LineSpec>& lines, const std::vector<PointSpec>& points,
                const EnvironmentSpec& env, const std::vector<BodySpec>& bodies = {});

// The islands of `model` (Model::islands, line_island) from its shared points and free
// bodies; throws Error naming an inextensible line in a coupled island.
void FindIslands(Model& model);

// Island k as a model of its own: its lines, the points they end at and the bodies those are
// on, renumbered in the model's order (`lines`, `points`, `bodies`: the model's index of each
// of its lines, points and bodies). The statics solve an island so.
Model IslandModel(const Model& model, int k, std::vector<int>* lines = nullptr,
                  std::vector<int>* points = nullptr, std::vector<int>* bodies = nullptr);

// Body b at rest at `pose` (body_poses[b]): its points and the lines' ends there moved with it
// (their motions about the new rest positions); a held or driven body's rest pose too.
void PlaceBody(Model& sys, int b, const Vec6& pose);

// The model with body b held at `pose` (its points fixed where the pose puts them, the lines'
// ends with them; its islands found anew): how the statics and the quasi-static tools place
// a body.
Model HoldBody(const Model& sys, int b, const Vec6& pose);

// Moves the ends of model `line` that are at points of body b to where `pose` puts them
// (held there: fixed ends).
void PlaceBodyEnds(const Model& sys, int b, const Vec6& pose, int line, LineModel& model);

}  // namespace cablefilm
