#pragma once
// A first guess for the system's statics (equilibrium.h) where lines meet two at a
// time: a leg of chain, clump weight and wire, or chain-wire-chain joined at free points, runs
// between two held ends and is, at rest, one line with the points' weights at its joints. Solved
// as that one line (single-line statics, from its catenary guess), it gives the joints'
// positions and each line's shape at once; the system's Newton on the points then starts at
// (or within round-off of) its answer. Without it, the points walk from the scene's guesses,
// each trial re-solving their lines: a clump that comes to rest on the seabed took 21 such
// steps and 336 line solves on scenes/spread_mooring.toml.
#include <vector>

#include "core/cancel.h"
#include "core/line_data.h"
#include "core/line_equilibrium.h"
#include "core/model.h"

namespace cablefilm {

struct ChainGuess {
  std::vector<State> states;     // per line: its shape, or empty (x.size() == 0) off any chain
  std::vector<char> guessed;     // per shared point (its index among them): placed below
  Points shared_positions;       // per shared point: where its chain puts it [m]
  int chains = 0;                // chains solved
};

// Finds the chains (shared free points with exactly two line ends, the lines beyond them
// ending at held points) and solves each as one line at rest (from its coarse copies' shape
// when long). A chain whose one-line statics fails is left out (the system's Newton starts
// there from the scene's guess, as before). Each chain's solve is bounded by max_work
// station-passes (StaticsWorkError past it, naming the chain's lines; a chain whose stations
// could not fit is left out), and they are added up in *work when given.
ChainGuess GuessChains(const Model& sys, const CancelFlag* cancel = nullptr,
                       double* work = nullptr, double max_work = kMostLineStaticsWork);

}  // namespace cablefilm
