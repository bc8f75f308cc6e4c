#include "core/chain_guess.h"

#include <algorithm>

#include "core/coarse_guess.h"
#include "core/line_equilibrium.h"

namespace cablefilm {
namespace {

// A line of a chain, walked from its end `from` (0: station 0, 1: station s) to its other.
struct ChainLink {
  int line = 0;
  int from = 0;
};

// A free point where exactly two ends of two different lines meet: a joint of a chain.
bool IsJoint(const Model& sys, int p) {
  const Point& point = sys.points[p];
  return point.kind == PointKind::kFree && point.shared >= 0 && point.ends.size() == 2 &&
         point.ends[0].line != point.ends[1].line;
}

bool Held(const Model& sys, int line, int e) {
  const LineModel& m = sys.lines[line];
  return (e == 0 ? m.ends.start : m.ends.end).prescribed();
}

// The chain that starts at line i's held end e (its lines in order), or empty when the walk
// does not end at a held end of another line through joints only.
std::vector<ChainLink> Walk(const Model& sys, int i, int e) {
  std::vector<ChainLink> chain{{i, e}};
  for (size_t guard = 0; guard < sys.lines.size(); ++guard) {
    const ChainLink& last = chain.back();
    const int to = 1 - last.from;
    const int p = sys.line_points[last.line][to];
    if (!IsJoint(sys, p)) {
      if (chain.size() >= 2 && Held(sys, last.line, to)) return chain;
      return {};
    }
    const int station = to == 0 ? 0 : sys.lines[last.line].line.links;
    const Point& joint = sys.points[p];
    const LineEnd& next = joint.ends[0].line == last.line && joint.ends[0].station == station
                              ? joint.ends[1] : joint.ends[0];
    for (const ChainLink& l : chain)
      if (l.line == next.line) return {};  // a loop
    chain.push_back({next.line, next.station == 0 ? 0 : 1});
  }
  return {};
}

// The chain as one line: its lines' sections end to end (a line walked from its station s
// reversed), their weights and the joints' own terms as prisms at their stations, held where
// its first and last lines are held; and what it is made of (its coarse copies' making).
struct ChainLine {
  LineMaking making;
  LineModel model;
};
ChainLine ChainModel(const Model& sys, const std::vector<ChainLink>& chain) {
  std::vector<SectionSpec> sections;
  std::vector<PrismSpec> prisms;
  int offset = 0;
  for (size_t k = 0; k < chain.size(); ++k) {
    const ChainLink& l = chain[k];
    const LineSpec& spec = sys.line_specs[l.line];
    const int n = sys.lines[l.line].line.links;
    if (l.from == 0) sections.insert(sections.end(), spec.sections.begin(), spec.sections.end());
    else sections.insert(sections.end(), spec.sections.rbegin(), spec.sections.rend());
    for (PrismSpec prism : spec.prisms) {
      prism.station = offset + (l.from == 0 ? prism.station : n - prism.station);
      prisms.push_back(prism);
    }
    offset += n;
    if (k + 1 < chain.size()) {  // the joint at its far end
      PrismSpec joint = sys.point_specs[sys.line_points[l.line][1 - l.from]].body;
      joint.station = offset;
      prisms.push_back(joint);
    }
  }
  const LineModel& first = sys.lines[chain.front().line];
  const LineModel& last = sys.lines[chain.back().line];
  const EndMotion start = chain.front().from == 0 ? first.ends.start : first.ends.end;
  const EndMotion end = chain.back().from == 0 ? last.ends.end : last.ends.start;
  ChainLine line{LineMaking{std::move(sections), std::move(prisms), sys.env, LinkLaw::kElastic},
                 LineModel{}};
  line.model = MakeLineModel(line.making.sections, line.making.prisms, sys.env, start, end,
                             LinkLaw::kElastic);
  return line;
}

}  // namespace

ChainGuess GuessChains(const Model& sys, const CancelFlag* cancel, double* work,
                       double max_work) {
  const int nl = static_cast<int>(sys.lines.size());
  ChainGuess g;
  g.states.resize(nl);
  g.guessed.assign(sys.shared_count(), 0);
  g.shared_positions = Points::Zero(kDim, sys.shared_count());
  // The specs are what the chain is made from (a system made otherwise has none).
  if (static_cast<int>(sys.line_specs.size()) != nl ||
      sys.point_specs.size() != sys.points.size())
    return g;
  std::vector<char> used(nl, 0);
  for (int i = 0; i < nl; ++i)
    for (int e = 0; e < 2; ++e) {
      if (used[i] || !Held(sys, i, e) || !IsJoint(sys, sys.line_points[i][1 - e])) continue;
      const std::vector<ChainLink> chain = Walk(sys, i, e);
      if (chain.empty()) continue;
      for (const ChainLink& l : chain) used[l.line] = 1;
      // A chain too long for the statics' bound as one line is left out (its lines each fit
      // it: the system's Newton starts there from the scene's guess).
      double stations = 1;
      for (const ChainLink& l : chain) stations += sys.lines[l.line].line.links;
      if (kLeastStaticPasses * stations > max_work) continue;
      State rest;
      double own = 0;  // this chain's station-passes, its coarse copies' included
      try {
        // From its coarse copies' shape when long, as a single line's.
        const ChainLine line = ChainModel(sys, chain);
        LineEquilibriumOptions options;
        options.cancel = cancel;
        options.max_work = max_work;
        options.work = &own;
        rest = SolveLongLineEquilibrium(line.model, line.making, nullptr, options);
        if (work) *work += own;
      } catch (const CancelledError&) {
        throw;
      } catch (const StaticsWorkError& e) {
        std::string names;
        for (const ChainLink& l : chain)
          names += (names.empty() ? "\"" : ", \"") + sys.line_names[l.line] + "\"";
        throw StaticsWorkError("the chain of lines " + names + " solved as one line: " +
                               e.what());
      } catch (const Error&) {
        if (work) *work += own;
        continue;  // the system's Newton from the scene's guesses
      }
      int offset = 0;
      for (size_t k = 0; k < chain.size(); ++k) {
        const ChainLink& l = chain[k];
        const int n = sys.lines[l.line].line.links;
        State& s = g.states[l.line];
        s.t = 0;
        s.x.resize(kDim, n + 1);
        for (int j = 0; j <= n; ++j) s.x.col(j) = rest.x.col(offset + (l.from == 0 ? j : n - j));
        s.v = Points::Zero(kDim, n + 1);
        offset += n;
        if (k + 1 < chain.size()) {
          const int shared = sys.points[sys.line_points[l.line][1 - l.from]].shared;
          g.shared_positions.col(shared) = rest.x.col(offset);
          g.guessed[shared] = 1;
        }
      }
      ++g.chains;
    }
  return g;
}

}  // namespace cablefilm
