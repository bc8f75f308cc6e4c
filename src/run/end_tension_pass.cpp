#include "run/end_tension_pass.h"

#include <limits>
#include <memory>

#include "run/welch_spectrum.h"

namespace cablefilm {

void EndTensionPass(const MaxTensionLog& rows, const RunningMoments moments[2], double interval,
                    TensionStatistics stats[2], EndTensionSpectrum* spectrum) {
  *spectrum = EndTensionSpectrum();
  const long n = rows.rows();
  const int segment = WelchSpectrum::SegmentFor(n);
  std::unique_ptr<WelchSpectrum> welch[2];
  UpcrossingCounter crossings[2] = {UpcrossingCounter(moments[0].mean()),
                                    UpcrossingCounter(moments[1].mean())};
  for (int e = 0; e < 2; ++e)
    if (segment > 0 && interval > 0)
      welch[e] = std::make_unique<WelchSpectrum>(segment, interval, moments[e].mean());
  MaxTensionLog::Cursor cursor(rows);
  double t = 0, tmax = 0, end[2] = {0, 0};
  const double all = std::numeric_limits<double>::infinity();
  while (cursor.Next(all, &t, &tmax, &end[0], &end[1]))
    for (int e = 0; e < 2; ++e) {
      crossings[e].Add(end[e]);
      if (welch[e]) welch[e]->Add(end[e]);
    }
  for (int e = 0; e < 2; ++e) {
    TensionStatistics& s = stats[e];
    s = TensionStatistics();
    s.samples = moments[e].count();
    if (s.samples == 0) continue;
    s.mean = moments[e].mean();
    s.sigma = moments[e].sigma();
    s.min = moments[e].min();
    s.max = moments[e].max();
    s.upcrossings = crossings[e].count();
    s.mpm = RayleighMpm(s.mean, s.sigma, s.upcrossings);
    if (welch[e] && welch[e]->segments() > 0) s.psd_m0 = welch[e]->m0();
  }
  if (!welch[0] || welch[0]->segments() == 0) return;
  spectrum->segment = segment;
  spectrum->segments = welch[0]->segments();
  for (int k = 0; k < welch[0]->bins(); ++k) {
    spectrum->frequency.push_back(welch[0]->frequency(k));
    for (int e = 0; e < 2; ++e) spectrum->density[e].push_back(welch[e]->density(k));
  }
}

}  // namespace cablefilm
