// A long line's static equilibrium from a coarse copy's (run/coarse_guess.h, issue 23): the
// same equilibrium as from the chord, in a few Newton iterations; none where no merge keeps
// the sections whole.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "core/line_equilibrium.h"
#include "core/coarse_guess.h"
#include "run/initial_state.h"
#include "scene/build_model.h"
#include "scene/scene_loader.h"
#include "../core/test_support.h"
#include "scene_line.h"

namespace cablefilm {
namespace {

using testing::Figure;

// P63 (a current, a weight 27.432 m from the anchor) with each section's links times `times`.
SceneDef P63Links(int times) {
  SceneDef s = LoadScene(std::string(CABLEFILM_SOURCE_DIR) + "/scenes/polachek1963.toml");
  for (SectionDef& sec : s.lines[0].sections) sec.segments *= times;
  return s;
}

TEST(CoarseGuess, GivesTheChordsEquilibriumInAFewIterations) {
  const SceneDef scene = P63Links(50);  // 3 000 links
  const LineModel m = LineOf(scene);
  ASSERT_GE(m.line.links, kCoarseGuessFromLinks);
  ASSERT_TRUE(CoarseEquilibriumGuess(BuildModel(scene), 0, nullptr).has_value());
  LineEquilibriumReport coarse, chord;
  const State a = InitialStateOf(scene, &coarse);
  const State b = SolveLineEquilibrium(m, &chord);
  const double gap = (a.x - b.x).cwiseAbs().maxCoeff();
  RecordProperty("gap_m", Figure(gap));
  RecordProperty("iterations_coarse", coarse.iterations);
  RecordProperty("iterations_chord", chord.iterations);
  // Both stop at the same tolerance (1e-9 of the load) from the same side of Newton's
  // quadratic convergence: the same stations to far below a micrometre (measured 5e-15 m).
  EXPECT_LT(gap, 1e-7);
  // From the coarse shape (within the 300-link line's discretisation of the answer) Newton
  // needs a few iterations; from the chord it needed 14 (measured 3 against 14).
  EXPECT_LE(coarse.iterations, 5);
  EXPECT_GT(chord.iterations, 2 * coarse.iterations);
}

TEST(CoarseGuess, NoneWhereNoMergeKeepsTheSectionsWhole) {
  SceneDef scene = P63Links(50);
  scene.lines[0].sections[1].segments += 1;  // 1 500 and 1 501 links: no common factor
  const LineModel m = LineOf(scene);
  EXPECT_FALSE(CoarseEquilibriumGuess(BuildModel(scene), 0, nullptr).has_value());
  // The line then starts from the chord, as lines of fewer links do.
  LineEquilibriumReport report;
  const State s = InitialStateOf(scene, &report);
  EXPECT_GT(report.iterations, 5);
  // Converged as the solver counts it: the tolerance, or the round-off floor of 3 000 stiff links.
  EXPECT_LE(report.residual, std::max(1e-9 * report.force_scale, report.roundoff_floor));
}

TEST(CoarseGuess, NoneForAShortLine) {
  const SceneDef scene = P63Links(1);
  EXPECT_FALSE(CoarseEquilibriumGuess(BuildModel(scene), 0, nullptr).has_value());
}

}  // namespace
}  // namespace cablefilm
