#pragma once
// The stability limit of explicit time stepping: the highest axial frequency of the lumped
// cable, bounded above (Gershgorin) so the step it gives is safe.
//
// Computed once, from the model, it holds in every state the cable reaches, so it need not be
// recomputed as the cable moves: the block Gershgorin bound of M^-1/2 K M^-1/2 uses the norm of
// each link's kDim x kDim stiffness, which stretched to L > l is (sigma E / l) t t^T + (T / L)(I - t t^T)
// (axial, and the geometric stiffness across), of norm sigma E / l since T / L = sigma E (L - l)
// / (l L) < sigma E / l at any strain; a slack link has none. And m_j + min(m^x_j, m^y_j) is the
// least inertia of station j in any direction: the links' normal added mass only adds to it.
// (tests/core/stability_test.cpp checks the bound against the exact highest frequency of
// stretched, curved, partly slack states in water.) What the limit does not cover is a link
// going slack or snapping taut within a step: see explicit_integrator.h. A seabed adds its
// spring (up to 2 k l_j: the dashpot adds at most the spring's force) and dashpot c_j to every
// station's row (a station off the bed only loses them).
#include "core/line_model.h"

namespace cablefilm {

struct StabilityLimit {
  double omega_max = 0;    // upper bound of the highest natural frequency [rad/s]
  double time_step = 0;    // 2 / omega_max [s] (less with axial damping): central differences
                           // are stable below it
  int station = 0;         // the station whose row gives the bound (the stiffest place)
};

StabilityLimit ComputeStabilityLimit(const LineModel& m);

}  // namespace cablefilm
