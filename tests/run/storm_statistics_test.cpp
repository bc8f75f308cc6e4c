// The statistics of a storm's end tensions (run/end_tension_pass.h, run/welch_spectrum.h,
// run/gumbel_fit.h) against independent truths: a synthetic Gaussian record of known variance
// and bandwidth, a sinusoid of known frequency and power, closed forms of the Gumbel fit; and
// the --set ranges A..B of a sweep (run/sweep_plan.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "core/error.h"
#include "run/end_tension_pass.h"
#include "run/gumbel_fit.h"
#include "run/running_moments.h"
#include "run/sweep_plan.h"
#include "run/tension_statistics.h"
#include "run/welch_spectrum.h"

namespace cablefilm {
namespace {

// A narrow-banded Gaussian record: the sum of M cosines of equal amplitude a and random phases,
// their frequencies spread evenly over [f0 - B/2, f0 + B/2]: a Gaussian process (the central
// limit over M) of variance m0 = M a^2 / 2 and second moment m2 = sum (a^2 / 2) (2 pi f_i)^2.
struct NarrowBand {
  static constexpr int kM = 200;
  static constexpr double kMean = 5.0e4;    // [N]
  static constexpr double kSigma = 1.0e3;   // [N]
  static constexpr double kF0 = 0.1;        // [Hz], a 10 s wave
  static constexpr double kBand = 0.02;     // [Hz]
  std::vector<double> f, phase;             // [Hz], [rad]
  double a = kSigma * std::sqrt(2.0 / kM);  // [N]
  NarrowBand() {
    std::mt19937_64 random(20261207);
    std::uniform_real_distribution<double> uniform(0, 2 * M_PI);
    for (int i = 0; i < kM; ++i) {
      f.push_back(kF0 - kBand / 2 + kBand * (i + 0.5) / kM);
      phase.push_back(uniform(random));
    }
  }
  double At(double t) const {
    double x = kMean;
    for (int i = 0; i < kM; ++i) x += a * std::cos(2 * M_PI * f[i] * t + phase[i]);
    return x;
  }
  // Rice's rate of mean up-crossings sqrt(m2 / m0) / (2 pi) [1/s].
  double RiceRate() const {
    double m2 = 0;
    for (double fi : f) m2 += 0.5 * a * a * std::pow(2 * M_PI * fi, 2);
    return std::sqrt(m2 / (kSigma * kSigma)) / (2 * M_PI);
  }
};

// A 3-hour storm at 0.1 s rows: 108001 rows, far beyond MaxTensionLog::kMemoryRows, so the
// second pass reads them back from the temporary file.
constexpr double kDt = 0.1;          // [s]
constexpr long kRows = 108001;       // t = 0 to 10800 s
constexpr double kDuration = 10800;  // [s]

// End 0: the narrow band; end 1: a sinusoid of amplitude kA at kFs on a mean kC.
constexpr double kA = 300, kFs = 0.0737, kC = 2.0e4;  // [N], [Hz], [N]

struct Storm {
  NarrowBand band;
  MaxTensionLog log;
  RunningMoments moments[2];
  TensionStatistics stats[2];
  EndTensionSpectrum spectrum;
  Storm() {
    for (long k = 0; k < kRows; ++k) {
      const double t = k * kDt;
      const double x0 = band.At(t), x1 = kC + kA * std::sin(2 * M_PI * kFs * t);
      log.Append(t, std::max(x0, x1), x0, x1);
      moments[0].Add(x0);
      moments[1].Add(x1);
    }
    EndTensionPass(log, moments, kDt, stats, &spectrum);
    std::printf("[ storm ] narrow band: mean %.6f N, sigma %.4f N, %ld up-crossings (Rice %.1f), "
                "max %.1f N, MPM %.1f N, m0 / variance %.5f; sinusoid: m0 / (A^2 / 2) %.8f, "
                "%ld up-crossings\n",
                stats[0].mean, stats[0].sigma, stats[0].upcrossings,
                band.RiceRate() * kDuration, stats[0].max, stats[0].mpm,
                stats[0].psd_m0 / (stats[0].sigma * stats[0].sigma), stats[1].psd_m0 / (kA * kA / 2),
                stats[1].upcrossings);
  }
};

const Storm& TheStorm() {
  static const Storm storm;
  return storm;
}

TEST(StormStatistics, MomentsOfAGaussianRecordOfKnownVariance) {
  const TensionStatistics& s = TheStorm().stats[0];
  EXPECT_EQ(s.samples, kRows);
  // The mean: each cosine's average over n samples is at most a / (n sin(pi f dt)) (a geometric
  // sum), so |mean - kMean| <= M a / (n sin(pi f_min dt)) = 6.6 N, a bound, not a likelihood.
  const double f_min = NarrowBand::kF0 - NarrowBand::kBand / 2;
  const double bound = NarrowBand::kM * TheStorm().band.a / (kRows * std::sin(M_PI * f_min * kDt));
  EXPECT_NEAR(s.mean, NarrowBand::kMean, bound);
  // The standard deviation: a record of a band B over T holds about B T = 216 independent
  // values of its power, so its variance has a relative standard error of 1 / sqrt(B T) = 6.8 %,
  // its sigma half that, 3.4 %: within 4 standard errors, 14 %.
  const double se = 0.5 / std::sqrt(NarrowBand::kBand * kDuration);
  EXPECT_NEAR(s.sigma / NarrowBand::kSigma, 1.0, 4 * se) << s.sigma;
  // The least and largest values bracket the mean by a few sigma (a Gaussian's 1e5 samples).
  EXPECT_LT(s.min, s.mean - 3 * s.sigma);
  EXPECT_GT(s.max, s.mean + 3 * s.sigma);
}

TEST(StormStatistics, UpcrossingsFollowRicesFormula) {
  const Storm& storm = TheStorm();
  const TensionStatistics& s = storm.stats[0];
  const double expected = storm.band.RiceRate() * kDuration;  // about 1080
  // The crossings of a narrow-banded process are more regular than a Poisson stream's (nearly
  // one a cycle), whose count has the standard deviation sqrt(N): within 4 sqrt(N), 12 %.
  EXPECT_NEAR(static_cast<double>(s.upcrossings), expected, 4 * std::sqrt(expected))
      << "Rice: " << expected;
  // Counting both directions, or crossings of zero rather than of the mean, is far outside.
}

TEST(StormStatistics, RayleighMostProbableMaximum) {
  // The formula itself: mean + sigma sqrt(2 ln N).
  EXPECT_NEAR(RayleighMpm(100, 10, 1000), 137.16922, 1e-5);  // sqrt(2 ln 1000) = 3.7169221
  EXPECT_DOUBLE_EQ(RayleighMpm(100, 10, 1), 100.0);
  EXPECT_TRUE(std::isnan(RayleighMpm(100, 10, 0)));
  // The record's: its own N, and near the record's largest value. The largest of N Rayleigh
  // peaks has the standard deviation (pi / sqrt 6) sigma / sqrt(2 ln N) = 0.35 sigma at N =
  // 1080 (the Gumbel limit): the maximum within 4 of them of the MPM.
  const TensionStatistics& s = TheStorm().stats[0];
  EXPECT_DOUBLE_EQ(s.mpm, s.mean + s.sigma * std::sqrt(2 * std::log(double(s.upcrossings))));
  const double spread = M_PI / std::sqrt(6.0) * s.sigma / std::sqrt(2 * std::log(1080.0));
  EXPECT_NEAR(s.max, s.mpm, 4 * spread) << "MPM " << s.mpm;
}

TEST(StormStatistics, WelchSpectrumIntegratesToTheVariance) {
  const Storm& storm = TheStorm();
  const EndTensionSpectrum& p = storm.spectrum;
  ASSERT_FALSE(p.empty());
  // 108001 rows: the largest power of two at most n / 8 = 13500, 8192 samples (819.2 s) a
  // segment, 25 of them at half overlap.
  EXPECT_EQ(p.segment, 8192);
  EXPECT_EQ(p.segments, 25);
  ASSERT_EQ(p.frequency.size(), 4097u);
  EXPECT_DOUBLE_EQ(p.frequency[1], 1 / (8192 * kDt));
  EXPECT_DOUBLE_EQ(p.frequency.back(), 0.5 / kDt);  // Nyquist
  const double df = p.frequency[1];
  for (int e = 0; e < 2; ++e) {
    double m0 = 0;
    for (double s : p.density[e]) m0 += s * df;
    EXPECT_NEAR(m0, storm.stats[e].psd_m0, 1e-9 * m0) << e;
  }
  // The narrow band (Parseval): m0 is the record's mean square less the mean, Hann-weighted
  // (Hann squared at half overlap weighs the rows from 0.5 to 1, periodic in 410 s) over the
  // first 106496 of its rows: it differs from the variance by that weighting of a power known
  // to 6.8 % (B T = 216, above) with a ripple of a quarter: 1.7 %; within 4 of them, 7 %.
  const double var = std::pow(storm.stats[0].sigma, 2);
  EXPECT_NEAR(storm.stats[0].psd_m0 / var, 1.0, 0.07);
  // Nearly all of it in the band, widened by the Hann window's main lobe (2 bins).
  double in_band = 0;
  for (std::size_t k = 0; k < p.frequency.size(); ++k)
    if (std::abs(p.frequency[k] - NarrowBand::kF0) <= NarrowBand::kBand / 2 + 2 * df)
      in_band += p.density[0][k] * df;
  EXPECT_GT(in_band / storm.stats[0].psd_m0, 0.99);
}

TEST(StormStatistics, WelchSpectrumOfASinusoid) {
  const Storm& storm = TheStorm();
  const EndTensionSpectrum& p = storm.spectrum;
  ASSERT_FALSE(p.empty());
  // Its power A^2 / 2 exactly (the window's weighting of cos(2 omega t) over 60 periods a
  // segment, and the record mean's offset of at most A / (n sin(pi f dt)), are below 1e-4).
  EXPECT_NEAR(storm.stats[1].psd_m0, kA * kA / 2, 1e-4 * kA * kA / 2);
  EXPECT_NEAR(storm.stats[1].sigma, kA / std::sqrt(2.0), 1e-3 * kA);
  // Its peak in the bin nearest to kFs (not a bin's frequency: 60.4 bins).
  std::size_t peak = 0;
  for (std::size_t k = 1; k < p.frequency.size(); ++k)
    if (p.density[1][k] > p.density[1][peak]) peak = k;
  const double df = p.frequency[1];
  EXPECT_LE(std::abs(p.frequency[peak] - kFs), 0.5 * df) << p.frequency[peak];
  // One crossing of the mean a period.
  EXPECT_NEAR(static_cast<double>(storm.stats[1].upcrossings), kFs * kDuration, 1.0);
}

TEST(StormStatistics, SegmentLength) {
  EXPECT_EQ(WelchSpectrum::SegmentFor(7), 0);      // too few rows: no spectrum
  EXPECT_EQ(WelchSpectrum::SegmentFor(8), 8);      // the largest power of two in the record
  EXPECT_EQ(WelchSpectrum::SegmentFor(100), 16);   // at least 16
  EXPECT_EQ(WelchSpectrum::SegmentFor(1001), 64);  // 1001 / 8 = 125
  EXPECT_EQ(WelchSpectrum::SegmentFor(10000000), WelchSpectrum::kMaxSegment);
}

TEST(StormStatistics, RunningMomentsAreWelfordsExactly) {
  // Values whose mean is far from zero: a sum of squares would lose them all.
  RunningMoments m;
  const double x[] = {1e9 + 4, 1e9 + 7, 1e9 + 13, 1e9 + 16};
  for (double v : x) m.Add(v);
  EXPECT_EQ(m.count(), 4);
  EXPECT_DOUBLE_EQ(m.mean(), 1e9 + 10);
  EXPECT_DOUBLE_EQ(m.variance(), 22.5);  // (36 + 9 + 9 + 36) / 4
  EXPECT_DOUBLE_EQ(m.min(), 1e9 + 4);
  EXPECT_DOUBLE_EQ(m.max(), 1e9 + 16);
  EXPECT_TRUE(std::isnan(RunningMoments().mean()));
}

TEST(GumbelFit, MethodOfMomentsClosedForm) {
  // Maxima 1, 2, 3: mean 2, s = 1; beta = sqrt(6) / pi = 0.7796968, mu = 2 - 0.5772157 beta =
  // 1.5499468, the 90 % quantile mu + 2.2503673 beta = 3.3045510.
  GumbelFit g;
  ASSERT_TRUE(FitGumbel({3, 1, 2}, &g));
  EXPECT_EQ(g.maxima, 3);
  EXPECT_DOUBLE_EQ(g.mean, 2.0);
  EXPECT_DOUBLE_EQ(g.std, 1.0);
  EXPECT_NEAR(g.beta, 0.7796968, 1e-7);
  EXPECT_NEAR(g.mu, 1.5499468, 1e-7);
  EXPECT_NEAR(g.p90, 3.3045510, 1e-7);
  EXPECT_NEAR(g.Quantile(std::exp(-1.0)), g.mu, 1e-12);  // F(mu) = 1 / e
  // Too few: no fit; NaN maxima left out.
  GumbelFit none;
  EXPECT_FALSE(FitGumbel({1, 2}, &none));
  EXPECT_FALSE(FitGumbel({1, 2, std::nan("")}, &none));
}

TEST(GumbelFit, RecoversTheDistributionOfItsQuantiles) {
  // 100000 maxima at the quantiles (i - 0.5) / n of a Gumbel of mu = 1e6 N, beta = 5e4 N:
  // their mean and standard deviation are the distribution's to within the grid's truncation
  // of its tails (a few 1e-4 of beta).
  const double mu = 1e6, beta = 5e4;
  const int n = 100000;
  std::vector<double> x;
  for (int i = 0; i < n; ++i) x.push_back(mu - beta * std::log(-std::log((i + 0.5) / n)));
  GumbelFit g;
  ASSERT_TRUE(FitGumbel(x, &g));
  EXPECT_NEAR(g.beta, beta, 2e-3 * beta);
  EXPECT_NEAR(g.mu, mu, 2e-3 * beta);
  EXPECT_NEAR(g.p90, mu - beta * std::log(-std::log(0.9)), 4e-3 * beta);
}

TEST(SweepRange, WholeNumbersExpand) {
  EXPECT_EQ(ParseSetOption("waves.seed=1..4").values,
            (std::vector<std::string>{"1", "2", "3", "4"}));
  EXPECT_EQ(ParseSetOption("k = 0, 5 .. 7, 9").values,
            (std::vector<std::string>{"0", "5", "6", "7", "9"}));
  EXPECT_EQ(ParseSetOption("k=-2..1").values,
            (std::vector<std::string>{"-2", "-1", "0", "1"}));
  EXPECT_EQ(ParseSetOption("k=3..3").values, (std::vector<std::string>{"3"}));
  EXPECT_EQ(ParseSetOption("k=1..10000").values.size(), 10000u);
  // Not a range: a string holding "..".
  EXPECT_EQ(ParseSetOption("k=\"a..b\"").values, (std::vector<std::string>{"\"a..b\""}));
}

TEST(SweepRange, BadRangesAreRefusedNamingTheKey) {
  auto message = [](const std::string& option) {
    try {
      ParseSetOption(option);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string down = message("waves.seed=5..1");
  EXPECT_NE(down.find("waves.seed"), std::string::npos) << down;
  EXPECT_NE(down.find("A <= B"), std::string::npos) << down;
  for (const char* bad : {"waves.seed=1..x", "waves.seed=1.5..3", "waves.seed=..3",
                          "waves.seed=1...3", "waves.seed=1..99999999999999999999"}) {
    const std::string m = message(bad);
    EXPECT_NE(m.find("waves.seed"), std::string::npos) << bad << ": " << m;
    EXPECT_NE(m.find("whole numbers"), std::string::npos) << bad << ": " << m;
  }
  const std::string many = message("waves.seed=1..10001");
  EXPECT_NE(many.find("10001 values"), std::string::npos) << many;
  EXPECT_NE(many.find("at most 10000"), std::string::npos) << many;
}

}  // namespace
}  // namespace cablefilm
