#pragma once
// A long line's first guess for its static equilibrium: the same line with each section's
// links merged k at a time, solved, and its shape laid onto the line's stations along the
// unstretched arc length. Newton from the chord (EquilibriumGuess) takes a dozen or more
// iterations, each over every station; from the coarse line's shape, which differs from the
// line's by the discretisation's O(l^2), a few (the statics at 60 000 links).
#include <optional>

#include "core/cancel.h"
#include "core/line_model.h"
#include "core/model.h"

namespace cablefilm {

// Lines of fewer links solve as fast from the chord (and their results stay as they were).
constexpr int kCoarseGuessFromLinks = 2000;

// The guess for line i of `model` (its sections and prisms), or none: too few links, no merge
// that keeps every section whole and every weight on a station, or a coarse line with no
// equilibrium (the line itself then goes from the chord and says why if it fails too).
// Throws CancelledError.
std::optional<Points> CoarseEquilibriumGuess(const Model& model, int i, const CancelFlag* cancel);

}  // namespace cablefilm
