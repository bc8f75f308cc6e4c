#include "run/sweep_maxima.h"

#include <cmath>
#include <cstdio>

namespace cablefilm {
namespace {

std::string Number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

}  // namespace

std::vector<SweepMaxima> CollectSweepMaxima(const std::vector<CaseOutcome>& outcomes) {
  struct Column {
    const char* name;
    double (*value)(const RunSummary&);
  };
  const Column columns[] = {
      {"peak_tension", [](const RunSummary& s) { return s.peak; }},
      {"tension_start_max", [](const RunSummary& s) { return s.ends[0].max; }},
      {"tension_end_max", [](const RunSummary& s) { return s.ends[1].max; }},
  };
  std::vector<SweepMaxima> out;
  for (const Column& c : columns) {
    SweepMaxima m;
    m.name = c.name;
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
      if (!outcomes[i].has_summary) continue;
      const double v = c.value(outcomes[i].summary);
      if (!std::isfinite(v)) continue;
      m.cases.push_back(i);
      m.maxima.push_back(v);
    }
    m.fitted = FitGumbel(m.maxima, &m.fit);
    out.push_back(std::move(m));
  }
  return out;
}

std::string SweepMaximaToml(const std::vector<SweepMaxima>& columns) {
  std::string t =
      "# cablefilm sweep: the maxima of the finished cases and, from 3 of them, their Gumbel fit\n"
      "# (method of moments: beta = std sqrt(6) / pi, mu = mean - 0.5772 beta; F(x) =\n"
      "# exp(-exp(-(x - mu) / beta)))\n";
  for (const SweepMaxima& m : columns) {
    t += std::string("\n[") + m.name + "]\ncases = [";
    for (std::size_t k = 0; k < m.cases.size(); ++k)
      t += (k ? ", " : "") + std::to_string(m.cases[k]);
    t += "]\nmaxima = [";
    for (std::size_t k = 0; k < m.maxima.size(); ++k) t += (k ? ", " : "") + Number(m.maxima[k]);
    t += "]  # [N], case by case\n";
    if (!m.fitted) continue;
    const GumbelFit& g = m.fit;
    t += "mean = " + Number(g.mean) + "  # [N], of the maxima\n";
    t += "std = " + Number(g.std) + "  # [N], their sample standard deviation (over n - 1)\n";
    t += "gumbel_beta = " + Number(g.beta) + "  # [N], scale\n";
    t += "gumbel_mu = " + Number(g.mu) + "  # [N], location: the mode, the most probable maximum\n";
    t += "gumbel_p90 = " + Number(g.p90) + "  # [N], the 90 % quantile, mu - beta ln(-ln 0.9)\n";
  }
  return t;
}

std::vector<std::string> DescribeSweepMaxima(const std::vector<SweepMaxima>& columns) {
  std::vector<std::string> lines;
  for (const SweepMaxima& m : columns) {
    if (!m.fitted) continue;
    const GumbelFit& g = m.fit;
    lines.push_back(std::string(m.name) + ": Gumbel fit of " + std::to_string(g.maxima) +
                    " maxima: most probable maximum (mode) " + Number(g.mu) +
                    " N, 90 % quantile " + Number(g.p90) + " N (mean " + Number(g.mean) +
                    " N, std " + Number(g.std) + " N)");
  }
  return lines;
}

}  // namespace cablefilm
