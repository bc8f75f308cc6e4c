#include "core/coarse_guess.h"

#include <algorithm>

#include "core/error.h"
#include "core/line_equilibrium.h"

namespace cablefilm {
namespace {

// The coarse line: about kCoarseLinks links (the solve costs a tenth or less of the line's
// and its shape is within (k l)^2 of the line's); k divides every section's links.
constexpr int kCoarseLinks = 300;

// The stations of `coarse` (positions at arc lengths s_c) at the arc lengths s of `fine`,
// linear between them [m].
Points LaidOnto(const LineModel& coarse, const Points& xc, const LineModel& fine) {
  Points x(kDim, fine.stations());
  int i = 0;
  for (int j = 0; j < fine.stations(); ++j) {
    const double s = fine.line.arc_length[j];
    while (i < coarse.line.links - 1 && coarse.line.arc_length[i + 1] < s) ++i;
    const double s0 = coarse.line.arc_length[i], s1 = coarse.line.arc_length[i + 1];
    const double f = std::clamp((s - s0) / (s1 - s0), 0.0, 1.0);
    x.col(j) = (1.0 - f) * xc.col(i) + f * xc.col(i + 1);
  }
  return x;
}

}  // namespace

std::optional<Points> CoarseEquilibriumGuess(const Model& model, int i, const CancelFlag* cancel) {
  const LineModel& m = model.lines[i];
  if (m.line.links < kCoarseGuessFromLinks || m.line.law != LinkLaw::kElastic) return {};
  // The largest merge that leaves at least kCoarseLinks links, keeps each section's links
  // whole and each weight on a station; smaller ones if the weights forbid it.
  for (int k = m.line.links / kCoarseLinks; k >= 2; --k) {
    std::vector<SectionSpec> sections = model.line_specs[i].sections;
    bool whole = true;
    for (SectionSpec& s : sections) {
      whole = whole && s.segments % k == 0;
      s.segments /= k;
    }
    std::vector<PrismSpec> prisms = model.line_prisms[i];
    for (PrismSpec& p : prisms) {
      whole = whole && p.station % k == 0;  // a weight between the coarse stations
      p.station /= k;
    }
    if (!whole) continue;
    const LineModel cm = MakeLineModel(sections, prisms, model.env, m.ends.start, m.ends.end, m.line.law);
    try {
      LineEquilibriumOptions options;
      options.cancel = cancel;
      const State s = SolveLineEquilibrium(cm, nullptr, options);
      return LaidOnto(cm, s.x, m);
    } catch (const CancelledError&) {
      throw;
    } catch (const Error&) {
      return {};
    }
  }
  return {};
}

}  // namespace cablefilm
