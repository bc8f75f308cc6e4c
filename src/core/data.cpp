#include "core/data.h"

#include <algorithm>
#include <string>

#include "core/coupled_explicit_step.h"
#include "core/coupled_step.h"
#include "core/error.h"

namespace cablefilm {

Data MakeData(const Model& model, const Inputs& in, const StepOptions& options,
              const std::vector<State>& states, const std::vector<Points>* friction_anchors) {
  const int nl = static_cast<int>(model.lines.size());
  if (static_cast<int>(states.size()) != nl)
    throw Error("MakeData: one state per line is needed");
  Data d;
  d.t = nl > 0 ? states[0].t : 0.0;
  for (int i = 0; i < nl; ++i)
    d.lines.push_back(MakeLineData(
        model.lines[i], in, LineStepOptions(options, model.lines[i]), states[i],
        friction_anchors && i < static_cast<int>(friction_anchors->size())
            ? &(*friction_anchors)[i]
            : nullptr));
  for (int b : model.free_bodies) {
    const BodySpec& body = model.bodies[b];
    Vec6 inertia;
    inertia << Vec::Constant(body.mass), body.inertia;
    inertia += body.added_mass;
    if (!(inertia.minCoeff() > 0))
      throw Error("body \"" + body.name + "\" is free: to move in time it needs a mass and "
                  "moments of inertia (with its added mass, above 0 in each of its six degrees "
                  "of freedom)");
    BodyMotion m;
    m.q = m.tq = model.body_poses[b];
    for (const Point& p : model.points)
      if (p.on_body == b) m.arm = std::max(m.arm, p.local.norm());
    d.bodies.push_back(m);
  }
  d.islands.resize(model.islands.size());
  for (int k = 0; k < static_cast<int>(model.islands.size()); ++k) {
    const Island& isl = model.islands[k];
    if (!isl.coupled()) continue;
    PrepareCoupledIsland(model, k, d);
    // The coupled stations' and free bodies' accelerations from the sum of their rows (a free
    // body's zero at its equilibrium, but for the dynamic terms a moving start would add), at
    // rest in the water: the current's drag on a body (the statics hold it).
    std::vector<Vec6> rates;
    for (int b : d.islands[k].bodies) rates.push_back(d.bodies[b].v);
    CoupleAccelerations(model, k, d, d.t, rates);
    if (options.scheme != Scheme::kImplicit) continue;  // generalized-alpha's memory: abar = a
    for (int p : isl.shared_points)
      for (const LineEnd& e : model.points[p].ends)
        d.lines[e.line].abar.col(e.station) = d.lines[e.line].a.col(e.station);
    for (int b : d.islands[k].bodies) {
      BodyMotion& m = d.bodies[b];
      m.abar = m.ta = m.tabar = m.a;
    }
    const IslandData& id = d.islands[k];
    for (std::size_t i = 0; i < isl.lines.size(); ++i)
      for (int e = 0; e < 2; ++e)
        if (id.couplings[i][e].body >= 0) {
          LineData& ld = d.lines[isl.lines[i]];
          const int j = e == 0 ? 0 : model.lines[isl.lines[i]].line.links;
          ld.abar.col(j) = ld.a.col(j);
        }
  }
  return d;
}

namespace {

// Adds line record r to `all` (every line's step range; the snaps of all; the first
// unresolved one of the line that had the earliest).
void AddRecord(const StepRecord& r, bool first, StepRecord& all) {
  if (first) {
    all = r;
    return;
  }
  if (r.smallest_step > 0 && (all.smallest_step == 0 || r.smallest_step < all.smallest_step))
    all.smallest_step = r.smallest_step;
  all.largest_step = std::max(all.largest_step, r.largest_step);
  all.snaps += r.snaps;
  all.unresolved_snaps += r.unresolved_snaps;
  all.worst_snap_ratio = std::max(all.worst_snap_ratio, r.worst_snap_ratio);
  if (r.first_unresolved_time >= 0 &&
      (all.first_unresolved_time < 0 || r.first_unresolved_time < all.first_unresolved_time)) {
    all.first_unresolved_time = r.first_unresolved_time;
    all.first_unresolved_link = r.first_unresolved_link;
  }
}

}  // namespace

StepStats LineStepStats(const Model& model, const Data& d, int i) {
  StepStats s = d.lines[i].step_stats();
  const int k = model.line_island[i];
  if (!model.islands[k].coupled()) return s;
  const StepStats& island = d.islands[k].stats;  // its steps are every line's of it
  s.rejected = island.rejected;
  s.snap_windows = island.snap_windows;
  s.explicit_steps = island.explicit_steps;
  if (island.finest_refinement > s.finest_refinement) s.finest_refinement = island.finest_refinement;
  return s;
}

StepStats ModelStepStats(const Model& model, const Data& d) {
  StepStats all;
  bool first = true;
  for (int k = 0; k < static_cast<int>(model.islands.size()); ++k) {
    const Island& isl = model.islands[k];
    const StepStats line = d.lines[isl.lines.front()].step_stats();
    const StepStats& own = isl.coupled() ? d.islands[k].stats : line;
    all.steps += own.steps;
    all.rejected += own.rejected;
    all.finest_refinement = std::max(all.finest_refinement, own.finest_refinement);
    // Each line of a coupled island counts every Newton iteration of its coupled solve: the
    // island's are any line's.
    all.newton_iterations += line.newton_iterations;
    all.snap_windows += own.snap_windows;
    all.explicit_steps += own.explicit_steps;
    for (int i : isl.lines) {
      AddRecord(d.lines[i].step_stats().record, first, all.record);
      first = false;
    }
  }
  return all;
}

}  // namespace cablefilm
