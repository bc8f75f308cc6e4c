// The step loops allocate nothing once the integrators are built: every scratch buffer is
// sized at construction. Counted by replacing the global operator new in this test program.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "core/line_equilibrium.h"
#include "test_support.h"
#include "core/explicit_step.h"
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

long AllocationsWhileStepping(Scheme kind, CableModelKind model, double dt,
                              double error_tolerance, bool waves = false,
                              const char* scene_file = "polachek1963.toml",
                              bool turning_end = false) {
  SceneDef scene = LoadScene(std::string(CABLEFILM_SOURCE_DIR) + "/scenes/" + scene_file);
  scene.lines[0].model = model;
  if (!scene.seabed.present)
    scene.environment.current = 0.5;  // every force term active: drag with current, prisms
  if (waves) {  // and the waves' terms, the surface 2.5 m above the moving end's rest
    scene.waves.present = true;
    scene.waves.height = 2;
    scene.waves.period = 8;
    scene.waves.depth = 50;
    scene.waves.surface_y = 33;
    scene.waves.ramp_rate = 0.5;
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
  std::vector<double>* v = new std::vector<double>(100);
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
                                     false, "polachek1963.toml", true),
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

TEST(NoAllocation, EverySchemeInWaves) {
  EXPECT_EQ(AllocationsWhileStepping(Scheme::kExplicit, CableModelKind::kElastic, 2e-4, 0,
                                     true),
            0);
  EXPECT_EQ(AllocationsWhileStepping(Scheme::kImplicit, CableModelKind::kElastic, 1.0 / 30,
                                     1e-5, true),
            0);
  EXPECT_EQ(AllocationsWhileStepping(Scheme::kInextensible, CableModelKind::kInextensible,
                                     1.0 / 30, 1e-6, true),
            0);
}

// On the seabed with the stick-slip friction (its anchors move as steps are accepted), in waves
// and a sheared current: the grounded mooring scene.
TEST(NoAllocation, EverySchemeOnTheSeabedWithStickSlipFriction) {
  const char* grounded = "grounded_mooring.toml";
  EXPECT_EQ(AllocationsWhileStepping(Scheme::kExplicit, CableModelKind::kElastic, 2e-4, 0,
                                     false, grounded),
            0);
  EXPECT_EQ(AllocationsWhileStepping(Scheme::kImplicit, CableModelKind::kElastic, 1.0 / 30,
                                     1e-4, false, grounded),
            0);
  EXPECT_EQ(AllocationsWhileStepping(Scheme::kInextensible, CableModelKind::kInextensible,
                                     1.0 / 30, 1e-4, false, grounded),
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

}  // namespace
}  // namespace cablefilm
