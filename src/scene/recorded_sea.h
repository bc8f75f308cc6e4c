#pragma once
// An irregular sea from a measured record of the surface elevation at one point (not in the
// paper): its discrete Fourier transform, by FFTW.
#include <vector>

#include "core/sea_components.h"

namespace cablefilm {

// The components that reproduce a recorded elevation eta_n [m] at equally spaced times t_n [s]
// at the reference point (x0, z0) [m]: its discrete Fourier transform (FFTW), the mean removed,
// each frequency 2 pi j / (N dt) travelling along `heading` [rad]. The sum reproduces the
// record at its times and repeats after N dt. Components below 1e-9 of the largest amplitude are
// left out, and with band_hi > 0 those outside [band_lo, band_hi] [rad/s] (the record filtered).
// Throws Error when the times are not equally spaced (to 1e-6 of the step), there are fewer
// than 4, or more than kMaxSeaComponents components are left.
SeaComponents RecordComponents(const std::vector<double>& times, const std::vector<double>& eta,
                               double x0, double z0, double heading, double gravity, double depth,
                               double band_lo = 0, double band_hi = 0);

}  // namespace cablefilm
