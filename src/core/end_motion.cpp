#include "core/end_motion.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "core/error.h"
#include "core/rotation_rates.h"

namespace cablefilm {

EndMotion EndMotion::Fixed(Vec rest) {
  EndMotion m;
  m.kind_ = EndKind::kFixed;
  m.rest_ = rest;
  return m;
}

EndMotion EndMotion::Free(Vec start) {
  EndMotion m;
  m.kind_ = EndKind::kFree;
  m.rest_ = start;
  return m;
}

EndMotion EndMotion::Trochoid(Vec rest, Vec cos_amplitudes, Vec sin_amplitudes, double omega,
                              double nu) {
  EndMotion m;
  m.kind_ = EndKind::kTrochoid;
  m.rest_ = rest;
  m.cos_ = cos_amplitudes;
  m.sin_ = sin_amplitudes;
  m.omega_ = omega;
  m.nu_ = nu;
  return m;
}

EndMotion EndMotion::Harmonics(Vec rest, std::vector<Harmonic> harmonics, double nu) {
  if (harmonics.empty()) throw Error("internal: an orbit of no harmonic");
  // The largest first: its period is the motion's period().
  const auto size = [](const Harmonic& h) { return h.cos.squaredNorm() + h.sin.squaredNorm(); };
  std::iter_swap(harmonics.begin(),
                 std::max_element(harmonics.begin(), harmonics.end(),
                                  [&](const Harmonic& a, const Harmonic& b) {
                                    return size(a) < size(b);
                                  }));
  EndMotion m = Trochoid(rest, harmonics[0].cos, harmonics[0].sin, harmonics[0].omega, nu);
  if (harmonics.size() > 1)
    m.more_ = std::make_shared<const std::vector<Harmonic>>(harmonics.begin() + 1,
                                                            harmonics.end());
  return m;
}

EndMotion EndMotion::Table(Vec rest, const std::vector<double>& times,
                           const std::vector<Vec>& offsets, TableInterpolation interpolation) {
  if (times.size() < 2 || offsets.size() != times.size())
    throw Error("end motion table needs at least two rows, each a time and an offset");
  EndMotion m;
  m.kind_ = EndKind::kTable;
  m.rest_ = rest;
  m.interpolation_ = interpolation;
  const size_t n = times.size();
  m.knot_t_.resize(n);
  m.knot_p_.resize(n);
  m.knot_m_.assign(n, Vec::Zero());
  for (size_t i = 0; i < n; ++i) {
    m.knot_t_[i] = times[i];
    m.knot_p_[i] = offsets[i];
    if (i > 0 && !(m.knot_t_[i] > m.knot_t_[i - 1]))
      throw Error("end motion table: times must increase strictly (row " + std::to_string(i + 1) +
                  ")");
  }
  if (interpolation == TableInterpolation::kLinear) return m;  // M_i = 0: straight segments
  // Natural cubic spline (zero second derivative at both ends): tridiagonal solve for the
  // second derivatives M_i, so position, velocity and acceleration are all continuous.
  std::vector<double> c_prime(n, 0.0);
  std::vector<Vec> d_prime(n, Vec::Zero());
  for (size_t i = 1; i + 1 < n; ++i) {
    const double h0 = m.knot_t_[i] - m.knot_t_[i - 1];
    const double h1 = m.knot_t_[i + 1] - m.knot_t_[i];
    const Vec rhs =
        6.0 * ((m.knot_p_[i + 1] - m.knot_p_[i]) / h1 - (m.knot_p_[i] - m.knot_p_[i - 1]) / h0);
    const double diag = 2.0 * (h0 + h1) - h0 * c_prime[i - 1];
    c_prime[i] = h1 / diag;
    d_prime[i] = (rhs - h0 * d_prime[i - 1]) / diag;
  }
  for (size_t i = n - 1; i-- > 1;) m.knot_m_[i] = d_prime[i] - c_prime[i] * m.knot_m_[i + 1];
  return m;
}

EndMotion EndMotion::WithTurn(const EndMotion& angles, const Vec& local) const {
  if (angles.turns()) throw Error("end motion: the angles' motion of a turning point turns itself");
  EndMotion m = *this;
  m.angles_ = std::make_shared<const EndMotion>(angles);
  m.local_ = local;
  m.rest_turn_ = RotationInTime(angles.rest(), Vec::Zero(), Vec::Zero()).R * local;
  return m;
}

Vec EndMotion::Position(double t) const { return At(t, 0); }
Vec EndMotion::Velocity(double t) const { return At(t, 1); }
Vec EndMotion::Acceleration(double t) const { return At(t, 2); }

Vec EndMotion::At(double t, int order) const {
  if (!angles_) return Evaluate(t, order);
  // The angles' rates only as far as the order asked needs them (R p needs none).
  const Vec rate = order >= 1 ? angles_->Evaluate(t, 1) : Vec::Zero();
  const Vec rate2 = order >= 2 ? angles_->Evaluate(t, 2) : Vec::Zero();
  return Evaluate(t, order) + TurnPart(angles_->Evaluate(t, 0), rate, rate2, order);
}

Vec EndMotion::TurnPart(const Vec& theta, const Vec& rate, const Vec& rate2, int order) const {
  const RotationRates r = RotationInTime(theta, rate, rate2);
  if (order == 0) return r.R * local_ - rest_turn_;
  if (order == 1) return r.dR * local_;
  return r.d2R * local_;
}

double EndMotion::period() const {
  if (kind_ == EndKind::kTrochoid) return omega_ > 0 ? 2 * 3.14159265358979323846 / omega_ : 0;
  if (kind_ == EndKind::kTable) return knot_t_.back() - knot_t_.front();
  return 0;
}

EndMotion EndMotion::WithAdded(const EndMotion& table) const {
  if (table.kind() != EndKind::kTable || table.turns() || table.has_added())
    throw Error("end motion: an added motion must be a plain table");
  EndMotion m = *this;
  m.added_ = std::make_shared<const EndMotion>(table);
  return m;
}

Vec EndMotion::Evaluate(double t, int order) const {
  if (!added_) return Own(t, order);
  return Own(t, order) + added_->EvaluateTable(t, order);
}

Vec EndMotion::Own(double t, int order) const {
  switch (kind_) {
    case EndKind::kTrochoid:
      return EvaluateTrochoid(t, order);
    case EndKind::kTable:
      return EvaluateTable(t, order);
    case EndKind::kFixed:
    case EndKind::kFree:
      break;
  }
  return order == 0 ? rest_ : Vec::Zero();
}

Vec EndMotion::EvaluateTrochoid(double t, int order) const {
  if (t <= 0) return order == 0 ? rest_ : Vec::Zero();
  // Ramp R(t) = 1 - (1 + nu t) e^{-nu t}; R' = nu^2 t e^{-nu t}; R'' = nu^2 (1 - nu t) e^{-nu t}.
  const double e = std::exp(-nu_ * t);
  const double ramp[3] = {1.0 - (1.0 + nu_ * t) * e, nu_ * nu_ * t * e,
                          nu_ * nu_ * (1.0 - nu_ * t) * e};
  Vec p[3];
  Orbit(t, p);
  if (order == 0) return rest_ + ramp[0] * p[0];
  if (order == 1) return ramp[1] * p[0] + ramp[0] * p[1];
  return ramp[2] * p[0] + 2.0 * ramp[1] * p[1] + ramp[0] * p[2];
}

void EndMotion::Orbit(double tau, Vec p[3]) const {
  // P(t) = (a cos wt + b sin wt, c cos wt + d sin wt) and its derivatives, each harmonic's.
  const double co = std::cos(omega_ * tau), si = std::sin(omega_ * tau);
  p[0] = cos_ * co + sin_ * si;
  p[1] = omega_ * (sin_ * co - cos_ * si);
  p[2] = -omega_ * omega_ * p[0];
  if (!more_) return;
  for (const Harmonic& h : *more_) {
    const double c = std::cos(h.omega * tau), s = std::sin(h.omega * tau);
    const Vec q = h.cos * c + h.sin * s;
    p[0] += q;
    p[1] += h.omega * (h.sin * c - h.cos * s);
    p[2] += -h.omega * h.omega * q;
  }
}

Vec EndMotion::Evaluate(double t, int order, const SmoothSchedule& scale,
                        const SmoothSchedule& clock) const {
  if (!angles_) return Translation(t, order, scale, clock);
  const Vec rate = order >= 1 ? angles_->Evaluate(t, 1, scale, clock) : Vec::Zero();
  const Vec rate2 = order >= 2 ? angles_->Evaluate(t, 2, scale, clock) : Vec::Zero();
  return Translation(t, order, scale, clock) +
         TurnPart(angles_->Evaluate(t, 0, scale, clock), rate, rate2, order);
}

Vec EndMotion::Translation(double t, int order, const SmoothSchedule& scale,
                           const SmoothSchedule& clock) const {
  const bool as_scene = scale.constant() && clock.constant() && scale.target() == 1.0 &&
                        clock.target() == 1.0;
  if (as_scene || !own_translates()) return Evaluate(t, order);
  if (added_) return Scaled(t, order, scale, clock) + added_->EvaluateTable(t, order);
  return Scaled(t, order, scale, clock);
}

Vec EndMotion::Scaled(double t, int order, const SmoothSchedule& scale,
                      const SmoothSchedule& clock) const {
  if (kind_ == EndKind::kTrochoid && t <= 0) return order == 0 ? rest_ : Vec::Zero();
  // offset(t) = G(t) P(tau(t)), G = scale x the ramp R of eq. (3) (1 for a table), tau the
  // motion's clock (tau' = rate); the derivatives by the product and chain rules.
  const SmoothSchedule::Value s = scale.At(t), r = clock.At(t);
  const double tau = r.integral;
  double g[3] = {s.value, s.rate, s.rate2};
  Vec p[3];  // P, dP/dtau, d2P/dtau2
  if (kind_ == EndKind::kTrochoid) {
    const double e = std::exp(-nu_ * t);
    const double ramp[3] = {1.0 - (1.0 + nu_ * t) * e, nu_ * nu_ * t * e,
                            nu_ * nu_ * (1.0 - nu_ * t) * e};
    g[2] = s.rate2 * ramp[0] + 2 * s.rate * ramp[1] + s.value * ramp[2];
    g[1] = s.rate * ramp[0] + s.value * ramp[1];
    g[0] = s.value * ramp[0];
    Orbit(tau, p);
  } else {
    p[0] = EvaluateTable(tau, 0) - rest_;
    p[1] = EvaluateTable(tau, 1);
    p[2] = EvaluateTable(tau, 2);
  }
  // d/dt P(tau) = P' r, d2/dt2 P(tau) = P'' r^2 + P' r'.
  const Vec q0 = p[0], q1 = p[1] * r.value,
                        q2 = p[2] * (r.value * r.value) + p[1] * r.rate;
  if (order == 0) return rest_ + g[0] * q0;
  if (order == 1) return g[1] * q0 + g[0] * q1;
  return g[2] * q0 + 2 * g[1] * q1 + g[0] * q2;
}

double EndMotion::EndSpeed() const {
  return kind_ == EndKind::kTable ? At(knot_t_.back(), 1).norm() : 0.0;
}

double EndMotion::NextKink(double t) const {
  const double own = OffsetKink(t);
  return angles_ ? std::min(own, angles_->OffsetKink(t)) : own;  // the offsets' and the angles'
}

double EndMotion::OffsetKink(double t) const {
  double kink = std::numeric_limits<double>::infinity();
  if (kind_ == EndKind::kTable && interpolation_ == TableInterpolation::kLinear) {
    const auto it = std::upper_bound(knot_t_.begin(), knot_t_.end(), t);
    if (it != knot_t_.end()) kink = *it;
  }
  return added_ ? std::min(kink, added_->OffsetKink(t)) : kink;
}

Vec EndMotion::EvaluateTable(double t, int order) const {
  const size_t n = knot_t_.size();
  // Held strictly outside [t_first, t_last]; the rows themselves are the spline's (line's).
  if (t < knot_t_.front()) return order == 0 ? Vec(rest_ + knot_p_.front()) : Vec::Zero();
  if (t > knot_t_.back()) return order == 0 ? Vec(rest_ + knot_p_.back()) : Vec::Zero();
  // The segment arriving at t: t_i < t <= t_{i+1} (the first segment at t_first). A step that
  // ends on a row sees the velocity it arrives with; the next step, past the row, the next
  // segment's.
  const size_t i = std::min<size_t>(
      n - 2, std::max<std::ptrdiff_t>(
                 0, std::lower_bound(knot_t_.begin(), knot_t_.end(), t) - knot_t_.begin() - 1));
  const double h = knot_t_[i + 1] - knot_t_[i];
  const double A = (knot_t_[i + 1] - t) / h, B = (t - knot_t_[i]) / h;
  const Vec &p0 = knot_p_[i], &p1 = knot_p_[i + 1];
  const Vec &m0 = knot_m_[i], &m1 = knot_m_[i + 1];
  // At a row A or B is exactly 0 or 1, so the position is the row's offset to round-off.
  if (order == 0)
    return rest_ + A * p0 + B * p1 + ((A * A * A - A) * m0 + (B * B * B - B) * m1) * (h * h / 6.0);
  if (order == 1)
    return (p1 - p0) / h + (-(3 * A * A - 1) * m0 + (3 * B * B - 1) * m1) * (h / 6.0);
  return A * m0 + B * m1;
}

}  // namespace cablefilm
