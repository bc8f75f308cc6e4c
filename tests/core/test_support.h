#pragma once
// Helpers shared by the core tests: model builders and the exact (continuous) elastic catenary
// of a piecewise-uniform line with concentrated weights, computed here from its closed form and
// not from anything in src/core, so that the lumped model is checked against an independent truth.
#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <cstdio>
#include <string>
#include <vector>

#include "core/line_data.h"
#include "core/line_model.h"
#include "core/step.h"
#include "core/waves.h"

namespace cablefilm::testing {

// The gradients of the water's velocity and acceleration at `at` [m], time t [s], by central
// differences of step d [m] (KinematicsAt's own gradients are checked against them).
inline void KinematicsGradientsByDifferences(const Wave& wave, const Vec& at, double t, double d,
                                             Mat* Gu, Mat* Ga) {
  for (int axis = 0; axis < kDim; ++axis) {
    const Vec e = d * Vec::Unit(axis);
    const WaterKinematics p = KinematicsAt(wave, at + e, t);
    const WaterKinematics m = KinematicsAt(wave, at - e, t);
    Gu->col(axis) = (p.velocity - m.velocity) / (2 * d);
    Ga->col(axis) = (p.acceleration - m.acceleration) / (2 * d);
  }
}

// The LineData a test steps: state `s` under a scheme, with the model's own inputs.
inline LineData StartData(const LineModel& m, const State& s, Scheme scheme, double rho_inf = 0.5,
                      double tolerance = 0, double safety_factor = 0) {
  StepOptions o;
  o.scheme = scheme;
  o.rho_inf = rho_inf;
  o.tolerance = tolerance;
  o.safety_factor = safety_factor;
  return MakeLineData(m, SceneInputs(m), o, s);
}

// A scheme as the tests step it: a LineData with the model's own inputs whose state follows the
// test's State (taken in before each step, given back after it), so that a test may look at
// and change its state between steps as it likes.
class Stepper {
 public:
  explicit Stepper(const StepOptions& options) : options_(options) {}
  Stepper(Scheme scheme, double rho_inf = 0.5, double tolerance = 0, double safety_factor = 0) {
    options_.scheme = scheme;
    options_.rho_inf = rho_inf;
    options_.tolerance = tolerance;
    options_.safety_factor = safety_factor;
  }
  void Initialize(const LineModel& m, const State& s) {
    inputs_ = SceneInputs(m);
    inputs_.stop = stop_;
    data_ = MakeLineData(m, inputs_, options_, s);
  }
  void Step(const LineModel& m, State& s, double dt) {
    data_.state = s;
    cablefilm::StepLine(m, data_, inputs_, dt);
    s = data_.state;
  }
  const Eigen::VectorXd& tensions() const { return data_.tension(); }
  StepStats stats() const { return data_.step_stats(); }
  const LineData& data() const { return data_; }
  LineData& data() { return data_; }
  const Inputs& inputs() const { return inputs_; }
  void set_cancel(const CancelFlag* stop) { stop_ = inputs_.stop = stop; }

 private:
  StepOptions options_;
  Inputs inputs_;
  const CancelFlag* stop_ = nullptr;
  LineData data_;
};

inline std::unique_ptr<Stepper> MakeStepper(Scheme scheme, const LineModel&, double rho_inf = 0.5,
                                            double tolerance = 0) {
  return std::make_unique<Stepper>(scheme, rho_inf, tolerance);
}

// A motion table in the plane: rows (t [s], dx [m], dy [m]).
inline EndMotion PlanarTable(const Vec& rest, const std::vector<Eigen::Vector3d>& rows) {
  std::vector<double> times;
  std::vector<Vec> offsets;
  for (const Eigen::Vector3d& r : rows) {
    times.push_back(r[0]);
    offsets.push_back(InPlane(r[1], r[2]));
  }
  return EndMotion::Table(rest, times, offsets);
}

// A state at rest at positions x (t = 0).
inline State AtRest(const Points& x) {
  State s;
  s.x = x;
  s.v = Points::Zero(kDim, x.cols());
  return s;
}

// A uniform line of `links` links between two end motions.
inline LineModel UniformCable(int links, double length, double mass_per_length, double area,
                               double youngs_modulus, const EnvironmentSpec& env, EndMotion start,
                               EndMotion end, double diameter = 0.0, double drag = 0.0,
                               double added_mass = 0.0) {
  SectionSpec s;
  s.length = length;
  s.segments = links;
  s.diameter = diameter;
  s.area = area;
  s.mass_per_length = mass_per_length;
  s.youngs_modulus = youngs_modulus;
  s.drag_coefficient = drag;
  s.added_mass_coefficient = added_mass;
  return MakeLineModel({s}, {}, env, std::move(start), std::move(end), LinkLaw::kElastic);
}

// The exact static shape of an elastic line in Lagrangian (unstretched) arc length s, Irvine
// (1981) "Cable Structures" ch. 2, generalised to uniform pieces and point loads; in its own
// plane (2D vectors: horizontal, vertical).
// Station 0 sits at the origin; F(s) = (H, V(s)) is the force the part beyond s exerts on the
// part before it (the tension vector, along the tangent). Equilibrium of an element gives
// dV/ds = w (w: net weight per unstretched length, N/m), a jump V(s+) = V(s-) + W at a point
// load W, and H constant. Hooke: |dr/ds| = 1 + T/EA with T = sqrt(H^2 + V^2), so
//   dx/ds = H/EA + H/T,   dy/ds = V/EA + V/T,
// which integrate over a piece starting with V = Va, for a length s, to
//   x = H s/EA + (H/w) [asinh((Va + w s)/H) - asinh(Va/H)]
//   y = (Va s + w s^2/2)/EA + (1/w) [sqrt(H^2 + (Va + w s)^2) - sqrt(H^2 + Va^2)].
class ExactCatenary {
 public:
  struct Piece {
    double length;      // unstretched [m]
    double w;           // net weight per unstretched length [N/m] (negative: buoyant)
    double EA;          // axial stiffness [N]
    double point_load;  // net concentrated weight at the piece's start [N]
  };

  explicit ExactCatenary(std::vector<Piece> pieces) : pieces_(std::move(pieces)) {}

  // Position (x, y) relative to station 0 and the tension at arc length s.
  void Evaluate(double H, double V0, double s, Eigen::Vector2d* r, double* tension) const {
    Eigen::Vector2d p = Eigen::Vector2d::Zero();
    double V = V0, start = 0;
    for (size_t i = 0; i < pieces_.size(); ++i) {
      const Piece& pc = pieces_[i];
      V += pc.point_load;  // the jump at the piece's start
      const double len = std::max(0.0, std::min(pc.length, s - start));
      p += Segment(H, V, pc.w, pc.EA, len);
      V += pc.w * len;
      if (s <= start + pc.length) break;
      start += pc.length;
    }
    if (r) *r = p;
    if (tension) *tension = std::hypot(H, V);
  }
  // dr/ds = (1 + T/EA) (H, V)/T at arc length s (just after s at a point load).
  Eigen::Vector2d Slope(double H, double V0, double s) const {
    double V = V0, start = 0, EA = pieces_.front().EA;
    for (const Piece& pc : pieces_) {
      if (s < start) break;
      V += pc.point_load;
      EA = pc.EA;
      V += pc.w * std::max(0.0, std::min(pc.length, s - start));
      start += pc.length;
    }
    const double T = std::hypot(H, V);
    return (1.0 + T / EA) / T * Eigen::Vector2d(H, V);
  }
  // d/ds of dr/ds at s, from the left (s^-) or the right (s^+) of a piece boundary:
  // with dV/ds = w, d/ds[(1/EA + 1/T)(H, V)] = (0, w/EA) + (w H / T^3)(-V, H).
  Eigen::Vector2d SlopeDerivative(double H, double V0, double s, bool from_left) const {
    double V = V0, start = 0, EA = 0, w = 0;
    for (const Piece& pc : pieces_) {
      V += pc.point_load;
      V += pc.w * std::max(0.0, std::min(pc.length, s - start));
      EA = pc.EA;
      w = pc.w;
      if (from_left ? s <= start + pc.length : s < start + pc.length) break;
      start += pc.length;
    }
    const double T = std::hypot(H, V);
    return Eigen::Vector2d(0.0, w / EA) + (w * H / (T * T * T)) * Eigen::Vector2d(-V, H);
  }
  double total_length() const {
    double L = 0;
    for (const Piece& p : pieces_) L += p.length;
    return L;
  }
  Eigen::Vector2d EndPoint(double H, double V0) const {
    Eigen::Vector2d r;
    Evaluate(H, V0, total_length(), &r, nullptr);
    return r;
  }

  // Newton on (log H, V0) so that the far end lands on `target` (relative to station 0), with a
  // finite-difference Jacobian and backtracking. The guess only selects the root; the answer is
  // fixed by the closed form. Returns the end-point miss [m].
  double Shoot(const Eigen::Vector2d& target, double H_guess, double V0_guess) {
    double u = std::log(H_guess), V0 = V0_guess;
    auto miss = [&](double uu, double vv) -> Eigen::Vector2d { return EndPoint(std::exp(uu), vv) - target; };
    Eigen::Vector2d r = miss(u, V0);
    for (int it = 0; it < 200 && r.norm() > 1e-13 * total_length(); ++it) {
      const double du = 1e-7, dv = 1e-7 * (std::abs(V0) + std::exp(u));
      Eigen::Matrix2d J;
      J.col(0) = (miss(u + du, V0) - miss(u - du, V0)) / (2 * du);
      J.col(1) = (miss(u, V0 + dv) - miss(u, V0 - dv)) / (2 * dv);
      const Eigen::Vector2d step = -J.fullPivLu().solve(r);
      double a = 1.0;
      Eigen::Vector2d r_new;
      for (int k = 0; k < 60; ++k, a *= 0.5) {
        const double su = std::max(-2.0, std::min(2.0, a * step[0]));
        r_new = miss(u + su, V0 + a * step[1]);
        if (std::isfinite(r_new.norm()) && r_new.norm() < r.norm()) {
          u += su;
          V0 += a * step[1];
          break;
        }
      }
      if (!(r_new.norm() < r.norm())) break;  // no further progress: at the round-off floor
      r = r_new;
    }
    H_ = std::exp(u);
    V0_ = V0;
    return r.norm();
  }
  double H() const { return H_; }
  double V0() const { return V0_; }

 private:
  static Eigen::Vector2d Segment(double H, double Va, double w, double EA, double s) {
    const double Vb = Va + w * s;
    const double x = H * s / EA + H / w * (std::asinh(Vb / H) - std::asinh(Va / H));
    // sqrt(H^2+Vb^2) - sqrt(H^2+Va^2) written without cancellation.
    const double dT = (Vb - Va) * (Vb + Va) / (std::hypot(H, Vb) + std::hypot(H, Va));
    const double y = (Va * s + 0.5 * w * s * s) / EA + dT / w;
    return Eigen::Vector2d(x, y);
  }

  std::vector<Piece> pieces_;
  double H_ = 0, V0_ = 0;
};

// The elastic catenary with a grounded portion (frictionless bed), from its closed form alone:
// the anchor on the bed at the origin, the fairlead at (X, h). The grounded part, of unstretched
// length Lb, lies flat and carries the horizontal tension H all along (no friction); the
// suspended part, of Ls = L - Lb, leaves the bed tangentially (V = 0 at touchdown), so it is the
// elastic catenary of Irvine (1981) from its lowest point:
//   x_s = H Ls / EA + (H / w) asinh(w Ls / H)
//   h   = w Ls^2 / (2 EA) + (H / w) (sqrt(1 + (w Ls / H)^2) - 1)
//   X   = Lb (1 + H / EA) + x_s
// Anchor tension H, fairlead tension sqrt(H^2 + (w Ls)^2), touchdown at x = Lb (1 + H / EA).
struct GroundedCatenary {
  double H = 0, Lb = 0;  // [N], [m unstretched]
  double L = 0, w = 0, EA = 0;
  double fairlead_tension() const { return std::hypot(H, w * (L - Lb)); }
  double touchdown_x() const { return Lb * (1.0 + H / EA); }
};

inline GroundedCatenary SolveGroundedCatenary(double L, double w, double EA, double X, double h) {
  auto height = [&](double H, double Ls) {
    const double r = w * Ls / H;
    return w * Ls * Ls / (2 * EA) + (H / w) * (r * r / (std::sqrt(1 + r * r) + 1));
  };
  // For a suspended length Ls, the H that lifts it to h (height falls as H grows).
  auto tension_for = [&](double Ls) {
    double lo = 1e-12, hi = 1e15;
    for (int i = 0; i < 400; ++i) {
      const double mid = std::sqrt(lo * hi);
      (height(mid, Ls) > h ? lo : hi) = mid;
      if (hi / lo - 1 < 1e-15) break;
    }
    return std::sqrt(lo * hi);
  };
  auto span = [&](double Ls) {
    const double H = tension_for(Ls);
    return (L - Ls) * (1 + H / EA) + H * Ls / EA + (H / w) * std::asinh(w * Ls / H) - X;
  };
  // The span grows with the suspended length (a longer suspended part is flatter): bisection
  // between the line hanging straight down (Ls ~ h) and all of it suspended.
  double lo = h * (1 + 1e-9), hi = L;
  if (!(span(lo) < 0) || !(span(hi) > 0))
    throw std::runtime_error("SolveGroundedCatenary: no grounded catenary spans X (the line is "
                             "too short, or too long for any of it to lift)");
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (span(mid) < 0 ? lo : hi) = mid;
  }
  GroundedCatenary c;
  const double Ls = 0.5 * (lo + hi);
  c.H = tension_for(Ls);
  c.Lb = L - Ls;
  c.L = L;
  c.w = w;
  c.EA = EA;
  return c;
}

// A measured figure as a test property (three significant digits).
inline std::string Figure(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// The systems' tests' chain: 60 kg/m, 0.1 m, EA = 3.9e8 N, Cd 2.4, Ca 1.
inline SectionSpec Chain(double length, int segments) {
  SectionSpec s;
  s.length = length;
  s.segments = segments;
  s.diameter = 0.1;
  s.area = 0.0078;
  s.mass_per_length = 60.0;
  s.youngs_modulus = 5e10;
  s.drag_coefficient = 2.4;
  s.added_mass_coefficient = 1.0;
  return s;
}

}  // namespace cablefilm::testing
