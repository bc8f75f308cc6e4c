#pragma once
// The stability limit of explicit time stepping: the highest axial frequency of the lumped
// cable, bounded above (Gershgorin) so the step it gives is safe.
#include "core/cable_model.h"

namespace cablefilm {

struct StabilityLimit {
  double omega_max = 0;    // upper bound of the highest natural frequency [rad/s]
  double time_step = 0;    // 2 / omega_max [s]: central differences are stable below it
  int station = 0;         // the station whose row gives the bound (the stiffest place)
};

StabilityLimit ComputeStabilityLimit(const CableModel& m);

}  // namespace cablefilm
