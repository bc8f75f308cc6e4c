// The statics of long lines, alone and in a system: the same equilibrium whichever way the
// line is written, found in work that grows as its stations (passes over them counted, not
// time), and given up at the bound with a message that names the line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/equilibrium.h"
#include "core/forces.h"
#include "core/line_equilibrium.h"
#include "core/model.h"
#include "test_support.h"

namespace cablefilm {
namespace {

using testing::Chain;
using testing::Figure;

constexpr double kRho = 1025, kG = 9.80665;
const Vec kAnchor(0.0, -100.0, 0.0), kFairlead(480.0, -10.0, 0.0);  // [m]
constexpr double kLength = 550;  // [m] of chain: 450 m of it on the bed

EnvironmentSpec Sea(bool current) {
  EnvironmentSpec env;
  env.fluid_density = kRho;
  env.gravity = kG;
  env.seabed.present = true;
  env.seabed.y = -100;
  if (current) {  // still at the bed, 0.5 m/s at the surface, across the line (along z)
    env.current_profile.y = {-100.0, -60.0, 0.0};
    env.current_profile.speed = {0.0, 0.2, 0.5};
    env.current_direction = Vec(0.0, 0.0, 1.0);
  }
  return env;
}

// The chain from its anchor on the bed to a fairlead 90 m above it, as one line of `links`
// links, or as two lines of links / 2 joined at a free point of no mass at its middle (a
// system: the two are one coupled island, its point solved with them).
Model OneLine(int links, bool current) {
  std::vector<PointSpec> points = {{"anchor", EndMotion::Fixed(kAnchor), {}},
                                   {"fairlead", EndMotion::Fixed(kFairlead), {}}};
  LineSpec line;
  line.name = "chain";
  line.sections = {Chain(kLength, links)};
  line.start_point = 0;
  line.end_point = 1;
  return MakeModel({line}, points, Sea(current));
}
Model TwoLines(int links, bool current) {
  std::vector<PointSpec> points = {{"anchor", EndMotion::Fixed(kAnchor), {}},
                                   {"joint", EndMotion::Free(Vec(240.0, -90.0, 0.0)), {}},
                                   {"fairlead", EndMotion::Fixed(kFairlead), {}}};
  std::vector<LineSpec> lines(2);
  for (int i = 0; i < 2; ++i) {
    lines[i].name = i == 0 ? "lower" : "upper";
    lines[i].sections = {Chain(0.5 * kLength, links / 2)};
    lines[i].start_point = i;
    lines[i].end_point = i + 1;
  }
  return MakeModel(lines, points, Sea(current));
}

// The largest distance between the one line's stations and the two lines' [m].
double Gap(const State& one, const std::vector<State>& two) {
  const int half = static_cast<int>(two[0].x.cols()) - 1;
  double gap = 0;
  for (int j = 0; j < one.x.cols(); ++j) {
    const Vec p = j <= half ? Vec(two[0].x.col(j)) : Vec(two[1].x.col(j - half));
    gap = std::max(gap, (one.x.col(j) - p).norm());
  }
  return gap;
}

// In still water the line lies in its vertical plane: the elastic catenary with a grounded
// part on a frictionless bed (test_support.h, from its closed form alone) is its truth, and the
// two lines' statics (the chain solved as one line from its coarse copies, then the joint
// balanced with each line held) give the one line's.
TEST(LongLineStatics, AGroundedChainInASystemIsTheLineAloneAndTheCatenary) {
  const int links = 40000;  // 13.75 mm links
  EquilibriumReport one_report, two_report;
  const Model one = OneLine(links, false), two = TwoLines(links, false);
  const State alone = SolveEquilibrium(one, &one_report)[0];
  const std::vector<State> held = SolveEquilibrium(two, &two_report);
  const double gap = Gap(alone, held);

  const SectionSpec c = Chain(1, 1);
  const double EA = c.area * c.youngs_modulus, w = (c.mass_per_length - kRho * c.area) * kG;
  const testing::GroundedCatenary exact = testing::SolveGroundedCatenary(
      kLength, w, EA, kFairlead[0] - kAnchor[0], kFairlead[1] - kAnchor[1]);
  ForceWorkspace ws(links);
  ComputeGeometry(alone.x, ws.geometry);
  ComputeHookeTensions(one.lines[0], ws.geometry, ws.tension);
  const double H = ws.tension[0], top = ws.tension[links - 1];  // [N]
  // The top link's tension is the catenary's at its middle, half a link below the fairlead.
  const double l = kLength / links;
  const double top_exact = std::hypot(exact.H, w * (kLength - exact.Lb - 0.5 * l));
  const double stations = links + 1.0;
  RecordProperty("gap_m", Figure(gap));
  RecordProperty("anchor_tension_error", Figure(H / exact.H - 1));
  RecordProperty("fairlead_tension_error", Figure(top / top_exact - 1));
  RecordProperty("passes_alone", Figure(one_report.line_work / stations));
  RecordProperty("passes_system", Figure(two_report.line_work / stations));
  std::printf("[ long ] grounded chain of %d links: anchor %.8g N (exact %.8g N), top link "
              "%.8g N (exact %.8g N); the system's stations within %.2e m of the line's; "
              "%.1f passes over its stations alone, %.1f in the system\n",
              links, H, exact.H, top, top_exact, gap,
              one_report.line_work / stations, two_report.line_work / stations);
  // The lumped line's tensions against the continuous catenary's: O((l / c)^2) apart (l / c =
  // 1.4e-3 at the touchdown's radius c = H / w = 10 m), and the bed's spring lets the grounded
  // part sink 3e-5 m, 3e-7 of the depth: 1e-5 holds both with room (measured 1e-6, 2e-7).
  EXPECT_NEAR(H / exact.H, 1.0, 1e-5);
  EXPECT_NEAR(top / top_exact, 1.0, 1e-5);
  // The same equilibrium to the statics' tolerance: each line's out-of-balance force within
  // its round-off (0.003 N a station at these links) moves a station by that over the
  // grounded part's stiffness along the bed, micrometres at most (measured 4e-13 m: the chain
  // solved as one line is this line, and the joint balances where it puts it).
  EXPECT_LT(gap, 1e-5);
  // Work as the stations, not their square: a line's statics take 9 to 19 passes over its
  // stations (coarse copies included), the system's the chain's solve as one line and each
  // line held once where it puts the joint (measured 18.3 and 25.3).
  EXPECT_LT(one_report.line_work, 30 * stations);
  EXPECT_LT(two_report.line_work, 40 * stations);
}

// A chain in a sheared current across its plane, its 450 m on the bed (the shipped spread
// mooring's leg): the current bows the suspended part sideways, so Newton's steps turn links
// where the line curves, and its matrix there is the stiff chain's (EA / T = 5e4 along and
// across a link); solved with pivots that are not backward stable, its steps left several
// newtons out of balance and 2 x 10^5 links took 42 iterations instead of 6. Alone and in a
// system the statics take a few Newton iterations from its coarse copies' shape, and give the
// same stations.
TEST(LongLineStatics, AChainInAShearedCurrentTakesAFewIterationsAloneOrInASystem) {
  const int links = 50000;  // 11 mm links
  EquilibriumReport one_report, two_report;
  const State alone = SolveEquilibrium(OneLine(links, true), &one_report)[0];
  const std::vector<State> held = SolveEquilibrium(TwoLines(links, true), &two_report);
  const double gap = Gap(alone, held);
  double sway = 0;  // [m] across the line's vertical plane
  for (int j = 0; j <= links; ++j) sway = std::max(sway, std::abs(alone.x(2, j)));
  const double stations = links + 1.0;
  RecordProperty("iterations", one_report.lines[0].iterations);
  RecordProperty("gap_m", Figure(gap));
  std::printf("[ long ] chain of %d links in a sheared current: %d Newton iterations, %.1f "
              "passes over its stations alone, %.1f in a system; swayed %.3g m; the system's "
              "stations within %.2e m of the line's\n",
              links, one_report.lines[0].iterations, one_report.line_work / stations,
              two_report.line_work / stations, sway, gap);
  EXPECT_GT(sway, 0.2);  // the case it is about: a 3D line, turned across its plane (0.42 m)
  // From the coarse copy's shape, quadratic convergence: a few iterations (measured 2).
  EXPECT_LE(one_report.lines[0].iterations, 6);
  EXPECT_FALSE(one_report.lines[0].fallback);
  EXPECT_LT(one_report.line_work, 30 * stations);
  EXPECT_LT(two_report.line_work, 40 * stations);
  // As above (the sway's stiffness is the tension's, T / L over the suspended part, softer
  // than the bed's: 1e-4 m; measured 6e-13 m) and work as above (measured 16.1 and 21.1).
  EXPECT_LT(gap, 1e-4);
}

// A line whose statics need more than their bound gives up there, saying so and naming the
// line, and nothing catches it: not the chain's or a coarse copy's fallback, not the system's
// relaxation (whose motion would cost more still).
TEST(LongLineStatics, AtTheBoundTheStaticsGiveUpNamingTheLine) {
  const int links = 4000;
  const double stations = links + 1.0;
  EquilibriumOptions options;
  options.max_line_statics = 12 * stations;  // above the least a solve takes, below its need
  StepOptions steps;
  steps.scheme = Scheme::kImplicit;
  options.relaxation = steps;
  options.inputs = SceneInputs(OneLine(links, true).lines[0]);
  for (bool system : {false, true}) {
    const Model model = system ? TwoLines(links, true) : OneLine(links, true);
    try {
      SolveEquilibrium(model, nullptr, options);
      FAIL() << "converged within 12 passes over its stations";
    } catch (const StaticsWorkError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("station-passes"), std::string::npos) << what;
      if (system) {
        EXPECT_NE(what.find("\"lower\", \"upper\""), std::string::npos) << what;
      }
      EXPECT_EQ(what.find("own motion"), std::string::npos) << what;  // no relaxation
    }
  }
  // The least a solve takes (kLeastStaticPasses over its stations) beyond what is left of the
  // bound: refused before anything is done.
  LineEquilibriumOptions line;
  double used = 0;
  line.work = &used;
  line.max_work = (kLeastStaticPasses - 1) * stations;
  EXPECT_THROW(SolveLineEquilibrium(OneLine(links, true).lines[0], nullptr, line),
               StaticsWorkError);
  EXPECT_EQ(used, 0.0);
}

}  // namespace
}  // namespace cablefilm
