// The step loops allocate nothing once the integrators are built: every scratch buffer is
// sized at construction. Counted by replacing the global operator new in this test program.
#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <cstdlib>
#include <new>
#include <vector>

#include "core/line_equilibrium.h"
#include "../core/test_support.h"
#include "core/equilibrium.h"
#include "core/explicit_step.h"
#include "core/sea_components.h"
#include "core/stability.h"
#include "core/step.h"
#include "scene/build_model.h"
#include "scene/scene_loader.h"
#include "scene_line.h"

namespace {
std::atomic<long> g_allocations{0};
}

// The replacement new and delete below are a matched malloc/free pair; GCC's heuristic, which
// sees free() inside an operator delete, cannot tell.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace cablefilm {
namespace {

// The water: still, a regular wave, or an irregular sea (its kinematics carried from their
// last exact evaluation, and evaluated afresh as the stations move away: both paths stepped).
enum class Water { kStill, kRegular, kIrregular };

long AllocationsWhileStepping(Scheme kind, CableModelKind model, double dt,
                              double error_tolerance, Water water = Water::kStill,
                              const char* scene_file = "polachek1963.toml",
                              bool turning_end = false) {
  SceneDef scene = LoadScene(std::string(CABLEFILM_SOURCE_DIR) + "/scenes/" + scene_file);
  scene.lines[0].model = model;
  if (!scene.seabed.present)
    scene.environment.current = 0.5;  // every force term active: drag with current, prisms
  if (water != Water::kStill) {  // and the waves' terms, the surface 2.5 m above the moving end
    scene.waves.present = true;
    scene.waves.height = 2;
    scene.waves.period = 8;
    scene.waves.depth = 50;
    scene.waves.surface_y = 33;
    scene.waves.ramp_rate = 0.5;
  }
  if (water == Water::kIrregular) {  // a JONSWAP sea of Hs 2 m, Tp 8 s in 50 components
    SpectrumSpec spectrum;
    spectrum.hs = 2;
    spectrum.tp = 8;
    spectrum.gamma = 3.3;
    SeaDiscretization d;
    d.components = 50;
    d.spreading = 4;
    scene.waves.sea = SeaKind::kJonswap;
    scene.waves.components_made = std::make_shared<const SeaComponents>(
        SpectrumComponents(spectrum, d, scene.environment.gravity, scene.waves.depth));
  }
  LineModel m = LineOf(scene);
  if (turning_end)  // its far end a point 3 m from a driven body's reference point, turning
    m.ends.end = m.ends.end.WithTurn(
        EndMotion::Trochoid(Vec::Zero(), Vec(0.05, 0.1, 0.0), Vec(0.0, 0.05, 0.1), 0.6, 0.5),
        Vec(3.0, 0.0, 0.0));
  State s = SolveLineEquilibrium(m);  // the elastic equilibrium: a fine start for either model
  auto integrator = testing::MakeStepper(kind, m, 0.5, error_tolerance);
  integrator->Initialize(m, s);
  for (int i = 0; i < 10; ++i) integrator->Step(m, s, dt);  // warm-up
  const long before = g_allocations;
  for (int i = 0; i < 200; ++i) integrator->Step(m, s, dt);
  return g_allocations - before;
}

TEST(NoAllocation, TheCounterCounts) {  // else the tests below could not fail
  const long before = g_allocations;
  // Through a volatile pointer: the compiler may not elide the pair (C++14 lets it elide a
  // new-expression whose result does not escape).
  std::vector<double>* volatile v = new std::vector<double>(100);
  delete v;
  EXPECT_EQ(g_allocations - before, 2);
}

TEST(NoAllocation, ExplicitStep) {
  EXPECT_EQ(AllocationsWhileStepping(Scheme::kExplicit, CableModelKind::kElastic, 2e-4, 0),
            0);
}

TEST(NoAllocation, ImplicitStepFixedAndAdaptive) {
  EXPECT_EQ(AllocationsWhileStepping(Scheme::kImplicit, CableModelKind::kElastic, 1.0 / 30, 0),
            0);
  EXPECT_EQ(
      AllocationsWhileStepping(Scheme::kImplicit, CableModelKind::kElastic, 1.0 / 30, 1e-5),
      0);
}

// A driven body's turning point (issue 20): its turn is evaluated at every stage, still
// without allocating.
TEST(NoAllocation, ImplicitStepWithATurningEnd) {
  EXPECT_EQ(AllocationsWhileStepping(Scheme::kImplicit, CableModelKind::kElastic, 1.0 / 30, 1e-5,
                                     Water::kStill, "polachek1963.toml", true),
            0);
}

TEST(NoAllocation, InextensibleStep) {
  EXPECT_EQ(AllocationsWhileStepping(Scheme::kInextensible, CableModelKind::kInextensible,
                                     1.0 / 30, 0),
            0);
}

TEST(NoAllocation, InextensibleStepUnderErrorControl) {
  EXPECT_EQ(AllocationsWhileStepping(Scheme::kInextensible, CableModelKind::kInextensible,
                                     1.0 / 30, 1e-6),
            0);
}

TEST(NoAllocation, EverySchemeInWavesAndAnIrregularSea) {
  for (const Water water : {Water::kRegular, Water::kIrregular}) {
    SCOPED_TRACE(water == Water::kRegular ? "regular wave" : "irregular sea");
    EXPECT_EQ(AllocationsWhileStepping(Scheme::kExplicit, CableModelKind::kElastic, 2e-4, 0,
                                       water),
              0);
    EXPECT_EQ(AllocationsWhileStepping(Scheme::kImplicit, CableModelKind::kElastic, 1.0 / 30,
                                       1e-5, water),
              0);
    EXPECT_EQ(AllocationsWhileStepping(Scheme::kInextensible, CableModelKind::kInextensible,
                                       1.0 / 30, 1e-6, water),
              0);
  }
}

// On the seabed with the stick-slip friction (its anchors move as steps are accepted), in waves
// and a sheared current: the grounded mooring scene.
TEST(NoAllocation, EverySchemeOnTheSeabedWithStickSlipFriction) {
  const char* grounded = "grounded_mooring.toml";
  EXPECT_EQ(AllocationsWhileStepping(Scheme::kExplicit, CableModelKind::kElastic, 2e-4, 0,
                                     Water::kStill, grounded),
            0);
  EXPECT_EQ(AllocationsWhileStepping(Scheme::kImplicit, CableModelKind::kElastic, 1.0 / 30,
                                     1e-4, Water::kStill, grounded),
            0);
  EXPECT_EQ(AllocationsWhileStepping(Scheme::kInextensible, CableModelKind::kInextensible,
                                     1.0 / 30, 1e-4, Water::kStill, grounded),
            0);
}

TEST(NoAllocation, ExplicitAutoStepThroughSnaps) {
  // The catenary chain released from its chord: its links first snap taut at t = 0.45 s, where
  // "auto" refines its substeps (the check that predicts the snaps, the cable's energy it then
  // needs) and takes them.
  const SceneDef scene = LoadScene(std::string(CABLEFILM_SOURCE_DIR) + "/scenes/catenary.toml");
  const LineModel m = LineOf(scene);
  State s;
  s.x = StraightChord(m);
  s.v = Points::Zero(kDim, m.stations());
  const double dt = 0.8 * ComputeStabilityLimit(m).time_step;
  testing::Stepper integrator(Scheme::kExplicit, 0.5, 0, 0.8);
  integrator.Initialize(m, s);
  while (s.t < 0.4) integrator.Step(m, s, dt);
  ASSERT_EQ(integrator.stats().rejected, 0);
  const long before = g_allocations;
  while (s.t < 0.6) integrator.Step(m, s, dt);
  EXPECT_EQ(g_allocations - before, 0);
  EXPECT_GT(integrator.stats().rejected, 0);  // it did refine in the counted steps
}

// A model with every kind of island (model.h): a line alone between an anchor and a ship's
// fairlead (inextensible or elastic), two lines joined at a clump weight (a shared station),
// and a line from an anchor to a free buoy body (a body's six unknowns); in a current, on a
// seabed with stick-slip friction, in waves.
Model EveryIsland(LinkLaw alone) {
  EnvironmentSpec env;
  env.fluid_density = 1025;
  env.current = 0.5;
  env.current_direction = Horizontal(0.4);
  env.seabed.present = true;
  env.seabed.y = -62;
  env.seabed.friction = 0.5;
  env.waves.present = true;
  env.waves.height = 2;
  env.waves.period = 8;
  env.waves.depth = 62;
  env.waves.ramp_rate = 0.5;
  const EndMotion ship = EndMotion::Trochoid(Vec(70.0, -5.0, 10.0), Vec(1.5, 0.8, 0.5),
                                             Vec(0.0, 0.6, -0.4), 2 * M_PI / 8.0, 0.5);
  PrismSpec clump;
  clump.mass = 3000;
  clump.volume = 0.4;
  clump.drag_coefficient = Vec(1.0, 1.0, 1.0);
  clump.drag_area = Vec(0.5, 0.5, 0.5);
  std::vector<PointSpec> points(7);
  points[0] = {"anchor", EndMotion::Fixed(Vec(0.0, -62.0, 0.0)), {}};
  points[1] = {"clump", EndMotion::Free(Vec(40.0, -45.0, 5.0)), clump};
  points[2] = {"fairlead", ship, {}};
  points[3] = {"anchor2", EndMotion::Fixed(Vec(0.0, -62.0, -30.0)), {}};
  points[4] = {"fairlead2", ship.WithRest(Vec(70.0, -5.0, -20.0)), {}};
  points[5] = {"anchor3", EndMotion::Fixed(Vec(0.0, -62.0, 40.0)), {}};
  points[6] = {"buoy", EndMotion::Fixed(Vec::Zero()), {}, 0, Vec::Zero()};
  BodySpec buoy;
  buoy.name = "buoy";
  buoy.kind = BodyKind::kFree;
  buoy.motion = EndMotion::Free(Vec(20.0, -20.0, 40.0));
  buoy.mass = 2000;
  buoy.volume = 6;
  buoy.inertia = Vec(500.0, 500.0, 500.0);
  buoy.added_mass << 1000, 1000, 1000, 100, 100, 100;
  buoy.quadratic_damping << 500, 500, 500, 50, 50, 50;
  std::vector<LineSpec> lines(4);
  const SectionSpec chain = testing::Chain(60, 24), upper = testing::Chain(45, 18);
  lines[0] = {"lower", {chain}, {}, LinkLaw::kElastic, 0, 1};
  lines[1] = {"upper", {upper}, {}, LinkLaw::kElastic, 1, 2};
  lines[2] = {"alone", {testing::Chain(110, 30)}, {}, alone, 3, 4};
  lines[3] = {"riser", {testing::Chain(40, 16)}, {}, LinkLaw::kElastic, 5, 6};
  return MakeModel(lines, points, env, {buoy});
}

long AllocationsWhileSteppingTheModel(Scheme scheme, LinkLaw alone, double tolerance) {
  const Model model = EveryIsland(alone);
  const std::vector<State> rest = SolveEquilibrium(model);
  Model placed = model;  // the buoy at its equilibrium
  EquilibriumReport report;
  SolveEquilibrium(model, &report);
  PlaceBody(placed, 0, report.body_poses[0]);
  StepOptions o;
  o.scheme = scheme;
  o.tolerance = tolerance;
  o.safety_factor = 0.8;
  o.explicit_snaps = true;
  const Inputs in = SceneInputs(placed);
  Data d = MakeData(placed, in, o, rest);
  for (int i = 0; i < 5; ++i) Step(placed, d, in, 1.0 / 30);  // warm-up
  const long before = g_allocations;
  for (int i = 0; i < 30; ++i) Step(placed, d, in, 1.0 / 30);
  return g_allocations - before;
}

// The model's step (step.h) over every island kind and scheme: an island of one line by the
// line's schemes, the coupled ones by the coupled implicit and explicit steps.
TEST(NoAllocation, TheModelsStepOverEveryIslandAndScheme) {
  ASSERT_EQ(EveryIsland(LinkLaw::kElastic).islands.size(), 3u);
  EXPECT_EQ(AllocationsWhileSteppingTheModel(Scheme::kImplicit, LinkLaw::kElastic, 1e-4), 0);
  EXPECT_EQ(AllocationsWhileSteppingTheModel(Scheme::kExplicit, LinkLaw::kElastic, 0), 0);
  // The line alone inextensible: its island the inextensible scheme, the others implicit.
  EXPECT_EQ(AllocationsWhileSteppingTheModel(Scheme::kImplicit, LinkLaw::kInextensible, 1e-4), 0);
}

}  // namespace
}  // namespace cablefilm
