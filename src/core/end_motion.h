#pragma once
// How an end of the cable (station 0 or s) moves. A prescribed end's position, velocity and
// acceleration are exact functions of time, evaluated at every stage of every step: a
// piecewise-constant end velocity would shake the stiff axial modes.
#include <memory>
#include <vector>

#include "core/smooth_schedule.h"
#include "core/vec.h"

namespace cablefilm {

enum class EndKind {
  kFixed,     // stays at its rest position
  kFree,      // an ordinary station with one link (a dangling or towed end)
  kTrochoid,  // eq. (3) of the paper
  kTable,     // offsets (t, dx, dy) from a table, interpolated in time (TableInterpolation)
};

// How a table's rows are joined in time.
enum class TableInterpolation {
  kSpline,  // natural cubic spline: position, velocity and acceleration continuous
  kLinear,  // piecewise linear: velocity the slope between rows (jumps at a row), no
            // acceleration between rows
};

class EndMotion {
 public:
  static EndMotion Fixed(Vec rest);
  static EndMotion Free(Vec start);
  // Eq. (3): x = x0 + R(t)(a cos wt + b sin wt), y = y0 + R(t)(c cos wt + d sin wt), and in 3D
  // z = z0 + R(t)(e cos wt + f sin wt), R(t) = 1 - (1 + nu t) exp(-nu t): `cos_amplitudes` =
  // (a, c, e), `sin_amplitudes` = (b, d, f) [m].
  static EndMotion Trochoid(Vec rest, Vec cos_amplitudes, Vec sin_amplitudes, double omega,
                            double nu);
  // Eq. (3) over many frequencies under the one ramp R(t): x = x0 + R(t) sum_i (a_i cos w_i t +
  // b_i sin w_i t) and the same for y, z (an end following an irregular sea through its RAOs).
  // At least one harmonic; period() is the largest one's.
  struct Harmonic {
    double omega = 0;        // [rad/s]
    Vec cos = Vec::Zero();   // [m] (or [rad] for a body's angles)
    Vec sin = Vec::Zero();
  };
  static EndMotion Harmonics(Vec rest, std::vector<Harmonic> harmonics, double nu);
  // Rows: times t [s], strictly increasing, at least two, and offsets [m] added to `rest`,
  // joined by `interpolation` on the closed span [t_first, t_last]: at a row the motion is the
  // one arriving at it (the segment before it; the first row: the first segment), so the last
  // row carries the motion's own end velocity. Strictly before the first row and strictly
  // after the last the end holds still at that row (a jump in velocity there if the table
  // starts or ends moving: EndSpeed()).
  static EndMotion Table(Vec rest, const std::vector<double>& times,
                         const std::vector<Vec>& offsets,
                         TableInterpolation interpolation = TableInterpolation::kSpline);

  // The same motion about another rest position (a point of a body that moves as its
  // reference point does).
  EndMotion WithRest(const Vec& rest) const {
    EndMotion m = *this;
    m.rest_ = rest;
    return m;
  }

  // The same motion for a point of a body that also turns (a driven body's, body.h): the point
  // at local position `local` [m] in the body's axes, the body's angles theta [rad] moving as
  // `angles` does (a trochoid or a table over the three angles about x, y, z; its rest() the
  // body's rest angles theta_0; it must not turn itself). The point is then at
  // rest() + offset(t) + (R(theta(t)) - R(theta_0)) local, its velocity and acceleration adding
  // R' local and R'' local (rotation_rates.h); rest() stays the point's rest position. The
  // live view's scale and clock apply to the angles as to the offsets.
  EndMotion WithTurn(const EndMotion& angles, const Vec& local) const;
  bool turns() const { return angles_ != nullptr; }
  // The angles' motion [rad] (turns() only).
  const EndMotion& angles() const { return *angles_; }

  // The same motion with a table's offsets added (a low-frequency drift or a recorded motion on
  // top of a wave-frequency one): `table` a Table() about a rest of zero, evaluated in real
  // time (the live view's scale and clock apply to this motion's own part, not to it). Its
  // kinks (a linear table's rows) are this motion's too.
  EndMotion WithAdded(const EndMotion& table) const;
  bool has_added() const { return added_ != nullptr; }
  const EndMotion& added() const { return *added_; }

  // The same motion, carried by the vessel the live view offsets (a ship's fairlead, a point
  // of a driven or held body): its position, velocity and acceleration then add Inputs'
  // offset (inputs.h), ramped. No run sets it: a run's ends move as the scene says.
  EndMotion Carried() const {
    EndMotion m = *this;
    m.carried_ = true;
    return m;
  }
  bool carried() const { return carried_; }

  EndKind kind() const { return kind_; }
  bool prescribed() const { return kind_ != EndKind::kFree; }
  bool moves() const { return translates() || turns(); }
  const Vec& rest() const { return rest_; }

  // The motion as the scene gives it.
  Vec Position(double t) const;      // [m]
  Vec Velocity(double t) const;      // [m/s]
  Vec Acceleration(double t) const;  // [m/s^2]

  // The motion changed while the cable runs (the live view, inputs.h): the orbit of eq. (3), or
  // the table's offsets, scaled by `scale` (1 = as the scene says), and the motion's own clock
  // running at `clock` times real time (the period becomes period / rate), its phase the
  // integral of the rate, so position, velocity and acceleration stay continuous through a
  // change. The ramp R(t) of eq. (3) keeps real time. Both constant at 1: exactly the scene's.
  // Order 0: position [m], 1: velocity [m/s], 2: acceleration [m/s^2].
  Vec Evaluate(double t, int order, const SmoothSchedule& scale,
               const SmoothSchedule& clock) const;
  double period() const;  // 2 pi / omega_s of eq. (3) [s]; the table's span; 0 otherwise
  double ramp_rate() const { return kind_ == EndKind::kTrochoid ? nu_ : 0.0; }  // nu_s [1/s]

  // A table's: its interpolation, first and last row's times [s], and the speed [m/s] at its
  // last row (what the end loses at once when a run goes on past it).
  TableInterpolation interpolation() const { return interpolation_; }
  double table_start() const { return knot_t_.empty() ? 0 : knot_t_.front(); }
  double table_end() const { return knot_t_.empty() ? 0 : knot_t_.back(); }
  double EndSpeed() const;  // a turning point's: its own speed there, the turn's part included
  // The first time after `t` [s] at which the motion's velocity jumps (a linear table's rows,
  // in the scene's clock), +infinity if none: where an adaptive step should land.
  double NextKink(double t) const;

 private:
  bool translates() const { return own_translates() || added_ != nullptr; }
  bool own_translates() const { return kind_ == EndKind::kTrochoid || kind_ == EndKind::kTable; }
  double OffsetKink(double t) const;  // NextKink of the offsets alone
  Vec At(double t, int order) const;  // as the scene gives it, the turn included
  Vec Evaluate(double t, int order) const;  // the offsets' part (no turn), the added table's in
  Vec Own(double t, int order) const;       // the offsets' part without the added table
  Vec Translation(double t, int order, const SmoothSchedule& scale,
                  const SmoothSchedule& clock) const;
  Vec Scaled(double t, int order, const SmoothSchedule& scale,  // Translation's own part, the
             const SmoothSchedule& clock) const;                // scale and clock applied
  // The turn's part, order 0, 1, 2, from the angles theta [rad] and their rates [rad/s],
  // [rad/s^2]: (R(theta) - R(theta_0)) local [m], R' local [m/s], R'' local [m/s^2].
  Vec TurnPart(const Vec& theta, const Vec& rate, const Vec& rate2, int order) const;
  Vec EvaluateTrochoid(double t, int order) const;
  // The orbit P(tau) of eq. (3) and its first two derivatives, every harmonic summed.
  void Orbit(double tau, Vec p[3]) const;
  Vec EvaluateTable(double t, int order) const;

  EndKind kind_ = EndKind::kFixed;
  Vec rest_ = Vec::Zero();  // x_s^0, y_s^0 [m]
  // Trochoid, eq. (3).
  Vec cos_ = Vec::Zero(), sin_ = Vec::Zero();  // (a, c, e), (b, d, f) [m]
  double omega_ = 0;                      // omega_s [rad/s]
  double nu_ = 0;                         // nu_s [1/s]
  // Harmonics beyond (cos_, sin_, omega_), the largest, of an orbit over many frequencies
  // (Harmonics()); shared: never changed in place.
  std::shared_ptr<const std::vector<Harmonic>> more_;
  // Table: knots and the spline's second derivatives at the knots.
  std::vector<double> knot_t_;
  std::vector<Vec> knot_p_, knot_m_;  // offsets [m]; spline: d2/dt2 [m/s^2] (linear: 0)
  TableInterpolation interpolation_ = TableInterpolation::kSpline;
  bool carried_ = false;  // moved by Inputs::offset_x, offset_z too
  // A point of a turning body: the angles' motion [rad], the point's local position [m] and
  // R(theta_0) local [m]. Shared: the angles' motion is never changed in place.
  std::shared_ptr<const EndMotion> angles_;
  Vec local_ = Vec::Zero(), rest_turn_ = Vec::Zero();
  // A table added to the offsets (WithAdded); shared, never changed in place.
  std::shared_ptr<const EndMotion> added_;
};

}  // namespace cablefilm
