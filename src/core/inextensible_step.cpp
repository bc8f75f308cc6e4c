#include "core/inextensible_step.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "core/cancel.h"
#include "core/seabed_friction.h"
#include "core/step_landing.h"

namespace cablefilm {
namespace {

// One substep of h from d.state into the scratch's trial (x, v, a and its forces); false if the
// positions cannot be projected back onto the rest lengths.
bool Trial(const LineModel& m, LineData& d, const Inputs& in, double h) {
  const State& s = d.state;
  Scratch& w = d.scratch;
  const double t1 = s.t + h;
  const int j0 = m.first_free(), j1 = m.last_free();
  w.x = s.x;
  w.v = s.v;
  for (int j = j0; j <= j1; ++j) {
    w.v_pred.col(j) = s.v.col(j) + h * d.a.col(j);
    w.v.col(j) += 0.5 * h * d.a.col(j);
    w.x.col(j) += h * w.v.col(j);
  }
  for (int j : {0, m.line.links}) {
    if (!m.prescribed(j)) continue;
    w.x.col(j) = EndPosition(m, in, j, t1);
    w.v.col(j) = EndVelocity(m, in, j, t1);
    w.v_pred.col(j) = w.v.col(j);
  }
  if (!w.constraints.ProjectPositions(m, w.x, 1e-13)) return false;
  w.trial.geometry.friction_anchor = d.forces.geometry.friction_anchor;  // same size: no copy
  w.constraints.Accelerations(m, in, d.water, t1, w.x, w.v_pred, w.trial, w.a);
  for (int j = j0; j <= j1; ++j) w.v.col(j) += 0.5 * h * w.a.col(j);
  w.constraints.ProjectVelocities(m, w.x, w.v);
  return true;
}

// The trial's local position error estimate [m].
double LocalError(const LineModel& m, const LineData& d, double h) {
  double da = 0;
  for (int j = m.first_free(); j <= m.last_free(); ++j)
    da = std::max(da, (d.scratch.a.col(j) - d.a.col(j)).lpNorm<Eigen::Infinity>());
  return h * h / 6.0 * da;
}

// Makes the trial the state.
void Accept(const LineModel& m, LineData& d, double h) {
  Scratch& w = d.scratch;
  d.state.x.swap(w.x);
  d.state.v.swap(w.v);
  d.a.swap(w.a);
  d.forces.geometry.length.swap(w.trial.geometry.length);
  d.forces.geometry.tangent.swap(w.trial.geometry.tangent);
  d.forces.tension.swap(w.trial.tension);
  d.forces.force.swap(w.trial.force);
  UpdateFrictionAnchors(m, d.state.x, d.state.v, d.forces.geometry);
  d.state.t += h;
  ++d.stats.steps;
  d.snaps.ObserveStep(h);
}

}  // namespace

double StableSubstep(const LineModel& m, const LineData& d) {
  // Transverse waves: a station between links under tension T has stiffness T/L across them.
  // Gershgorin: omega^2 <= max_j 2 (|T_{j-1}| + |T_j|) / (m_j l); half the resulting step, as
  // the tension may rise within it.
  const Line& line = m.line;
  const Eigen::VectorXd& T = d.forces.tension;
  double lambda = 0;
  for (int j = m.first_free(); j <= m.last_free(); ++j) {
    const double mj = line.cable_mass[j] + m.SmallestPrismMass(j);
    double stiffness = 0;
    if (j > 0) stiffness += std::abs(T[j - 1]) / line.rest_length[j - 1];
    if (j < line.links) stiffness += std::abs(T[j]) / line.rest_length[j];
    lambda = std::max(lambda, 2.0 * stiffness / mj);
  }
  if (m.env.seabed.present) {
    // The seabed's spring and dashpot on each station (any may land within the substep), with
    // the transverse stiffness: the bound of the explicit scheme with damping (stability.cpp),
    // omega h <= 2 (sqrt(1 + 4 zeta^2) - 2 zeta), halved as above.
    double gamma = 0;
    for (int j = m.first_free(); j <= m.last_free(); ++j) {
      const double mj = line.cable_mass[j] + m.SmallestPrismMass(j);
      // At most twice the spring's (forces.cpp), or the friction's shear spring across it.
      double stiffness = std::max(2.0 * line.seabed_stiffness[j], ShearStiffness(m, j));
      if (j > 0) stiffness += 2.0 * std::abs(T[j - 1]) / line.rest_length[j - 1];
      if (j < line.links) stiffness += 2.0 * std::abs(T[j]) / line.rest_length[j];
      lambda = std::max(lambda, stiffness / mj);
      gamma = std::max(gamma, std::max(line.seabed_damping[j], ShearDamping(m, j)) / mj);
    }
    if (!(lambda > 0)) return std::numeric_limits<double>::infinity();
    const double omega = std::sqrt(lambda), zeta = gamma / (2.0 * omega);
    return 0.5 * 2.0 * (std::sqrt(1.0 + 4.0 * zeta * zeta) - 2.0 * zeta) / omega;
  }
  return lambda > 0 ? 0.5 * 2.0 / std::sqrt(lambda) : std::numeric_limits<double>::infinity();
}

void InextensibleStep(const LineModel& m, LineData& d, const Inputs& in, double dt) {
  State& s = d.state;
  const double t_end = s.t + dt;
  const double tolerance = d.options.tolerance;
  if (!(tolerance > 0)) {
    while (!Landed(s.t, t_end, dt)) {
      ThrowIfCancelled(in.stop, "the inextensible step");
      const double remaining = t_end - s.t;
      const int pieces = static_cast<int>(std::ceil(remaining / StableSubstep(m, d) - 1e-9));
      const double h = remaining / std::max(1, pieces);
      if (!Trial(m, d, in, h)) {
        std::ostringstream os;
        os << "the inextensible cable cannot keep its length at t = " << s.t + h
           << " s: its ends are pulled further apart than the cable is long";
        throw BlowUpError(os.str(), s.t + h, m.line.links);
      }
      Accept(m, d, h);
    }
    s.t = t_end;
    CheckStateSane(m, s, d.forces.geometry.length);
    return;
  }
  if (!(d.proposed_step > 0) || d.proposed_step > dt) d.proposed_step = dt;
  const double smallest = kSmallestSubstep * dt;
  int failures = 0;  // rejections in a row
  while (!Landed(s.t, t_end, dt)) {
    ThrowIfCancelled(in.stop, "the inextensible step");
    const double longest = std::min(d.proposed_step, StableSubstep(m, d));
    const double h = StepToward(s.t, t_end, longest);
    const bool limited = h < d.proposed_step;  // by the wave limit or the end of the step asked
    const bool projected = longest >= smallest && Trial(m, d, in, h);
    double error = 0;
    if (projected) {
      error = LocalError(m, d, h);
      if (error <= tolerance) {
        Accept(m, d, h);
        failures = 0;
        // A substep cut short says nothing about the size the error allows.
        if (!limited)
          d.proposed_step = std::min(
              dt, h * std::min(2.0, 0.9 * std::cbrt(tolerance / std::max(error, 1e-300))));
        continue;
      }
    }
    ++d.stats.rejected;
    ++failures;
    // Error too large: the substep that would just meet the tolerance (the error grows as h^3),
    // with a margin. Projection failed: half the substep.
    const double next = projected ? h * std::max(0.2, 0.9 * std::cbrt(tolerance / error))
                                  : 0.5 * h;
    if (longest < smallest || next < smallest || failures > kMaxSubstepRejections) {
      std::ostringstream os;
      os << "the inextensible step cannot be made accurate at t = " << s.t << " s: ";
      if (longest < smallest)
        os << "its tensions (up to " << d.forces.tension.cwiseAbs().maxCoeff()
           << " N) allow substeps of only " << longest << " s (are the ends pulled as far apart "
           << "as the cable is long?)";
      else if (projected)
        os << "a substep of " << h << " s has a local position error of " << error
           << " m against the tolerance of " << tolerance << " m";
      else
        os << "a substep of " << h << " s cannot keep the link lengths (are the ends pulled "
           << "further apart than the cable is long?)";
      if (longest >= smallest) os << ", " << failures << " rejections in a row";
      os << "; the smallest substep is " << smallest << " s (" << kSmallestSubstep
         << " of the step asked)";
      throw BlowUpError(os.str(), s.t, m.line.links);
    }
    d.proposed_step = next;
  }
  s.t = t_end;
  CheckStateSane(m, s, d.forces.geometry.length);
}

}  // namespace cablefilm
