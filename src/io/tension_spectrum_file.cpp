#include "io/tension_spectrum_file.h"

#include "io/atomic_file.h"
#include "io/csv_line.h"

namespace cablefilm {

void WriteTensionSpectrumCsv(const std::string& path, const EndTensionSpectrum& spectrum) {
  AtomicFile file(path);
  std::FILE* f = file.stream();
  std::fputs("frequency,tension_start_psd,tension_end_psd\n", f);
  for (std::size_t k = 0; k < spectrum.frequency.size(); ++k) {
    CsvLine line(f);
    line.G(spectrum.frequency[k], 12).Comma().G(spectrum.density[0][k], 10).Comma();
    line.G(spectrum.density[1][k], 10).Char('\n');
  }
  file.Commit();
}

}  // namespace cablefilm
