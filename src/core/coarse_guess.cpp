#include "core/coarse_guess.h"

#include <algorithm>
#include <sstream>

#include "core/error.h"

namespace cablefilm {
namespace {

// The coarsest copy: about kCoarseLinks links, solved from its chord (its solve costs a tenth
// or less of the line's and its shape is within (k l)^2 of the line's). Each level above it
// merges at most kLevelRatio links into one: the line's Newton then starts within a few of its
// stations of its touchdown, and the levels together cost about a ninth of the line's own solve
// (10^-1 + 10^-2 + ...).
constexpr int kCoarseLinks = 300;
constexpr int kLevelRatio = 10;

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

// `making` with each section's links merged k at a time, k the largest divisor of its links up
// to `most` that keeps each of its weights on a station and its merged links no longer than
// `most` times the line's mean link (a section of a few long links next to one of many short
// ones stays as it is: merged alike, the shipped spread mooring's clump chain had links of 1 and
// 50 m, and Newton crawled on it); none when that leaves more than half the links.
std::optional<LineMaking> Merged(const LineMaking& making, int most) {
  LineMaking merged = making;
  const int n = static_cast<int>(making.sections.size());
  std::vector<int> factor(n), first(n), coarse_first(n);  // per section; first stations
  double length = 0;  // [m]
  int links_in_all = 0;
  for (const SectionSpec& section : making.sections) {
    length += section.length;
    links_in_all += section.segments;
  }
  const double longest = most * length / links_in_all;  // a merged link at most [m]
  int fine = 0, coarse = 0;
  for (int i = 0; i < n; ++i) {
    const int links = making.sections[i].segments;
    const double l = making.sections[i].length / links;  // [m]
    int k = std::min({most, links, static_cast<int>(longest / l * (1 + 1e-9))});
    for (; k > 1; --k) {
      if (links % k != 0) continue;
      bool on_stations = true;
      for (const PrismSpec& p : making.prisms)
        if (p.station >= fine && p.station <= fine + links && (p.station - fine) % k != 0)
          on_stations = false;
      if (on_stations) break;
    }
    factor[i] = std::max(k, 1);  // (a section of links longer than `longest`: 0)
    first[i] = fine;
    coarse_first[i] = coarse;
    merged.sections[i].segments = links / factor[i];
    fine += links;
    coarse += links / factor[i];
  }
  if (2 * coarse > fine) return {};
  for (PrismSpec& p : merged.prisms) {
    int i = 0;
    while (i + 1 < n && p.station > first[i] + making.sections[i].segments) ++i;
    p.station = coarse_first[i] + (p.station - first[i]) / factor[i];
  }
  return merged;
}

}  // namespace

std::optional<Points> CoarseEquilibriumGuess(const LineModel& m, const LineMaking& making,
                                             const LineEquilibriumOptions& options) {
  const int links = m.line.links;
  if (links < kCoarseGuessFromLinks || making.law != LinkLaw::kElastic) return {};
  // The merge: kLevelRatio links into one while the copy would still be long, else down to
  // about kCoarseLinks (the copy then solved from its chord); the other if that one merges too
  // little (the sections' links have no such divisors).
  const int last = std::max(2, links / kCoarseLinks);
  std::vector<int> most{last};
  if (links / kLevelRatio >= kCoarseGuessFromLinks) most.insert(most.begin(), kLevelRatio);
  for (int k : most) {
    const std::optional<LineMaking> coarse = Merged(making, k);
    if (!coarse) continue;
    const LineModel cm =
        MakeLineModel(coarse->sections, coarse->prisms, coarse->env, m.ends.start, m.ends.end,
                      coarse->law);
    LineEquilibriumOptions o;
    o.cancel = options.cancel;
    o.max_work = options.max_work;
    o.work = options.work;
    try {
      const State s = SolveLongLineEquilibrium(cm, *coarse, nullptr, o);
      return LaidOnto(cm, s.x, m);
    } catch (const CancelledError&) {
      throw;
    } catch (const StaticsWorkError&) {
      // Said of this line, not of its copy.
      std::ostringstream os;
      os << "the static equilibrium of its " << m.stations() << " stations gave up at its "
         << "bound of " << options.max_work << " station-passes while solving its coarse copy "
         << "of " << cm.stations() << " stations (each residual, step along the links and "
         << "Newton matrix counts the stations it passes over; a long line's statics take some "
         << "9 to 19 passes over its stations, its copies' included)";
      throw StaticsWorkError(os.str());
    } catch (const Error&) {
      return {};
    }
  }
  return {};
}

std::optional<Points> CoarseEquilibriumGuess(const Model& model, int i, const CancelFlag* cancel) {
  const LineModel& m = model.lines[i];
  if (i >= static_cast<int>(model.line_specs.size()) ||
      i >= static_cast<int>(model.line_prisms.size()))
    return {};
  LineEquilibriumOptions options;
  options.cancel = cancel;
  double work = 0;
  options.work = &work;
  return CoarseEquilibriumGuess(
      m, LineMaking{model.line_specs[i].sections, model.line_prisms[i], model.env, m.line.law},
      options);
}

State SolveLongLineEquilibrium(const LineModel& m, const LineMaking& making,
                               LineEquilibriumReport* report,
                               const LineEquilibriumOptions& options) {
  // The coarse copies' passes and the line's on one count; a line too large for the bound
  // refused before its coarse copies are solved.
  double own = 0;
  LineEquilibriumOptions o = options;
  if (!o.work) o.work = &own;
  RefuseIfTooLarge(m, o);
  if (const std::optional<Points> guess = CoarseEquilibriumGuess(m, making, o)) {
    // Near the answer, in the full current: Newton from it directly (the continuation from
    // still water only if that fails).
    o.warm_start = true;
    return SolveLineEquilibrium(m, *guess, report, o);
  }
  return SolveLineEquilibrium(m, report, o);
}

}  // namespace cablefilm
