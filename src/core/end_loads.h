#pragma once
// The loads at a line's two ends: the force [N] the line exerts on what holds each end (an
// anchor, a fairlead, a tow point), as MoorDyn reports a fixed point's load and as anchors and
// fairlead stoppers are designed. Not the end link's tension alone: the end station's lumped
// share of weight, buoyancy, drag and seabed reaction are part of what the holder carries.
#include "core/line_data.h"
#include "core/inputs.h"
#include "core/line_model.h"

namespace cablefilm {

// At a held end (station j fixed, moved or riding on a body, with acceleration a [m/s^2]):
// force_j - M_j a, the end station's force (the end link's pull T t and its external forces
// X_j, eq. 1) less its inertia (M_j, eq. 1's inertia tensor), since M_j a = force_j + F_holder.
// `station_force` holds ComputeStationForces' result for the state.
Vec HeldEndLoad(const LineModel& m, const LinkGeometry& g, const Points& station_force, int j,
                const Vec& a);

// At a free end e (0: station 0, 1: station s): the pull of its end link alone, T t along it
// (a free end carries its own weight and drag: no holder takes them).
Vec FreeEndPull(const LineModel& m, const ForceWorkspace& forces, int e);

// Both end loads of one line in a LineData (end e), computed per output row. Sized by the model
// (or at the first Compute); Compute allocates nothing after that.
class EndLoads {
 public:
  EndLoads() = default;
  explicit EndLoads(const LineModel& m);
  void Compute(const LineModel& m, const LineData& d, const Inputs& in);
  const Vec& at(int e) const { return load_[e]; }

 private:
  Points station_force_;  // ComputeStationForces of the state [N] (kDim x s+1)
  Vec load_[2]{Vec::Zero(), Vec::Zero()};
};

// The angle of a force above the horizontal [deg]: asin(f_y / |f|), -90..90 (y is up); 0 for
// a zero force. At a fairlead the line pulls down (negative), at a lifted anchor up.
double ElevationDegrees(const Vec& f);

}  // namespace cablefilm
