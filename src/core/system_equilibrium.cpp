#include "core/system_equilibrium.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"
#include "core/forces.h"

namespace cablefilm {
namespace {

// The force on station j of a line at rest in its scene's water [N] (tension, weight,
// buoyancy, the current's drag, the seabed).
Vec StaticStationForce(const Model& m, const State& s, int j) {
  const Water water = SceneWater(m);
  ForceWorkspace ws(m.line.links);
  ComputeGeometry(m, water, 0.0, s.x, ws.geometry);
  ComputeHookeTensions(m, ws.geometry, ws.tension);
  ComputeStationForces(m, water, ws.geometry, ws.tension, Points::Zero(kDim, m.stations()),
                       ws.force);
  return ws.force.col(j);
}

// The lines with their shared ends held at the shared points' positions X (kDim per point),
// and their equilibria.
class HeldLines {
 public:
  HeldLines(const SystemModel& sys, const SystemEquilibriumOptions& options)
      : sys_(sys), models_(sys.lines), states_(sys.lines.size()), reports_(sys.lines.size()) {
    line_options_.cancel = options.cancel;
  }

  static constexpr int kAll = -1;     // every line
  static constexpr int kShared = -2;  // the lines that end at a shared point

  // Moves the shared points to X and solves the lines that end at `point` (or kAll, kShared).
  void Solve(const Eigen::VectorXd& X, int point) {
    for (int i = 0; i < static_cast<int>(models_.size()); ++i) {
      const int P = sys_.shared_end(i, 0), Q = sys_.shared_end(i, 1);
      if (point >= 0 && P != point && Q != point) continue;
      if (point == kShared && P < 0 && Q < 0) continue;
      if (P >= 0) models_[i].ends.start = EndMotion::Fixed(X.segment<kDim>(kDim * P));
      if (Q >= 0) models_[i].ends.end = EndMotion::Fixed(X.segment<kDim>(kDim * Q));
      try {
        states_[i] = SolveHeld(i);
      } catch (const CancelledError&) {
        throw;
      } catch (const Error& e) {
        throw Error("line \"" + sys_.line_names[i] + "\": no static equilibrium: " + e.what());
      }
    }
  }

  // The net force on each shared point [N], kDim per point.
  Eigen::VectorXd Residual() const {
    Eigen::VectorXd R = Eigen::VectorXd::Zero(kDim * sys_.shared_count());
    for (int p : sys_.shared_points)
      for (const LineEnd& e : sys_.points[p].ends)
        R.segment<kDim>(kDim * sys_.points[p].shared) +=
            StaticStationForce(models_[e.line], states_[e.line], e.station);
    return R;
  }

  const std::vector<State>& states() const { return states_; }
  const std::vector<EquilibriumReport>& reports() const { return reports_; }
  void Restore(const std::vector<State>& states) { states_ = states; }

 private:
  // Line i's equilibrium: from its last one moved with its ends (warm), or when there is none
  // or that fails, from the first guess of a single line.
  State SolveHeld(int i) {
    if (states_[i].x.size() != 0) {
      line_options_.warm_start = true;
      try {
        return SolveEquilibrium(models_[i], MovedGuess(i), &reports_[i], line_options_);
      } catch (const CancelledError&) {
        throw;
      } catch (const Error&) {
        // From the first guess instead.
      }
    }
    line_options_.warm_start = false;
    return SolveEquilibrium(models_[i], EquilibriumGuess(models_[i]), &reports_[i], line_options_);
  }

  // The last equilibrium of line i with its held ends moved to their new positions, the
  // stations between shifted in proportion to their arc length.
  Points MovedGuess(int i) const {
    const Model& m = models_[i];
    Points x = states_[i].x;
    const int s = m.line.links;
    const Vec d0 = m.ends.start.prescribed() ? Vec(m.ends.start.rest() - x.col(0)) : Vec::Zero();
    const Vec d1 = m.ends.end.prescribed() ? Vec(m.ends.end.rest() - x.col(s)) : Vec::Zero();
    const double L = m.line.total_length();
    for (int j = 0; j <= s; ++j) {
      const double f = m.line.arc_length[j] / L;
      x.col(j) += (1.0 - f) * d0 + f * d1;
    }
    return x;
  }

  const SystemModel& sys_;
  std::vector<Model> models_;
  std::vector<State> states_;
  std::vector<EquilibriumReport> reports_;
  EquilibriumOptions line_options_;
};

// The shortest line at each shared point [m]: how far a Newton step may move it.
Eigen::VectorXd StepLimits(const SystemModel& sys) {
  Eigen::VectorXd limit = Eigen::VectorXd::Constant(sys.shared_count(), 1e300);
  for (int p : sys.shared_points)
    for (const LineEnd& e : sys.points[p].ends)
      limit[sys.points[p].shared] =
          std::min(limit[sys.points[p].shared], sys.lines[e.line].line.total_length());
  return limit;
}

}  // namespace

Points SharedPointResiduals(const SystemModel& sys, const std::vector<State>& states) {
  Points R = Points::Zero(kDim, sys.shared_count());
  for (int p : sys.shared_points)
    for (const LineEnd& e : sys.points[p].ends)
      R.col(sys.points[p].shared) += StaticStationForce(sys.lines[e.line], states[e.line], e.station);
  return R;
}

std::vector<State> SolveSystemEquilibrium(const SystemModel& sys, SystemEquilibriumReport* report,
                                          const SystemEquilibriumOptions& options) {
  const int n = kDim * sys.shared_count();
  Eigen::VectorXd X(n);
  for (int p : sys.shared_points) {
    const LineEnd& o = sys.owner(p);
    const Model& m = sys.lines[o.line];
    X.segment<kDim>(kDim * sys.points[p].shared) =
        (o.station == 0 ? m.ends.start : m.ends.end).rest();
  }
  HeldLines lines(sys, options);
  lines.Solve(X, HeldLines::kAll);
  double scale = 0;
  for (const Model& m : sys.lines) scale += StaticForceScale(m);
  SystemEquilibriumReport r;
  r.force_scale = scale;
  Eigen::VectorXd R = lines.Residual();
  const Eigen::VectorXd limit = StepLimits(sys);
  auto norm = [](const Eigen::VectorXd& v) { return v.size() ? v.lpNorm<Eigen::Infinity>() : 0.0; };
  // Broyden's method: the Jacobian dR/dX by forward differences (a point at a time, each
  // column re-solving that point's lines) at the start and whenever a step fails to reduce the
  // out-of-balance force, and updated by rank one after each step that does (the held lines'
  // solves are the cost: one per step instead of kDim + 1 per point).
  Eigen::MatrixXd J(n, n);
  bool fresh = false;
  auto differences = [&] {
    const std::vector<State> base = lines.states();
    for (int p = 0; p < sys.shared_count(); ++p) {
      const double delta = 1e-6 * limit[p];
      for (int k = 0; k < kDim; ++k) {
        Eigen::VectorXd Xd = X;
        Xd[kDim * p + k] += delta;
        lines.Solve(Xd, p);
        J.col(kDim * p + k) = (lines.Residual() - R) / delta;
        lines.Restore(base);
      }
      lines.Solve(X, p);
    }
    fresh = true;
  };
  differences();
  while (norm(R) > options.tolerance * scale) {
    if (++r.iterations > options.max_iterations) {
      std::ostringstream os;
      os << "the shared points of the system do not balance after " << options.max_iterations
         << " Newton iterations: out-of-balance force " << norm(R) << " N against a load of "
         << scale << " N";
      throw Error(os.str());
    }
    ThrowIfCancelled(options.cancel, "the system's static equilibrium");
    Eigen::VectorXd dX = J.partialPivLu().solve(-R);
    for (int p = 0; p < sys.shared_count(); ++p) {  // at most a tenth of the shortest line
      const double size = dX.segment<kDim>(kDim * p).norm(), most = 0.1 * limit[p];
      if (size > most) dX *= most / size;
    }
    const std::vector<State> base = lines.states();
    lines.Solve(X + dX, HeldLines::kShared);
    Eigen::VectorXd Rt = lines.Residual();
    if (!(norm(Rt) < norm(R)) && !fresh) {  // an old Jacobian: a fresh one, and again
      lines.Restore(base);
      lines.Solve(X, HeldLines::kShared);
      differences();
      --r.iterations;
      continue;
    }
    // Backtracking: the step halved until the out-of-balance force falls.
    double step = 1;
    for (int tries = 0; !(norm(Rt) < norm(R)) && tries < 12; ++tries) {
      lines.Restore(base);
      step *= 0.5;
      lines.Solve(X + step * dX, HeldLines::kShared);
      Rt = lines.Residual();
    }
    const Eigen::VectorXd s = step * dX;
    J += (Rt - R - J * s) * s.transpose() / s.squaredNorm();
    fresh = false;
    X += s;
    R = Rt;
  }
  r.residual = norm(R);
  r.lines = lines.reports();
  if (report) *report = r;
  return lines.states();
}

}  // namespace cablefilm
