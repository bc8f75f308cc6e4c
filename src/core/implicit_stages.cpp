#include "core/implicit_stages.h"

#include "core/force_jacobian.h"
#include "core/seabed_friction.h"

namespace cablefilm {
namespace {

// a_{n+1}, v_{n+1} and abar_{n+1} (scratch a, v, abar) implied by the positions x (free
// stations).
void Kinematics(const LineModel& m, LineData& d, const GeneralizedAlpha& c, double h, const Points& x) {
  const State& s = d.state;
  Scratch& w = d.scratch;
  // Over the free stations' columns at once (contiguous: vectorized), each entry computed as
  // a column at a time would.
  const int j0 = m.first_free(), n = m.last_free() - j0 + 1;
  if (n <= 0) return;
  auto abar = w.abar.middleCols(j0, n);
  const auto abar_n = d.abar.middleCols(j0, n);
  abar = (x.middleCols(j0, n) - s.x.middleCols(j0, n) - h * s.v.middleCols(j0, n) -
          h * h * (0.5 - c.beta) * abar_n) /
         (h * h * c.beta);
  w.a.middleCols(j0, n) =
      ((1.0 - c.am) * abar + c.am * abar_n - c.af * d.a.middleCols(j0, n)) / (1.0 - c.af);
  w.v.middleCols(j0, n) =
      s.v.middleCols(j0, n) + h * (1.0 - c.gamma) * abar_n + h * c.gamma * abar;
}

}  // namespace

void PredictStep(const LineModel& m, LineData& d, const Inputs& in, const GeneralizedAlpha& c,
                 double h) {
  const State& s = d.state;
  Scratch& w = d.scratch;
  const double t1 = s.t + h;
  // Predictor: the pseudo-acceleration carried over, and its rate of change over the last step
  // too. The step sets x_{n+1} - (x_n + h v_n + h^2/2 abar_n) = h^2 beta (abar_{n+1} - abar_n),
  // so a linear extrapolation of abar leaves Newton's first correction the curvature of abar
  // alone: on P63 at 6000 links 1e-6 m instead of 1e-5, whose smaller turn of the links lets
  // the kept matrix converge at once (2.3 Newton iterations a step instead of 4.1, 0.6 of the
  // time; at 600 links 2.0 instead of 2.4, at 60 links 2.0 either way). Only while the line is
  // taut and clear of the seabed (LineData::smooth): where links go slack and taut or stations
  // land, the accelerations jump, and on the spread mooring a slope cost 7 % more iterations;
  // and only after a step no shorter than this one (a slope over a shorter step is mostly the
  // scheme's damped ringing, which the longer step multiplies: rejected steps doubled).
  w.x = s.x;
  const bool slope = d.smooth && h <= d.last_step;  // (not smooth before the first step)
  const double r = slope ? c.beta * h * h * h / d.last_step : 0.0;  // [s^2]
  for (int j = m.first_free(); j <= m.last_free(); ++j) {
    w.x.col(j) += h * s.v.col(j) + 0.5 * h * h * d.abar.col(j);
    if (slope) w.x.col(j) += r * (d.abar.col(j) - d.abar_before.col(j));
  }
  for (int j : {0, m.line.links}) {
    if (!m.prescribed(j)) continue;
    w.x.col(j) = EndPosition(m, in, j, t1);
    w.v.col(j) = EndVelocity(m, in, j, t1);
  }
}

bool KeepsNewtonMatrix(const LineModel& m) {
  return !(m.env.seabed.present && m.env.seabed.friction > 0);
}

bool AssembleNewton(const LineModel& m, LineData& d, const GeneralizedAlpha& c, double h,
                    bool jacobian) {
  Scratch& w = d.scratch;
  ForceWorkspace& ws = d.forces;
  BlockTridiagonal& system = w.system;
  const int j0 = m.first_free(), j1 = m.last_free();
  const double t1 = d.state.t + h;
  const double ka = (1.0 - c.am) / ((1.0 - c.af) * c.beta * h * h);  // d a_{n+1} / d x_{n+1}
  const double kv = c.VelocityPerPosition(h);                        // d v_{n+1} / d x_{n+1}
  ++d.stats.newton_iterations;
  Kinematics(m, d, c, h, w.x);
  ComputeGeometry(m, d.water, t1, w.x, ws.geometry);
  ComputeTensions(m, ws.geometry, w.v, ws.tension);
  ComputeStationForces(m, d.water, ws.geometry, ws.tension, w.v, ws.force);
  // A link's axial stiffness is in the matrix while it is taut (force_jacobian.cpp).
  bool same = true;
  for (int k = 0; k < m.line.links; ++k) {
    const char taut = ws.geometry.length[k] > m.line.rest_length[k] && ws.tension[k] > 0;
    if (jacobian) w.matrix_taut[k] = taut;
    else same = same && w.matrix_taut[k] == taut;
  }
  if (jacobian) {
    SetInertiaJacobian(m, ws.geometry, w.a, ka, system);
    AddForceJacobian(m, d.water, ws.geometry, ws.tension, w.v, kv, system);
  }
  for (int j = j0; j <= j1; ++j)
    system.rhs[j - j0] = ws.force.col(j) - StationInertiaTimes(m, ws.geometry, j, w.a.col(j));
  return same;
}

bool FindSnappingLinks(const LineModel& m, LineData& d) {
  Scratch& w = d.scratch;
  const std::vector<Vec>& dx = w.system.rhs;
  const LinkGeometry& g = d.forces.geometry;
  const int j0 = m.first_free(), j1 = m.last_free();
  auto step = [&](int j) { return j >= j0 && j <= j1 ? dx[j - j0] : Vec::Zero(); };
  bool found = false;
  for (int k = 0; k < m.line.links; ++k) {
    if (w.snapping[k] || !(g.length[k] < m.line.rest_length[k])) continue;
    const Vec stepped = g.length[k] * g.tangent.col(k) + step(k + 1) - step(k);
    if (stepped.norm() > m.line.rest_length[k]) w.snapping[k] = found = true;
  }
  return found;
}

void ClearSnappingLinks(LineData& d) {
  std::fill(d.scratch.snapping.begin(), d.scratch.snapping.end(), 0);
}

void KeepResidual(LineData& d) { d.scratch.residual = d.scratch.system.rhs; }

void RestoreResidual(LineData& d) { d.scratch.system.rhs = d.scratch.residual; }

void AddSnappingLinks(const LineModel& m, LineData& d) {
  Scratch& w = d.scratch;
  BlockTridiagonal& s = w.system;
  const LinkGeometry& g = d.forces.geometry;
  const int j0 = m.first_free(), j1 = m.last_free();
  RestoreResidual(d);
  for (int k = 0; k < m.line.links; ++k) {
    if (!w.snapping[k]) continue;
    const Vec t = g.tangent.col(k);
    const double EA = m.line.axial_stiffness[k], l = m.line.rest_length[k];  // [N], [m]
    const Vec pull = (EA * (g.length[k] - l) / l) * t;  // [N] on station k; minus on k + 1
    const int a = k, c = k + 1;
    const bool fa = a >= j0 && a <= j1, fc = c >= j0 && c <= j1;
    if (fa) s.rhs[a - j0] += pull;
    if (fc) s.rhs[c - j0] -= pull;
    if (w.snapping[k] == 2) continue;  // its stiffness is in the matrix already
    w.snapping[k] = 2;
    w.matrix_taut[k] = 1;  // the matrix holds its taut stiffness: kept while it stays taut
    const Mat B = (EA / l) * (t * t.transpose());  // -dF_k/dx_k, as force_jacobian.cpp's
    if (fa) s.diag[a - j0] += B;
    if (fa && fc) s.upper[a - j0] -= B, s.lower[c - j0] -= B;
    if (fc) s.diag[c - j0] += B;
  }
}

double CorrectionSize(const LineModel& m, const LineData& d) {
  const std::vector<Vec>& dx = d.scratch.system.rhs;
  double size = 0;
  for (int j = 0; j <= m.last_free() - m.first_free(); ++j) {
    const double s = dx[j].norm();
    if (std::isnan(s)) return s;
    size = std::max(size, s);
  }
  return size;
}

namespace {

// The part of station j's correction dx [m] that Newton may apply along the bed. A station
// sliding one way whose correction would have it slide the other way has crossed its stick
// zone (|K l_j s + C_j v_h| <= mu N_j, seabed_friction.h), of width 2 mu N_j / (K l_j) along
// the slide: micrometres where it just touches the bed. On either sliding branch Newton's
// model has the line's stiffness alone (the friction is mu N_j whatever the slip), so it
// steps over the zone to the other branch and back, the same correction each way, and the
// step was rejected (460 of grounded_chain.toml's 556 rejected steps, the station at the
// touchdown). The step stops where the sticking force's component along the old slide
// vanishes (the force is linear in the step there: K l_j + C_j kv per metre), inside the
// zone, where the next iteration sees the stick tangent. Where the answer is sliding the
// other way, the iterations get there from the zone as from any sticking state.
Vec FrictionStep(const LineModel& m, const Scratch& w, const LinkGeometry& g, double kv, int j,
                 const Vec& dx) {
  const SeabedSpec& bed = m.env.seabed;
  const double p = bed.y - w.x(kVertical, j);  // penetration [m]
  if (!(p > 0) || g.stick.cols() == 0) return dx;
  const double K = m.line.friction_stiffness[j], C = m.line.friction_damping[j];  // [N/m], [N s/m]
  const double limit = bed.friction * SeabedNormal(m, j, p, w.v(kVertical, j)).N;  // mu N [N]
  const Vec trial = -(K * g.stick.col(j) + C * HorizontalPart(w.v.col(j)));      // [N]
  const double size = trial.norm();
  if (!(size > limit)) return dx;  // sticking
  const Vec u = trial / size;      // the slide's force direction
  const Vec step = HorizontalPart(dx);
  const double per_metre = K + C * kv;  // [N/m]
  // A zone narrower than the station's position can resolve (a friction of 1e-15 or less:
  // mu N_j / (K l_j) below a few units in the last place of x_j) cannot be landed in, and
  // cutting there never ends; stepping over it changes the force by 2 mu N_j, a friction too
  // small for Newton to see, so the step goes whole.
  const double resolution = 16 * std::numeric_limits<double>::epsilon() *
                            (w.x.col(j).cwiseAbs().maxCoeff() + 1.0);  // [m]
  if (limit / per_metre < resolution) return dx;
  const Vec after = trial - per_metre * step;
  if (!(after.dot(u) < 0) || !(after.norm() > limit)) return dx;  // no reversal past the zone
  const double along = per_metre * step.dot(u);  // > size here
  return dx - (1.0 - size / along) * step;
}

}  // namespace

double ApplyCorrection(const LineModel& m, LineData& d, double kv, bool* contact_changed, bool* cut) {
  Scratch& w = d.scratch;
  const BlockTridiagonal& system = w.system;
  const SeabedSpec& bed = m.env.seabed;
  const bool sticks = HasStickSlip(m);
  const int j0 = m.first_free(), j1 = m.last_free();
  double dx_max = 0;
  bool changed = false, shortened = false;
  for (int j = j0; j <= j1; ++j) {
    const bool above_bed = bed.present && w.x(1, j) >= bed.y;
    const Vec& dx = system.rhs[j - j0];
    if (sticks && !above_bed) {
      const Vec step = FrictionStep(m, w, d.forces.geometry, kv, j, dx);
      shortened = shortened || step != dx;
      w.x.col(j) += step;
    } else {
      w.x.col(j) += dx;
    }
    const double size = dx.norm();
    if (!(size <= dx_max) && !std::isnan(dx_max)) dx_max = size;  // a NaN stays
    if (bed.present && above_bed != (w.x(1, j) >= bed.y)) changed = true;
    // A station above the seabed that the iteration would drive into it (its linear model
    // knows nothing of the bed) lands at its resting penetration instead: otherwise the next
    // iteration, in the bed's stiff spring and dashpot, throws it back above and Newton
    // cycles between the two (a touchdown at a fixed step of 0.05 s blew up so).
    if (above_bed && w.x(1, j) < bed.y - m.line.seabed_rest_depth[j])
      w.x(1, j) = bed.y - m.line.seabed_rest_depth[j];
  }
  if (contact_changed) *contact_changed = changed;
  if (cut) *cut = shortened;
  return dx_max;
}

void FinishSolve(const LineModel& m, LineData& d, const GeneralizedAlpha& c, double h) {
  ForceWorkspace& ws = d.forces;
  Kinematics(m, d, c, h, d.scratch.x);
  ComputeGeometry(m, d.water, d.state.t + h, d.scratch.x, ws.geometry);
  ComputeTensions(m, ws.geometry, d.scratch.v, ws.tension);
}

double LocalError(const LineModel& m, const LineData& d, const GeneralizedAlpha& c, double h) {
  // Zienkiewicz & Xie's estimate for Newmark-type schemes: the step's position error is the
  // cubic term the scheme misses, h^2 |beta - 1/6| |a_{n+1} - a_n|.
  const SeabedSpec& bed = m.env.seabed;
  const Scratch& w = d.scratch;
  double da = 0;
  for (int j = m.first_free(); j <= m.last_free(); ++j) {
    // A station in the seabed at the step's end: its vertical acceleration jumps as the bed
    // takes its weight (a landing). How the step resolves that does not carry on: the bed's
    // critically damped spring leaves the station at rest at its resting penetration either
    // way, so the error there is of the penetration's scale (millimetres) and does not grow.
    // Resolving it cost 1.5 times the steps near a moving touchdown, for a larger tension error
    // (docs/model.md, "Seabed"). Along the bed (x and z) it is measured as anywhere.
    if (bed.present && w.x(kVertical, j) < bed.y) {
      da = std::max({da, std::abs(w.a(0, j) - d.a(0, j)), std::abs(w.a(2, j) - d.a(2, j))});
      continue;
    }
    da = std::max(da, (w.a.col(j) - d.a.col(j)).lpNorm<Eigen::Infinity>());
  }
  return h * h * std::abs(c.beta - 1.0 / 6.0) * da;
}

void SettleLandings(const LineModel& m, LineData& d, double h) {
  // A bed damped at least critically stops a landing station within about its landing time
  // sqrt(m_j / k_j) (1 ms for steel wire, 2 ms for chain on the default bed, at any link
  // length). A step longer than that cannot resolve the stop: the scheme's answer to the
  // unresolved stiff contact threw the station back up by millimetres, to land again and again,
  // each landing a short step (2.5 times the resolved run's landings on a ship-driven line). So
  // a landing step ends with the station at rest vertically, the state a resolved landing
  // reaches within the step; the line's own motion still lifts it when it does
  // (SeabedDynamics.LandingsStopWithoutRebound). On the grounded mooring scene: 20 % fewer
  // steps, a third of the rejections, tensions as close to the converged explicit run's.
  const SeabedSpec& bed = m.env.seabed;
  if (!bed.present) return;
  Scratch& w = d.scratch;
  bool settled = false;
  for (int j = m.first_free(); j <= m.last_free(); ++j) {
    const bool landed = d.state.x(1, j) >= bed.y && w.x(1, j) < bed.y;
    if (!landed || !(h > m.line.seabed_landing_time[j])) continue;
    w.v(1, j) = 0;
    w.a(1, j) = 0;
    w.abar(1, j) = 0;
    settled = true;
  }
  // The tensions' axial damping sees the velocities.
  if (settled) ComputeTensions(m, d.forces.geometry, w.v, d.forces.tension);
}

void Commit(const LineModel& m, LineData& d, double h) {
  State& s = d.state;
  Scratch& w = d.scratch;
  s.x.swap(w.x);
  s.v.swap(w.v);
  // A station at rest (on the seabed) sees its velocity and acceleration decay geometrically
  // step by step, down to subnormal numbers, whose arithmetic (in drag's q |q|, say) is a hundred
  // times slower: a grounded line ran 25 % slower from the minute its anchor end came to rest.
  // Below 1e-100 (m/s, m/s^2) they are zero.
  auto flush = [](double& q) {
    if (std::abs(q) < 1e-100) q = 0;
  };
  for (int j = m.first_free(); j <= m.last_free(); ++j) {
    for (int i = 0; i < kDim; ++i) {
      flush(s.v(i, j));
      flush(w.a(i, j));
      flush(w.abar(i, j));
    }
    d.a.col(j) = w.a.col(j);
    d.abar_before.col(j) = d.abar.col(j);
    d.abar.col(j) = w.abar.col(j);
  }
  UpdateFrictionAnchors(m, s.x, s.v, d.forces.geometry);
  d.last_step = h;
  d.smooth = true;
  for (int k = 0; k < m.line.links && d.smooth; ++k) d.smooth = d.forces.tension[k] > 0;
  for (int j = m.first_free(); j <= m.last_free() && d.smooth && m.env.seabed.present; ++j)
    d.smooth = s.x(kVertical, j) >= m.env.seabed.y;
  s.t += h;
  ++d.stats.steps;
  d.snaps.Observe(s.t, h, d.forces.geometry.length);
}

int WorstLink(const LineModel& m, const LineData& d) {
  int worst = 0;
  d.forces.geometry.length.cwiseQuotient(m.line.rest_length).maxCoeff(&worst);
  return worst;
}

}  // namespace cablefilm
