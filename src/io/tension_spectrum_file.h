#pragma once
// tension_spectrum.csv: the one-sided spectral density of a line's end tensions (Welch's method,
// run/end_tension_pass.h), frequency,tension_start_psd,tension_end_psd in Hz and N^2/Hz, a row
// a frequency from 0 to Nyquist. Written whole or not at all.
#include <string>

#include "run/end_tension_pass.h"

namespace cablefilm {

// Writes `spectrum` (not empty) to `path`. Throws Error.
void WriteTensionSpectrumCsv(const std::string& path, const EndTensionSpectrum& spectrum);

}  // namespace cablefilm
