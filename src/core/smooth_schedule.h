#pragma once
// A quantity changed while a simulation runs (an amplitude scale, a clock rate, a current) that
// must not jump: each change ramps from the old target to the new one along the quintic
// "smootherstep" h(u) = 10u^3 - 15u^4 + 6u^5, u = (t - t0) / duration, whose first and second
// derivatives vanish at both ends. Changes are superposed, so a change made while an earlier one
// is still ramping stays smooth too:
//   q(t) = base + sum_k dq_k h(u_k),
// and q, dq/dt, d2q/dt2 and the integral of q from 0 are all continuous. A prescribed end
// driven through such a schedule keeps a continuous position, velocity and acceleration.
// Fixed-size storage: no allocation, copyable by value (it lives inside EndMotion).
#include <array>

namespace cablefilm {

class SmoothSchedule {
 public:
  static constexpr int kMaxRamps = 32;  // changes ramping at once; Change() refuses more

  explicit SmoothSchedule(double value = 0) : base_(value), target_(value) {}

  // Starts a change to `target` at time t0 [s], complete after `duration` [s] (> 0). Returns
  // false (and changes nothing) when kMaxRamps changes are still ramping.
  bool Change(double t0, double target, double duration);
  // Folds the ramps complete at time t into the base (keeps the storage free); exact.
  void Retire(double t);

  struct Value {
    double value = 0;     // q(t)
    double rate = 0;      // dq/dt [1/s]
    double rate2 = 0;     // d2q/dt2 [1/s^2]
    double integral = 0;  // integral of q from 0 to t [s]
  };
  Value At(double t) const;
  double ValueAt(double t) const { return At(t).value; }

  double target() const { return target_; }  // the value once every ramp is complete
  bool constant() const { return count_ == 0; }
  int ramping() const { return count_; }

 private:
  struct Ramp {
    double t0 = 0, duration = 1, delta = 0;
  };
  double base_;              // q once the retired ramps are complete
  double integral_offset_ = 0;  // integral of q = base_ t + integral_offset_ (retired ramps)
  double target_;
  std::array<Ramp, kMaxRamps> ramps_{};
  int count_ = 0;
};

}  // namespace cablefilm
