#include "core/line_equilibrium.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "core/block_tridiagonal.h"
#include "core/constraints.h"
#include "core/error.h"
#include "core/force_jacobian.h"
#include "core/forces.h"

namespace cablefilm {
namespace {

double MinAxialStiffness(const LineModel& m) { return m.line.axial_stiffness.minCoeff(); }

// Stations hanging from the prescribed end along the net weight, each link stretched by the
// weight it carries (exact for a vertical chain in still fluid).
Points HangingGuess(const LineModel& m) {
  const bool from_start = m.ends.start.prescribed();
  const Vec top = from_start ? m.ends.start.Position(0) : m.ends.end.Position(0);
  const double total = m.line.net_weight.sum();
  Vec dir = Vec::Zero();  // down, or up for a buoyant line
  dir[kVertical] = total >= 0 ? -1.0 : 1.0;
  Points x(kDim, m.stations());
  const int s = m.line.links;
  double carried = 0, along = 0;  // weight below the link [N], stretched length so far [m]
  // Walk from the free end towards the prescribed one, accumulating the carried weight.
  Eigen::VectorXd stretched(s);
  for (int k = 0; k < s; ++k) {
    const int link = from_start ? s - 1 - k : k;
    const int below = from_start ? link + 1 : link;
    carried += m.line.net_weight[below];
    stretched[link] = m.line.rest_length[link] * (1.0 + std::abs(carried) / m.line.axial_stiffness[link]);
  }
  for (int k = 0; k <= s; ++k) {
    const int j = from_start ? k : s - k;
    x.col(j) = top + along * dir;
    if (k < s) along += stretched[from_start ? j : j - 1];
  }
  return x;
}

// The horizontal distance from a to b [m] and the horizontal unit vector from a towards b (along
// x when b is straight above or below a).
double HorizontalSpan(const Vec& a, const Vec& b, Vec* direction) {
  const Vec d = HorizontalPart(b - a);
  const double span = d.norm();
  *direction = span > 0 ? Vec(d / span) : Vec(1.0, 0.0, 0.0);
  return span;
}

Vec Up() {
  Vec up = Vec::Zero();
  up[kVertical] = 1.0;
  return up;
}

// Stations on the catenary of length `length` through a and b, in the vertical plane through
// them, at arc length proportional to the unstretched arc length; `sag_up` flips it for a
// buoyant cable.
Points CatenaryGuess(const LineModel& m, const Vec& a, const Vec& b, double length, bool sag_up) {
  Vec e;  // horizontal, from a towards b
  const double h = HorizontalSpan(a, b, &e);
  const double sy = sag_up ? -1.0 : 1.0;
  const double v = sy * (b[kVertical] - a[kVertical]);
  const double S = std::sqrt(length * length - v * v);
  // Solve sinh(z)/z = S/h for z = h/(2a) by bisection (the left side increases with z).
  double lo = 1e-9, hi = 700.0;
  for (int it = 0; it < 200; ++it) {
    const double z = 0.5 * (lo + hi);
    (std::sinh(z) / z < S / h ? lo : hi) = z;
  }
  const double z = 0.5 * (lo + hi);
  const double c = h / (2.0 * z);                       // catenary parameter H/w [m]
  const double xm = 0.5 * h - c * std::atanh(v / length);  // abscissa of the lowest point
  const double s0 = std::sinh(-xm / c), c0 = std::cosh(-xm / c);
  Points x(kDim, m.stations());
  for (int j = 0; j <= m.line.links; ++j) {
    const double arc = m.line.arc_length[j] / m.line.total_length() * length;
    const double xl = xm + c * std::asinh(arc / c + s0);
    const double yl = c * (std::cosh((xl - xm) / c) - c0);
    x.col(j) = a + xl * e + (sy * yl) * Up();
  }
  x.col(0) = a;
  x.col(m.line.links) = b;
  return x;
}

// The work of a line's statics as it is done, in station-passes: each pass over the line's
// stations (a residual, an energy, a step along the links, a Newton matrix assembled, factored
// and solved) counts its stations. Past the bound it throws StaticsWorkError.
class WorkCount {
 public:
  WorkCount(const LineModel& m, const LineEquilibriumOptions& options)
      : stations_(m.stations()), most_(options.max_work),
        total_(options.work ? options.work : &own_) {}
  void Pass() {
    *total_ += stations_;
    done_ += stations_;
    if (*total_ > most_) {
      std::ostringstream os;
      os << "the static equilibrium of its " << static_cast<long long>(stations_)
         << " stations gave up at its bound of " << most_ << " station-passes (each residual, "
         << "step along the links and Newton matrix counts the stations it passes over; a long "
         << "line's statics take some 9 to 19 passes over its stations)";
      throw StaticsWorkError(os.str());
    }
  }
  double done() const { return done_; }  // this solve's own [station-passes]

 private:
  double stations_, most_;
  double* total_;
  double own_ = 0, done_ = 0;
};

// Residual (out-of-balance force on every station, ends at rest) and, when `system` is given,
// the negated Jacobian -dR/dx of the free stations plus beta on the diagonal. One for a solve:
// its water set for each stage of the continuation in the current (SetWater).
class StaticProblem {
 public:
  StaticProblem(const LineModel& m, const Water& water, WorkCount& work)
      : m_(m), water_(water), work_(work), ws_(m.line.links),
        zero_v_(Points::Zero(kDim, m.stations())),
        slack_tension_(m.env.seabed.present ? StaticForceScale(m, water) : 0.0) {
    // Backward stable (a chain's pivots are cond 5e4: their inverses left Newton's step an
    // out-of-balance force of several newtons where a long line curves), and over the matrix
    // it makes anew for each solve.
    system_.factored_pivots = true;
    system_.in_place = true;
    system_.Resize(m.last_free() - m.first_free() + 1);
  }
  void SetWater(const Water& water) {
    water_ = water;
    slack_tension_ = m_.env.seabed.present ? StaticForceScale(m_, water) : 0.0;
  }
  const Water& water() const { return water_; }
  WorkCount& work() { return work_; }

  const Points& Residual(const Points& x) {
    work_.Pass();
    ComputeGeometry(m_, water_, 0.0, x, ws_.geometry);
    ComputeHookeTensions(m_, ws_.geometry, ws_.tension);
    ComputeStationForces(m_, water_, ws_.geometry, ws_.tension, zero_v_, ws_.force);
    return ws_.force;
  }
  double MaxResidual(int* station = nullptr) const {
    double r = 0;
    for (int j = m_.first_free(); j <= m_.last_free(); ++j) {
      const double f = ws_.force.col(j).lpNorm<Eigen::Infinity>();
      if (!(f <= r)) {  // also catches NaN
        r = f;
        if (station) *station = j;
      }
    }
    return r;
  }
  // The forces on the end stations at the last residual's positions, into the report.
  void EndForces(LineEquilibriumReport& report) const {
    report.start_force = ws_.force.col(0);
    report.end_force = ws_.force.col(m_.line.links);
  }
  double ResidualDot(const Points& dx) const {
    double d = 0;
    for (int j = m_.first_free(); j <= m_.last_free(); ++j) d += ws_.force.col(j).dot(dx.col(j));
    return d;
  }
  double ResidualNorm2() const {
    return ws_.force.middleCols(m_.first_free(), m_.last_free() - m_.first_free() + 1)
        .squaredNorm();
  }
  // Total potential energy of the conservative forces: strain energy plus net weight [J].
  double Energy(const Points& x) {
    work_.Pass();
    ComputeGeometry(x, ws_.geometry);
    return ElasticEnergy(m_, ws_.geometry) + PotentialEnergy(m_, x);
  }

  // Solves (-J + beta I) dx = R at x (Residual(x) must be current). Returns false if singular.
  // With a seabed the contact is taken from where the step lands rather than from where it
  // starts (a primal-dual active set): a station above the bed that the step takes into it gets
  // the bed's spring k (y_b - y) in its linear model, one in the bed that the step lifts off
  // loses it, and the step is solved again until the set is consistent (a few passes). Without
  // this a station just above the bed sees no support, the step drops it far into the stiff bed
  // and the line search cuts the whole step to the few millimetres it may fall.
  bool NewtonStep(double beta, Points& dx) {
    const int j0 = m_.first_free(), j1 = m_.last_free();
    if (m_.env.seabed.present) {
      landed_.resize(m_.stations());
      for (int j = j0; j <= j1; ++j) landed_[j] = m_.env.seabed.y - ws_.geometry.elevation[j] > 0;
    }
    for (int pass = 0; pass < kActiveSetPasses; ++pass) {
      work_.Pass();
      system_.SetZero();
      AddForceJacobian(m_, water_, ws_.geometry, ws_.tension, zero_v_, 0.0, system_);
      for (int j = j0; j <= j1; ++j) {
        system_.diag[j - j0].diagonal().array() += beta;
        system_.rhs[j - j0] = ws_.force.col(j);
      }
      if (m_.env.seabed.present) {
        AddSlackStiffness();
        for (int j = j0; j <= j1; ++j) {
          const double p = m_.env.seabed.y - ws_.geometry.elevation[j];  // the bed's force: k p
          if (landed_[j] == (p > 0)) continue;
          const double k = m_.line.seabed_stiffness[j];
          const double sign = landed_[j] ? 1.0 : -1.0;  // add the spring, or take it away
          system_.diag[j - j0](kVertical, kVertical) += sign * k;
          system_.rhs[j - j0][kVertical] += sign * k * p;
        }
      }
      if (!system_.Solve()) return false;
      dx.setZero();
      for (int j = j0; j <= j1; ++j) dx.col(j) = system_.rhs[j - j0];
      if (!dx.allFinite()) return false;
      if (!m_.env.seabed.present) break;
      bool changed = false;
      for (int j = j0; j <= j1; ++j) {
        const bool lands = ws_.geometry.elevation[j] + dx(kVertical, j) < m_.env.seabed.y;
        changed |= lands != landed_[j];
        landed_[j] = lands;
      }
      if (!changed) break;
    }
    return true;
  }

 private:
  static constexpr int kActiveSetPasses = 8;
  // A slack link has no stiffness, so a slack stretch of line resting on a frictionless bed
  // feels no force at all: Newton moves it only where its taut neighbour pulls it, a link per
  // iteration (a guess or a start with the grounded part laid down short). With a seabed the
  // matrix (not the residual, so not the answer) gives each slack link, along it, the
  // transverse stiffness T / l it would have under the line's whole weight as its tension
  // (StaticForceScale), and the step carries the whole slack stretch along: the poor starts of
  // tests/core/seabed_test.cpp (200 links) take 100-240 iterations instead of 350-4000 (most of
  // them in the pseudo-transient fallback). A fraction of sigma E / l instead worked for a
  // chain and failed for a line 1000 times stiffer (the inextensible model's penalty). The
  // term is positive semi-definite, so the step still descends the energy.
  void AddSlackStiffness() {
    const int j0 = m_.first_free(), j1 = m_.last_free();
    for (int k = 0; k < m_.line.links; ++k) {
      if (ws_.geometry.length[k] > m_.line.rest_length[k]) continue;
      const Vec t = ws_.geometry.tangent.col(k);
      const Mat K = (slack_tension_ / m_.line.rest_length[k]) * t * t.transpose();
      const int a = k, c = k + 1;
      const bool fa = a >= j0 && a <= j1, fc = c >= j0 && c <= j1;
      if (fa) system_.diag[a - j0] += K;
      if (fc) system_.diag[c - j0] += K;
      if (fa && fc) {
        system_.upper[a - j0] -= K;
        system_.lower[c - j0] -= K;
      }
    }
  }

  const LineModel& m_;
  Water water_;
  WorkCount& work_;
  ForceWorkspace ws_;
  Points zero_v_;
  BlockTridiagonal system_;
  std::vector<char> landed_;  // per station: in the bed after the step (seabed only)
  double slack_tension_;      // [N]: see AddSlackStiffness (seabed only)
};

// x + dx, with each link turned and stretched as dx says to first order instead of
// translated: a linear step that turns a link by an angle phi also stretches it by
// l (1/cos(phi) - 1), which for stiff links is a force far larger than any load and makes
// Newton and the pseudo-transient flow crawl. Stations are rebuilt from station 0 and the
// closure error at a prescribed last station is taken up by the links by their compliance.
void CurvilinearUpdate(const LineModel& m, const Points& x, const Points& dx, double alpha,
                       Points& y) {
  y.col(0) = x.col(0) + alpha * dx.col(0);
  for (int j = 0; j < m.line.links; ++j) {
    const Vec d = x.col(j + 1) - x.col(j);
    const double L = d.norm();
    const Vec delta = alpha * (dx.col(j + 1) - dx.col(j));
    if (!(L > 1e-12 * m.line.rest_length[j])) {
      y.col(j + 1) = y.col(j) + d + delta;
      continue;
    }
    const Vec t = d / L;
    const double stretched = std::max(L + t.dot(delta), 1e-3 * L);  // new length [m]
    // Turned towards the part of delta across it, by that part over L (a rotation about
    // t x delta, Rodrigues' formula for a vector at right angles to the axis).
    const Vec across = delta - t * t.dot(delta);
    const double size = across.norm();
    const double turn = size / L;  // rotation [rad]
    const Vec turned = size > 0 ? Vec(std::cos(turn) * t + std::sin(turn) * (across / size)) : t;
    y.col(j + 1) = y.col(j) + stretched * turned;
  }
  if (!m.ends.end.prescribed()) return;
  // The closure error at the prescribed last station (second order in the turns) taken up by
  // the links as springs in series: link k by C_k lambda, C_k = (l / EA) t t^T + (l / T)(I -
  // t t^T) its compliance (along it, and turning under its tension T), lambda = -(sum C_k)^-1
  // closure. Spread evenly along the arc instead, it stretched every link alike, a tension
  // change of EA closure / length that a stiff chain felt where it bends (its touchdown: 250 N
  // from a 0.1 mm closure on a 550 m chain, and Newton crawled in a current at 1/32 steps); a
  // slack or turning link takes it almost free.
  const int s = m.line.links;
  const Vec closure = y.col(s) - (x.col(s) + alpha * dx.col(s));
  const SeabedSpec& bed = m.env.seabed;
  // C_k, and its largest eigenvalue over l_k into *most (L / T across it, or L / EA along it).
  auto compliance = [&](int k, const Vec& d, double* most) {  // d: the link as rebuilt
    const double L = std::max(d.norm(), 1e-12 * m.line.rest_length[k]);
    const Vec t = d / L;
    const double EA = m.line.axial_stiffness[k], l0 = m.line.rest_length[k];
    // A floor of 1e-9 EA on the tension: a slack link's turning is a billion times softer
    // than its stretch, not infinitely (the sum stays invertible).
    const double T = std::max(EA * (L - l0) / l0, 1e-9 * EA);
    if (most) *most = std::max(*most, std::max(L / T, L / EA) / l0);
    Mat C = (L / T) * Mat::Identity();
    C.noalias() += (L / EA - L / T) * (t * t.transpose());
    // A link on the seabed turns freely along it only: the bed holds it up or down as firmly
    // as the link holds its length.
    if (bed.present && std::min(x(kVertical, k), x(kVertical, k + 1)) <= bed.y) {
      Vec n = t.cross(Up());
      const double size = n.norm();
      C = (L / EA) * Mat::Identity();
      if (size > 1e-6) {
        n /= size;
        C.noalias() += (L / T - L / EA) * (n * n.transpose());
      }
    }
    return C;
  };
  Mat total = Mat::Zero();
  double most = 0;  // max over k of |C_k| / l_k [1/N]
  for (int k = 0; k < s; ++k) total += compliance(k, y.col(k + 1) - y.col(k), &most);
  const Vec lambda = -total.ldlt().solve(closure);
  // That is a small correction's model: a closure that would move a link by a tenth of its
  // length (a far step of a very soft line, its slack links taking all) is spread along the
  // arc length as it comes. |C_k lambda| <= |C_k| |lambda| tells most steps so without a pass.
  bool small = lambda.allFinite();
  if (small && most * lambda.norm() > 0.1)
    for (int k = 0; k < s && small; ++k)
      small = (compliance(k, y.col(k + 1) - y.col(k), nullptr) * lambda).norm() <=
              0.1 * m.line.rest_length[k];
  if (!small) {
    for (int j = 1; j <= s; ++j) y.col(j) -= (m.line.arc_length[j] / m.line.total_length()) * closure;
    return;
  }
  Vec shift = Vec::Zero(), from = y.col(0);
  for (int k = 0; k < s; ++k) {
    const Vec to = y.col(k + 1);
    shift += compliance(k, to - from, nullptr) * lambda;
    y.col(k + 1) = to + shift;
    from = to;
  }
}

// Whether Newton has stalled within the round-off floor: its residual within `floor` and five
// steps in a row not lowering it below its best (or no step of the line search lowering the
// merit: NoStep). Within the floor the residual is the tensions' round-off, which the
// iterations stir rather than lower: a taut tether of 100 000 links of 11 um (floor 3e-3 N,
// 1e-9 of its load asked for) iterated 500 Newton and 5 000 fallback steps there, 145 s. The
// floor is a bound: an iteration may get some way below it, so it is given those steps.
class RoundoffStall {
 public:
  RoundoffStall(double floor, double r_inf) : floor_(floor), best_(r_inf) {}
  bool Stalled(double r_inf) {
    if (r_inf < best_) {
      best_ = r_inf;
      since_best_ = 0;
      return false;
    }
    return ++since_best_ >= kStallIterations && r_inf <= floor_;
  }
  bool NoStep(double r_inf) const { return r_inf <= floor_; }

 private:
  static constexpr int kStallIterations = 5;
  double floor_, best_;
  int since_best_ = 0;
};

// The line search's halvings of Newton's step at most, and within the round-off floor
// (RoundoffStall::NoStep).
constexpr int kHalvings = 30;
constexpr int kFloorHalvings = 1;

// Newton with Levenberg-Marquardt damping, each step taken along the links (CurvilinearUpdate). Without current the problem is the minimum of the
// potential energy, and (-J + beta I) is positive definite for beta > 0 (tensions are never
// negative), so the step descends the energy: an Armijo line search on it makes the iteration
// converge from slack starts where the links carry nothing. With current the drag is not
// conservative and the residual norm is the merit function instead. Returns true if converged:
// within tol_force, or stalled within `floor`, the residual the tensions' round-off allows
// (RoundoffStall).
bool Newton(const LineModel& m, StaticProblem& problem, Points& x, double tol_force,
            double floor, int max_iter, LineEquilibriumReport& report, const CancelFlag* cancel) {
  const Water& water = problem.water();
  // The seabed's spring is conservative too (its energy is in PotentialEnergy); its damping
  // and friction vanish at rest.
  const bool conservative = !HasCurrent(m, water);
  // With a seabed, a step that lowers the residual but raises the energy is refused (beyond the
  // energy's round-off): the contact's kinks otherwise let the two criteria take turns and the
  // iteration cycle. Near the solution the energy's changes fall below its round-off and the
  // residual decides alone, as without a seabed.
  const bool energy_first = conservative && m.env.seabed.present;
  Points dx(kDim, m.stations()), trial(kDim, m.stations());
  const double length_scale = m.line.total_length();
  problem.Residual(x);
  double r_inf = problem.MaxResidual();
  double beta = 0;
  const double beta_start = std::max(r_inf, 1e-12) / (0.05 * length_scale);
  RoundoffStall stall(floor, r_inf);
  double energy_x = 0;        // the energy at x [J] (conservative only)
  bool energy_known = false;  // energy_x is x's
  for (; report.iterations < max_iter; ++report.iterations) {
    if (r_inf <= tol_force) return true;
    ThrowIfCancelled(cancel, "the static equilibrium");
    const double r2 = problem.ResidualNorm2();
    if (!problem.NewtonStep(beta, dx)) {
      beta = std::max(10.0 * beta, beta_start);
      continue;
    }
    const double descent = problem.ResidualDot(dx);  // -dEnergy/dalpha at alpha = 0
    // The energy at x: the accepted trial's (a pass less an iteration), or found.
    if (conservative && !energy_known) energy_x = problem.Energy(x);
    energy_known = conservative;
    const double energy = energy_x;
    bool accepted = false;
    double alpha = 1.0, e_trial = 0;
    // Within the round-off floor the merit is the tensions' round-off, which a shorter step
    // does not lower: a whole step that does not lower it is the stall NoStep means (the 30
    // halvings there cost 60 passes over the whole line for nothing, 3/4 of the statics of a
    // chain of 10^6 links).
    const int halvings = stall.NoStep(r_inf) ? kFloorHalvings : kHalvings;
    for (int ls = 0; ls < halvings && !accepted; ++ls, alpha *= 0.5) {
      problem.work().Pass();  // the step along the links
      CurvilinearUpdate(m, x, dx, alpha, trial);
      e_trial = conservative ? problem.Energy(trial) : 0.0;
      problem.Residual(trial);
      const double r2_trial = problem.ResidualNorm2();
      const bool energy_ok = conservative && e_trial <= energy - 1e-4 * alpha * descent;
      const bool energy_kept =
          !energy_first || e_trial <= energy + 1e-12 * std::abs(energy);
      accepted = energy_ok || (energy_kept && r2_trial < r2 * (1.0 - 1e-4 * alpha));
    }
    alpha *= 2.0;  // undo the last halving of the loop
    if (!accepted) {
      if (stall.NoStep(r_inf)) return true;
      problem.Residual(x);
      beta = std::max(10.0 * beta, beta_start);
      continue;
    }
    const double step = (alpha * dx).lpNorm<Eigen::Infinity>();
    x = trial;
    energy_x = e_trial;
    r_inf = problem.MaxResidual();
    if (stall.Stalled(r_inf)) return true;
    beta = alpha == 1.0 ? beta * 0.1 : std::max(2.0 * beta, beta_start * 1e-3);
    if (beta < 1e-12 * beta_start) beta = 0;
    // Round-off floor: a negligible step with a small residual is as converged as it gets.
    if (step <= 1e-13 * length_scale && r_inf <= 1e3 * tol_force) return true;
  }
  return r_inf <= tol_force;
}

// Pseudo-transient continuation: backward-Euler steps of the damped flow dx/dtau = R(x),
// (-J + beta I) dx = R with beta = 1/dtau, every step taken unless it makes the residual far
// worse. Where Newton's merit function has a false minimum (the drag is not conservative, so
// there is no energy to descend) the flow still runs into every stable equilibrium, the state
// a damped dynamic run would settle in. beta halves after a step that lowered the residual and
// doubles after one that raised it, so the last steps are Newton's. No link is stretched or
// turned by more than a quarter of its length in one step, so no step folds the line. Returns
// true if converged within tol_force.
bool PseudoTransient(const LineModel& m, StaticProblem& problem, Points& x, double tol_force,
                     int max_iter, LineEquilibriumReport& report, const CancelFlag* cancel) {
  Points dx(kDim, m.stations()), trial(kDim, m.stations());
  problem.Residual(x);
  double r_inf = problem.MaxResidual();
  double r2 = problem.ResidualNorm2();
  // Start where a step moves the most loaded station by about a tenth of the shortest link.
  const double beta0 = std::max(r_inf, 1e-12) / (0.1 * m.line.rest_length.minCoeff());  // [N/m]
  double beta = beta0;
  for (int it = 0; it < max_iter; ++it, ++report.iterations) {
    if (r_inf <= tol_force) return true;
    ThrowIfCancelled(cancel, "the static equilibrium");
    if (!problem.NewtonStep(beta, dx)) {
      beta = std::max(10.0 * beta, 1e-9 * beta0);
      continue;
    }
    double scale = 1.0;
    for (int j = 0; j < m.line.links; ++j) {
      const double relative = (dx.col(j + 1) - dx.col(j)).norm();  // [m]
      if (relative * scale > 0.25 * m.line.rest_length[j]) scale = 0.25 * m.line.rest_length[j] / relative;
    }
    dx *= scale;
    problem.work().Pass();  // the step along the links
    CurvilinearUpdate(m, x, dx, 1.0, trial);
    problem.Residual(trial);
    const double r2_trial = problem.ResidualNorm2();
    if (!(r2_trial <= 100.0 * r2)) {  // also catches NaN: back to x with a shorter pseudo-step
      problem.Residual(x);
      beta = std::max(10.0 * beta, 1e-9 * beta0);
      continue;
    }
    x = trial;
    r_inf = problem.MaxResidual();
    beta = std::max(beta * (r2_trial < r2 ? 0.5 : 2.0), 1e-9 * beta0);
    r2 = r2_trial;
  }
  return r_inf <= tol_force;
}

}  // namespace

double StaticForceScale(const LineModel& m) { return StaticForceScale(m, SceneWater(m)); }

double StaticForceScale(const LineModel& m, const Water& water) {
  // The cable's and prisms' net weights and the drag of the current on them (as if broadside,
  // and as if along the links for their tangential drag),
  // and, for ends further apart than the cable is long, the tension of the stretched chord: a
  // weightless taut line has no other force scale (without it the tolerance would be 1e-18 N).
  const double current_load = 0.5 * MaxCurrent(m, water) * MaxCurrent(m, water) *
                              (2.0 * (m.line.drag_factor.sum() + m.line.tangential_drag_factor.sum()) +
                               m.line.prism_drag.colwise().sum().sum());
  double chord_tension = 0;
  if (m.ends.start.prescribed() && m.ends.end.prescribed()) {
    const double chord = (m.ends.end.Position(0) - m.ends.start.Position(0)).norm();
    chord_tension = m.line.axial_stiffness.minCoeff() * std::max(0.0, chord / m.line.total_length() - 1.0);
  }
  const double thrust = m.line.prism_force.colwise().norm().sum();
  return std::max(m.line.net_weight.cwiseAbs().sum() + current_load + chord_tension + thrust,
                  1e-9);
}

Points StraightChord(const LineModel& m) {
  if (!m.ends.start.prescribed() && !m.ends.end.prescribed())
    throw Error("the cable needs at least one prescribed end (fixed or moving)");
  const Vec a = m.ends.start.Position(0), b = m.ends.end.Position(0);
  Points x(kDim, m.stations());
  for (int j = 0; j <= m.line.links; ++j) {
    const double f = m.line.arc_length[j] / m.line.total_length();
    x.col(j) = (1.0 - f) * a + f * b;
  }
  return x;
}

namespace {

// Stations of a guess that lie below the seabed raised onto it (the catenary of a long line sags
// through it): a guess far inside the bed's stiff spring starts Newton with forces far above
// any load.
Points OntoSeabed(const LineModel& m, Points x) {
  if (!m.env.seabed.present) return x;
  for (int j = m.first_free(); j <= m.last_free(); ++j)
    x(kVertical, j) = std::max(x(kVertical, j), m.env.seabed.y);
  return x;
}

// A line that the catenary guess sags through the seabed, laid out as the inextensible
// catenary with a grounded part: from the lower end straight down to the bed, along it, then
// up the catenary that leaves it tangentially to the other end, of total length `length` (the
// touchdown found by bisection on the length). Its grounded links are taut from the start
// (a clipped catenary leaves them short, and Newton would pull them straight a link at a time).
// False if no touchdown fits (the line too short to reach the bed tangentially, or so long it
// would pile up on it).
bool GroundedGuess(const LineModel& m, double length, Points& x) {
  const double bed = m.env.seabed.y;
  const bool start_low =
      m.ends.start.Position(0)[kVertical] <= m.ends.end.Position(0)[kVertical];
  const Vec A = start_low ? m.ends.start.Position(0) : m.ends.end.Position(0);
  const Vec B = start_low ? m.ends.end.Position(0) : m.ends.start.Position(0);
  const double drop = A[kVertical] - bed, rise = B[kVertical] - bed;  // [m], both >= 0
  Vec e;  // horizontal, from A towards B: the plane of the guess
  const double span = HorizontalSpan(A, B, &e);
  if (!(rise > 0) || !(span > 0) || drop < 0) return false;
  // The catenary from a touchdown `run` before B (horizontally) up to B: its parameter c
  // (rise = c (cosh(run / c) - 1), bisection: the rise falls as c grows) and arc length.
  auto parameter = [&](double run) {
    double lo = 1e-9 * run, hi = 1e9 * (run + rise);
    for (int it = 0; it < 200; ++it) {
      const double c = std::sqrt(lo * hi);
      (c * (std::cosh(std::min(run / c, 700.0)) - 1.0) > rise ? lo : hi) = c;
    }
    return std::sqrt(lo * hi);
  };
  auto path = [&](double run) {  // the whole path's length for a touchdown `run` before B
    const double c = parameter(run);
    return drop + (span - run) + std::sqrt(rise * rise + 2.0 * c * rise);
  };
  // The path shortens as the touchdown moves away from B (run from 0 to span): from
  // drop + span + rise down to the catenary from the lower end's foot.
  double lo = 1e-9 * span, hi = span;
  if (!(path(hi) <= length && path(lo) >= length)) return false;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (path(mid) > length ? lo : hi) = mid;
  }
  const double run = 0.5 * (lo + hi), c = parameter(run);
  const double grounded = span - run;
  x.resize(kDim, m.stations());
  for (int j = 0; j <= m.line.links; ++j) {
    const double f = m.line.arc_length[j] / m.line.total_length();
    double sigma = (start_low ? f : 1.0 - f) * length;  // path length from A
    Vec p = A;  // along e at the height `up` [m] above the bed
    double up = 0;
    if (sigma <= drop) {
      up = drop - sigma;
    } else if ((sigma -= drop) <= grounded) {
      p += sigma * e;
    } else {
      sigma -= grounded;  // arc length along the catenary from the touchdown
      const double u = std::asinh(sigma / c);
      p += (grounded + c * u) * e;
      up = c * (std::cosh(u) - 1.0);
    }
    p[kVertical] = bed + up;
    x.col(j) = p;
  }
  x.col(0) = m.ends.start.Position(0);
  x.col(m.line.links) = m.ends.end.Position(0);
  return true;
}

Points FreeGuess(const LineModel& m) {
  if (!m.ends.start.prescribed() || !m.ends.end.prescribed()) {
    StraightChord(m);  // throws when both ends are free
    return HangingGuess(m);
  }
  const Vec a = m.ends.start.Position(0), b = m.ends.end.Position(0);
  const double chord = (b - a).norm(), length = m.line.total_length();
  const double w = m.line.net_weight.sum() / length;  // mean net weight [N/m]
  // Stretch the guess by the tension a catenary of the mean weight would have, so that its
  // links are taut (a guess at exactly the rest length sits on the slack switch).
  const double tension_guess = std::abs(w) * length;
  const double stretched = length * (1.0 + std::max(1e-6, tension_guess / MinAxialStiffness(m)));
  Vec e;
  const double h = HorizontalSpan(a, b, &e);
  if (chord >= stretched || h < 1e-6 * length) return StraightChord(m);
  Points x = CatenaryGuess(m, a, b, stretched, w < 0);
  if (m.env.seabed.present && w > 0 && x.row(1).minCoeff() < m.env.seabed.y) GroundedGuess(m, stretched, x);
  return x;
}

}  // namespace

Points EquilibriumGuess(const LineModel& m) { return OntoSeabed(m, FreeGuess(m)); }

State SolveLineEquilibrium(const LineModel& m, LineEquilibriumReport* report,
                            const LineEquilibriumOptions& options) {
  return SolveLineEquilibrium(m, EquilibriumGuess(m), report, options);
}

constexpr int kWarmStartIterations = 150;

void RefuseIfTooLarge(const LineModel& m, const LineEquilibriumOptions& options) {
  const double left = options.max_work - (options.work ? *options.work : 0.0);
  if (!(kLeastStaticPasses * m.stations() > left)) return;
  std::ostringstream os;
  os << "the static equilibrium of its " << m.stations() << " stations takes some "
     << kLeastStaticPasses * m.stations() << " station-passes at the least ("
     << kLeastStaticPasses << " passes over its stations), more than the " << left
     << " left of its bound of " << options.max_work;
  throw StaticsWorkError(os.str());
}

State SolveLineEquilibrium(const LineModel& m, const Points& guess,
                            LineEquilibriumReport* report_out, const LineEquilibriumOptions& options) {
  if (!m.ends.start.prescribed() && !m.ends.end.prescribed())
    throw Error("the cable needs at least one prescribed end (fixed or moving)");
  RefuseIfTooLarge(m, options);
  LineEquilibriumReport report;
  Points x = guess;
  x.col(0) = m.ends.start.prescribed() ? m.ends.start.Position(0) : x.col(0);
  x.col(m.line.links) = m.ends.end.prescribed() ? m.ends.end.Position(0) : x.col(m.line.links);

  report.force_scale = StaticForceScale(m);
  const double tol = options.tolerance * report.force_scale;
  // The residual may not fall below the round-off of the link tensions: a position is known to
  // its last bits, eps |x|, and a link's tension to EA / l times that. The inextensible model's
  // penalty line (EA a million times the load) can stall there: 5e-3 N at x = 375 m, ten times
  // the 5e-4 N asked, and a grounded chain in a sheared current never converged. An iteration
  // that stalls within that floor has converged as far as double precision allows.
  const double reach = std::max(x.cwiseAbs().maxCoeff(), 1.0);  // m
  const double stiffest = (m.line.axial_stiffness.array() / m.line.rest_length.array()).maxCoeff();  // N/m
  report.roundoff_floor = 4.0 * std::numeric_limits<double>::epsilon() * reach * stiffest;

  // Continuation in the current: solve still water first, then raise the current in steps,
  // each starting from the last equilibrium (the drag load is not conservative). The
  // parameter is the uniform current itself, or with a profile the fraction of the whole
  // current (uniform and profile alike).
  // With waves the mean state: the line in calm water with the current, under the still water
  // level (a station above it has no buoyancy, drag or added mass, as in the run); the waves'
  // ramp starts the run from it.
  Water calm = SceneWater(m);
  calm.wave.amplitude = 0;
  calm.wave.spec.height = 0;
  const bool profile = !m.env.current_profile.empty();
  const double full = profile ? 1.0 : m.env.current;
  auto with_current = [&](double level) {
    Water w = calm;
    (profile ? w.current_scale : w.current) = level;
    return w;
  };
  // A guess that is an equilibrium nearby (a held end moved a little: equilibrium.h)
  // is already in the current: Newton from it in the full current first, for at most
  // kWarmStartIterations: one that has not converged by then is not near (a grounded stretch
  // crawling a station an iteration), and the continuation from still water costs less than
  // going on. On the spread mooring's statics (3 x 200 links, a clump landing on the bed) a
  // cap of 75 / 100 / 150 / 200 / 300 / 500 iterations took 594 / 542 / 541 / 507 / 742 /
  // 1091 ms for the same equilibrium.
  // One problem for the whole solve (its matrix is the solve's memory: some 0.5 kB a station),
  // its water set for each stage; its passes counted against the bound.
  WorkCount work(m, options);
  StaticProblem problem(m, calm, work);
  // Written into the report also when a solve throws (a held line's work is counted then too).
  struct Tally {
    LineEquilibriumReport& report;
    LineEquilibriumReport* out;
    const WorkCount& work;
    ~Tally() {
      report.work = work.done();
      if (out) *out = report;
    }
  } tally{report, report_out, work};
  if (options.warm_start) {
    Points trial = x;
    problem.SetWater(with_current(full));
    if (Newton(m, problem, trial, tol, report.roundoff_floor,
               std::min(options.max_iterations, kWarmStartIterations), report,
               options.cancel)) {
      problem.SetWater(calm);
      problem.Residual(trial);
      report.residual = problem.MaxResidual(nullptr);
      problem.EndForces(report);
      State state;
      state.x = std::move(trial);
      state.v = Points::Zero(kDim, m.stations());
      return state;
    }
  }
  problem.SetWater(with_current(0.0));
  bool ok = Newton(m, problem, x, tol, report.roundoff_floor, options.max_iterations, report,
                   options.cancel);
  double reached = 0;
  double increment = 0.25 * full;
  // Bounded: a current so small that a quarter of it underflows goes in at once.
  while (ok && reached != full && report.current_steps < options.max_current_steps) {
    double target = std::abs(full - reached) <= std::abs(increment) * 1.0000001
                        ? full
                        : reached + increment;
    if (target == reached) target = full;
    Points trial = x;
    ++report.current_steps;
    problem.SetWater(with_current(target));
    if (Newton(m, problem, trial, tol, report.roundoff_floor, options.max_iterations, report,
               options.cancel)) {
      x = std::move(trial);
      reached = target;
    } else if (std::abs(increment) > 1e-3 * std::abs(full) &&
               report.iterations < options.max_iterations) {
      increment *= 0.5;
    } else {
      ok = false;
    }
  }

  if (reached != full) ok = false;  // the continuation ran out of steps
  if (!ok) {
    // Newton found no way down; the damped flow from the last equilibrium reached (or the
    // first guess) does not need one.
    report.fallback = true;
    const int before = report.iterations;
    problem.SetWater(calm);
    ok = PseudoTransient(m, problem, x, tol, options.max_pseudo_transient_iterations, report,
                         options.cancel);
    report.fallback_iterations = report.iterations - before;
  }
  problem.SetWater(calm);
  problem.Residual(x);
  int worst = 0;
  report.residual = problem.MaxResidual(&worst);
  problem.EndForces(report);
  ok = ok || report.residual <= report.roundoff_floor;
  if (!ok || !(report.residual <= std::max(1e3 * tol, report.roundoff_floor))) {
    std::ostringstream os;
    os << "static equilibrium did not converge after " << report.iterations
       << " Newton iterations (" << report.fallback_iterations
       << " of them pseudo-transient steps): the largest out-of-balance force is "
       << report.residual << " N at station " << worst << " (tolerance " << tol
       << " N); the cable may have no steady state between its ends in this current (ends "
          "further apart than it can stretch, or loads nothing can balance)";
    throw Error(os.str());
  }
  State state;
  state.t = 0;
  state.x = std::move(x);
  state.v = Points::Zero(kDim, m.stations());
  return state;
}


State SolveInextensibleEquilibrium(const LineModel& m, LineEquilibriumReport* report,
                                  const CancelFlag* cancel, double max_work) {
  if (m.ends.start.prescribed() && m.ends.end.prescribed()) {
    const double chord = (m.ends.end.Position(0) - m.ends.start.Position(0)).norm();
    if (chord >= m.line.total_length()) {
      std::ostringstream os;
      os << "the ends are " << chord << " m apart but the inextensible cable is only "
         << m.line.total_length() << " m long";
      throw Error(os.str());
    }
  }
  // A penalty stiffness that stretches the cable by about 1e-6 under its loads: stiff enough
  // for Richardson extrapolation in 1/EA to be exact to O(1e-12), soft enough for the Newton
  // residual to stay above round-off.
  const double load = StaticForceScale(m);
  LineModel stiff = m;
  stiff.line.law = LinkLaw::kElastic;
  stiff.line.axial_stiffness.setConstant(1e6 * load);
  // Both solves poll the run's cancel flag (a fuzzed scene's stop at 0.3 s could not reach them:
  // a seed ran 11 s under the sanitizers).
  LineEquilibriumOptions options;
  options.cancel = cancel;
  double work = 0;  // both solves on one count
  options.max_work = max_work;
  options.work = &work;
  RefuseIfTooLarge(m, options);
  LineEquilibriumReport first;
  const State soft = SolveLineEquilibrium(stiff, &first, options);
  stiff.line.axial_stiffness *= 2.0;
  State hard = SolveLineEquilibrium(stiff, soft.x, report, options);
  if (report) {
    report->iterations += first.iterations;
    report->work += first.work;
  }
  hard.x = 2.0 * hard.x - soft.x;  // the limit EA -> infinity, error O(1/EA^2)
  ConstraintSolver solver(m);
  if (!solver.ProjectPositions(m, hard.x, 1e-13))
    throw Error("cannot place the inextensible cable at its rest lengths between its ends");
  return hard;
}

}  // namespace cablefilm
