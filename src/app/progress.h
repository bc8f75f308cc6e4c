#pragma once
// A progress line for long work: shown on a terminal (stderr), updated in place a few times a
// second with the fraction done and an estimate of the time left; silent when not on one.
#include <chrono>
#include <string>

namespace cablefilm {

class ProgressLine {
 public:
  ProgressLine(std::string label, double total, std::string unit);
  ~ProgressLine();
  void Update(double done);
  void Finish();  // clears the line

 private:
  std::string label_, unit_;
  double total_;
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace cablefilm
