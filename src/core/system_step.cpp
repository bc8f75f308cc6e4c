#include "core/system_step.h"

#include <cmath>
#include <string>

#include "core/error.h"
#include "core/force_jacobian.h"
#include "core/implicit_stages.h"

namespace cablefilm {
namespace {

// Makes every copy of each shared station equal to its owner's trial position (`x`) or
// trial velocity and accelerations (`motion`).
void SyncShared(const SystemModel& sys, SystemData& sd, bool motion) {
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
}

// Line i's share of the shared stations' system: its interior eliminated (A_II^-1 for the
// right-hand side and for the columns coupling it to its shared ends), the Schur complement
// rows of its shared ends added. False when a pivot is singular.
bool EliminateInterior(const SystemModel& sys, SystemData& sd, int i) {
  BlockTridiagonal& A = sd.lines[i].scratch.system;
  std::vector<Mat>& zs = sd.start_columns[i];
  std::vector<Mat>& ze = sd.end_columns[i];
  const int n = A.size();
  const int P = sys.shared_end(i, 0), Q = sys.shared_end(i, 1);
  const int f = P >= 0 ? 1 : 0, l = Q >= 0 ? n - 2 : n - 1;  // the interior rows
  const bool interior = f <= l;
  if (interior) {
    if (!A.Factor(f, l)) return false;
    A.SolveFactored(A.rhs);
    if (P >= 0) {
      for (int r = f; r <= l; ++r) zs[r].setZero();
      zs[f] = A.lower[f];
      A.SolveFactored(zs);
    }
    if (Q >= 0) {
      for (int r = f; r <= l; ++r) ze[r].setZero();
      ze[l] = A.upper[l];
      A.SolveFactored(ze);
    }
  }
  auto block = [&](int a, int b) { return sd.schur.block<kDim, kDim>(kDim * a, kDim * b); };
  auto rhs = [&](int a) { return sd.schur_rhs.segment<kDim>(kDim * a); };
  if (P >= 0) {  // row 0
    block(P, P) += interior ? Mat(A.diag[0] - A.upper[0] * zs[f]) : A.diag[0];
    rhs(P) += interior ? Vec(A.rhs[0] - A.upper[0] * A.rhs[f]) : A.rhs[0];
    if (Q >= 0) block(P, Q) += interior ? Mat(-A.upper[0] * ze[f]) : A.upper[0];
  }
  if (Q >= 0) {  // row n - 1
    const int e = n - 1;
    block(Q, Q) += interior ? Mat(A.diag[e] - A.lower[e] * ze[l]) : A.diag[e];
    rhs(Q) += interior ? Vec(A.rhs[e] - A.lower[e] * A.rhs[l]) : A.rhs[e];
    if (P >= 0) block(Q, P) += interior ? Mat(-A.lower[e] * zs[l]) : A.lower[e];
  }
  return true;
}

// Line i's corrections from the shared stations' (sd.schur_x): x_I = y - Z x_B.
void BackSubstitute(const SystemModel& sys, SystemData& sd, int i) {
  BlockTridiagonal& A = sd.lines[i].scratch.system;
  const int n = A.size();
  const int P = sys.shared_end(i, 0), Q = sys.shared_end(i, 1);
  const int f = P >= 0 ? 1 : 0, l = Q >= 0 ? n - 2 : n - 1;
  for (int r = f; r <= l; ++r) {
    if (P >= 0) A.rhs[r].noalias() -= sd.start_columns[i][r] * sd.schur_x.segment<kDim>(kDim * P);
    if (Q >= 0) A.rhs[r].noalias() -= sd.end_columns[i][r] * sd.schur_x.segment<kDim>(kDim * Q);
  }
  if (P >= 0) A.rhs[0] = sd.schur_x.segment<kDim>(kDim * P);
  if (Q >= 0) A.rhs[n - 1] = sd.schur_x.segment<kDim>(kDim * Q);
}

// Solves Newton's system of every line, coupled at the shared stations, into each line's
// system.rhs. False when a pivot or the shared stations' system is singular.
bool SolveCoupled(const SystemModel& sys, SystemData& sd) {
  if (sys.shared_count() == 0) {
    for (Data& d : sd.lines)
      if (!d.scratch.system.Solve()) return false;
    return true;
  }
  sd.schur.setZero();
  sd.schur_rhs.setZero();
  for (int i = 0; i < static_cast<int>(sd.lines.size()); ++i)
    if (!EliminateInterior(sys, sd, i)) return false;
  sd.schur_lu.compute(sd.schur);
  sd.schur_x.noalias() = sd.schur_lu.solve(sd.schur_rhs);
  if (!sd.schur_x.allFinite()) return false;
  for (int i = 0; i < static_cast<int>(sd.lines.size()); ++i) BackSubstitute(sys, sd, i);
  return true;
}

// The system through the adaptive loop (implicit_stages.h).
struct SystemStepper {
  const SystemModel& sys;
  SystemData& sd;
  const Inputs& in;
  GeneralizedAlpha c;

  int lines() const { return static_cast<int>(sd.lines.size()); }
  double& Time() { return sd.t; }
  double& ProposedStep() { return sd.proposed_step; }
  long& Rejected() { return sd.stats.rejected; }
  int WorstLink() const {
    // The most stretched link of all lines (its index in its line).
    int worst = 0;
    double stretch = 0;
    for (int i = 0; i < lines(); ++i) {
      const int k = cablefilm::WorstLink(sys.lines[i], sd.lines[i]);
      const double r = sd.lines[i].forces.geometry.length[k] / sys.lines[i].line.rest_length[k];
      if (r > stretch) stretch = r, worst = k;
    }
    return worst;
  }
  double Error(double h) const {
    double e = 0;
    for (int i = 0; i < lines(); ++i) e = std::max(e, LocalError(sys.lines[i], sd.lines[i], c, h));
    return e;
  }
  void Accept(double h) {
    for (int i = 0; i < lines(); ++i) SettleLandings(sys.lines[i], sd.lines[i], h);
    if (sys.env.seabed.present && sys.shared_count() > 0) {
      // The owner's landing decides a shared station's; the others' tensions see it (their
      // axial damping).
      SyncShared(sys, sd, true);
      for (int i = 0; i < lines(); ++i)
        ComputeTensions(sys.lines[i], sd.lines[i].forces.geometry, sd.lines[i].scratch.v,
                        sd.lines[i].forces.tension);
    }
    for (int i = 0; i < lines(); ++i) Commit(sys.lines[i], sd.lines[i], h);
    sd.t += h;
    ++sd.stats.steps;
  }
  bool Solve(double h) {
    for (int i = 0; i < lines(); ++i) PredictStep(sys.lines[i], sd.lines[i], in, c, h);
    for (int it = 1; it <= kMaxNewtonIterations; ++it) {
      for (int i = 0; i < lines(); ++i) AssembleNewton(sys.lines[i], sd.lines[i], c, h);
      if (!SolveCoupled(sys, sd)) return false;
      bool converged = true;
      for (int i = 0; i < lines(); ++i) {
        const double dx = ApplyCorrection(sys.lines[i], sd.lines[i]);
        if (!std::isfinite(dx)) return false;
        converged = converged && dx <= sd.lines[i].scratch.newton_tolerance;
      }
      SyncShared(sys, sd, false);  // the seabed's landing clamp is the owner's
      if (converged) {
        for (int i = 0; i < lines(); ++i) FinishSolve(sys.lines[i], sd.lines[i], c, h);
        return true;
      }
    }
    return false;
  }
};

}  // namespace

SystemData MakeSystemData(const SystemModel& sys, const Inputs& in, const StepOptions& options,
                          const std::vector<State>& states) {
  if (options.scheme != Scheme::kImplicit)
    throw Error("a system of lines is stepped by the implicit scheme only");
  const int nl = static_cast<int>(sys.lines.size());
  if (static_cast<int>(states.size()) != nl)
    throw Error("MakeSystemData: one state per line is needed");
  SystemData sd;
  sd.t = nl > 0 ? states[0].t : 0.0;
  for (int i = 0; i < nl; ++i) {
    sd.lines.push_back(MakeData(sys.lines[i], in, options, states[i]));
    const int n = sd.lines[i].scratch.system.size();
    sd.start_columns.emplace_back(n, Mat::Zero());
    sd.end_columns.emplace_back(n, Mat::Zero());
  }
  const int ns = kDim * sys.shared_count();
  sd.schur = Eigen::MatrixXd::Zero(ns, ns);
  sd.schur_rhs = sd.schur_x = Eigen::VectorXd::Zero(ns);
  sd.schur_lu = Eigen::PartialPivLU<Eigen::MatrixXd>(ns);
  // A shared station's acceleration is that of its whole mass under all its forces.
  for (int p : sys.shared_points) {
    Mat M = Mat::Zero();
    Vec F = Vec::Zero();
    for (const LineEnd& e : sys.points[p].ends) {
      const Data& d = sd.lines[e.line];
      M += StationInertia(sys.lines[e.line], d.forces.geometry, e.station);
      F += d.forces.force.col(e.station);
    }
    const Vec a = M.inverse() * F;
    for (const LineEnd& e : sys.points[p].ends) {
      sd.lines[e.line].a.col(e.station) = a;
      sd.lines[e.line].abar.col(e.station) = a;
    }
  }
  return sd;
}

void StepSystem(const SystemModel& sys, SystemData& sd, const Inputs& in, double dt) {
  for (int i = 0; i < static_cast<int>(sd.lines.size()); ++i)
    UpdateWater(sys.lines[i], in, sd.t + 0.5 * dt, &sd.lines[i].water);
  const StepOptions& o = sd.lines.empty() ? StepOptions{} : sd.lines[0].options;
  SystemStepper stepper{sys, sd, in, GeneralizedAlphaCoefficients(o.rho_inf)};
  AdaptiveImplicitSteps(stepper, o.tolerance, in.stop, dt);
  for (int i = 0; i < static_cast<int>(sd.lines.size()); ++i) {
    try {
      CheckStateSane(sys.lines[i], sd.lines[i].state, sd.lines[i].forces.geometry.length);
    } catch (const BlowUpError& e) {
      throw BlowUpError("line \"" + sys.line_names[i] + "\": " + e.what(), e.time, e.station);
    }
  }
}

PointLoads::PointLoads(const SystemModel& sys) {
  for (const Model& m : sys.lines) station_forces_.push_back(Points::Zero(kDim, m.stations()));
  const int np = static_cast<int>(sys.points.size());
  positions_ = forces_ = Points::Zero(kDim, np);
  for (int p = 0; p < np; ++p) positions_.col(p) = sys.points[p].motion.rest();
}

void PointLoads::Compute(const SystemModel& sys, const SystemData& sd, const Inputs& in) {
  forces_.setZero();
  for (int i = 0; i < static_cast<int>(sd.lines.size()); ++i) {
    const Model& m = sys.lines[i];
    const Data& d = sd.lines[i];
    Points& f = station_forces_[i];
    ComputeStationForces(m, d.water, d.forces.geometry, d.forces.tension, d.state.v, f);
    for (int e = 0; e < 2; ++e) {
      const int p = sys.line_points[i][e];
      const int j = e == 0 ? 0 : m.line.links;
      positions_.col(p) = d.state.x.col(j);
      if (sys.points[p].kind == PointKind::kFree) {
        const int k = e == 0 ? 0 : m.line.links - 1;  // the end link
        const Vec pull = d.forces.tension[k] * d.forces.geometry.tangent.col(k);
        forces_.col(p) += e == 0 ? pull : Vec(-pull);
        continue;
      }
      Vec a = Vec::Zero();
      if (sys.points[p].kind == PointKind::kMoved) a = EndAcceleration(m, in, j, d.state.t);
      forces_.col(p) += f.col(j) - StationInertia(m, d.forces.geometry, j) * a;
    }
  }
}

}  // namespace cablefilm
