#include "core/coupled_explicit_step.h"

#include <Eigen/LU>
#include <cmath>
#include <limits>

#include "core/cancel.h"
#include "core/coupled_step.h"
#include "core/explicit_stages.h"
#include "core/explicit_step.h"
#include "core/island_view.h"

namespace cablefilm {
namespace {

// The island's drift of a substep h: each free body's pose and half-step rate (tq, tv), then
// every line's (Drift), the stations on the bodies where the drifted poses put them; true if a
// link changes between slack and taut in it.
bool DriftIsland(const IslandView& v, const Inputs& in, double h) {
  for (int k = 0; k < v.bodies(); ++k) {
    BodyMotion& b = v.body(k);
    b.tv = b.v + 0.5 * h * b.a;  // dq/dt at n + 1/2
    b.tq = b.q + h * b.tv;
  }
  bool changed = false;
  for (int i = 0; i < v.lines(); ++i) changed |= Drift(v.M(i), v.L(i), in, h);
  for (int i = 0; i < v.lines(); ++i)
    for (int e = 0; e < 2; ++e) {
      const EndCoupling& c = v.id.couplings[i][e];
      if (c.body < 0) continue;
      const BodyMotion& b = v.d.bodies[c.body];
      const int j = v.end_station(i, e);
      const PointMap T = BodyPointJacobian(b.tq, c.local);
      Scratch& w = v.L(i).scratch;
      w.x.col(j) = BodyPoint(b.tq, c.local);
      w.v.col(j) = T * b.tv;
      w.v_pred.col(j) = T * (b.v + h * b.a);
    }
  return changed;
}

bool IslandSnapsResolved(const IslandView& v, double h) {
  for (int i = 0; i < v.lines(); ++i)
    if (!SnapsResolved(v.M(i), v.L(i), h)) return false;
  return true;
}

// Completes the drifted substep h: the forces and accelerations at its end, coupled, then the
// velocities' second half; each body's pose and rate, its stations moving with it.
void CommitIsland(const IslandView& v, int island, const Inputs& in, double h) {
  std::vector<Vec6>& rates = v.id.body_rates;
  for (int i = 0; i < v.lines(); ++i) MoveToDrift(v.M(i), v.L(i), in, h);
  for (int k = 0; k < v.bodies(); ++k) {
    const BodyMotion& b = v.body(k);
    rates[k] = b.v + h * b.a;  // predicted dq/dt at n + 1, for its damping
  }
  for (int k = 0; k < v.bodies(); ++k) v.body(k).q = v.body(k).tq;
  CoupleAccelerations(v.model, island, v.d, v.L(0).state.t + h, rates);
  for (int i = 0; i < v.lines(); ++i) FinishDrift(v.M(i), v.L(i), h);
  for (int k = 0; k < v.bodies(); ++k) {
    BodyMotion& b = v.body(k);
    b.v = b.tv + 0.5 * h * b.a;
  }
  for (int i = 0; i < v.lines(); ++i)
    for (int e = 0; e < 2; ++e) {
      const EndCoupling& c = v.id.couplings[i][e];
      if (c.body < 0) continue;
      const int j = v.end_station(i, e);
      v.L(i).state.v.col(j) = v.id.end_maps[i][e] * v.d.bodies[c.body].v;
    }
  ++v.id.stats.steps;
}

}  // namespace

void CoupleAccelerations(const Model& model, int k, Data& d, double t,
                         const std::vector<Vec6>& rates) {
  const IslandView v(model, k, d);
  // A shared station's acceleration is that of its whole mass under all its forces.
  for (int p : v.isl.shared_points) {
    Mat M = Mat::Zero();
    Vec F = Vec::Zero();
    for (const LineEnd& e : model.points[p].ends) {
      const LineData& ld = d.lines[e.line];
      M += StationInertia(model.lines[e.line], ld.forces.geometry, e.station);
      F += ld.forces.force.col(e.station);
    }
    const Vec a = M.inverse() * F;
    for (const LineEnd& e : model.points[p].ends) d.lines[e.line].a.col(e.station) = a;
  }
  // A free body's from its mass and its stations' under its loads and theirs.
  for (int kb = 0; kb < v.bodies(); ++kb) {
    BodyMotion& b = v.body(kb);
    const BodySpec& body = v.body_spec(kb);
    Mat6 M = BodyMassMatrix(body, b.q);
    Vec6 Q = BodyOwnLoad(model, body, b.q);
    Q += BodyDampingLoad(body, rates[kb],
                         WaterVelocityAt(v.M(0), v.L(0).water, b.q.head<3>(), t));
    for (int i = 0; i < v.lines(); ++i)
      for (int e = 0; e < 2; ++e) {
        const EndCoupling& c = v.id.couplings[i][e];
        if (c.body != v.id.bodies[kb]) continue;
        PointMap& T = v.id.end_maps[i][e];
        T = BodyPointJacobian(b.q, c.local);
        const int j = v.end_station(i, e);
        const LineData& ld = v.L(i);
        M += T.transpose() * StationInertia(v.M(i), ld.forces.geometry, j) * T;
        Q += T.transpose() * ld.forces.force.col(j);
      }
    b.a = M.partialPivLu().solve(Q);
    for (int i = 0; i < v.lines(); ++i)
      for (int e = 0; e < 2; ++e)
        if (v.id.couplings[i][e].body == v.id.bodies[kb])
          v.L(i).a.col(v.end_station(i, e)) = v.id.end_maps[i][e] * b.a;
  }
}

void StepCoupledExplicit(const Model& model, int k, Data& d, const Inputs& in, double dt) {
  const IslandView v(model, k, d);
  IslandData& id = v.id;
  const StepOptions& o = v.L(0).options;
  // Fixed steps (no safety factor): the step asked, as it is.
  const double max_substep =
      o.safety_factor > 0 ? id.max_substep : std::numeric_limits<double>::infinity();
  SettleRefinement(dt, max_substep, &id.refinement, &id.quiet_time);
  const double t0 = id.t;
  long done = 0;  // substeps of dt / 2^refinement taken
  while (done < (1L << id.refinement)) {
    ThrowIfCancelled(in.stop, "the explicit step");
    double h = dt / static_cast<double>(1L << id.refinement);
    bool changed = DriftIsland(v, in, h);
    while (o.safety_factor > 0 && changed && !IslandSnapsResolved(v, h) &&
           id.refinement < kMaxRefinement) {
      ++id.stats.rejected;
      ++id.refinement;
      done *= 2;
      h *= 0.5;
      changed = DriftIsland(v, in, h);
    }
    if (id.refinement > id.stats.finest_refinement) id.stats.finest_refinement = id.refinement;
    CommitIsland(v, k, in, h);
    ++done;
    const double t = t0 + static_cast<double>(done) * h;
    for (int i = 0; i < v.lines(); ++i) v.L(i).state.t = t;
    id.quiet_time = changed ? 0.0 : id.quiet_time + h;
  }
  id.t = t0 + dt;
}

}  // namespace cablefilm
