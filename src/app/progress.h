#pragma once
// A progress line for long work: shown on a terminal (stderr), updated in place a few times a
// second with the fraction done and an estimate of the time left; silent when not on one.
#include <chrono>
#include <functional>
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

// The progress line of a system's statics while their relaxation moves it
// (core/system_relaxation.h), against its bound (the time left is at most what it shows):
// `fraction` is what run/system_run.h's `relaxing` takes.
class RelaxationProgress {
 public:
  RelaxationProgress();
  std::function<void(double)> fraction() {
    return [this](double f) { line_.UpdateBound(f); };
  }

 private:
  ProgressLine line_;
};

}  // namespace cablefilm
