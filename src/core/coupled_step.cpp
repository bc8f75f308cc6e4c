#include "core/coupled_step.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/coupled_explicit_step.h"
#include "core/error.h"
#include "core/explicit_snaps.h"
#include "core/force_jacobian.h"
#include "core/implicit_stages.h"
#include "core/island_view.h"

namespace cablefilm {
namespace {

// Makes every copy of the island's shared stations equal to its owner's trial position (`x`)
// or trial velocity and accelerations (`motion`); with `x`, puts each station on a free body
// where the body's trial pose puts its point.
void SyncCoupled(const IslandView& v, bool motion) {
  for (int p : v.isl.shared_points) {
    const LineEnd& o = v.model.owner(p);
    const Scratch& w = v.d.lines[o.line].scratch;
    for (const LineEnd& e : v.model.points[p].ends) {
      if (e.line == o.line && e.station == o.station) continue;
      Scratch& u = v.d.lines[e.line].scratch;
      if (!motion) {
        u.x.col(e.station) = w.x.col(o.station);
        continue;
      }
      u.v.col(e.station) = w.v.col(o.station);
      u.a.col(e.station) = w.a.col(o.station);
      u.abar.col(e.station) = w.abar.col(o.station);
    }
  }
  if (motion) return;
  for (int i = 0; i < v.lines(); ++i)
    for (int e = 0; e < 2; ++e) {
      const EndCoupling& c = v.id.couplings[i][e];
      if (c.body < 0) continue;
      const int j = e == 0 ? 0 : v.M(i).line.links;
      const Vec6& tq = v.d.bodies[c.body].tq;
      v.L(i).scratch.x.col(j) = BodyPoint(tq, c.local);
      v.id.end_maps[i][e] = BodyPointJacobian(tq, c.local);
    }
}

// Adds T_a^T S T_b to `schur`'s block of the unknowns of ends a and b.
void AddCoupledBlock(Eigen::MatrixXd& schur, const EndCoupling& ca, const PointMap& Ta,
                     const EndCoupling& cb, const PointMap& Tb, const Mat& S) {
  const Mat6 block = Ta.transpose() * S * Tb;
  schur.block(ca.offset, cb.offset, ca.size, cb.size) += block.topLeftCorner(ca.size, cb.size);
}

void AddCoupledRhs(IslandData& id, const EndCoupling& c, const PointMap& T, const Vec& r) {
  const Vec6 rows = T.transpose() * r;
  id.schur_rhs.segment(c.offset, c.size) += rows.head(c.size);
}

// The correction of a coupled end station from the dense system's solution: T dq.
Vec CoupledCorrection(const IslandData& id, const EndCoupling& c, const PointMap& T) {
  Vec6 u = Vec6::Zero();
  u.head(c.size) = id.schur_x.segment(c.offset, c.size);
  return T * u;
}

// Line i's share of the dense system: its interior eliminated (A_II^-1 for the right-hand side
// and for the columns coupling it to its coupled ends), the Schur complement rows of its
// coupled ends (into id.line_schur[i]) added through their maps T. False when a pivot is
// singular. Without `matrix` the right-hand side alone, on the factors, columns and share of
// the last call with it.
bool EliminateInterior(const IslandView& v, int i, bool matrix) {
  IslandData& id = v.id;
  BlockTridiagonal& A = v.L(i).scratch.system;
  std::vector<Mat>& zs = id.start_columns[i];
  std::vector<Mat>& ze = id.end_columns[i];
  const int n = A.size();
  const EndCoupling &cP = id.couplings[i][0], &cQ = id.couplings[i][1];
  const PointMap &TP = id.end_maps[i][0], &TQ = id.end_maps[i][1];
  const bool P = cP.size > 0, Q = cQ.size > 0;
  const int f = P ? 1 : 0, l = Q ? n - 2 : n - 1;  // the interior rows
  const bool interior = f <= l;
  Eigen::MatrixXd& S = id.line_schur[i];
  if (matrix) S.setZero();
  if (interior) {
    if (matrix && !A.Factor(f, l)) return false;
    A.SolveFactored(A.rhs);
    if (matrix && P) {
      for (int r = f; r <= l; ++r) zs[r].setZero();
      zs[f] = A.lower[f];
      A.SolveFactored(zs);
    }
    if (matrix && Q) {
      for (int r = f; r <= l; ++r) ze[r].setZero();
      ze[l] = A.upper[l];
      A.SolveFactored(ze);
    }
  }
  if (P) {  // row 0
    AddCoupledRhs(id, cP, TP, interior ? Vec(A.rhs[0] - A.upper[0] * A.rhs[f]) : A.rhs[0]);
    if (matrix) {
      AddCoupledBlock(S, cP, TP, cP, TP, interior ? Mat(A.diag[0] - A.upper[0] * zs[f]) : A.diag[0]);
      if (Q) AddCoupledBlock(S, cP, TP, cQ, TQ, interior ? Mat(-A.upper[0] * ze[f]) : A.upper[0]);
    }
  }
  if (Q) {  // row n - 1
    const int e = n - 1;
    AddCoupledRhs(id, cQ, TQ, interior ? Vec(A.rhs[e] - A.lower[e] * A.rhs[l]) : A.rhs[e]);
    if (matrix) {
      AddCoupledBlock(S, cQ, TQ, cQ, TQ, interior ? Mat(A.diag[e] - A.lower[e] * ze[l]) : A.diag[e]);
      if (P) AddCoupledBlock(S, cQ, TQ, cP, TP, interior ? Mat(-A.lower[e] * zs[l]) : A.lower[e]);
    }
  }
  return true;
}

// Line i's corrections from the dense system's solution: x_B = T dq, x_I = y - Z x_B.
void BackSubstitute(const IslandView& v, int i) {
  IslandData& id = v.id;
  BlockTridiagonal& A = v.L(i).scratch.system;
  const int n = A.size();
  const EndCoupling &cP = id.couplings[i][0], &cQ = id.couplings[i][1];
  const bool P = cP.size > 0, Q = cQ.size > 0;
  const Vec xP = P ? CoupledCorrection(id, cP, id.end_maps[i][0]) : Vec::Zero();
  const Vec xQ = Q ? CoupledCorrection(id, cQ, id.end_maps[i][1]) : Vec::Zero();
  const int f = P ? 1 : 0, l = Q ? n - 2 : n - 1;
  for (int r = f; r <= l; ++r) {
    if (P) A.rhs[r].noalias() -= id.start_columns[i][r] * xP;
    if (Q) A.rhs[r].noalias() -= id.end_columns[i][r] * xQ;
  }
  if (P) A.rhs[0] = xP;
  if (Q) A.rhs[n - 1] = xQ;
}

// a_{n+1}, v_{n+1} and abar_{n+1} of a free body implied by its trial pose (as Kinematics of
// implicit_stages.cpp for a station).
void BodyKinematics(BodyMotion& b, const GeneralizedAlpha& c, double h) {
  b.tabar = (b.tq - b.q - h * b.v - h * h * (0.5 - c.beta) * b.abar) / (h * h * c.beta);
  b.ta = ((1.0 - c.am) * b.tabar + c.am * b.abar - c.af * b.a) / (1.0 - c.af);
  b.tv = b.v + h * (1.0 - c.gamma) * b.abar + h * c.gamma * b.tabar;
}

// The water's velocity at a free body's reference point at time t (the island's first line's
// water of this step) [m/s].
Vec BodyFlow(const IslandView& v, const Vec6& q, double t) {
  return WaterVelocityAt(v.M(0), v.L(0).water, q.head<3>(), t);
}

// Free body k's own rows of the dense system at its trial pose: the matrix
// ka M + kv dD/dv - dQ/dq and the residual Q + D - M a (its lines' rows come through their
// ends); without `matrix` the residual alone.
void AssembleBody(const IslandView& v, int k, const GeneralizedAlpha& c, double h, int offset,
                  bool matrix) {
  IslandData& id = v.id;
  BodyMotion& b = v.body(k);
  const BodySpec& body = v.body_spec(k);
  BodyKinematics(b, c, h);
  const double ka = (1.0 - c.am) / ((1.0 - c.af) * c.beta * h * h);
  const double kv = c.VelocityPerPosition(h);
  const Mat6 M = BodyMassMatrix(body, b.tq);
  const Vec6 Q = BodyOwnLoad(v.model, body, b.tq);
  // The water at its reference point at the step's end (the lines' water of this step).
  const Vec flow = BodyFlow(v, b.tq, v.id.t + h);
  id.schur_rhs.segment<6>(offset) += Q + BodyDampingLoad(body, b.tv, flow) - M * b.ta;
  if (!matrix) return;  // its rows in id.body_schur stay
  Mat6 K = ka * M;
  K.diagonal() -= kv * BodyDampingSlope(body, b.tv, flow);
  for (int col = 0; col < 6; ++col) {  // -dQ/dq by forward differences (a cheap closed form)
    Vec6 dq = b.tq;
    const double step = 1e-7 * (col < 3 ? std::max(1.0, b.tq.head<3>().norm()) : 1.0);
    dq[col] += step;
    K.col(col) -= (BodyOwnLoad(v.model, body, dq) - Q) / step;
  }
  id.body_schur.block<6, 6>(offset, offset) += K;
}


// Solves Newton's system of every line and free body of the island, coupled at the shared
// stations and the bodies, into each line's system.rhs and the bodies' corrections
// (id.schur_x). False when a pivot or the dense system is singular. A line whose `fresh` is 0
// (a simplified Newton iteration) solves on the factors and share of the dense system of its
// last fresh one; the bodies' rows and the dense system's factors are made anew when any
// line's are.
bool SolveCoupled(const IslandView& v, const GeneralizedAlpha& c, double h,
                  const std::vector<char>& fresh) {
  IslandData& id = v.id;
  const int nl = v.lines();
  if (id.schur.rows() == 0) {
    for (int i = 0; i < nl; ++i) {
      BlockTridiagonal& A = v.L(i).scratch.system;
      if (!fresh[i]) A.SolveFactored(A.rhs);
      else if (!A.Solve()) return false;
    }
    return true;
  }
  const bool matrix = std::find(fresh.begin(), fresh.end(), 1) != fresh.end();
  id.schur_rhs.setZero();
  for (int i = 0; i < nl; ++i)
    if (!EliminateInterior(v, i, fresh[i])) return false;
  if (matrix) id.body_schur.setZero();
  for (int k = 0; k < static_cast<int>(id.bodies.size()); ++k)
    AssembleBody(v, k, c, h, v.body0() + 6 * k, matrix);
  if (matrix) {
    id.schur = id.body_schur;
    for (int i = 0; i < nl; ++i) id.schur += id.line_schur[i];
    id.schur_lu.compute(id.schur);
  }
  id.schur_x.noalias() = id.schur_lu.solve(id.schur_rhs);
  if (!id.schur_x.allFinite()) return false;
  for (int i = 0; i < nl; ++i) BackSubstitute(v, i);
  return true;
}

// The largest of a pose change's translation and its turns times the arm [m].
double PoseSize(const Vec6& d, double arm) {
  return std::max(d.head<3>().lpNorm<Eigen::Infinity>(), arm * d.tail<3>().lpNorm<Eigen::Infinity>());
}

// The island through the adaptive loop (implicit_stages.h).
struct CoupledStepper {
  IslandView v;
  const Inputs& in;
  GeneralizedAlpha c;

  int lines() const { return v.lines(); }
  double& Time() { return v.id.t; }
  double& ProposedStep() { return v.id.proposed_step; }
  long& Rejected() { return v.id.stats.rejected; }
  int WorstLink() const { return WorstLinkOf(nullptr); }
  double handed_off = 0;  // the step it left to explicit ones [s]
  // A solved step that snaps a line's link taut too fast for it, with a load that matters
  // (explicit_snaps.h): left to the island's explicit steps.
  bool HandsOff(double h) {
    if (!(v.id.snap_window > 0)) return false;
    for (int i = 0; i < lines(); ++i)
      if (StepsThroughSnaps(v.L(i)) && SnapsUnresolved(v.M(i), v.L(i), h)) {
        handed_off = h;
        return true;
      }
    return false;
  }
  double NextKink(double t) const {
    double kink = std::numeric_limits<double>::infinity();
    if (!ClockAsScene(in)) return kink;
    for (int i : v.isl.lines)
      for (int at : v.model.line_points[i]) {
        const Point& p = v.model.points[at];
        if (p.kind == PointKind::kMoved) kink = std::min(kink, p.motion.NextKink(t));
        if (p.on_body < 0) continue;
        const BodySpec& b = v.model.bodies[p.on_body];
        kink = std::min({kink, b.motion.NextKink(t), b.turn.NextKink(t)});
      }
    return kink;
  }
  // The most stretched link of the island's lines (its index in its line; its line, the
  // island's index of it, in `line`).
  int WorstLinkOf(int* line) const {
    int worst = 0;
    double stretch = 0;
    for (int i = 0; i < lines(); ++i) {
      const int k = cablefilm::WorstLink(v.M(i), v.L(i));
      const double r = v.L(i).forces.geometry.length[k] / v.M(i).line.rest_length[k];
      if (r > stretch) {
        stretch = r, worst = k;
        if (line) *line = i;
      }
    }
    return worst;
  }
  double Error(double h) const {
    double e = 0;
    for (int i = 0; i < lines(); ++i) e = std::max(e, LocalError(v.M(i), v.L(i), c, h));
    // A free body's, as a station's (implicit_stages.cpp, LocalError).
    for (int k = 0; k < static_cast<int>(v.id.bodies.size()); ++k) {
      const BodyMotion& b = v.body(k);
      e = std::max(e, h * h * std::abs(c.beta - 1.0 / 6.0) * PoseSize(b.ta - b.a, b.arm));
    }
    return e;
  }
  void Accept(double h) {
    for (int i = 0; i < lines(); ++i) SettleLandings(v.M(i), v.L(i), h);
    if (v.model.env.seabed.present && v.shared() > 0) {
      // The owner's landing decides a shared station's; the others' tensions see it (their
      // axial damping).
      SyncCoupled(v, true);
      for (int i = 0; i < lines(); ++i)
        ComputeTensions(v.M(i), v.L(i).forces.geometry, v.L(i).scratch.v, v.L(i).forces.tension);
    }
    for (int i = 0; i < lines(); ++i) Commit(v.M(i), v.L(i), h);
    for (int k = 0; k < static_cast<int>(v.id.bodies.size()); ++k) {
      BodyMotion& b = v.body(k);
      b.q = b.tq;
      b.v = b.tv;
      b.a = b.ta;
      b.abar = b.tabar;
    }
    v.id.t += h;
    ++v.id.stats.steps;
  }
  // The largest correction that the solved system holds, over its tolerance (a line's, a
  // body's), before it is applied.
  double CorrectionSize() const {
    double size = 0;
    for (int i = 0; i < lines(); ++i)
      size = std::max(size, cablefilm::CorrectionSize(v.M(i), v.L(i)) /
                                v.L(i).scratch.newton_tolerance);
    for (int k = 0; k < static_cast<int>(v.id.bodies.size()); ++k)
      size = std::max(size, PoseSize(v.id.schur_x.segment<6>(v.body0() + 6 * k), v.body(k).arm) /
                                v.id.newton_tolerance);
    return size;
  }
  bool Solve(double h) {
    IslandData& id = v.id;
    for (int i = 0; i < lines(); ++i) PredictStep(v.M(i), v.L(i), in, c, h);
    for (int k = 0; k < static_cast<int>(id.bodies.size()); ++k) {
      BodyMotion& b = v.body(k);
      b.tq = b.q + h * b.v + 0.5 * h * h * b.abar;
    }
    SyncCoupled(v, false);
    const double kv = c.VelocityPerPosition(h);  // d v / d x [1/s]
    // The corrections measured against their tolerances (a line's, a body's): converged at 1.
    NewtonConvergence newton(1.0);
    // Per line: whether this iteration's matrix is assembled anew (else its last one's factors
    // and share of the dense system), and its last correction over its tolerance. Each line
    // keeps its own: a touchdown or a snap on one leg made every leg's matrix anew (a quarter
    // of a spread mooring's fresh matrices).
    std::vector<char>& fresh = id.fresh;
    std::vector<double>& last = id.last_correction;
    std::fill(fresh.begin(), fresh.end(), 1);
    std::fill(last.begin(), last.end(), 0.0);
    auto all_fresh = [&] { return std::find(fresh.begin(), fresh.end(), 0) == fresh.end(); };
    for (int it = 1; it <= kMaxNewtonIterations; ++it) {
      for (int i = 0; i < lines(); ++i)
        if (!AssembleNewton(v.M(i), v.L(i), c, h, fresh[i])) {
          fresh[i] = 1;  // its kept matrix no longer holds (a link slack or taut): a new one
          AssembleNewton(v.M(i), v.L(i), c, h, true);
        }
      for (int i = 0; i < lines(); ++i) {
        if (fresh[i]) ClearSnappingLinks(v.L(i));
        KeepResidual(v.L(i));
      }
      if (!SolveCoupled(v, c, h, fresh)) return false;
      bool kept_snaps = false;  // a kept matrix's step snaps a slack link taut
      for (int i = 0; i < lines(); ++i)
        if (!fresh[i] && FindSnappingLinks(v.M(i), v.L(i))) kept_snaps = true;
      if (!all_fresh() && (kept_snaps || !(CorrectionSize() <= newton.last()))) {
        std::fill(fresh.begin(), fresh.end(), 1);  // the kept matrices do not contract here
        --it;                                      // (or miss a snap): new ones at this
        continue;                                  // iterate (and none was applied)
      }
      for (int pass = 0; pass < kSnappingPasses; ++pass) {
        bool found = false;
        for (int i = 0; i < lines(); ++i)
          if (fresh[i] && FindSnappingLinks(v.M(i), v.L(i))) found = true;
        if (!found) break;
        for (int i = 0; i < lines(); ++i) {
          if (fresh[i]) AddSnappingLinks(v.M(i), v.L(i));
          else RestoreResidual(v.L(i));
        }
        if (!SolveCoupled(v, c, h, fresh)) return false;
      }
      const bool was_fresh = all_fresh();
      double correction = 0;  // the largest, over its tolerance
      bool cut = false;       // a line's correction not applied whole
      for (int i = 0; i < lines(); ++i) {
        bool changed = false, line_cut = false;
        const double dx = ApplyCorrection(v.M(i), v.L(i), kv, &changed, &line_cut);
        cut = cut || line_cut;
        if (!std::isfinite(dx)) return false;
        const double size = dx / v.L(i).scratch.newton_tolerance;
        correction = std::max(correction, size);
        // A new matrix next unless its corrections contract (or are within its tolerance)
        // and no station crossed the seabed's level.
        const bool contracts = size <= 1 || size <= kFrozenJacobianRate * last[i] || last[i] == 0;
        fresh[i] = !KeepsNewtonMatrix(v.M(i)) || changed || !contracts;
        last[i] = size;
      }
      for (int k = 0; k < static_cast<int>(id.bodies.size()); ++k) {
        BodyMotion& b = v.body(k);
        const Vec6 dq = id.schur_x.segment<6>(v.body0() + 6 * k);
        b.tq += dq;
        const double size = PoseSize(dq, b.arm);
        if (!std::isfinite(size)) return false;
        correction = std::max(correction, size / id.newton_tolerance);
      }
      SyncCoupled(v, false);  // the seabed's landing clamp is the owner's
      if (cut) {
        newton.Cut();
      } else if (newton.Converged(correction)) {
        for (int i = 0; i < lines(); ++i) FinishSolve(v.M(i), v.L(i), c, h);
        for (int k = 0; k < static_cast<int>(id.bodies.size()); ++k)
          BodyKinematics(v.body(k), c, h);
        return true;
      }
      if (was_fresh && newton.Stalled()) return false;
      // The whole island's corrections not contracting (a body's, say): every matrix anew.
      if (newton.Stalled() || !(newton.rate() <= kFrozenJacobianRate))
        if (std::find(fresh.begin(), fresh.end(), 1) == fresh.end())
          std::fill(fresh.begin(), fresh.end(), 1);
    }
    return false;
  }
};

// Line `line`'s ends' couplings in island `isl`: a shared point's 3 unknowns, a free body's 6.
std::array<EndCoupling, 2> Couplings(const Model& model, const Island& isl, int line) {
  std::array<EndCoupling, 2> out;
  for (int e = 0; e < 2; ++e) {
    const int at = model.line_points[line][e];
    const Point& p = model.points[at];
    if (p.shared >= 0) {
      const auto s = std::find(isl.shared_points.begin(), isl.shared_points.end(), at);
      out[e].offset = kDim * static_cast<int>(s - isl.shared_points.begin());
      out[e].size = kDim;
    }
    if (p.kind != PointKind::kBody) continue;
    const auto b = std::find(isl.free_bodies.begin(), isl.free_bodies.end(), p.on_body);
    const int local = static_cast<int>(b - isl.free_bodies.begin());
    out[e].offset = kDim * static_cast<int>(isl.shared_points.size()) + 6 * local;
    out[e].size = 6;
    out[e].body = static_cast<int>(
        std::find(model.free_bodies.begin(), model.free_bodies.end(), p.on_body) -
        model.free_bodies.begin());
    out[e].local = p.local;
  }
  return out;
}

}  // namespace

Vec6 BodyOwnLoad(const Model& model, const BodySpec& body, const Vec6& q) {
  return GeneralizedLoad(q, BodyOwnLoads(body, q, model.env.fluid_density, model.env.gravity));
}

void PrepareCoupledIsland(const Model& model, int k, Data& d) {
  const Island& isl = model.islands[k];
  IslandData& id = d.islands[k];
  id.t = d.t;
  id.newton_tolerance = 1e300;
  PointMap point_map = PointMap::Zero();
  point_map.leftCols<3>().setIdentity();
  for (int line : isl.lines) {
    const LineData& ld = d.lines[line];
    const int n = ld.scratch.system.size();
    id.start_columns.emplace_back(n, Mat::Zero());
    id.end_columns.emplace_back(n, Mat::Zero());
    id.couplings.push_back(Couplings(model, isl, line));
    id.end_maps.push_back({point_map, point_map});
    if (ld.scratch.newton_tolerance > 0)
      id.newton_tolerance = std::min(id.newton_tolerance, ld.scratch.newton_tolerance);
    if (ld.scratch.max_substep > 0)
      id.max_substep = id.max_substep > 0 ? std::min(id.max_substep, ld.scratch.max_substep)
                                          : ld.scratch.max_substep;
    id.snap_window = std::max(id.snap_window, ld.scratch.snap_window);
  }
  id.start_time = d.t;
  for (int b : isl.free_bodies)
    id.bodies.push_back(static_cast<int>(
        std::find(model.free_bodies.begin(), model.free_bodies.end(), b) -
        model.free_bodies.begin()));
  const int nl = static_cast<int>(isl.lines.size());
  const int ns = kDim * static_cast<int>(isl.shared_points.size()) +
                 6 * static_cast<int>(isl.free_bodies.size());
  id.schur = id.body_schur = Eigen::MatrixXd::Zero(ns, ns);
  id.line_schur.assign(nl, Eigen::MatrixXd::Zero(ns, ns));
  id.fresh.assign(nl, 1);
  id.last_correction.assign(nl, 0.0);
  id.schur_rhs = id.schur_x = Eigen::VectorXd::Zero(ns);
  id.schur_lu = Eigen::PartialPivLU<Eigen::MatrixXd>(ns);
  id.body_rates.assign(isl.free_bodies.size(), Vec6::Zero());
  SyncCoupled(IslandView(model, k, d), false);  // the maps T at the rest poses
}

void SyncCoupledState(const Model& model, int k, Data& d) {
  const IslandView v(model, k, d);
  for (int p : v.isl.shared_points) {
    const LineEnd& o = model.owner(p);
    const LineData& w = d.lines[o.line];
    for (const LineEnd& e : model.points[p].ends) {
      if (e.line == o.line && e.station == o.station) continue;
      LineData& u = d.lines[e.line];
      u.state.x.col(e.station) = w.state.x.col(o.station);
      u.state.v.col(e.station) = w.state.v.col(o.station);
      u.a.col(e.station) = w.a.col(o.station);
      u.abar.col(e.station) = w.abar.col(o.station);
    }
  }
  for (int i = 0; i < v.lines(); ++i)
    for (int e = 0; e < 2; ++e) {
      const EndCoupling& c = v.id.couplings[i][e];
      if (c.body < 0) continue;
      const BodyMotion& b = d.bodies[c.body];
      const int j = e == 0 ? 0 : v.M(i).line.links;
      v.id.end_maps[i][e] = BodyPointJacobian(b.q, c.local);
      v.L(i).state.x.col(j) = BodyPoint(b.q, c.local);
      v.L(i).state.v.col(j) = v.id.end_maps[i][e] * b.v;
    }
}

void StepCoupledIsland(const Model& model, int k, Data& d, const Inputs& in, double dt) {
  const IslandView v(model, k, d);
  const StepOptions& o = v.L(0).options;
  IslandData& id = v.id;
  id.t = d.t;
  CoupledStepper stepper{v, in, GeneralizedAlphaCoefficients(o.rho_inf)};
  const double t_end = id.t + dt;
  try {
    // Implicit steps, and explicit ones through the snaps they hand off (explicit_snaps.h).
    double rest = dt;  // [s] (dt itself unless a window took part of it)
    for (;;) {
      if (id.t < id.explicit_until) {
        StepCoupledExplicitWindow(model, k, d, in, t_end);
        if (!(id.t < t_end)) break;
        rest = t_end - id.t;
      }
      if (AdaptiveImplicitSteps(stepper, o, in.stop, rest, dt)) break;
      EnterCoupledExplicitWindow(model, k, d, in, stepper.handed_off);
      rest = t_end - id.t;
    }
  } catch (const BlowUpError& e) {  // its link is the most stretched: name that link's line
    int line = 0;
    stepper.WorstLinkOf(&line);
    throw BlowUpError("line \"" + model.line_names[v.isl.lines[line]] + "\": " + e.what(),
                      e.time, e.station);
  }
  id.t = t_end;
}

void EnterCoupledExplicitWindow(const Model& model, int k, Data& d, const Inputs& in, double h) {
  const IslandView v(model, k, d);
  IslandData& id = v.id;
  // The state's forces (the trial step left its own in each line's) and its true
  // accelerations, coupled, which the explicit step carries.
  for (int i = 0; i < v.lines(); ++i) {
    LineData& l = v.L(i);
    ComputeAccelerations(v.M(i), in, l.water, l.state.t, l.state.x, l.state.v, l.forces, l.a);
  }
  for (int b = 0; b < v.bodies(); ++b) id.body_rates[b] = v.body(b).v;
  CoupleAccelerations(model, k, d, id.t, id.body_rates);
  id.explicit_until =
      ExplicitWindowEnd(id.t, h, id.snap_window, id.start_time, id.max_substep,
                        id.stats.explicit_steps, v.L(0).stats.newton_iterations);
  id.refinement = 0;
  id.quiet_time = 0;
  ++id.stats.snap_windows;
}

void StepCoupledExplicitWindow(const Model& model, int k, Data& d, const Inputs& in,
                               double t_end) {
  const IslandView v(model, k, d);
  IslandData& id = v.id;
  const ExplicitWindowSpan w =
      WindowSpan(id.t, t_end, id.snap_window, id.max_substep, &id.explicit_until);
  const long before = id.stats.steps;
  const double t0 = id.t;
  for (long i = 1; i <= w.pieces; ++i) {  // refined where links go slack or taut
    StepCoupledExplicit(model, k, d, in, w.h);
    id.t = i == w.pieces ? w.stop : t0 + static_cast<double>(i) * w.h;
    for (int l = 0; l < v.lines(); ++l) v.L(l).state.t = id.t;
  }
  id.stats.explicit_steps += id.stats.steps - before;
  if (id.t < id.explicit_until) return;
  // The implicit scheme starts afresh from the state, as at t = 0 (MakeData): its acceleration
  // memory the state's true accelerations, coupled.
  for (int i = 0; i < v.lines(); ++i) {
    LineData& l = v.L(i);
    ComputeAccelerations(v.M(i), in, l.water, l.state.t, l.state.x, l.state.v, l.forces, l.a);
  }
  for (int b = 0; b < v.bodies(); ++b) id.body_rates[b] = v.body(b).v;
  CoupleAccelerations(model, k, d, id.t, id.body_rates);
  for (int i = 0; i < v.lines(); ++i) {
    LineData& l = v.L(i);
    l.abar = l.abar_before = l.a;
    l.last_step = 0;
    l.smooth = false;
  }
  for (int b = 0; b < v.bodies(); ++b) {
    BodyMotion& m = v.body(b);
    m.abar = m.ta = m.tabar = m.a;
  }
  id.explicit_until = -1;
}

}  // namespace cablefilm
