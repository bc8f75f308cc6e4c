// Coupled islands: lines joined at free points, stepped together through the Schur complement
// on the shared stations (coupled_step.h) or by the coupled explicit scheme
// (coupled_explicit_step.h), in equilibrium by Newton on the shared points
// (coupled_equilibrium.h). The truths: the same system written as one line with a weight
// at the junction (a single line's model and step, which the rest of the suite checks against
// closed forms and MoorDyn), and the exact elastic catenary (test_support.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "core/line_equilibrium.h"
#include "core/error.h"
#include "core/forces.h"
#include "core/equilibrium.h"
#include "core/point_loads.h"
#include "core/stability.h"
#include "core/step.h"
#include "test_support.h"

namespace cablefilm {
namespace {

using testing::Chain;
using testing::Figure;



// A clump weight with its own buoyancy, added mass and drag.
PrismSpec Clump() {
  PrismSpec p;
  p.mass = 3000;
  p.volume = 0.4;
  p.added_volume = Vec(0.2, 0.3, 0.2);
  p.drag_coefficient = Vec(1.0, 1.2, 1.0);
  p.drag_area = Vec(0.8, 1.0, 0.8);
  return p;
}

EnvironmentSpec Water3D() {
  EnvironmentSpec env;
  env.fluid_density = 1025;
  env.current = 0.4;
  env.current_direction = Horizontal(0.6);  // across the lines' plane: a 3D shape
  return env;
}

const Vec kAnchor(0.0, -60.0, 0.0), kFairlead(70.0, 0.0, 10.0);

// The fairlead on a ship: eq. (3) in three directions.
EndMotion Ship() {
  return EndMotion::Trochoid(kFairlead, Vec(1.5, 0.8, 0.5), Vec(0.0, 0.6, -0.4),
                             2 * M_PI / 8.0, 0.5);
}

// The chain, with its tangential (axial) drag and added mass when `axial` (MoorDyn's CdAx and
// CaAx of a studless chain, 0.4 and 0.5).
SectionSpec LegChain(double length, int segments, bool axial) {
  SectionSpec s = Chain(length, segments);
  if (axial) {
    s.tangential_drag_coefficient = 0.4;
    s.tangential_added_mass_coefficient = 0.5;
  }
  return s;
}

// Anchor -> 60 m -> clump -> 45 m -> fairlead: as two lines joined at a free point.
Model ClumpSystem(bool axial = false) {
  std::vector<PointSpec> points(3);
  points[0] = {"anchor", EndMotion::Fixed(kAnchor), {}};
  points[1] = {"clump", EndMotion::Free(Vec(40.0, -45.0, 5.0)), Clump()};
  points[2] = {"fairlead", Ship(), {}};
  std::vector<LineSpec> lines(2);
  lines[0].name = "lower";
  lines[0].sections = {LegChain(60, 24, axial)};
  lines[0].start_point = 0;
  lines[0].end_point = 1;
  lines[1].name = "upper";
  lines[1].sections = {LegChain(45, 18, axial)};
  lines[1].start_point = 1;
  lines[1].end_point = 2;
  return MakeModel(lines, points, Water3D());
}

// The same as one line with the clump as a weight at its station 24.
LineModel ClumpLine(bool axial = false) {
  PrismSpec clump = Clump();
  clump.station = 24;
  return MakeLineModel({LegChain(60, 24, axial), LegChain(45, 18, axial)}, {clump}, Water3D(),
                   EndMotion::Fixed(kAnchor), Ship(), LinkLaw::kElastic);
}

// Largest distance between the system's stations and the one line's [m].
double PositionGap(const std::vector<State>& lines, const Points& one) {
  double gap = 0;
  for (int j = 0; j <= 24; ++j) gap = std::max(gap, (lines[0].x.col(j) - one.col(j)).norm());
  for (int j = 0; j <= 18; ++j) gap = std::max(gap, (lines[1].x.col(j) - one.col(24 + j)).norm());
  return gap;
}

TEST(Model, RefusesWhatNothingHolds) {
  const EnvironmentSpec env = Water3D();
  LineSpec line;
  line.name = "l";
  line.sections = {Chain(10, 4)};
  line.start_point = 0;
  line.end_point = 1;
  const PointSpec fixed{"a", EndMotion::Fixed(Vec::Zero()), {}};
  const PointSpec free{"f", EndMotion::Free(Vec(5.0, -5.0, 0.0)), {}};
  // A free point no line holds.
  EXPECT_THROW(MakeModel({line}, {fixed, free, free}, env), Error);
  // A line whose ends are both free points that hold nothing else.
  EXPECT_THROW(MakeModel({line}, {free, free}, env), Error);
  // A line end at a point that does not exist.
  line.end_point = 5;
  EXPECT_THROW(MakeModel({line}, {fixed, free}, env), Error);
  line.end_point = 1;
  // An inextensible line joined to another at a free point: the coupled step is the elastic
  // lines'. Alone between a fixed point and its free end it is an island of its own.
  line.law = LinkLaw::kInextensible;
  LineSpec second = line;
  second.law = LinkLaw::kElastic;
  second.start_point = 1;
  second.end_point = 2;
  const PointSpec other{"b", EndMotion::Fixed(Vec(10.0, 0.0, 0.0)), {}};
  EXPECT_THROW(MakeModel({line, second}, {fixed, free, other}, env), Error);
  const Model alone = MakeModel({line}, {fixed, free}, env);
  ASSERT_EQ(alone.islands.size(), 1u);
  EXPECT_FALSE(alone.islands[0].coupled());
  line.law = LinkLaw::kElastic;
  const Model ok = MakeModel({line}, {fixed, free}, env);
  EXPECT_EQ(ok.shared_count(), 0);  // a free end, not a shared station
  EXPECT_FALSE(ok.lines[0].ends.end.prescribed());
  // Two lines joined at a free point are one island; a third from the same anchor another.
  LineSpec third = second;
  third.start_point = 0;
  third.end_point = 2;
  const Model two = MakeModel({ok.line_specs[0], second, third}, {fixed, free, other}, env);
  ASSERT_EQ(two.islands.size(), 2u);
  EXPECT_EQ(two.islands[0].lines, (std::vector<int>{0, 1}));
  EXPECT_EQ(two.islands[0].shared_points, (std::vector<int>{1}));
  EXPECT_TRUE(two.islands[0].coupled());
  EXPECT_EQ(two.islands[1].lines, (std::vector<int>{2}));
  EXPECT_FALSE(two.islands[1].coupled());
  EXPECT_EQ(two.line_island, (std::vector<int>{0, 0, 1}));
}

void ExpectClumpEquilibriumIsTheLine(bool axial) {
  const Model sys = ClumpSystem(axial);
  ASSERT_EQ(sys.shared_count(), 1);
  EquilibriumReport report;
  const std::vector<State> states = SolveEquilibrium(sys, &report);
  const State one = SolveLineEquilibrium(ClumpLine(axial));
  // Both are solved to 1e-9 of the static load (about 60 kN here): a station's position then
  // differs by that force over the line's stiffness across it (T / l ~ 1e4 N/m): ~6e-9 m
  // (measured 4.6e-10 m).
  ::testing::Test::RecordProperty("position_gap", Figure(PositionGap(states, one.x)));
  std::printf("[ system ]%s equilibrium: stations %.2e m from the one line's\n",
              axial ? " tangential terms:" : "", PositionGap(states, one.x));
  EXPECT_LT(PositionGap(states, one.x), 1e-7);
  EXPECT_LE(report.residual, 1e-9 * report.force_scale);
  EXPECT_GT(std::abs(states[0].x(2, 24) - 0.0), 0.5);  // the current bends it out of z = 0
}

TEST(CoupledEquilibrium, ClumpJunctionIsTheLineWithAWeight) { ExpectClumpEquilibriumIsTheLine(false); }

// With the tangential drag and added mass (issue 21) on both lines: the shared point's copies
// carry each line's half link of them, as the one line's station does.
TEST(CoupledEquilibrium, ClumpJunctionWithTangentialTermsIsTheLineWithAWeight) {
  ExpectClumpEquilibriumIsTheLine(true);
}

void ExpectClumpDynamicsIsTheLine(bool axial) {
  const Model sys = ClumpSystem(axial);
  const LineModel line = ClumpLine(axial);
  const std::vector<State> rest = SolveEquilibrium(sys);
  const State one_rest = SolveLineEquilibrium(line);
  StepOptions o;
  o.scheme = Scheme::kImplicit;
  o.tolerance = 1e-4;  // the default's scale (1e-6 of the line's length)
  Data sd = MakeData(sys, SceneInputs(line), o, rest);
  LineData one = MakeLineData(line, SceneInputs(line), o, one_rest);
  // Newton's tolerance a tenth of its default (1e-10 of a link, 2.5e-10 m) in both: the system
  // keeps each line's Newton matrix on its own and the one line its whole matrix, so the two
  // iterate differently and differ by what Newton leaves in each step (at the default
  // tolerance 1.4e-5 of the peak, 1.0e-6 at a tenth, 2.7e-7 at a hundredth: it is Newton's,
  // not the equations').
  one.scratch.newton_tolerance *= 0.1;
  for (IslandData& island : sd.islands) island.newton_tolerance *= 0.1;
  for (LineData& d : sd.lines) d.scratch.newton_tolerance *= 0.1;
  double gap = 0, peak = 0, tension_gap = 0;
  for (int k = 0; k < 200; ++k) {  // 20 s: the ship's ramp and two periods
    Step(sys, sd, SceneInputs(line), 0.1);
    StepLine(line, one, SceneInputs(line), 0.1);
    std::vector<State> now = {sd.lines[0].state, sd.lines[1].state};
    gap = std::max(gap, PositionGap(now, one.state.x));
    peak = std::max(peak, one.tension().maxCoeff());
    tension_gap = std::max(tension_gap, std::abs(sd.lines[1].tension()[17] - one.tension()[41]));
  }
  // The same equations, stepped with the same steps (both adapt on the same largest error of
  // the same stations); they differ by Newton's tolerance (2.5e-10 m here, per step) and
  // round-off, far below the step's own error (1e-4 m). A link's tension moves by EA / l =
  // 1.6e8 N/m times that, 0.04 N: 5e-7 of the 85 kN peak; the bound allows twenty steps'
  // worth of it (the steps' leftovers do not add up coherently: measured 1.0e-6).
  ::testing::Test::RecordProperty("gap", Figure(gap));
  ::testing::Test::RecordProperty("tension_gap_of_peak", Figure(tension_gap / peak));
  std::printf("[ system ]%s 20 s: stations %.2e m and tensions %.2e of the %.6g N peak from the "
              "one line's, %ld steps\n",
              axial ? " tangential terms:" : "", gap, tension_gap / peak, peak, ModelStepStats(sys, sd).steps);
  EXPECT_LT(gap, 1e-6);
  EXPECT_LT(tension_gap, 1e-5 * peak);
  EXPECT_EQ(ModelStepStats(sys, sd).steps, one.stats.steps);
}

TEST(CoupledDynamics, ClumpJunctionMovesAsTheLineWithAWeight) { ExpectClumpDynamicsIsTheLine(false); }

// The explicit scheme on the same system and line, with the same fixed steps (a fifth of the
// stability limit: velocity Verlet on each): the system's shared station accelerates by the sum
// of its two copies' rows, the line's station by its own, the same sums in another order.
// They differ by round-off grown by the motion (measured below 1e-9 m over 10 s).
TEST(CoupledDynamics, ExplicitClumpJunctionMovesAsTheLineWithAWeight) {
  const Model sys = ClumpSystem();
  const LineModel line = ClumpLine();
  const std::vector<State> rest = SolveEquilibrium(sys);
  State one_rest;
  one_rest.x = Points(kDim, 43);
  one_rest.x.leftCols(25) = rest[0].x;
  one_rest.x.rightCols(18) = rest[1].x.rightCols(18);
  one_rest.v = Points::Zero(kDim, 43);
  StepOptions o;
  o.scheme = Scheme::kExplicit;  // fixed steps as asked
  const double dt = 0.2 * ComputeStabilityLimit(line).time_step;
  Data sd = MakeData(sys, SceneInputs(line), o, rest);
  LineData one = MakeLineData(line, SceneInputs(line), o, one_rest);
  double gap = 0;
  for (double t = 0; t < 10.0; t += dt) {
    Step(sys, sd, SceneInputs(line), dt);
    StepLine(line, one, SceneInputs(line), dt);
    std::vector<State> now = {sd.lines[0].state, sd.lines[1].state};
    gap = std::max(gap, PositionGap(now, one.state.x));
  }
  ::testing::Test::RecordProperty("gap", Figure(gap));
  EXPECT_LT(gap, 1e-6);
  EXPECT_GT((sd.lines[0].state.x.col(24) - rest[0].x.col(24)).norm(), 0.3);  // it moved
}

// The coupled explicit scheme conserves energy as velocity Verlet does (energy_test.cpp does it
// for a line): two lines of 10 m (EA 1e5 N) joined at a free 2 kg junction between fixed ends,
// stretched 1 % (T0 = 1 kN) and released straight in vacuum: they sag and swing, every link
// taut, the axial modes ring. Kinetic + strain + gravity energy (each line's, the junction's
// mass on its owner's copy) stays within O(dt^2) of its start: halving the step divides the
// largest error by 4, it is small against the energy exchanged, and it does not drift.
struct SystemEnergyRun {
  double max_error = 0, swing = 0, first_mean = 0, last_mean = 0, min_tension = 1e300;
};

SystemEnergyRun RunReleasedSystem(double dt_fraction) {
  SectionSpec wire;
  wire.length = 10;
  wire.segments = 20;
  wire.diameter = 0.01;
  wire.area = 1e-4;
  wire.mass_per_length = 1;
  wire.youngs_modulus = 1e9;
  std::vector<PointSpec> points(3);
  PrismSpec junction;
  junction.mass = 2;
  points[0] = {"a", EndMotion::Fixed(InPlane(0.0, 0.0)), {}};
  points[1] = {"junction", EndMotion::Free(InPlane(10.1, 0.0)), junction};
  points[2] = {"b", EndMotion::Fixed(InPlane(20.2, 0.0)), {}};
  std::vector<LineSpec> lines(2);
  lines[0].name = "left";
  lines[0].sections = {wire};
  lines[0].start_point = 0;
  lines[0].end_point = 1;
  lines[1].name = "right";
  lines[1].sections = {wire};
  lines[1].start_point = 1;
  lines[1].end_point = 2;
  EnvironmentSpec vacuum;
  vacuum.fluid_density = 0;
  const Model sys = MakeModel(lines, points, vacuum);
  std::vector<State> start(2);
  for (int i = 0; i < 2; ++i) {
    start[i].x = StraightChord(sys.lines[i]);
    start[i].v = Points::Zero(kDim, sys.lines[i].stations());
  }
  StepOptions o;
  o.scheme = Scheme::kExplicit;  // fixed steps as asked
  const double dt = dt_fraction * ComputeStabilityLimit(sys.lines[0]).time_step;
  const Inputs in = SceneInputs(sys.lines[0]);
  Data d = MakeData(sys, in, o, start);
  auto energy = [&](double* kinetic) {
    double e = 0;
    *kinetic = 0;
    for (int i = 0; i < 2; ++i) {
      const LineModel& m = sys.lines[i];
      const LineData& l = d.lines[i];
      *kinetic += KineticEnergy(m, l.forces.geometry, l.state.v);
      e += ElasticEnergy(m, l.forces.geometry) + PotentialEnergy(m, l.state.x);
    }
    return e + *kinetic;
  };
  double kinetic = 0;
  const double e0 = energy(&kinetic);
  const long steps = std::lround(6.0 / dt);  // ~10 periods of the fundamental
  SystemEnergyRun r;
  long n_first = 0, n_last = 0;
  for (long k = 1; k <= steps; ++k) {
    Step(sys, d, in, dt);
    const double err = energy(&kinetic) - e0;
    r.max_error = std::max(r.max_error, std::abs(err));
    r.swing = std::max(r.swing, kinetic);
    for (const LineData& l : d.lines) r.min_tension = std::min(r.min_tension, l.tension().minCoeff());
    if (k <= steps / 4) r.first_mean += err, ++n_first;
    if (k > steps - steps / 4) r.last_mean += err, ++n_last;
  }
  r.first_mean /= n_first;
  r.last_mean /= n_last;
  return r;
}

TEST(CoupledDynamics, ExplicitSystemConservesEnergyToSecondOrder) {
  const SystemEnergyRun a = RunReleasedSystem(0.2), b = RunReleasedSystem(0.1);
  const double ratio = a.max_error / b.max_error;
  std::printf("[ energy ] explicit system in vacuum: max |E - E0| %.3e J (0.2 x limit), %.3e J "
              "(0.1 x), ratio %.3f, of %.3e J exchanged; least tension %.1f N\n",
              a.max_error, b.max_error, ratio, a.swing, a.min_tension);
  ::testing::Test::RecordProperty("ratio", Figure(ratio));
  EXPECT_GT(a.min_tension, 0.0);  // every link taut (the scheme's order argument needs it)
  // Second order, as the line's (energy_test.cpp): 3..5 for the higher-order terms.
  EXPECT_GT(ratio, 3.0);
  EXPECT_LT(ratio, 5.0);
  EXPECT_LT(a.max_error, 0.1 * a.swing);
  for (const SystemEnergyRun* r : {&a, &b})
    EXPECT_LT(std::abs(r->last_mean - r->first_mean), 0.2 * r->max_error);
}

// A coupled island's snaps left to explicit steps (coupled_step.h, as a line's:
// explicit_snaps.h), against a conservation law. In vacuum, without gravity or damping, a
// junction of no mass of its own between two one-link lines to fixed anchors, both links
// slack, rattles between them: it moves at v until a link comes taut, bounces off it (an
// elastic collision: it leaves at v) and crosses to the other. Implicit steps of 10 ms (3 of
// the links' contact time) with a loose tolerance (1 % of a link, so that the error control
// alone steps over each contact) take a share of its energy at every bounce; the explicit
// windows keep it. Each contact lies within one step asked, away from the window's substep
// grid, as ExplicitSnaps.SnapInVacuumKeepsTheStationsSpeed's does: a contact that begins
// exactly at a substep's start, or runs across the end of a step asked, is not refined by the
// explicit steps (a line's alike; the snap check reports it unresolved).
struct Rattle {
  double speed;  // the junction's speed after its bounces [m/s]
  StepStats stats;
};

Rattle RattleJunction(bool explicit_snaps) {
  const double l0 = 1.0957, v = 1.5;  // each link's rest length [m]; the junction's speed [m/s]
  SectionSpec link;
  link.length = l0;
  link.segments = 1;
  link.diameter = 0.01;
  link.area = 1e-4;
  link.mass_per_length = 1;        // the junction: half of each link, 1.095 kg
  link.youngs_modulus = 1e10;      // EA 1e6 N: k = 9.1e5 N/m, in contact pi sqrt(m/k) = 3.4 ms
  std::vector<PointSpec> points(3);
  points[0] = {"a", EndMotion::Fixed(InPlane(0.0, 0.0)), {}};
  points[1] = {"junction", EndMotion::Free(InPlane(1.0, 0.0)), {}};
  points[2] = {"b", EndMotion::Fixed(InPlane(2.0, 0.0)), {}};
  std::vector<LineSpec> lines(2);
  lines[0] = {"left", {link}, {}, LinkLaw::kElastic, 0, 1};
  lines[1] = {"right", {link}, {}, LinkLaw::kElastic, 1, 2};
  EnvironmentSpec vacuum;
  vacuum.fluid_density = 0;
  vacuum.gravity = 0;
  const Model sys = MakeModel(lines, points, vacuum);
  std::vector<State> start(2);
  for (int i = 0; i < 2; ++i) {
    start[i].x = StraightChord(sys.lines[i]);
    start[i].v = Points::Zero(kDim, 2);
  }
  start[0].v.col(1) = InPlane(v, 0);  // the junction: station 1 of the left line,
  start[1].v.col(0) = InPlane(v, 0);  // station 0 of the right
  StepOptions o;
  o.scheme = Scheme::kImplicit;
  o.rho_inf = 0.5;
  o.tolerance = 1e-2;
  o.safety_factor = 0.8;
  o.explicit_snaps = explicit_snaps;
  const Inputs in = SceneInputs(sys);
  Data d = MakeData(sys, in, o, start);
  // The left link is taut from 0.0633 to 0.0668 s, the right from 0.1935 to 0.1969 s: both
  // bounces by 0.25 s, the junction then crossing between them.
  for (int k = 0; k < 25; ++k) Step(sys, d, in, 0.01);
  return {d.lines[0].state.v.col(1).norm(), ModelStepStats(sys, d)};
}

TEST(CoupledDynamics, SnapsInAnIslandAreSteppedExplicitlyAndKeepTheEnergy) {
  const Rattle with = RattleJunction(true), without = RattleJunction(false);
  std::printf("[ snaps ] junction after two bounces: %.5f m/s with explicit windows (%ld "
              "windows, %ld explicit steps of %ld), %.5f m/s without; came in at 1.5 m/s\n",
              with.speed, with.stats.snap_windows, with.stats.explicit_steps, with.stats.steps,
              without.speed);
  EXPECT_EQ(with.stats.snap_windows, 2);
  EXPECT_EQ(without.stats.snap_windows, 0);
  // As a line's snap (ExplicitSnaps.SnapInVacuumKeepsTheStationsSpeed): velocity Verlet at 0.8
  // of the stability limit, its slack-taut changes refined to 1 % of the link's energy each:
  // each bounce within about 2 % of the energy, two within 2 % of the speed.
  EXPECT_NEAR(with.speed, 1.5, 0.02 * 1.5);
  // Without: the implicit steps over each contact lose a share a test must see.
  EXPECT_LT(without.speed, 0.95 * 1.5);
}

TEST(CoupledDynamics, ClumpJunctionWithTangentialTermsMovesAsTheLineWithAWeight) {
  ExpectClumpDynamicsIsTheLine(true);
}

TEST(CoupledDynamics, ABlowUpNamesItsLine) {
  // The fairlead shaken far faster than any step can follow: the step falls below its floor
  // and the error says so, naming the line that holds the most stretched link.
  std::vector<PointSpec> points(3);
  points[0] = {"anchor", EndMotion::Fixed(kAnchor), {}};
  points[1] = {"clump", EndMotion::Free(Vec(40.0, -45.0, 5.0)), Clump()};
  points[2] = {"fairlead", EndMotion::Trochoid(kFairlead, Vec(30.0, 30.0, 0.0), Vec::Zero(),
                                               2 * M_PI / 1e-3, 1e3), {}};
  std::vector<LineSpec> lines(2);
  lines[0] = {"lower", {Chain(60, 24)}, {}, LinkLaw::kElastic, 0, 1};
  lines[1] = {"upper", {Chain(45, 18)}, {}, LinkLaw::kElastic, 1, 2};
  const Model sys = MakeModel(lines, points, Water3D());
  StepOptions o;
  o.scheme = Scheme::kImplicit;
  o.tolerance = 1e-4;
  Data sd = MakeData(sys, SceneInputs(sys.lines[0]), o, SolveEquilibrium(sys));
  try {
    for (int k = 0; k < 10; ++k) Step(sys, sd, SceneInputs(sys.lines[0]), 0.01);
    FAIL() << "no blow-up";
  } catch (const BlowUpError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("line \"upper\""), std::string::npos) << what;
    RecordProperty("message", what);
  }
}

// A buoy held down by three identical legs to anchors 120 degrees apart, pushed sideways by a
// steady thrust: a spread mooring in its offset under a steady load.
struct Spread {
  double rho = 1025, g = 9.80665;
  double length = 350;                 // each leg [m]
  double anchor_radius = 300;          // [m] from the centre
  double anchor_y = -100;              // [m]
  double buoyancy = 3.0e5;             // the buoy's net buoyancy rho g V - m g [N]
  Vec thrust = Vec(4.0e4, 0.0, 1.5e4);  // [N]
  SectionSpec leg(int links) const { return Chain(length, links); }
  double w() const {  // the legs' net weight per metre [N/m]
    const SectionSpec c = Chain(1, 1);
    return (c.mass_per_length - rho * c.area) * g;
  }
  Vec anchor(int i) const {
    return Vec(0.0, anchor_y, 0.0) + anchor_radius * Horizontal(2 * M_PI * i / 3.0 + 0.3);
  }
  PrismSpec buoy() const {
    PrismSpec p;
    p.mass = 2.0e4;
    p.volume = (buoyancy + p.mass * g) / (rho * g);
    p.force = thrust;
    return p;
  }
  Model System(int links) const {
    EnvironmentSpec env;
    env.fluid_density = rho;
    env.gravity = g;
    std::vector<PointSpec> points = {{"buoy", EndMotion::Free(Vec(0.0, -20.0, 0.0)), buoy()}};
    std::vector<LineSpec> lines(3);
    for (int i = 0; i < 3; ++i) {
      points.push_back({"anchor" + std::to_string(i), EndMotion::Fixed(anchor(i)), {}});
      lines[i].name = "leg" + std::to_string(i);
      lines[i].sections = {leg(links)};
      lines[i].start_point = i + 1;  // from the anchor up to the buoy
      lines[i].end_point = 0;
    }
    return MakeModel(lines, points, env);
  }
  // The exact answer: the buoy where the three exact elastic catenaries, its net buoyancy and
  // the thrust balance (Newton with central differences on the continuous catenaries).
  Vec ExactBuoy() const {
    const SectionSpec c = Chain(1, 1);
    const double EA = c.area * c.youngs_modulus;
    auto net = [&](const Vec& P) {
      Vec F = thrust + Vec(0.0, buoyancy, 0.0);
      for (int i = 0; i < 3; ++i) {
        testing::ExactCatenary cat({{length, w(), EA, 0.0}});
        const Vec A = anchor(i);
        const Vec d = HorizontalPart(P - A);
        const double span = d.norm();
        cat.Shoot(Eigen::Vector2d(span, P[1] - A[1]), 0.5 * w() * length, 0.3 * w() * length);
        // The top's tension (H, V0 + w L) pulls the buoy back towards the anchor and down.
        F -= cat.H() * d / span + Vec(0.0, cat.V0() + w() * length, 0.0);
      }
      return F;
    };
    Vec P(0.0, -20.0, 0.0);
    for (int it = 0; it < 50; ++it) {
      const Vec F = net(P);
      if (F.norm() < 1e-6) break;
      Mat J;
      for (int k = 0; k < kDim; ++k) {
        Vec e = Vec::Zero();
        e[k] = 1e-4;
        J.col(k) = (net(P + e) - net(P - e)) / 2e-4;
      }
      P -= J.inverse() * F;
    }
    return P;
  }
};

TEST(CoupledEquilibrium, SpreadMooringOffsetConvergesToTheExactCatenaries) {
  const Spread spread;
  const Vec exact = spread.ExactBuoy();
  double error[2];
  int k = 0;
  for (int links : {35, 70}) {
    const Model sys = spread.System(links);
    const std::vector<State> states = SolveEquilibrium(sys);
    error[k++] = (states[0].x.col(links) - exact).norm();
    // The lines' pull balances the buoy: the forces on it at rest sum to zero (PointForces
    // reports the lines' pull on a free point).
    StepOptions o;
    Data sd = MakeData(sys, SceneInputs(sys.lines[0]), o, states);
    PointLoads loads(sys);
    loads.Compute(sys, sd, SceneInputs(sys.lines[0]));
    const Points& forces = loads.forces();
    const Vec own = spread.thrust + Vec(0.0, spread.buoyancy, 0.0);
    // The lines' pull is the end links' tension; the end stations' lumped weight (half a link
    // each) is the rest of the balance.
    const double half_links = 3 * 0.5 * spread.w() * spread.length / links;
    EXPECT_LT((forces.col(0) + own - Vec(0.0, half_links, 0.0)).norm(), 1e-6 * own.norm());
  }
  // The buoy moved by the thrust: tens of metres.
  EXPECT_GT(HorizontalPart(exact).norm(), 5.0);
  // Second order in the link length: halving it quarters the error (within 10 %: the next
  // term), and the finer answer is within a centimetre.
  RecordProperty("error_35", Figure(error[0]));
  RecordProperty("error_70", Figure(error[1]));
  EXPECT_NEAR(error[0] / error[1], 4.0, 0.4);
  EXPECT_LT(error[1], 1e-2);
}

// The held lines' work is counted (each pass of a line solve over its line's stations: a
// residual, a step along the links, a Newton matrix) and bounded: a system whose statics would
// take more gives up with a message that says so, in place of running for minutes (a fuzzed
// file's 100 000-link tether did).
TEST(CoupledEquilibrium, HeldLinesWorkIsCountedAndBounded) {
  const Spread spread;
  const Model sys = spread.System(35);
  std::vector<double> fractions;
  EquilibriumOptions options;
  options.solving = [&](double f) { fractions.push_back(f); };
  EquilibriumReport report;
  SolveEquilibrium(sys, &report, options);
  ASSERT_GT(report.iterations, 1);
  // At least every line's first solve (three legs of 36 stations, a residual, a matrix and a
  // step each) and the finite differences' re-solves; far under the bound.
  EXPECT_GE(report.line_work, 3 * 3 * 36.0);
  EXPECT_LT(report.line_work, 1e-2 * kMostStaticLineWork);
  // Progress at every iteration, growing, within (0, 1].
  ASSERT_EQ(static_cast<int>(fractions.size()), report.iterations);
  for (std::size_t k = 0; k < fractions.size(); ++k) {
    EXPECT_GT(fractions[k], 0.0);
    EXPECT_LE(fractions[k], 1.0);
    if (k > 0) {
      EXPECT_GE(fractions[k], fractions[k - 1]);
    }
  }
  // The same statics with half that work allowed: an Error naming the bound, the work done
  // then past it by less than half the run's work (the solve that crossed it is the last).
  options.max_line_work = 0.5 * report.line_work;
  double used = 0;
  options.line_work = &used;
  try {
    SolveEquilibrium(sys, nullptr, options);
    FAIL() << "converged within half the work it needed";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("station-passes"), std::string::npos) << e.what();
  }
  EXPECT_GT(used, options.max_line_work);
  EXPECT_LE(used, options.max_line_work + 0.5 * report.line_work);
  // A shared count goes on from where it stands: at the bound already, the first solve ends it.
  options.max_line_work = used;
  EXPECT_THROW(SolveEquilibrium(sys, nullptr, options), Error);
}

}  // namespace
}  // namespace cablefilm
