// The system's statics start from its chains solved as one line each (core/chain_guess.h):
// a chain-wire-chain leg with a clump weight and a buoy at its joints, its wire written from
// the buoy down (its station 0 at the far joint: the chain is walked against it). The truth: the
// same leg written by hand as one line with the clump and buoy as weights at its stations, and
// the system's own out-of-balance forces at its points.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/chain_guess.h"
#include "core/line_equilibrium.h"
#include "core/equilibrium.h"
#include "test_support.h"

namespace cablefilm {
namespace {

using testing::Chain;

SectionSpec Wire(double length, int segments) {
  SectionSpec s;
  s.length = length;
  s.segments = segments;
  s.diameter = 0.08;
  s.area = 0.0035;
  s.mass_per_length = 30.0;
  s.youngs_modulus = 1e11;
  s.drag_coefficient = 1.2;
  s.added_mass_coefficient = 1.0;
  return s;
}

PrismSpec Clump() {  // 4 t of steel
  PrismSpec p;
  p.mass = 4000;
  p.volume = 0.51;
  p.drag_coefficient = Vec(1.0, 1.0, 1.0);
  p.drag_area = Vec(1.0, 1.0, 1.0);
  return p;
}

PrismSpec Buoy() {  // 3 m^3 that floats 2.5 t
  PrismSpec p;
  p.mass = 500;
  p.volume = 3.0;
  p.drag_coefficient = Vec(0.8, 0.8, 0.8);
  p.drag_area = Vec(2.0, 2.0, 2.0);
  return p;
}

PrismSpec Weight(int station) {  // a 300 kg collar on the wire
  PrismSpec p;
  p.station = station;
  p.mass = 300;
  p.volume = 0.04;
  return p;
}

EnvironmentSpec Sea() {
  EnvironmentSpec env;
  env.fluid_density = 1025;
  env.current = 0.3;
  env.current_direction = Horizontal(0.5);  // across the leg: a 3D shape
  env.seabed.present = true;
  env.seabed.y = -100;
  return env;
}

const Vec kAnchor(0.0, -100.0, 0.0), kFairlead(260.0, -10.0, 0.0);

// anchor -> 150 m chain -> clump -> 120 m wire (written buoy -> clump) -> buoy -> 40 m chain
// -> fairlead.
Model Leg() {
  std::vector<PointSpec> points(4);
  points[0] = {"anchor", EndMotion::Fixed(kAnchor), {}};
  points[1] = {"clump", EndMotion::Free(Vec(120.0, -70.0, 0.0)), Clump()};
  points[2] = {"buoy", EndMotion::Free(Vec(200.0, -50.0, 0.0)), Buoy()};
  points[3] = {"fairlead", EndMotion::Fixed(kFairlead), {}};
  std::vector<LineSpec> lines(3);
  lines[0] = {"lower", {Chain(150, 50)}, {}, LinkLaw::kElastic, 0, 1};
  lines[1] = {"wire", {Wire(120, 40)}, {Weight(10)}, LinkLaw::kElastic, 2, 1};
  lines[2] = {"upper", {Chain(40, 16)}, {}, LinkLaw::kElastic, 2, 3};
  return MakeModel(lines, points, Sea());
}

LineModel LegAsOneLine() {
  PrismSpec clump = Clump(), buoy = Buoy();
  clump.station = 50;
  buoy.station = 90;
  return MakeLineModel({Chain(150, 50), Wire(120, 40), Chain(40, 16)},
                   {clump, Weight(50 + 40 - 10), buoy}, Sea(), EndMotion::Fixed(kAnchor),
                   EndMotion::Fixed(kFairlead), LinkLaw::kElastic);
}

// Largest distance between the system's stations and the one line's [m] (the wire reversed).
double PositionGap(const std::vector<State>& s, const Points& one) {
  double gap = 0;
  for (int j = 0; j <= 50; ++j) gap = std::max(gap, (s[0].x.col(j) - one.col(j)).norm());
  for (int j = 0; j <= 40; ++j) gap = std::max(gap, (s[1].x.col(j) - one.col(90 - j)).norm());
  for (int j = 0; j <= 16; ++j) gap = std::max(gap, (s[2].x.col(j) - one.col(90 + j)).norm());
  return gap;
}

TEST(ChainGuess, ALegThroughTwoJointsIsSolvedAsOneLine) {
  const Model sys = Leg();
  ASSERT_EQ(sys.shared_count(), 2);
  const ChainGuess guess = GuessChains(sys);
  EXPECT_EQ(guess.chains, 1);
  EXPECT_TRUE(guess.guessed[0] && guess.guessed[1]);
  const State one = SolveLineEquilibrium(LegAsOneLine());
  // The guess is the hand-written line's equilibrium, solved from the same first guess: the
  // same to round-off if the chain is put together as that line (sections, the wire reversed,
  // its collar at station 80, the joints' weights at 50 and 90).
  const double guess_gap = PositionGap(guess.states, one.x);
  EXPECT_LT(guess_gap, 1e-9) << "the chain is not the hand-written line";
  EXPECT_LT((guess.shared_positions.col(sys.points[1].shared) - one.x.col(50)).norm(), 1e-9);
  EXPECT_LT((guess.shared_positions.col(sys.points[2].shared) - one.x.col(90)).norm(), 1e-9);
}

TEST(ChainGuess, TheSystemsNewtonStartsAtItsAnswer) {
  const Model sys = Leg();
  EquilibriumReport report;
  const std::vector<State> states = SolveEquilibrium(sys, &report);
  const State one = SolveLineEquilibrium(LegAsOneLine());
  // The system's answer against its own forces (each line's end stations summed at the joints)
  // and the one line's: both solved to 1e-9 of the static load (~400 kN), a station then
  // differs by that force over the stiffness across it (~1e5 N/m): ~4e-9 m.
  const double gap = PositionGap(states, one.x);
  std::printf("[ chain ] joints from the one line: %d outer iterations, stations %.2e m off; "
              "clump at y = %.4f m\n", report.iterations, gap, states[0].x(1, 50));
  EXPECT_LT(gap, 1e-7);
  EXPECT_LE(report.residual, 1e-9 * report.force_scale);
  EXPECT_EQ(report.chains, 1);
  // From the scene's guesses its joints took Newton steps on their own; from the chain's
  // answer at most one (what the two lumpings leave in round-off).
  EXPECT_LE(report.iterations, 1);
  EXPECT_GT(std::abs(states[1].x(2, 20)), 0.5);  // the current bends it out of z = 0
}

// A joint of three lines is not on a chain: its point starts from the scene's guess as before.
TEST(ChainGuess, AJointOfThreeLinesIsLeftToTheSystem) {
  std::vector<PointSpec> points(4);
  points[0] = {"a", EndMotion::Fixed(kAnchor), {}};
  points[1] = {"j", EndMotion::Free(Vec(100.0, -60.0, 0.0)), Clump()};
  points[2] = {"b", EndMotion::Fixed(kFairlead), {}};
  points[3] = {"c", EndMotion::Fixed(Vec(120.0, -10.0, 120.0)), {}};
  std::vector<LineSpec> lines(3);
  // All three taut, nothing on the bed (a grounded chain in this current has no rest).
  lines[0] = {"one", {Chain(100, 30)}, {}, LinkLaw::kElastic, 0, 1};
  lines[1] = {"two", {Wire(180, 30)}, {}, LinkLaw::kElastic, 1, 2};
  lines[2] = {"three", {Wire(135, 30)}, {}, LinkLaw::kElastic, 1, 3};
  const Model sys = MakeModel(lines, points, Sea());
  EXPECT_EQ(GuessChains(sys).chains, 0);
  EquilibriumReport report;
  SolveEquilibrium(sys, &report);
  EXPECT_EQ(report.chains, 0);
  EXPECT_LE(report.residual, 1e-9 * report.force_scale);
}

}  // namespace
}  // namespace cablefilm
