#pragma once
// What changes while a model (model.h) runs (MuJoCo's mjData): each line's LineData (its state,
// tensions and scheme's memory: line_data.h), each free body's motion, and each island's own
// memory (a coupled island's step size, statistics and the scratch of its coupled solve). A
// complete checkpoint: a copy, stepped with the same model and inputs, goes on exactly as the
// original would (a restart, a film frame, a continuation). Scratch is sized once (MakeData),
// so that stepping allocates nothing.
#include <Eigen/Core>
#include <Eigen/LU>
#include <array>
#include <vector>

#include "core/line_data.h"
#include "core/model.h"

namespace cablefilm {

// A free body's motion in the time-stepping schemes: pose q, its rate, its acceleration and
// (implicit) pseudo-acceleration, committed and trial.
struct BodyMotion {
  Vec6 q = Vec6::Zero(), v = Vec6::Zero(), a = Vec6::Zero(), abar = Vec6::Zero();
  Vec6 tq = Vec6::Zero(), tv = Vec6::Zero(), ta = Vec6::Zero(), tabar = Vec6::Zero();
  double arm = 1;  // its farthest point from its reference, >= 1 [m]: a turn's reach
};

// How a line end takes part in its island's dense system: its unknowns' offset and count (3
// for a shared point, 6 for a free body; 0: not coupled), the free body (its index in
// Data::bodies) and the point's local position on it.
struct EndCoupling {
  int offset = 0, size = 0;
  int body = -1;
  Vec local = Vec::Zero();
};

using PointMap = Eigen::Matrix<double, 3, 6>;  // T: a pose change to a body point's motion

// A coupled island's memory (model.h, Island; empty for an island of one line, whose LineData
// carries its own). Per line of the island (in the island's order) and per unknown of its
// dense system: kDim per shared point, then 6 per free body.
struct IslandData {
  double t = 0;               // its clock within a step of the model [s]
  double proposed_step = 0;   // implicit: the next step to try [s]
  double newton_tolerance = 0;  // a body's Newton iteration has converged below it [m]
  StepStats stats;            // the island's steps and rejections (its lines count their own
                              // Newton iterations)
  int refinement = 0;         // explicit, automatic: k, steps asked are cut into 2^k substeps
  double quiet_time = 0;      // explicit, automatic: since a link last went slack or taut [s]
  double max_substep = 0;     // explicit (and implicit's steps through snaps): the least of its
                              // lines' [s]
  double snap_window = 0;     // implicit, explicit_snaps: the window after a snap, its lines'
                              // longest [s]
  double explicit_until = -1; // implicit: explicit steps through a snap until then [s]
  double start_time = 0;      // the clock when the Data was made [s]
  std::vector<int> bodies;    // its free bodies' indices in Data::bodies
  std::vector<std::array<EndCoupling, 2>> couplings;  // per line, its two ends'
  std::vector<std::array<PointMap, 2>> end_maps;      // their T at the trial pose
  // Scratch of the coupled solve, sized once.
  std::vector<std::vector<Mat>> start_columns, end_columns;  // per line: A_II^-1 A_IB
  Eigen::MatrixXd schur;      // the dense system of the shared stations and bodies
  // Each line's share of `schur` and the free bodies' own rows, as last assembled: a line whose
  // kept matrix still serves keeps its share while another's is made anew.
  std::vector<Eigen::MatrixXd> line_schur;
  Eigen::MatrixXd body_schur;
  std::vector<char> fresh;              // per line: its Newton matrix made anew this iteration
  std::vector<double> last_correction;  // per line: its last correction over its tolerance
  Eigen::VectorXd schur_rhs, schur_x;
  Eigen::PartialPivLU<Eigen::MatrixXd> schur_lu;
  // Explicit: each free body's predicted rate at a substep's end (its damping's) [m/s, rad/s].
  std::vector<Vec6> body_rates;
};

struct Data {
  double t = 0;                      // [s]
  std::vector<LineData> lines;       // each line's (a coupled island's shared stations in sync)
  std::vector<BodyMotion> bodies;    // the free bodies' (in the order of Model::free_bodies)
  std::vector<IslandData> islands;   // each island's (Model::islands)
};

// The Data of each line at `states` (shared stations equal in every line that holds them; the
// free bodies at their poses in model.body_poses, at rest) under the model's `options`, each
// line with its own of them (LineStepOptions: an inextensible line's scheme is its own): an
// island of one line as MakeLineData makes it; a coupled island's shared stations and free
// bodies accelerated by the sum of their rows. Throws BlowUpError for a state that is not
// sane, Error for a free body without mass.
Data MakeData(const Model& model, const Inputs& in, const StepOptions& options,
              const std::vector<State>& states,
              const std::vector<Points>* friction_anchors = nullptr);

// The steps of the model's run so far: its islands' steps, rejections and Newton iterations
// added up (an island of one line its line's), the explicit windows and steps too, the
// step range over all, the snaps of every line.
StepStats ModelStepStats(const Model& model, const Data& d);
// Line i's: its own, with its island's steps and rejections (a coupled island's are every
// line's of it).
StepStats LineStepStats(const Model& model, const Data& d, int i);

}  // namespace cablefilm
