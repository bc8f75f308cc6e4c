// An irregular sea (sea_spectrum.h, sea_components.h, waves.h): the spectra against their
// closed-form areas, the drawn components against the target spectrum (Hs, the peak, the first
// moment), the elevation they make against a Gaussian record, the spreading against its
// closed-form mean, a one-component sea against the regular wave it is, and the summed
// kinematics against the sum of the components' own (linear theory is linear) and against
// their gradients by differences.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "core/sea_components.h"
#include "core/sea_spectrum.h"
#include "core/waves.h"
#include "test_support.h"

namespace cablefilm {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kG = 9.80665;

SpectrumSpec Jonswap(double hs, double tp, double gamma) {
  SpectrumSpec s;
  s.kind = SpectrumKind::kJonswap;
  s.hs = hs;
  s.tp = tp;
  s.gamma = gamma;
  return s;
}

Wave SeaWave(const SeaComponents& sea, double hs, double tp, double depth,
             WaveKinematics kinematics = WaveKinematics::kWheeler, double ramp_rate = 0) {
  WaveSpec spec;
  spec.present = true;
  spec.height = hs;
  spec.period = tp;
  spec.depth = depth;
  spec.kinematics = kinematics;
  spec.ramp_rate = ramp_rate;
  spec.sea = std::make_shared<const SeaComponents>(sea);
  return MakeWave(spec, kG);
}

// Pierson-Moskowitz integrates to Hs^2 / 16 exactly (substitute u = (omega_p / omega)^4: the
// integral of 5/16 Hs^2 / 4 (5/4)^{-1} d(e^{-5u/4}) over u in (0, inf)). Simpson's rule on
// 0.1 to 20 omega_p with 20000 cells: the tail beyond holds 2e-6 of it; 1e-5.
TEST(SeaSpectrum, PiersonMoskowitzHoldsHsSquaredOverSixteen) {
  SpectrumSpec pm = Jonswap(6.0, 10.0, 1.0);
  pm.kind = SpectrumKind::kPiersonMoskowitz;
  const double wp = 2 * kPi / 10.0;
  EXPECT_NEAR(SpectrumArea(pm, 0.1 * wp, 20 * wp, 20000), 36.0 / 16.0, 1e-5 * 36.0 / 16.0);
  // gamma = 1 is Pierson-Moskowitz; DNV's A_gamma keeps 4 sqrt(m0) near Hs for gamma to 7
  // (DNV-RP-C205 3.5.5.3 says "about 1 %": measured below 1.5 % at 3.3 and 7).
  for (double gamma : {1.0, 3.3, 7.0}) {
    const double m0 = SpectrumArea(Jonswap(6.0, 10.0, gamma), 0.1 * wp, 20 * wp, 20000);
    EXPECT_NEAR(4 * std::sqrt(m0), 6.0, 0.015 * 6.0) << gamma;
  }
  // DNV's gamma rule: 5 at Tp / sqrt(Hs) <= 3.6, 1 from 5, exp(5.75 - 1.15 r) between.
  EXPECT_EQ(DnvJonswapGamma(9.0, 10.0), 5.0);
  EXPECT_EQ(DnvJonswapGamma(1.0, 10.0), 1.0);
  EXPECT_NEAR(DnvJonswapGamma(4.0, 8.6), std::exp(5.75 - 1.15 * 4.3), 1e-14);
  // JONSWAP's density at the peak: A_gamma gamma S_PM(omega_p) = A_gamma gamma 5/16 Hs^2 /
  // omega_p e^{-5/4}.
  const double peak = (1 - 0.287 * std::log(3.3)) * 3.3 * 5.0 / 16.0 * 36.0 / wp * std::exp(-1.25);
  EXPECT_NEAR(SpectralDensity(Jonswap(6.0, 10.0, 3.3), wp), peak, 1e-12 * peak);
}

// The drawn components hold the spectrum: Hs from their m0 within 1 % of the target's (they
// hold the band's area exactly, by Simpson on 16 intervals a bin, and the band leaves out 1e-3
// of the area: 0.05 % of Hs), the peak within a bin of omega_p, and the first moment m1 / m0
// within 1 % of the target's (a bin's frequency is drawn anywhere in it: the mean frequency of
// 200 bins moves by about dw / sqrt(12 * 200) relative to the bins').
TEST(SeaComponents, DrawnComponentsHoldTheSpectrum) {
  const SpectrumSpec s = Jonswap(6.0, 10.0, 3.3);
  SeaDiscretization d;
  d.components = 200;
  d.seed = 7;
  const SeaComponents sea = SpectrumComponents(s, d, kG, 200.0);
  ASSERT_EQ(sea.size(), 200);
  const double wp = 2 * kPi / 10.0;
  const double m0 = SpectrumArea(s, 0.1 * wp, 20 * wp, 20000);
  EXPECT_NEAR(sea.SignificantHeight(), 4 * std::sqrt(m0), 0.01 * 4 * std::sqrt(m0));
  int peak = 0;
  double m1 = 0;
  for (int i = 0; i < sea.size(); ++i) {
    if (sea.amplitude[i] > sea.amplitude[peak]) peak = i;
    m1 += 0.5 * sea.amplitude[i] * sea.amplitude[i] * sea.omega[i];
  }
  EXPECT_NEAR(sea.omega[peak], wp, sea.frequency_step);
  double target_m1 = 0;  // int omega S d omega, Simpson on the same span
  {
    const int n = 20000;
    const double lo = 0.1 * wp, hi = 20 * wp, h = (hi - lo) / n;
    for (int i = 0; i <= n; ++i) {
      const double w = lo + i * h, f = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
      target_m1 += f * w * SpectralDensity(s, w) * h / 3;
    }
  }
  EXPECT_NEAR(m1 / sea.Variance(), target_m1 / m0, 0.01 * target_m1 / m0);
  // The same seed: the same components, to the bit; another seed: other phases.
  const SeaComponents again = SpectrumComponents(s, d, kG, 200.0);
  EXPECT_EQ(again.phase, sea.phase);
  EXPECT_EQ(again.omega, sea.omega);
  EXPECT_EQ(again.amplitude, sea.amplitude);
  d.seed = 8;
  EXPECT_NE(SpectrumComponents(s, d, kG, 200.0).phase, sea.phase);
}

// The elevation the components make at a point over three hours (every 0.25 s) is a Gaussian
// record of the spectrum's variance: its variance within sampling error of m0, its skewness and
// excess kurtosis within theirs. The record holds about T / tau independent values, tau the
// correlation time ~ Tp / 2 (2160 here): the sample variance's relative error is then about
// sqrt(2 / 2160) = 3 %, skewness's sqrt(6 / 2160) = 0.053 and kurtosis's sqrt(24 / 2160) = 0.11;
// bounds of 3 standard errors (an honest Gaussian fails them 0.3 % of the time, and the seed is
// fixed).
TEST(SeaComponents, ElevationIsAGaussianRecordOfTheSpectrum) {
  SeaDiscretization d;
  d.seed = 3;
  const SeaComponents sea = SpectrumComponents(Jonswap(6.0, 10.0, 3.3), d, kG, 200.0);
  const Wave wave = SeaWave(sea, 6.0, 10.0, 200.0);
  std::vector<double> eta;
  for (double t = 0; t < 10800; t += 0.25) eta.push_back(SurfaceAt(wave, Vec(30, 0, -20), t));
  double mean = 0;
  for (double e : eta) mean += e;
  mean /= eta.size();
  double m2 = 0, m3 = 0, m4 = 0;
  for (double e : eta) {
    const double x = e - mean;
    m2 += x * x;
    m3 += x * x * x;
    m4 += x * x * x * x;
  }
  m2 /= eta.size();
  m3 /= eta.size();
  m4 /= eta.size();
  const double skew = m3 / std::pow(m2, 1.5), kurt = m4 / (m2 * m2) - 3;
  std::printf("[ 3 h of JONSWAP Hs 6 m, Tp 10 s ] variance %.4f m^2 (m0 %.4f), skewness %.4f, "
              "excess kurtosis %.4f\n", m2, sea.Variance(), skew, kurt);
  EXPECT_NEAR(m2, sea.Variance(), 3 * 0.03 * sea.Variance());
  EXPECT_NEAR(skew, 0.0, 3 * 0.053);
  EXPECT_NEAR(kurt, 0.0, 3 * 0.11);
}

// Short-crested: the directions drawn from cos^{2s}((beta - heading) / 2) have the mean
// E[cos(beta - heading)] = s / (s + 1) (the first circular moment of cos-2s) and a mean sine
// of 0. 2000 components: the sample mean's standard error is at most sqrt(var / 2000) < 0.022;
// 3 of them.
TEST(SeaComponents, SpreadDirectionsFollowCosTwoS) {
  for (double s : {1.0, 4.0, 15.0}) {
    SeaDiscretization d;
    d.components = 2000;
    d.spreading = s;
    d.heading = 0.6;
    const SeaComponents sea = SpectrumComponents(Jonswap(4.0, 9.0, 2.0), d, kG, 150.0);
    double c = 0, sn = 0;
    for (int i = 0; i < sea.size(); ++i) {
      const double b = std::atan2(sea.dir_z[i], sea.dir_x[i]) - 0.6;
      c += std::cos(b);
      sn += std::sin(b);
    }
    c /= sea.size();
    sn /= sea.size();
    EXPECT_NEAR(c, s / (s + 1), 3 * 0.022) << s;
    EXPECT_NEAR(sn, 0.0, 3 * 0.022) << s;
  }
  // The inverse distribution itself: the median is the heading, the quartiles symmetric about
  // it; s = 0 spreads evenly round the circle (its quartiles at -+pi / 2). To the tabulation's
  // 1e-6.
  EXPECT_NEAR(SpreadingAngle(4.0, 0.5), 0.0, 1e-6);
  EXPECT_NEAR(SpreadingAngle(4.0, 0.25), -SpreadingAngle(4.0, 0.75), 1e-6);
  EXPECT_NEAR(SpreadingAngle(0.0, 0.25), -kPi / 2, 1e-6);
}

// A sea of one component is the regular wave it is: every field of the kinematics, in every
// mode, under and over the still water level, during the ramp, to round-off (1e-13 of the
// field's scale: the same arithmetic, summed from zero).
TEST(SeaComponents, OneComponentIsTheRegularWave) {
  for (WaveKinematics kin : {WaveKinematics::kWheeler, WaveKinematics::kLinear,
                             WaveKinematics::kExtrapolated}) {
    WaveSpec spec;
    spec.present = true;
    spec.height = 4.0;
    spec.period = 9.0;
    spec.depth = 40.0;
    spec.phase = 0.7;
    spec.heading = 0.4;
    spec.ramp_rate = 0.3;
    spec.kinematics = kin;
    const Wave regular = MakeWave(spec, kG);
    SeaComponents one;
    one.Add(2.0, regular.omega, 0.7, 0.4, kG, 40.0);
    const Wave sea = SeaWave(one, 4.0, 9.0, 40.0, kin, 0.3);
    const double su = regular.amplitude * regular.omega * 2, sa = su * regular.omega;
    for (double t : {0.5, 3.0, 20.0})
      for (double y : {-39.0, -10.0, -1.0, 0.5, 1.5, 3.0}) {
        const Vec at(13.0, y, -7.0);
        const WaterKinematics a = KinematicsAt(regular, at, t), b = KinematicsAt(sea, at, t);
        EXPECT_NEAR(a.eta, b.eta, 1e-13 * 2);
        EXPECT_LE((a.velocity - b.velocity).norm(), 1e-13 * su);
        EXPECT_LE((a.acceleration - b.acceleration).norm(), 1e-13 * sa);
        EXPECT_LE((a.velocity_gradient - b.velocity_gradient).norm(), 1e-13 * su);
        EXPECT_LE((a.acceleration_gradient - b.acceleration_gradient).norm(), 1e-13 * sa);
        EXPECT_NEAR(SurfaceAt(regular, at, t), SurfaceAt(sea, at, t), 1e-13 * 2);
      }
  }
}

// Linear theory is linear: under the troughs, unstretched ("linear"), the sea's velocity and
// acceleration are the sums of its components' own, each a regular wave; and the summed
// gradients match central differences of the summed fields (step 1e-5 of the shortest wave:
// truncation (k d)^2 / 6 ~ 1e-10, round-off 1e-16 / 1e-5; 1e-6 of the scale). Stretched
// (Wheeler's), the sum is evaluated under the whole surface, so only the gradients are checked.
TEST(SeaComponents, KinematicsAreTheSumOfTheComponentsAndTheirGradientsHold) {
  SeaDiscretization d;
  d.components = 12;
  d.spreading = 5;
  d.seed = 11;
  const SeaComponents sea = SpectrumComponents(Jonswap(3.0, 8.0, 3.3), d, kG, 60.0);
  Wave linear = SeaWave(sea, 3.0, 8.0, 60.0, WaveKinematics::kLinear);
  linear.sea_cutoff = 0;  // every component, as the regular waves sum them
  double su = 0, sa = 0;  // scales of the velocity [m/s] and acceleration [m/s^2]
  for (int i = 0; i < sea.size(); ++i) {
    su += sea.amplitude[i] * sea.omega[i];
    sa += sea.amplitude[i] * sea.omega[i] * sea.omega[i];
  }
  for (double t : {2.0, 47.0}) {
    const Vec at(21.0, -12.0, 5.0);
    const WaterKinematics all = KinematicsAt(linear, at, t);
    Vec u = Vec::Zero(), a = Vec::Zero();
    for (int i = 0; i < sea.size(); ++i) {
      WaveSpec spec;
      spec.present = true;
      spec.height = 2 * sea.amplitude[i];
      spec.period = 2 * kPi / sea.omega[i];
      spec.depth = 60.0;
      spec.phase = sea.phase[i];
      spec.heading = std::atan2(sea.dir_z[i], sea.dir_x[i]);
      spec.kinematics = WaveKinematics::kLinear;
      const WaterKinematics one = KinematicsAt(MakeWave(spec, kG), at, t);
      u += one.velocity;
      a += one.acceleration;
    }
    EXPECT_LE((all.velocity - u).norm(), 1e-12 * su);
    EXPECT_LE((all.acceleration - a).norm(), 1e-12 * sa);
  }
  const Wave wheeler = SeaWave(sea, 3.0, 8.0, 60.0);
  const double step = 1e-5 * sea.ShortestLength();
  for (double y : {-30.0, -5.0, -0.5}) {
    const Vec at(4.0, y, 9.0);
    const WaterKinematics w = KinematicsAt(wheeler, at, 31.0);
    Mat Gu, Ga;
    testing::KinematicsGradientsByDifferences(wheeler, at, 31.0, step, &Gu, &Ga);
    double kmax = 0;
    for (double k : sea.k) kmax = std::max(kmax, k);
    EXPECT_LE((w.velocity_gradient - Gu).cwiseAbs().maxCoeff(), 1e-6 * su * kmax) << y;
    EXPECT_LE((w.acceleration_gradient - Ga).cwiseAbs().maxCoeff(), 1e-6 * sa * kmax) << y;
  }
}

// A component whose depth profile at a station is under the cutoff (1e-8) of its surface value
// is left out of the station's velocity and acceleration: each left out moves them by at most
// the cutoff times its part at the surface, so all together by at most 1e-8 of the scales
// sum a omega and sum a omega^2 (and their gradients by that times k_max). A JONSWAP storm (Hs
// 6 m, Tp 10 s, 200 components to 4 rad/s) in 100 m of water: near the surface nothing is left
// out (the same sums to the bit); deeper the shortest components are.
TEST(SeaComponents, ComponentsTooDeepToMatterAreLeftOut) {
  SeaDiscretization d;
  d.seed = 5;
  const SeaComponents sea = SpectrumComponents(Jonswap(6.0, 10.0, 3.3), d, kG, 100.0);
  const Wave cut = SeaWave(sea, 6.0, 10.0, 100.0);
  Wave all = cut;
  all.sea_cutoff = 0;
  double su = 0, sa = 0;  // the scales [m/s], [m/s^2]
  for (int i = 0; i < sea.size(); ++i) {
    su += sea.amplitude[i] * sea.omega[i];
    sa += sea.amplitude[i] * sea.omega[i] * sea.omega[i];
  }
  for (double t : {20.0, 75.0}) {
    for (double y : {-2.0, -20.0, -50.0, -99.0}) {
      const Vec at(30.0, y, -8.0);
      const WaterKinematics a = KinematicsAt(cut, at, t), b = KinematicsAt(all, at, t);
      EXPECT_EQ(a.eta, b.eta);  // the surface is every component's
      EXPECT_LE((a.velocity - b.velocity).norm(), 1e-8 * su) << y;
      EXPECT_LE((a.acceleration - b.acceleration).norm(), 1e-8 * sa) << y;
      EXPECT_LE((a.velocity_gradient - b.velocity_gradient).cwiseAbs().maxCoeff(),
                1e-8 * su * sea.max_k) << y;
      EXPECT_LE((a.acceleration_gradient - b.acceleration_gradient).cwiseAbs().maxCoeff(),
                1e-8 * sa * sea.max_k) << y;
      EXPECT_EQ(b.omega_max, sea.max_omega);
      if (y == -2.0) {  // nothing left out near the surface
        EXPECT_EQ(a.velocity, b.velocity);
        EXPECT_EQ(a.omega_max, sea.max_omega);
      } else {  // the short ones left out: 2 e^{k z_e} < 1e-8 for k above 19.1 / |z_e|
        EXPECT_LT(a.omega_max, 0.8 * sea.max_omega) << y;
        EXPECT_LT(a.k_max, 19.2 / (-y - 6.0)) << y;  // z_e within the crests' 6 m of y
      }
    }
  }
}

// The rates the carried kinematics use (wave_forces.cpp): d eta / dt and the acceleration's
// rate against central differences in time at a fixed point under the troughs, unstretched
// ("linear": there z_e is the point's own elevation), during the ramp (its second derivative
// enters) and after it. Step 1e-4 s: truncation (omega_max h)^2 / 6 ~ 3e-8, round-off 1e-16 /
// 1e-4; 1e-6 of the scale.
TEST(SeaComponents, RatesInTimeMatchDifferences) {
  SeaDiscretization d;
  d.components = 30;
  d.seed = 4;
  const SeaComponents sea = SpectrumComponents(Jonswap(3.0, 8.0, 3.3), d, kG, 60.0);
  const Wave wave = SeaWave(sea, 3.0, 8.0, 60.0, WaveKinematics::kLinear, 0.5);
  double se = 0, sj = 0;  // scales [m/s] and [m/s^3]
  for (int i = 0; i < sea.size(); ++i) {
    se += sea.amplitude[i] * sea.omega[i];
    sj += sea.amplitude[i] * std::pow(sea.omega[i], 3);
  }
  const double h = 1e-4;
  for (double t : {1.0, 4.0, 30.0}) {
    const Vec at(7.0, -9.0, 3.0);
    const WaterKinematics w = KinematicsAt(wave, at, t);
    const WaterKinematics p = KinematicsAt(wave, at, t + h), m = KinematicsAt(wave, at, t - h);
    EXPECT_NEAR(w.eta_rate, (p.eta - m.eta) / (2 * h), 1e-6 * se) << t;
    EXPECT_LE((w.jerk - (p.acceleration - m.acceleration) / (2 * h)).norm(), 1e-6 * sj) << t;
  }
}

}  // namespace
}  // namespace cablefilm
