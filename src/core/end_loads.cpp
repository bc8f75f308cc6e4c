#include "core/end_loads.h"

#include <algorithm>
#include <cmath>

#include "core/forces.h"

namespace cablefilm {

Vec HeldEndLoad(const LineModel& m, const LinkGeometry& g, const Points& station_force, int j,
                const Vec& a) {
  return station_force.col(j) - StationInertia(m, g, j) * a;
}

Vec FreeEndPull(const LineModel& m, const ForceWorkspace& forces, int e) {
  const int k = e == 0 ? 0 : m.line.links - 1;  // the end link k+1/2
  const Vec pull = forces.tension[k] * forces.geometry.tangent.col(k);
  return e == 0 ? pull : Vec(-pull);
}

EndLoads::EndLoads(const LineModel& m) : station_force_(Points::Zero(kDim, m.stations())) {}

void EndLoads::Compute(const LineModel& m, const LineData& d, const Inputs& in) {
  if (station_force_.cols() != m.stations()) station_force_ = Points::Zero(kDim, m.stations());
  ComputeStationForces(m, d.water, d.forces.geometry, d.forces.tension, d.state.v,
                       station_force_);
  for (int e = 0; e < 2; ++e) {
    const int j = e == 0 ? 0 : m.line.links;
    load_[e] = m.prescribed(j) ? HeldEndLoad(m, d.forces.geometry, station_force_, j,
                                             EndAcceleration(m, in, j, d.state.t))
                               : FreeEndPull(m, d.forces, e);
  }
}

double ElevationDegrees(const Vec& f) {
  const double size = f.norm();
  if (!(size > 0)) return 0;
  return std::asin(std::clamp(f[1] / size, -1.0, 1.0)) * (180.0 / 3.14159265358979323846);
}

}  // namespace cablefilm
