#pragma once
// A progress line for long work: shown on a terminal (stderr), updated in place a few times a
// second with the fraction done and an estimate of the time left; silent when not on one.
#include <chrono>
#include <functional>
#include <optional>
#include <string>

namespace cablefilm {

class ProgressLine {
 public:
  ProgressLine(std::string label, double total, std::string unit);
  ~ProgressLine();
  void Update(double done);
  // The fraction of a bound on the work done (the work may end sooner): the time left shown
  // as at most so much.
  void UpdateBound(double fraction);
  void Finish();  // clears the line

 private:
  void Show(double fraction, const char* amount, const char* bound);
  std::string label_, unit_;
  double total_;
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_, last_;
};

// The progress lines of a system's statics, against their bounds (the time left is at most
// what they show): while Newton balances the shared points and bodies, then while the
// relaxation moves the system (core/relaxation.h). `solving` and `relaxing` are what
// run/initial_state.h's MakeInitialState takes (StaticsCallbacks).
class StaticsProgress {
 public:
  std::function<void(double)> solving() {
    return [this](double f) { Show(newton_, "Newton on the shared points and bodies", f); };
  }
  std::function<void(double)> relaxing();

 private:
  void Show(std::optional<ProgressLine>& line, const std::string& what, double fraction);
  std::optional<ProgressLine> newton_, motion_;
};

}  // namespace cablefilm
