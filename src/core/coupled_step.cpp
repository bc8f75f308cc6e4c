#include "core/coupled_step.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/end_loads.h"
#include "core/error.h"
#include "core/force_jacobian.h"
#include "core/implicit_stages.h"

namespace cablefilm {
namespace {

using Map36 = Eigen::Matrix<double, 3, 6>;

// Makes every copy of each shared station equal to its owner's trial position (`x`) or
// trial velocity and accelerations (`motion`); with `x`, puts each station on a free body
// where the body's trial pose puts its point.
void SyncCoupled(const Model& sys, Data& sd, bool motion) {
  for (int p : sys.shared_points) {
    const LineEnd& o = sys.owner(p);
    const Scratch& w = sd.lines[o.line].scratch;
    for (const LineEnd& e : sys.points[p].ends) {
      if (e.line == o.line && e.station == o.station) continue;
      Scratch& v = sd.lines[e.line].scratch;
      if (!motion) {
        v.x.col(e.station) = w.x.col(o.station);
        continue;
      }
      v.v.col(e.station) = w.v.col(o.station);
      v.a.col(e.station) = w.a.col(o.station);
      v.abar.col(e.station) = w.abar.col(o.station);
    }
  }
  if (motion) return;
  for (int i = 0; i < static_cast<int>(sd.lines.size()); ++i)
    for (int e = 0; e < 2; ++e) {
      const EndCoupling& c = sd.couplings[i][e];
      if (c.body < 0) continue;
      const int j = e == 0 ? 0 : sys.lines[i].line.links;
      sd.lines[i].scratch.x.col(j) = BodyPoint(sd.bodies[c.body].tq, c.local);
      sd.end_maps[i][e] = BodyPointJacobian(sd.bodies[c.body].tq, c.local);
    }
}

// Adds T_a^T S T_b to `schur`'s block of the unknowns of ends a and b.
void AddCoupledBlock(Eigen::MatrixXd& schur, const EndCoupling& ca, const Map36& Ta,
                     const EndCoupling& cb, const Map36& Tb, const Mat& S) {
  const Mat6 block = Ta.transpose() * S * Tb;
  schur.block(ca.offset, cb.offset, ca.size, cb.size) += block.topLeftCorner(ca.size, cb.size);
}

void AddCoupledRhs(Data& sd, const EndCoupling& c, const Map36& T, const Vec& r) {
  const Vec6 rows = T.transpose() * r;
  sd.schur_rhs.segment(c.offset, c.size) += rows.head(c.size);
}

// The correction of a coupled end station from the dense system's solution: T dq.
Vec CoupledCorrection(const Data& sd, const EndCoupling& c, const Map36& T) {
  Vec6 u = Vec6::Zero();
  u.head(c.size) = sd.schur_x.segment(c.offset, c.size);
  return T * u;
}

// Line i's share of the dense system: its interior eliminated (A_II^-1 for the right-hand side
// and for the columns coupling it to its coupled ends), the Schur complement rows of its
// coupled ends (into sd.line_schur[i]) added through their maps T. False when a pivot is
// singular. Without `matrix` the right-hand side alone, on the factors, columns and share of
// the last call with it.
bool EliminateInterior(Data& sd, int i, bool matrix) {
  BlockTridiagonal& A = sd.lines[i].scratch.system;
  std::vector<Mat>& zs = sd.start_columns[i];
  std::vector<Mat>& ze = sd.end_columns[i];
  const int n = A.size();
  const EndCoupling &cP = sd.couplings[i][0], &cQ = sd.couplings[i][1];
  const Map36 &TP = sd.end_maps[i][0], &TQ = sd.end_maps[i][1];
  const bool P = cP.size > 0, Q = cQ.size > 0;
  const int f = P ? 1 : 0, l = Q ? n - 2 : n - 1;  // the interior rows
  const bool interior = f <= l;
  Eigen::MatrixXd& S = sd.line_schur[i];
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
    AddCoupledRhs(sd, cP, TP, interior ? Vec(A.rhs[0] - A.upper[0] * A.rhs[f]) : A.rhs[0]);
    if (matrix) {
      AddCoupledBlock(S, cP, TP, cP, TP, interior ? Mat(A.diag[0] - A.upper[0] * zs[f]) : A.diag[0]);
      if (Q) AddCoupledBlock(S, cP, TP, cQ, TQ, interior ? Mat(-A.upper[0] * ze[f]) : A.upper[0]);
    }
  }
  if (Q) {  // row n - 1
    const int e = n - 1;
    AddCoupledRhs(sd, cQ, TQ, interior ? Vec(A.rhs[e] - A.lower[e] * A.rhs[l]) : A.rhs[e]);
    if (matrix) {
      AddCoupledBlock(S, cQ, TQ, cQ, TQ, interior ? Mat(A.diag[e] - A.lower[e] * ze[l]) : A.diag[e]);
      if (P) AddCoupledBlock(S, cQ, TQ, cP, TP, interior ? Mat(-A.lower[e] * zs[l]) : A.lower[e]);
    }
  }
  return true;
}

// Line i's corrections from the dense system's solution: x_B = T dq, x_I = y - Z x_B.
void BackSubstitute(Data& sd, int i) {
  BlockTridiagonal& A = sd.lines[i].scratch.system;
  const int n = A.size();
  const EndCoupling &cP = sd.couplings[i][0], &cQ = sd.couplings[i][1];
  const bool P = cP.size > 0, Q = cQ.size > 0;
  const Vec xP = P ? CoupledCorrection(sd, cP, sd.end_maps[i][0]) : Vec::Zero();
  const Vec xQ = Q ? CoupledCorrection(sd, cQ, sd.end_maps[i][1]) : Vec::Zero();
  const int f = P ? 1 : 0, l = Q ? n - 2 : n - 1;
  for (int r = f; r <= l; ++r) {
    if (P) A.rhs[r].noalias() -= sd.start_columns[i][r] * xP;
    if (Q) A.rhs[r].noalias() -= sd.end_columns[i][r] * xQ;
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

// A free body's own generalized load at a pose [N, N m]: weight, buoyancy, waterplane,
// constant loads.
Vec6 OwnLoad(const Model& sys, const BodySpec& body, const Vec6& q) {
  return GeneralizedLoad(q, BodyOwnLoads(body, q, sys.env.fluid_density, sys.env.gravity));
}

// Free body k's own rows of the dense system at its trial pose: the matrix
// ka M + kv dD/dv - dQ/dq and the residual Q + D - M a (its lines' rows come through their
// ends); without `matrix` the residual alone.
void AssembleBody(const Model& sys, Data& sd, int k, const GeneralizedAlpha& c,
                  double h, int offset, bool matrix) {
  BodyMotion& b = sd.bodies[k];
  const BodySpec& body = sys.bodies[sys.free_bodies[k]];
  BodyKinematics(b, c, h);
  const double ka = (1.0 - c.am) / ((1.0 - c.af) * c.beta * h * h);
  const double kv = c.VelocityPerPosition(h);
  const Mat6 M = BodyMassMatrix(body, b.tq);
  const Vec6 Q = OwnLoad(sys, body, b.tq);
  // The water at its reference point at the step's end (the lines' water of this step).
  const Vec flow = sd.lines.empty() ? Vec::Zero()
                                    : WaterVelocityAt(sys.lines[0], sd.lines[0].water,
                                                      b.tq.head<3>(), sd.t + h);
  sd.schur_rhs.segment<6>(offset) += Q + BodyDampingLoad(body, b.tv, flow) - M * b.ta;
  if (!matrix) return;  // its rows in sd.body_schur stay
  Mat6 K = ka * M;
  K.diagonal() -= kv * BodyDampingSlope(body, b.tv, flow);
  for (int col = 0; col < 6; ++col) {  // -dQ/dq by forward differences (a cheap closed form)
    Vec6 d = b.tq;
    const double step = 1e-7 * (col < 3 ? std::max(1.0, b.tq.head<3>().norm()) : 1.0);
    d[col] += step;
    K.col(col) -= (OwnLoad(sys, body, d) - Q) / step;
  }
  sd.body_schur.block<6, 6>(offset, offset) += K;
}

// Solves Newton's system of every line and free body, coupled at the shared stations and the
// bodies, into each line's system.rhs and the bodies' corrections (sd.schur_x). False when a
// pivot or the dense system is singular. A line whose `fresh` is 0 (a simplified Newton
// iteration) solves on the factors and share of the dense system of its last fresh one; the
// bodies' rows and the dense system's factors are made anew when any line's are.
bool SolveCoupled(const Model& sys, Data& sd, const GeneralizedAlpha& c, double h,
                  const std::vector<char>& fresh) {
  const int nl = static_cast<int>(sd.lines.size());
  if (sd.schur.rows() == 0) {
    for (int i = 0; i < nl; ++i) {
      BlockTridiagonal& A = sd.lines[i].scratch.system;
      if (!fresh[i]) A.SolveFactored(A.rhs);
      else if (!A.Solve()) return false;
    }
    return true;
  }
  const bool matrix = std::find(fresh.begin(), fresh.end(), 1) != fresh.end();
  sd.schur_rhs.setZero();
  for (int i = 0; i < nl; ++i)
    if (!EliminateInterior(sd, i, fresh[i])) return false;
  const int body0 = kDim * sys.shared_count();
  if (matrix) sd.body_schur.setZero();
  for (int k = 0; k < static_cast<int>(sd.bodies.size()); ++k)
    AssembleBody(sys, sd, k, c, h, body0 + 6 * k, matrix);
  if (matrix) {
    sd.schur = sd.body_schur;
    for (int i = 0; i < nl; ++i) sd.schur += sd.line_schur[i];
    sd.schur_lu.compute(sd.schur);
  }
  sd.schur_x.noalias() = sd.schur_lu.solve(sd.schur_rhs);
  if (!sd.schur_x.allFinite()) return false;
  for (int i = 0; i < static_cast<int>(sd.lines.size()); ++i) BackSubstitute(sd, i);
  return true;
}

// The largest of a pose change's translation and its turns times the arm [m].
double PoseSize(const Vec6& d, double arm) {
  return std::max(d.head<3>().lpNorm<Eigen::Infinity>(), arm * d.tail<3>().lpNorm<Eigen::Infinity>());
}

// The system through the adaptive loop (implicit_stages.h).
struct CoupledStepper {
  const Model& sys;
  Data& sd;
  const Inputs& in;
  GeneralizedAlpha c;

  int lines() const { return static_cast<int>(sd.lines.size()); }
  double& Time() { return sd.t; }
  double& ProposedStep() { return sd.proposed_step; }
  long& Rejected() { return sd.stats.rejected; }
  int WorstLink() const { return WorstLinkOf(nullptr); }
  bool HandsOff(double) const { return false; }  // a system's snaps: implicit steps
  double NextKink(double t) const {
    double kink = std::numeric_limits<double>::infinity();
    if (!ClockAsScene(in)) return kink;
    for (const Point& p : sys.points)
      if (p.kind == PointKind::kMoved) kink = std::min(kink, p.motion.NextKink(t));
    for (const BodySpec& b : sys.bodies)
      kink = std::min({kink, b.motion.NextKink(t), b.turn.NextKink(t)});
    return kink;
  }
  // The most stretched link of all lines (its index in its line; its line in `line`).
  int WorstLinkOf(int* line) const {
    int worst = 0;
    double stretch = 0;
    for (int i = 0; i < lines(); ++i) {
      const int k = cablefilm::WorstLink(sys.lines[i], sd.lines[i]);
      const double r = sd.lines[i].forces.geometry.length[k] / sys.lines[i].line.rest_length[k];
      if (r > stretch) {
        stretch = r, worst = k;
        if (line) *line = i;
      }
    }
    return worst;
  }
  double Error(double h) const {
    double e = 0;
    for (int i = 0; i < lines(); ++i) e = std::max(e, LocalError(sys.lines[i], sd.lines[i], c, h));
    // A free body's, as a station's (implicit_stages.cpp, LocalError).
    for (const BodyMotion& b : sd.bodies)
      e = std::max(e, h * h * std::abs(c.beta - 1.0 / 6.0) * PoseSize(b.ta - b.a, b.arm));
    return e;
  }
  void Accept(double h) {
    for (int i = 0; i < lines(); ++i) SettleLandings(sys.lines[i], sd.lines[i], h);
    if (sys.env.seabed.present && sys.shared_count() > 0) {
      // The owner's landing decides a shared station's; the others' tensions see it (their
      // axial damping).
      SyncCoupled(sys, sd, true);
      for (int i = 0; i < lines(); ++i)
        ComputeTensions(sys.lines[i], sd.lines[i].forces.geometry, sd.lines[i].scratch.v,
                        sd.lines[i].forces.tension);
    }
    for (int i = 0; i < lines(); ++i) Commit(sys.lines[i], sd.lines[i], h);
    for (BodyMotion& b : sd.bodies) {
      b.q = b.tq;
      b.v = b.tv;
      b.a = b.ta;
      b.abar = b.tabar;
    }
    sd.t += h;
    ++sd.stats.steps;
  }
  // The largest correction that the solved system holds, over its tolerance (a line's, a
  // body's), before it is applied.
  double CorrectionSize() const {
    double size = 0;
    for (int i = 0; i < lines(); ++i)
      size = std::max(size, cablefilm::CorrectionSize(sys.lines[i], sd.lines[i]) /
                                sd.lines[i].scratch.newton_tolerance);
    const int body0 = kDim * sys.shared_count();
    for (int k = 0; k < static_cast<int>(sd.bodies.size()); ++k)
      size = std::max(size, PoseSize(sd.schur_x.segment<6>(body0 + 6 * k), sd.bodies[k].arm) /
                                sd.newton_tolerance);
    return size;
  }
  bool Solve(double h) {
    for (int i = 0; i < lines(); ++i) PredictStep(sys.lines[i], sd.lines[i], in, c, h);
    for (BodyMotion& b : sd.bodies) b.tq = b.q + h * b.v + 0.5 * h * h * b.abar;
    SyncCoupled(sys, sd, false);
    const int body0 = kDim * sys.shared_count();
    const double kv = c.VelocityPerPosition(h);  // d v / d x [1/s]
    // The corrections measured against their tolerances (a line's, a body's): converged at 1.
    NewtonConvergence newton(1.0);
    // Per line: whether this iteration's matrix is assembled anew (else its last one's factors
    // and share of the dense system), and its last correction over its tolerance. Each line
    // keeps its own: a touchdown or a snap on one leg made every leg's matrix anew (a quarter
    // of a spread mooring's fresh matrices).
    std::vector<char>& fresh = sd.fresh;
    std::vector<double>& last = sd.last_correction;
    std::fill(fresh.begin(), fresh.end(), 1);
    std::fill(last.begin(), last.end(), 0.0);
    auto all_fresh = [&] { return std::find(fresh.begin(), fresh.end(), 0) == fresh.end(); };
    for (int it = 1; it <= kMaxNewtonIterations; ++it) {
      for (int i = 0; i < lines(); ++i)
        if (!AssembleNewton(sys.lines[i], sd.lines[i], c, h, fresh[i])) {
          fresh[i] = 1;  // its kept matrix no longer holds (a link slack or taut): a new one
          AssembleNewton(sys.lines[i], sd.lines[i], c, h, true);
        }
      for (int i = 0; i < lines(); ++i) {
        if (fresh[i]) ClearSnappingLinks(sd.lines[i]);
        KeepResidual(sd.lines[i]);
      }
      if (!SolveCoupled(sys, sd, c, h, fresh)) return false;
      bool kept_snaps = false;  // a kept matrix's step snaps a slack link taut
      for (int i = 0; i < lines(); ++i)
        if (!fresh[i] && FindSnappingLinks(sys.lines[i], sd.lines[i])) kept_snaps = true;
      if (!all_fresh() && (kept_snaps || !(CorrectionSize() <= newton.last()))) {
        std::fill(fresh.begin(), fresh.end(), 1);  // the kept matrices do not contract here
        --it;                                      // (or miss a snap): new ones at this
        continue;                                  // iterate (and none was applied)
      }
      for (int pass = 0; pass < kSnappingPasses; ++pass) {
        bool found = false;
        for (int i = 0; i < lines(); ++i)
          if (fresh[i] && FindSnappingLinks(sys.lines[i], sd.lines[i])) found = true;
        if (!found) break;
        for (int i = 0; i < lines(); ++i) {
          if (fresh[i]) AddSnappingLinks(sys.lines[i], sd.lines[i]);
          else RestoreResidual(sd.lines[i]);
        }
        if (!SolveCoupled(sys, sd, c, h, fresh)) return false;
      }
      const bool was_fresh = all_fresh();
      double correction = 0;  // the largest, over its tolerance
      bool cut = false;       // a line's correction not applied whole
      for (int i = 0; i < lines(); ++i) {
        bool changed = false, line_cut = false;
        const double dx = ApplyCorrection(sys.lines[i], sd.lines[i], kv, &changed, &line_cut);
        cut = cut || line_cut;
        if (!std::isfinite(dx)) return false;
        const double size = dx / sd.lines[i].scratch.newton_tolerance;
        correction = std::max(correction, size);
        // A new matrix next unless its corrections contract (or are within its tolerance)
        // and no station crossed the seabed's level.
        const bool contracts = size <= 1 || size <= kFrozenJacobianRate * last[i] || last[i] == 0;
        fresh[i] = !KeepsNewtonMatrix(sys.lines[i]) || changed || !contracts;
        last[i] = size;
      }
      for (int k = 0; k < static_cast<int>(sd.bodies.size()); ++k) {
        BodyMotion& b = sd.bodies[k];
        const Vec6 dq = sd.schur_x.segment<6>(body0 + 6 * k);
        b.tq += dq;
        const double size = PoseSize(dq, b.arm);
        if (!std::isfinite(size)) return false;
        correction = std::max(correction, size / sd.newton_tolerance);
      }
      SyncCoupled(sys, sd, false);  // the seabed's landing clamp is the owner's
      if (cut) {
        newton.Cut();
      } else if (newton.Converged(correction)) {
        for (int i = 0; i < lines(); ++i) FinishSolve(sys.lines[i], sd.lines[i], c, h);
        for (BodyMotion& b : sd.bodies) BodyKinematics(b, c, h);
        return true;
      }
      if (was_fresh && newton.Stalled()) return false;
      // The whole system's corrections not contracting (a body's, say): every matrix anew.
      if (newton.Stalled() || !(newton.rate() <= kFrozenJacobianRate))
        if (std::find(fresh.begin(), fresh.end(), 1) == fresh.end())
          std::fill(fresh.begin(), fresh.end(), 1);
    }
    return false;
  }
};

// Line i's ends' couplings: a shared point's 3 unknowns, a free body's 6.
std::array<EndCoupling, 2> Couplings(const Model& sys, int i) {
  std::array<EndCoupling, 2> out;
  for (int e = 0; e < 2; ++e) {
    const Point& p = sys.points[sys.line_points[i][e]];
    if (p.shared >= 0) {
      out[e].offset = kDim * p.shared;
      out[e].size = kDim;
    }
    if (p.kind != PointKind::kBody) continue;
    const int k = static_cast<int>(
        std::find(sys.free_bodies.begin(), sys.free_bodies.end(), p.on_body) -
        sys.free_bodies.begin());
    out[e].offset = kDim * sys.shared_count() + 6 * k;
    out[e].size = 6;
    out[e].body = k;
    out[e].local = p.local;
  }
  return out;
}

}  // namespace

Data MakeData(const Model& sys, const Inputs& in, const StepOptions& options,
                          const std::vector<State>& states) {
  if (options.scheme != Scheme::kImplicit)
    throw Error("a system of lines is stepped by the implicit scheme only");
  const int nl = static_cast<int>(sys.lines.size());
  if (static_cast<int>(states.size()) != nl)
    throw Error("MakeData: one state per line is needed");
  Data sd;
  sd.t = nl > 0 ? states[0].t : 0.0;
  sd.newton_tolerance = 1e300;
  for (int i = 0; i < nl; ++i) {
    sd.lines.push_back(MakeLineData(sys.lines[i], in, options, states[i]));
    const int n = sd.lines[i].scratch.system.size();
    sd.start_columns.emplace_back(n, Mat::Zero());
    sd.end_columns.emplace_back(n, Mat::Zero());
    sd.couplings.push_back(Couplings(sys, i));
    Map36 point_map = Map36::Zero();
    point_map.leftCols<3>().setIdentity();
    sd.end_maps.push_back({point_map, point_map});
    sd.newton_tolerance = std::min(sd.newton_tolerance, sd.lines[i].scratch.newton_tolerance);
  }
  for (int b : sys.free_bodies) {
    const BodySpec& body = sys.bodies[b];
    Vec6 inertia;
    inertia << Vec::Constant(body.mass), body.inertia;
    inertia += body.added_mass;
    if (!(inertia.minCoeff() > 0))
      throw Error("body \"" + body.name + "\" is free: to move in time it needs a mass and "
                  "moments of inertia (with its added mass, above 0 in each of its six degrees "
                  "of freedom)");
    BodyMotion m;
    m.q = m.tq = sys.body_poses[b];
    for (const Point& p : sys.points)
      if (p.on_body == b) m.arm = std::max(m.arm, p.local.norm());
    sd.bodies.push_back(m);
  }
  const int ns = kDim * sys.shared_count() + 6 * static_cast<int>(sys.free_bodies.size());
  sd.schur = sd.body_schur = Eigen::MatrixXd::Zero(ns, ns);
  sd.line_schur.assign(nl, Eigen::MatrixXd::Zero(ns, ns));
  sd.fresh.assign(nl, 1);
  sd.last_correction.assign(nl, 0.0);
  sd.schur_rhs = sd.schur_x = Eigen::VectorXd::Zero(ns);
  sd.schur_lu = Eigen::PartialPivLU<Eigen::MatrixXd>(ns);
  SyncCoupled(sys, sd, false);  // the maps T at the rest poses
  // A shared station's acceleration is that of its whole mass under all its forces.
  for (int p : sys.shared_points) {
    Mat M = Mat::Zero();
    Vec F = Vec::Zero();
    for (const LineEnd& e : sys.points[p].ends) {
      const LineData& d = sd.lines[e.line];
      M += StationInertia(sys.lines[e.line], d.forces.geometry, e.station);
      F += d.forces.force.col(e.station);
    }
    const Vec a = M.inverse() * F;
    for (const LineEnd& e : sys.points[p].ends) {
      sd.lines[e.line].a.col(e.station) = a;
      sd.lines[e.line].abar.col(e.station) = a;
    }
  }
  // A free body's from its mass and its stations' under its loads and theirs (zero at its
  // equilibrium, but for the dynamic terms a moving start would add).
  for (int k = 0; k < static_cast<int>(sd.bodies.size()); ++k) {
    BodyMotion& b = sd.bodies[k];
    const BodySpec& body = sys.bodies[sys.free_bodies[k]];
    Mat6 M = BodyMassMatrix(body, b.q);
    Vec6 Q = OwnLoad(sys, body, b.q);
    if (nl > 0)  // at rest in the water: the current's drag (the statics hold it)
      Q += BodyDampingLoad(body, b.v,
                           WaterVelocityAt(sys.lines[0], sd.lines[0].water, b.q.head<3>(), sd.t));
    for (int i = 0; i < nl; ++i)
      for (int e = 0; e < 2; ++e) {
        if (sd.couplings[i][e].body != k) continue;
        const Map36& T = sd.end_maps[i][e];
        const int j = e == 0 ? 0 : sys.lines[i].line.links;
        const LineData& d = sd.lines[i];
        M += T.transpose() * StationInertia(sys.lines[i], d.forces.geometry, j) * T;
        Q += T.transpose() * d.forces.force.col(j);
      }
    b.a = b.abar = b.ta = b.tabar = M.partialPivLu().solve(Q);
    for (int i = 0; i < nl; ++i)
      for (int e = 0; e < 2; ++e) {
        if (sd.couplings[i][e].body != k) continue;
        const int j = e == 0 ? 0 : sys.lines[i].line.links;
        sd.lines[i].a.col(j) = sd.lines[i].abar.col(j) = sd.end_maps[i][e] * b.a;
      }
  }
  return sd;
}

void Step(const Model& sys, Data& sd, const Inputs& in, double dt) {
  for (int i = 0; i < static_cast<int>(sd.lines.size()); ++i)
    UpdateWater(sys.lines[i], in, sd.t + 0.5 * dt, &sd.lines[i].water);
  const StepOptions& o = sd.lines.empty() ? StepOptions{} : sd.lines[0].options;
  CoupledStepper stepper{sys, sd, in, GeneralizedAlphaCoefficients(o.rho_inf)};
  try {
    AdaptiveImplicitSteps(stepper, o, in.stop, dt);
  } catch (const BlowUpError& e) {  // its link is the most stretched: name that link's line
    int line = 0;
    stepper.WorstLinkOf(&line);
    throw BlowUpError("line \"" + sys.line_names[line] + "\": " + e.what(), e.time, e.station);
  }
  for (int i = 0; i < static_cast<int>(sd.lines.size()); ++i) {
    try {
      CheckStateSane(sys.lines[i], sd.lines[i].state, sd.lines[i].forces.geometry.length);
    } catch (const BlowUpError& e) {
      throw BlowUpError("line \"" + sys.line_names[i] + "\": " + e.what(), e.time, e.station);
    }
  }
  for (int k = 0; k < static_cast<int>(sd.bodies.size()); ++k)
    if (!sd.bodies[k].q.allFinite() || !sd.bodies[k].v.allFinite())
      throw BlowUpError("body \"" + sys.bodies[sys.free_bodies[k]].name +
                            "\": its pose is not finite at t = " + std::to_string(sd.t) + " s",
                        sd.t, 0);
}

PointLoads::PointLoads(const Model& sys) {
  for (const LineModel& m : sys.lines) station_forces_.push_back(Points::Zero(kDim, m.stations()));
  const int np = static_cast<int>(sys.points.size());
  positions_ = forces_ = Points::Zero(kDim, np);
  for (int p = 0; p < np; ++p) positions_.col(p) = sys.points[p].motion.rest();
  body_poses_ = sys.body_poses;
  body_loads_.assign(sys.bodies.size(), Vec6::Zero());
}

void PointLoads::Compute(const Model& sys, const Data& sd, const Inputs& in) {
  forces_.setZero();
  for (int i = 0; i < static_cast<int>(sd.lines.size()); ++i) {
    const LineModel& m = sys.lines[i];
    const LineData& d = sd.lines[i];
    Points& f = station_forces_[i];
    ComputeStationForces(m, d.water, d.forces.geometry, d.forces.tension, d.state.v, f);
    for (int e = 0; e < 2; ++e) {
      const int p = sys.line_points[i][e];
      const int j = e == 0 ? 0 : m.line.links;
      positions_.col(p) = d.state.x.col(j);
      const PointKind kind = sys.points[p].kind;
      if (kind == PointKind::kFree) {
        forces_.col(p) += FreeEndPull(m, d.forces, e);
        continue;
      }
      Vec a = Vec::Zero();
      // A fixed point's is zero, unless the live view's offset carries it (inputs.h).
      if (kind == PointKind::kMoved || kind == PointKind::kFixed)
        a = EndAcceleration(m, in, j, d.state.t);
      if (kind == PointKind::kBody) a = d.a.col(j);
      forces_.col(p) += HeldEndLoad(m, d.forces.geometry, f, j, a);
    }
  }
  // The bodies: a free one's pose as stepped, a driven one's reference point and angles as
  // they move [m, rad].
  for (int b = 0; b < static_cast<int>(sys.bodies.size()); ++b) {
    const BodySpec& body = sys.bodies[b];
    if (body.kind != BodyKind::kDriven) continue;
    body_poses_[b].head<3>() = body.motion.Position(sd.t);
    if (body.turn.moves()) body_poses_[b].tail<3>() = body.turn.Position(sd.t);
  }
  for (int k = 0; k < static_cast<int>(sd.bodies.size()); ++k)
    body_poses_[sys.free_bodies[k]] = sd.bodies[k].q;
  for (int b = 0; b < static_cast<int>(sys.bodies.size()); ++b) {
    body_loads_[b].setZero();
    for (int p = 0; p < static_cast<int>(sys.points.size()); ++p)
      if (sys.points[p].on_body == b)
        body_loads_[b] += LoadAbout(body_poses_[b].head<3>(), positions_.col(p), forces_.col(p));
  }
}

}  // namespace cablefilm
