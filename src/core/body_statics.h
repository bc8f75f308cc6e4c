#pragma once
// The quasi-static tools of a moored body (MoorPy's): the load of the moorings on a body held at
// a pose, their 6x6 stiffness matrix there, and the offset-restoring curve (the body moved along
// a heading, its other degrees of freedom held, against the restoring force and the tensions at
// its lines' ends). Each pose is a static equilibrium of the system (equilibrium.h) with
// the body held there: the lines, the shared points and the other free bodies balance.
#include <vector>

#include "core/coupled_equilibrium.h"

namespace cablefilm {

struct MooringLoad {
  Vec6 load = Vec6::Zero();  // the lines' force [N] and moment about the reference point [N m]
  // Per line: the load at its end on the body (the end station's force: its end link's tension
  // and lumped share, as points.csv reports a fairlead's) [N]; NaN for a line not on the body.
  std::vector<double> end_tension;
  std::vector<State> states;  // the lines' equilibrium
};

// Body b's pose at the system's equilibrium (Newton's from the scene's positions, or the
// relaxation of options.relaxation where Newton fails: equilibrium.h).
Vec6 EquilibriumPose(const Model& sys, int b, const EquilibriumOptions& options = {});

// The moorings' load on body b held at `pose` (its statics from options.guess when given: the
// system's equilibrium, say, which the scene's positions may not reach).
MooringLoad LoadAtPose(const Model& sys, int b, const Vec6& pose,
                       const EquilibriumOptions& options = {});

// K = -d(load)/d(pose) at `pose` [N/m, N/rad, N m/m, N m/rad] by central differences: steps of
// `step` [m] in translation and step / (the body's size) [rad] in rotation (a turn moving its
// farthest point as far). The moorings' stiffness only: the body's hydrostatics are its own.
Mat6 MooringStiffness(const Model& sys, int b, const Vec6& pose, double step,
                      const EquilibriumOptions& options = {});

struct OffsetPoint {
  double offset = 0;     // along the heading [m]
  double restoring = 0;  // the load's horizontal force against the heading [N]
  MooringLoad load;
};

// The headings the offset curve takes [deg], either way: a turn at most (beyond it a number is
// a mistake, and 1e308 degrees overflows in radians).
constexpr double kMaxHeading = 360;

// Body b moved from `pose` by each of `offsets` [m] along the horizontal heading [deg] from +x
// towards +z, its other degrees of freedom held. Throws Error naming the heading when it is not
// within +-kMaxHeading: every front end's one check.
std::vector<OffsetPoint> OffsetCurve(const Model& sys, int b, const Vec6& pose,
                                     double heading, const std::vector<double>& offsets,
                                     const EquilibriumOptions& options = {});

// The largest distance from body b's reference point to a point on it where a line ends, at
// least 1 m: its size, as the stiffness's rotation steps use it.
double BodySize(const Model& sys, int b);

// The unstretched length of the shortest line with an end on body b [m]: the scale of the
// quasi-static tools' steps (stiffness: 1e-4 of it; the offset curve's default reach: 5 %).
// Throws Error when no line ends on the body.
double ShortestLineOn(const Model& sys, int b);

}  // namespace cablefilm
