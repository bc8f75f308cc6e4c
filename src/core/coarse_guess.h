#pragma once
// A long line's first guess for its static equilibrium: the same line with each section's
// links merged k at a time, solved, and its shape laid onto the line's stations along the
// unstretched arc length. Newton from the chord (EquilibriumGuess) takes a dozen or more
// iterations, each over every station; from the coarse line's shape, which differs from the
// line's by the discretisation's O((k l)^2), a few (the statics at 60 000 links).
// The coarse line is itself solved from its own coarse copy when it is long, k about 10 at
// each level: a chain on the seabed laid onto 10^6 links from 300 put its touchdown 1 m (2 000
// stations) off, and the seabed's contacts then moved some 100 stations a Newton step.
#include <optional>
#include <vector>

#include "core/cancel.h"
#include "core/line_equilibrium.h"
#include "core/line_model.h"
#include "core/model.h"

namespace cablefilm {

// Lines of fewer links solve as fast from the chord (and their results stay as they were).
constexpr int kCoarseGuessFromLinks = 2000;

// What a line is made of (MakeLineModel's arguments besides its ends): what its coarse copies
// are made from.
struct LineMaking {
  std::vector<SectionSpec> sections;
  std::vector<PrismSpec> prisms;
  EnvironmentSpec env;
  LinkLaw law = LinkLaw::kElastic;
};

// The guess for the line `m` made of `making`, or none: too few links, no merge that keeps
// every section whole and every weight on a station, or a coarse line with no equilibrium (the
// line itself then goes from the chord and says why if it fails too). The coarse solves share
// options.work's bound (StaticsWorkError past it). Throws CancelledError.
std::optional<Points> CoarseEquilibriumGuess(const LineModel& m, const LineMaking& making,
                                             const LineEquilibriumOptions& options);
// Line i of `model` (its sections and prisms).
std::optional<Points> CoarseEquilibriumGuess(const Model& model, int i, const CancelFlag* cancel);

// The statics of the line `m` made of `making`: from its coarse copies' shape when it is long
// (Newton from it in the full current, the continuation from still water only if that fails),
// else from EquilibriumGuess. Throws as SolveLineEquilibrium.
State SolveLongLineEquilibrium(const LineModel& m, const LineMaking& making,
                               LineEquilibriumReport* report,
                               const LineEquilibriumOptions& options);

}  // namespace cablefilm
