#pragma once
// What the lines hold at their points and bodies (points.csv, body.csv, results.nc, the live
// view's loads).
#include <vector>

#include "core/data.h"
#include "core/inputs.h"

namespace cablefilm {

// The points' positions [m] and the forces the lines exert on them [N] in a state (column p:
// point p). At a fixed or moved point, or a point on a body, the force is the sum over its
// line ends of their end stations' forces (the end link's tension, and the station's lumped
// share of weight, buoyancy and drag), less their inertia where the point moves: what an
// anchor or a fairlead must hold, as MoorDyn reports it. At a free point, the pull of its
// lines' end links (their tensions along them). Each body's pose and the lines' load on it
// (force [N], moment about its reference point [N m]). Sized once; Compute allocates nothing.
class PointLoads {
 public:
  explicit PointLoads(const Model& model);
  void Compute(const Model& model, const Data& d, const Inputs& in);
  const Points& positions() const { return positions_; }
  const Points& forces() const { return forces_; }
  const std::vector<Vec6>& body_poses() const { return body_poses_; }
  const std::vector<Vec6>& body_loads() const { return body_loads_; }

 private:
  std::vector<Points> station_forces_;  // per line
  Points positions_, forces_;
  std::vector<Vec6> body_poses_, body_loads_;
};

}  // namespace cablefilm
