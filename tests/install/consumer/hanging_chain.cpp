// A downstream program on cablefilm::core: the static equilibrium of a chain hanging in water
// from a fixed point with a clump weight at its free end, against the closed form.
//
// A link's tension carries everything below it: T(s) = W* + w (L - s), w = (mu - rho sigma) g
// the chain's net weight per length, W* = (m* - rho V*) g the clump's. In the lumped model the
// links' tensions are this at their midpoints exactly, so the top link (the anchor takes half
// its weight) carries W* + w (L - l/2), and the stretched chain reaches
// L + (W* L + w L^2 / 2) / (E sigma) below the fixed point.
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/line_model.h"
#include "core/line_equilibrium.h"
#include "core/forces.h"

int main() {
  using namespace cablefilm;
  const int n = 40;
  const double L = 50.0, g = 9.80665, rho = 1025.0;
  SectionSpec chain;  // 1 in steel wire rope
  chain.length = L;
  chain.segments = n;
  chain.diameter = 0.0254;
  chain.area = 5.067e-4;
  chain.mass_per_length = 2.75;
  chain.youngs_modulus = 9.0e10;
  chain.drag_coefficient = 1.2;
  chain.added_mass_coefficient = 1.0;
  PrismSpec clump;
  clump.station = n;
  clump.mass = 200.0;
  clump.volume = 0.025;
  EnvironmentSpec sea;
  sea.gravity = g;
  sea.fluid_density = rho;
  // Fixed at the origin; the free end starts off to the side, so the solver has work to do.
  const LineModel m = MakeLineModel({chain}, {clump}, sea, EndMotion::Fixed(InPlane(0.0, 0.0)),
                                       EndMotion::Free(InPlane(20.0, -40.0)), LinkLaw::kElastic);
  LineEquilibriumReport report;
  const State state = SolveLineEquilibrium(m, StraightChord(m), &report);

  ForceWorkspace ws(m.line.links);
  ComputeGeometry(state.x, ws.geometry);
  ComputeHookeTensions(m, ws.geometry, ws.tension);

  const double w = (chain.mass_per_length - rho * chain.area) * g;
  const double W = (clump.mass - rho * clump.volume) * g;
  const double l = L / n, EA = chain.youngs_modulus * chain.area;
  const double top = W + w * (L - 0.5 * l);
  const double depth = L + (W * L + 0.5 * w * L * L) / EA;
  const double top_error = std::abs(ws.tension[0] - top) / top;
  const double depth_error = std::abs(-state.x(1, n) - depth);
  const double side_error = std::abs(state.x(0, n));
  std::printf("hanging chain: %d Newton iterations\n", report.iterations);
  std::printf("top tension %.6f N, closed form %.6f N (relative error %.1e)\n", ws.tension[0],
              top, top_error);
  std::printf("depth of the clump %.9f m, closed form %.9f m (error %.1e m, sideways %.1e m)\n",
              -state.x(1, n), depth, depth_error, side_error);
  const bool ok = top_error < 1e-7 && depth_error < 1e-7 && side_error < 1e-7;
  std::printf("%s\n", ok ? "agrees with the closed form" : "DISAGREES with the closed form");
  return ok ? 0 : 1;
}
