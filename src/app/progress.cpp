#include "app/progress.h"

#include "core/relaxation.h"

#include <cstdio>
#include <unistd.h>

namespace cablefilm {

ProgressLine::ProgressLine(std::string label, double total, std::string unit)
    : label_(std::move(label)), unit_(std::move(unit)), total_(total),
      enabled_(::isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()),
      last_(start_) {}

ProgressLine::~ProgressLine() { Finish(); }

std::function<void(double)> StaticsProgress::relaxing() {
  return [this](double f) {
    if (newton_) newton_->Finish();  // Newton gave way to the motion
    Show(motion_,
         "the system's own motion (at most " +
             std::to_string(static_cast<int>(kLongestRelaxation)) + " s, " +
             std::to_string(kMostRelaxationSteps) + " steps)",
         f);
  };
}

void StaticsProgress::Show(std::optional<ProgressLine>& line, const std::string& what,
                           double fraction) {
  if (!line) line.emplace("static equilibrium: " + what, 1, "");
  line->UpdateBound(fraction);
}

void ProgressLine::Update(double done) {
  char amount[96];
  std::snprintf(amount, sizeof amount, " %.1f / %.1f %s", done, total_, unit_.c_str());
  Show(total_ > 0 ? done / total_ : 0, amount, "");
}

void ProgressLine::UpdateBound(double fraction) { Show(fraction, "", "at most "); }

void ProgressLine::Show(double fraction, const char* amount, const char* bound) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::milliseconds(200)) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double left = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
  std::fprintf(stderr, "\r%s%s (%3.0f%%), %s%.0f s left   ", label_.c_str(), amount,
               100 * fraction, bound, left);
  std::fflush(stderr);
  shown_ = true;
}

void ProgressLine::Finish() {
  if (!shown_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  shown_ = false;
}

}  // namespace cablefilm
