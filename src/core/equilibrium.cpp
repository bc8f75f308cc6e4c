#include "core/equilibrium.h"

#include <algorithm>

#include "core/cancel.h"
#include "core/coarse_guess.h"
#include "core/coupled_equilibrium.h"
#include "core/error.h"
#include "core/relaxation.h"

namespace cablefilm {
namespace {

// Line i alone between points that hold it: the line's statics (the inextensible line's
// own; an elastic one from its coarse copies' shape when long, Newton in the full current from
// there, else continued in the current from its catenary), within options.max_line_statics
// station-passes.
State SolveSingleLine(const Model& model, int i, const EquilibriumOptions& options,
                      LineEquilibriumReport* report) {
  const LineModel& m = model.lines[i];
  if (m.line.law == LinkLaw::kInextensible)
    return SolveInextensibleEquilibrium(m, report, options.cancel, options.max_line_statics);
  LineEquilibriumOptions line;
  line.cancel = options.cancel;
  line.max_work = options.max_line_statics;
  double work = 0;
  line.work = &work;
  try {
    // A model made in code may have no specs: no coarse copies then.
    const bool specs = i < static_cast<int>(model.line_specs.size()) &&
                       i < static_cast<int>(model.line_prisms.size());
    const State s =
        specs ? SolveLongLineEquilibrium(m,
                                         LineMaking{model.line_specs[i].sections,
                                                    model.line_prisms[i], model.env, m.line.law},
                                         report, line)
              : SolveLineEquilibrium(m, report, line);
    report->work = work;
    return s;
  } catch (const Error&) {
    report->work = work;
    throw;
  }
}

// Island k's statics: Newton on its shared points and free bodies (and the relaxation where it
// fails, when options ask), its lines' states and its bodies' poses into the model's.
void SolveIsland(const Model& model, int k, const EquilibriumOptions& options,
                 std::vector<State>& states, EquilibriumReport& report) {
  std::vector<int> lines, points, bodies;
  const bool whole = model.islands.size() == 1;
  // The island's own model, whose lines are held in place (their ends moved and put back):
  // one copy of its lines, not two.
  Model m = whole ? model : IslandModel(model, k, &lines, &points, &bodies);
  if (whole) {
    for (int i = 0; i < static_cast<int>(model.lines.size()); ++i) lines.push_back(i);
    for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b) bodies.push_back(b);
  }
  EquilibriumOptions o = options;
  std::vector<State> guess;
  std::vector<Vec6> guess_poses;
  if (options.guess) {
    for (int i : lines) guess.push_back((*options.guess)[i]);
    for (int b : bodies) guess_poses.push_back(options.guess_poses[b]);
    o.guess = &guess;
    o.guess_poses = guess_poses.data();
  }
  EquilibriumReport r;
  const std::vector<State> solved =
      options.relaxation
          ? SolveCoupledEquilibriumRelaxing(m, options.inputs, *options.relaxation, &r, o)
          : SolveCoupledEquilibriumInPlace(m, m.lines, &r, o);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    states[lines[i]] = solved[i];
    if (i < r.lines.size()) report.lines[lines[i]] = r.lines[i];
  }
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (b < r.body_poses.size()) report.body_poses[bodies[b]] = r.body_poses[b];
  report.iterations += r.iterations;
  report.chains += r.chains;
  report.residual = std::max(report.residual, r.residual);
  report.line_work += r.line_work;
  report.relaxed = std::max(report.relaxed, r.relaxed);
}

}  // namespace

std::vector<State> SolveEquilibrium(const Model& model, EquilibriumReport* report,
                                    const EquilibriumOptions& options) {
  const int nl = static_cast<int>(model.lines.size());
  std::vector<State> states(nl);
  EquilibriumReport r;
  r.lines.resize(nl);
  r.body_poses = model.body_poses;
  for (const LineModel& m : model.lines) r.force_scale += StaticForceScale(m);
  for (int k = 0; k < static_cast<int>(model.islands.size()); ++k) {
    const Island& isl = model.islands[k];
    ThrowIfCancelled(options.cancel, "the static equilibrium");
    if (isl.coupled() || options.guess) {
      SolveIsland(model, k, options, states, r);
      continue;
    }
    const int i = isl.lines.front();
    try {
      states[i] = SolveSingleLine(model, i, options, &r.lines[i]);
    } catch (const CancelledError&) {
      throw;
    } catch (const StaticsWorkError& e) {
      if (nl == 1) throw;
      throw StaticsWorkError("line \"" + model.line_names[i] + "\": " + e.what());
    } catch (const Error& e) {
      if (nl == 1) throw;
      throw Error("line \"" + model.line_names[i] + "\": no static equilibrium: " + e.what());
    }
    r.residual = std::max(r.residual, r.lines[i].residual);
    r.line_work += r.lines[i].work;

  }
  if (report) *report = r;
  return states;
}

std::vector<State> StraightStart(const Model& model) {
  std::vector<State> states;
  for (const LineModel& m : model.lines) {
    State s;
    s.x = StraightChord(m);
    s.v = Points::Zero(kDim, m.stations());
    states.push_back(s);
  }
  return states;
}

}  // namespace cablefilm
