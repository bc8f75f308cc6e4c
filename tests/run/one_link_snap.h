#pragma once
// A snap with a closed form (snap_monitor_test, explicit_snaps_test).
#include <cmath>

#include "../core/test_support.h"

namespace cablefilm::testing {

// One link in vacuum, without gravity: station 0 fixed, station 1 moving away at v with the
// link slack. When the link comes taut the station is a mass m on a one-sided spring k = EA/l:
// the tension rises as k (v / omega) sin(omega t), omega^2 = k / m, to v sqrt(k m) after
// pi / (2 omega), and the link goes slack again after pi / omega.
struct OneLinkSnap {
  double l = 1.0, EA = 1e6, mu = 2.0, v = 1.5;  // [m], [N], [kg/m], [m/s]
  LineModel model;
  State state;
  OneLinkSnap() {
    EnvironmentSpec vacuum;
    vacuum.fluid_density = 0;
    vacuum.gravity = 0;
    model = UniformCable(1, l, mu, 1e-4, EA / 1e-4, vacuum, EndMotion::Fixed(InPlane(0, 0)),
                         EndMotion::Free(InPlane(0.9 * l, 0)));
    state.t = 0;
    state.x = Points::Zero(kDim, 2);
    state.x.col(1) = InPlane(0.9 * l, 0);  // slack: 0.1 l to go
    state.v = Points::Zero(kDim, 2);
    state.v.col(1) = InPlane(v, 0);
  }
  double station_mass() const { return model.line.cable_mass[1]; }  // mu l / 2
  double peak() const { return v * std::sqrt(EA / l * station_mass()); }
};

}  // namespace cablefilm::testing
