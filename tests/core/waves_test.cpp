// Waves (issue 10, part 3): the dispersion relation against its deep- and shallow-water limits
// and an independent bisection; the water particle kinematics against the Airy formulas written
// out here (cosh, sinh) at several depths, Wheeler's stretching at the crest and the bed, the
// field's own properties (incompressible, irrotational) and its gradients; a neutrally buoyant
// point in the wave follows the water particle orbit of linear theory; a grounded mooring line
// driven by its ship in waves runs without NaN in both models and converges as N grows.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "core/line_equilibrium.h"
#include "core/explicit_step.h"
#include "core/forces.h"
#include "core/step.h"
#include "core/wave_forces.h"
#include "core/waves.h"
#include "test_support.h"

namespace cablefilm {
namespace {

constexpr double kG = 9.80665;
constexpr double kPi = 3.14159265358979323846;

// x tanh x = y by bisection alone (no derivative, no initial guess): an independent root.
double BisectKh(double y) {
  double lo = 0, hi = std::max(1.0, y) + 1.0;
  for (int i = 0; i < 400; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mid * std::tanh(mid) < y ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(WaveDispersion, MatchesBisectionFromVeryShallowToDeep) {
  // kh from about 1e-6 to 1e5: T = 10 s at depths from 1e-9 m (shallow) to 1.6e6 m (deep).
  const double omega = 2 * kPi / 10.0;
  double worst = 0;
  int count = 0;
  for (double h = 1e-9; h < 2e6; h *= 1.7, ++count) {
    const double k = WaveNumber(omega, kG, h);
    const double x = BisectKh(omega * omega * h / kG);
    worst = std::max(worst, std::abs(k * h - x) / x);
  }
  std::printf("[ dispersion ] %d depths, kh 1e-6 to 1e5: largest relative difference from "
              "bisection %.2e\n", count, worst);
  // Both are good to a few ulps of x: bisection to its last bit, Newton stopped at 1e-15.
  EXPECT_LT(worst, 1e-13);
}

TEST(WaveDispersion, DeepAndShallowLimits) {
  for (double T : {2.0, 10.0, 25.0}) {
    const double omega = 2 * kPi / T, k_deep = omega * omega / kG;
    // Deep: k h >= 20, tanh(k h) = 1 - 2e-17, which is 1 in a double: k = omega^2 / g exactly
    // up to the iteration's last bit.
    const double h_deep = 20.0 / k_deep;
    EXPECT_NEAR(WaveNumber(omega, kG, h_deep) / k_deep, 1.0, 1e-14) << "T = " << T;
    EXPECT_NEAR(WaveNumber(omega, kG, 1e4 * h_deep) / k_deep, 1.0, 1e-14) << "T = " << T;
    // Shallow: omega^2 = g h k^2 (1 - (kh)^2 / 3 + ...), so k = omega / sqrt(g h) (1 + (kh)^2 / 6
    // + O((kh)^4)): the relative departure from the limit is (kh)^2 / 6 to within (kh)^4.
    for (double h : {1e-2, 1e-4, 1e-6}) {
      const double k_shallow = omega / std::sqrt(kG * h);
      const double k = WaveNumber(omega, kG, h), kh = k * h;
      EXPECT_NEAR(k / k_shallow - 1.0, kh * kh / 6.0, kh * kh * kh * kh + 1e-15)
          << "T = " << T << " s, h = " << h << " m, kh = " << kh;
    }
  }
}

// The Airy formulas at elevation z above the still water level, written out with cosh and sinh
// (moderate kh only: no overflow care), with R = 1.
struct Airy {
  double a, omega, k, h;
  double C(double z) const { return std::cosh(k * (z + h)) / std::sinh(k * h); }
  double S(double z) const { return std::sinh(k * (z + h)) / std::sinh(k * h); }
  Vec velocity(double z, double th) const {
    return a * omega * InPlane(C(z) * std::cos(th), S(z) * std::sin(th));
  }
  Vec acceleration(double z, double th) const {
    return a * omega * omega * InPlane(C(z) * std::sin(th), -S(z) * std::cos(th));
  }
};

WaveSpec Spec(double H, double T, double h, double phase = 0.0) {
  WaveSpec w;
  w.present = true;
  w.height = H;
  w.period = T;
  w.depth = h;
  w.surface_y = 0;
  w.phase = phase;
  w.ramp_rate = 0;  // no ramp: R = 1
  return w;
}

struct DepthCase {
  double T, h;
  const char* what;
};
const DepthCase kDepths[] = {{20.0, 5.0, "shallow"}, {10.0, 40.0, "intermediate"},
                             {6.0, 300.0, "deep"}};

// A wave 1e-4 of its length high: Wheeler's stretching moves the evaluation point by at most
// a (z + h) / (h + eta) <= a, so it departs from the formulas by a relative k a = 3e-4 at most;
// at the zero crossings (eta = 0) it does not depart at all.
TEST(WaveKinematics, AiryFormulasAtSeveralDepths) {
  for (const DepthCase& c : kDepths) {
    const double omega = 2 * kPi / c.T;
    const double k0 = WaveNumber(omega, kG, c.h), L = 2 * kPi / k0;
    const Wave wave = MakeWave(Spec(1e-4 * L, c.T, c.h, 0.3), kG);
    const Airy airy{wave.amplitude, omega, wave.k, c.h};
    double worst = 0;
    for (double zf : {-1.0, -0.7, -0.4, -0.1, -0.01}) {
      const double z = zf * c.h;
      for (double x : {0.0, 0.13 * L, 0.5 * L}) {
        for (double t : {0.0, 0.3 * c.T, 0.77 * c.T}) {
          const double th = wave.k * x - omega * t + 0.3;
          const WaterKinematics w = KinematicsAt(wave, InPlane(x, z), t);
          const double scale_u = airy.a * omega * airy.C(0), scale_a = scale_u * omega;
          worst = std::max(worst, (w.velocity - airy.velocity(z, th)).norm() / scale_u);
          worst = std::max(worst, (w.acceleration - airy.acceleration(z, th)).norm() / scale_a);
          EXPECT_NEAR(SurfaceAt(wave, InPlane(x, 0.0), t), airy.a * std::cos(th), 1e-12 * airy.a);
        }
      }
    }
    std::printf("[ airy ] %s (T %.0f s, h %.0f m, kh %.3f): largest departure %.2e of the "
                "surface velocity amplitude\n", c.what, c.T, c.h, wave.k * c.h, worst);
    EXPECT_LT(worst, 3.2e-4);
  }
}

// A steep wave (H / L = 1/10): at the zero crossing (theta = pi/2, eta = 0) Wheeler's mapping is
// the identity, so the formulas hold exactly at every depth; at the crest (theta = 0, z = eta)
// the stretched velocity is the linear surface velocity a omega coth(kh); at the bed (z = -h)
// it is a omega cos(theta) / sinh(kh) with no vertical part, whatever eta.
TEST(WaveKinematics, WheelerStretchingAtZeroCrossingCrestAndBed) {
  for (const DepthCase& c : kDepths) {
    const double omega = 2 * kPi / c.T;
    const double L = 2 * kPi / WaveNumber(omega, kG, c.h);
    const double H = std::min(0.1 * L, 0.5 * c.h);
    const Wave wave = MakeWave(Spec(H, c.T, c.h), kG);
    const Airy airy{wave.amplitude, omega, wave.k, c.h};
    const double scale = airy.a * omega * airy.C(0);
    // theta = k x - omega t = pi / 2 at t = 0.
    const double x_cross = 0.5 * kPi / wave.k;
    for (double zf : {-1.0, -0.5, -0.1, 0.0}) {
      const WaterKinematics w = KinematicsAt(wave, InPlane(x_cross, zf * c.h), 0.0);
      EXPECT_LT((w.velocity - airy.velocity(zf * c.h, 0.5 * kPi)).norm(), 1e-12 * scale);
      EXPECT_LT((w.acceleration - airy.acceleration(zf * c.h, 0.5 * kPi)).norm(),
                1e-12 * scale * omega);
    }
    const WaterKinematics crest = KinematicsAt(wave, InPlane(0.0, airy.a), 0.0);
    EXPECT_NEAR(crest.velocity.x(), airy.a * omega / std::tanh(wave.k * c.h), 1e-12 * scale);
    EXPECT_NEAR(crest.velocity.y(), 0.0, 1e-12 * scale);
    // Above the crest: held at the surface's value (the station is dry there anyway).
    EXPECT_NEAR(KinematicsAt(wave, InPlane(0.0, airy.a + 3.0), 0.0).velocity.x(), crest.velocity.x(),
                1e-12 * scale);
    for (double th : {0.0, 0.4, 2.0}) {
      const double x = th / wave.k;
      const WaterKinematics bed = KinematicsAt(wave, InPlane(x, -c.h), 0.0);
      EXPECT_NEAR(bed.velocity.x(), airy.a * omega * std::cos(th) / std::sinh(wave.k * c.h),
                  1e-12 * scale);
      EXPECT_NEAR(bed.velocity.y(), 0.0, 1e-12 * scale);
    }
  }
}

// The linear field is that of a potential in an incompressible fluid: du/dx + dw/dy = 0 and
// du/dy = dw/dx. With a small wave the gradients meet both to the order of the stretching,
// relative to k a omega C(0), the gradients' scale: its factor h / (h + eta) on d/dy departs
// from 1 by a / h, which in shallow water (a / h = k a / (k h)) exceeds k a.
TEST(WaveKinematics, IncompressibleAndIrrotational) {
  for (const DepthCase& c : kDepths) {
    const double omega = 2 * kPi / c.T;
    const double L = 2 * kPi / WaveNumber(omega, kG, c.h);
    const Wave wave = MakeWave(Spec(1e-4 * L, c.T, c.h, 1.1), kG);
    const double scale = wave.k * wave.amplitude * omega / std::tanh(wave.k * c.h);
    const double order = 1.1 * std::max(wave.k * wave.amplitude, wave.amplitude / c.h);
    for (double zf : {-0.9, -0.5, -0.05})
      for (double x : {0.1 * L, 0.6 * L}) {
        const WaterKinematics w = KinematicsAt(wave, InPlane(x, zf * c.h), 1.3);
        const Mat& G = w.velocity_gradient;
        EXPECT_LT(std::abs(G(0, 0) + G(1, 1)), order * scale) << c.what;
        EXPECT_LT(std::abs(G(0, 1) - G(1, 0)), order * scale) << c.what;
      }
  }
}

// The gradients the implicit scheme's Jacobian uses, against central differences of the
// kinematics themselves, with the stretching of a steep wave and half-way up the ramp (R' != 0).
// Step 1e-5 of the wave length: truncation (k dx)^2 ~ 4e-9, round-off 1e-16 / 6e-5 ~ 2e-12.
TEST(WaveKinematics, GradientsMatchCentralDifferences) {
  for (const DepthCase& c : kDepths) {
    WaveSpec spec = Spec(0, c.T, c.h, 0.7);
    spec.heading = 0.6;  // [rad] off the x axis, so that all nine gradient terms are live
    const double L = 2 * kPi / WaveNumber(2 * kPi / c.T, kG, c.h);
    spec.height = std::min(0.1 * L, 0.5 * c.h);
    spec.ramp_rate = 1.0 / c.T;
    const Wave wave = MakeWave(spec, kG);
    const double t = 1.5 * c.T, d = 1e-5 * L;
    double worst = 0;
    for (double zf : {-0.95, -0.6, -0.2, 0.02})
      for (double xf : {0.05, 0.3, 0.8}) {
        const Vec at(xf * L, zf * c.h, -0.4 * xf * L);
        const WaterKinematics w = KinematicsAt(wave, at, t);
        Mat Gu, Ga;
        testing::KinematicsGradientsByDifferences(wave, at, t, d, &Gu, &Ga);
        const double su = wave.k * wave.amplitude * wave.omega / std::tanh(wave.k * c.h);
        worst = std::max(worst, (w.velocity_gradient - Gu).cwiseAbs().maxCoeff() / su);
        worst = std::max(worst,
                         (w.acceleration_gradient - Ga).cwiseAbs().maxCoeff() / (su * wave.omega));
      }
    EXPECT_LT(worst, 1e-7) << c.what;
  }
}

// The acceleration is the time derivative of the velocity at a fixed point (linear theory, R
// included: its ramp's rate enters), to the stretching's order k a for a small wave.
TEST(WaveKinematics, AccelerationIsTheVelocitysRate) {
  for (const DepthCase& c : kDepths) {
    WaveSpec spec = Spec(0, c.T, c.h, 0.2);
    const double L = 2 * kPi / WaveNumber(2 * kPi / c.T, kG, c.h);
    spec.height = 1e-4 * L;
    spec.ramp_rate = 0.5 / c.T;
    const Wave wave = MakeWave(spec, kG);
    const double scale = wave.amplitude * wave.omega * wave.omega / std::tanh(wave.k * c.h);
    for (double t : {0.3 * c.T, 2.1 * c.T}) {
      const double dt = 1e-5 * c.T;
      const Vec rate = (KinematicsAt(wave, InPlane(0.2 * L, -0.3 * c.h), t + dt).velocity -
                                    KinematicsAt(wave, InPlane(0.2 * L, -0.3 * c.h), t - dt).velocity) /
                                   (2 * dt);
      EXPECT_LT((KinematicsAt(wave, InPlane(0.2 * L, -0.3 * c.h), t).acceleration - rate).norm(),
                3.2e-4 * scale) << c.what;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// A neutrally buoyant point in the wave: one station carrying a prism, tied to an anchor by a
// single slack link (30 m long, its ends 25 m apart: it never pulls), 20 m below the still water
// level in 50 m of water, H = 0.5 m, T = 8 s (kh = 3.4, ka = 0.016). Linear theory: the water
// particle at (x0, z0) moves on the orbit
//   xi = -a C(z0) sin(theta),  zeta = a S(z0) cos(theta),  theta = k x0 - omega t + phase,
// and so does the point. Measured over the last 5 periods of 100 s (the ramp, nu = 0.5 1/s, is
// complete to 1e-20) by least squares on {1, t, cos omega t, sin omega t} (the trend takes the
// Stokes drift, a^2 omega k e^{2 k z0}, 0.2 mm/s).
struct OrbitFit {
  double amp_x, phase_x, amp_y, phase_y;  // [m], [rad] of cos(omega t - phase)
};

OrbitFit RunPoint(double drag_area, bool morison_inertia, long* steps) {
  const double rho = 1025, volume = 0.01;  // [kg/m^3], [m^3]
  EnvironmentSpec env;
  env.fluid_density = rho;
  env.waves = Spec(0.5, 8.0, 50.0, 0.0);
  env.waves.ramp_rate = 0.5;
  SectionSpec link{30.0, 1, 0.0, 1e-6, rho * 1e-6, 1e6, 0.0, 0.0};  // neutral, no drag
  PrismSpec p;
  p.station = 1;
  p.mass = rho * volume;  // neutrally buoyant
  p.volume = volume;
  p.added_volume = morison_inertia ? InPlane(volume, volume) : Vec::Zero();
  p.drag_coefficient = Vec(1.0, 1.0, 1.0);
  p.drag_area = Vec(drag_area, drag_area, drag_area);
  LineModel m = MakeLineModel({link}, {p}, env, EndMotion::Fixed(InPlane(0, -45)),
                                 EndMotion::Free(InPlane(0, -20)), LinkLaw::kElastic);
  if (!morison_inertia) m.line.prism_fluid_mass.setZero();  // drag alone carries the point
  State s;
  s.x = Points(kDim, 2);
  s.x << 0, 0, -45, -20, 0, 0;  // rows x, y, z
  s.v = Points::Zero(kDim, 2);
  auto integ = testing::MakeStepper(Scheme::kImplicit, m, 0.5, 1e-9);
  integ->Initialize(m, s);
  const double dt = 0.02, omega = m.env.wave.omega;
  Eigen::MatrixXd A(0, 4);
  std::vector<double> xs, ys, ts;
  for (int i = 1; i <= 5000; ++i) {
    integ->Step(m, s, dt);
    if (s.t > 60.0 - 1e-9) {
      ts.push_back(s.t);
      xs.push_back(s.x(0, 1));
      ys.push_back(s.x(1, 1));
    }
  }
  *steps = integ->stats().steps;
  const int n = static_cast<int>(ts.size());
  A.resize(n, 4);
  Eigen::VectorXd bx(n), by(n);
  for (int i = 0; i < n; ++i) {
    A.row(i) << 1.0, ts[i] - 80.0, std::cos(omega * ts[i]), std::sin(omega * ts[i]);
    bx[i] = xs[i];
    by[i] = ys[i];
  }
  const Eigen::Vector4d cx = A.colPivHouseholderQr().solve(bx);
  const Eigen::Vector4d cy = A.colPivHouseholderQr().solve(by);
  return {std::hypot(cx[2], cx[3]), std::atan2(cx[3], cx[2]), std::hypot(cy[2], cy[3]),
          std::atan2(cy[3], cy[2])};
}

double AngleDifference(double a, double b) { return std::remainder(a - b, 2 * kPi); }

void ExpectFollowsOrbit(const OrbitFit& f, double amp_tol, double phase_tol, const char* what) {
  const double h = 50.0, z0 = -20.0, omega = 2 * kPi / 8.0, a = 0.25;
  const double k = WaveNumber(omega, kG, h);
  const double C = std::cosh(k * (z0 + h)) / std::sinh(k * h);
  const double S = std::sinh(k * (z0 + h)) / std::sinh(k * h);
  // At x0 = 0, phase 0: xi = -a C sin(-omega t) = a C cos(omega t - pi/2), zeta = a S cos(omega t).
  std::printf("[ orbit ] %s: horizontal %.5f m (linear theory %.5f), phase %.3f deg (%.3f); "
              "vertical %.5f m (%.5f), phase %.3f deg (%.3f)\n",
              what, f.amp_x, a * C, f.phase_x * 180 / kPi, 90.0, f.amp_y, a * S,
              f.phase_y * 180 / kPi, 0.0);
  EXPECT_NEAR(f.amp_x / (a * C), 1.0, amp_tol) << what;
  EXPECT_NEAR(f.amp_y / (a * S), 1.0, amp_tol) << what;
  EXPECT_NEAR(AngleDifference(f.phase_x, 0.5 * kPi), 0.0, phase_tol) << what;
  EXPECT_NEAR(AngleDifference(f.phase_y, 0.0), 0.0, phase_tol) << what;
}

// With Morison's inertia (Froude-Krylov plus added mass) a neutrally buoyant body's equation is
// (m + rho V_a) x'' = rho (V + V_a) A(x) + drag: the water's local acceleration, so it moves
// with the water whatever its drag. What separates it from the linear orbit is second order:
// linear theory's local acceleration dU/dt leaves out the convective U . grad U, a relative
// k a C(z0) = 0.45 % of it, which nothing corrects without drag (measured 0.30 %); with drag
// the relative velocity is pulled back to 0 (measured 0.05 %). Phases within 0.1 degree.
TEST(WaveOrbit, NeutrallyBuoyantPointFollowsTheWaterParticle) {
  long steps = 0;
  ExpectFollowsOrbit(RunPoint(0.0, true, &steps), 4.5e-3, 2e-3, "Morison inertia, no drag");
  ExpectFollowsOrbit(RunPoint(50.0, true, &steps), 2e-3, 2e-3, "Morison inertia and drag");
}

// Drag-dominated: without the fluid inertia a neutrally buoyant body of mass m is carried by its
// drag alone, m x'' = f |U - x'| (U - x'). With f = rho/2 C S large it lags the water by a
// relative velocity d with f d^2 ~ m omega U, d / U ~ sqrt(m omega / (f U)) = 1.2 % here (S =
// 2000 m^2, m = 10 kg, U = 0.06 m/s): the orbit within 2 % and 1.5 degrees.
TEST(WaveOrbit, DragDominatedPointFollowsTheWaterParticle) {
  long steps = 0;
  ExpectFollowsOrbit(RunPoint(2000.0, false, &steps), 2e-2, 2.6e-2, "drag alone");
}

// ---------------------------------------------------------------------------------------------
// The whole run: the chain mooring line of the seabed tests (500 m of 76 mm chain, fairlead
// 450 m away and 100 m above the bed, 5 m below the still water level) in waves of H = 4 m,
// T = 10 s, its fairlead moved by the ship (3 m surge, 1 m heave, 12 s), 60 s.
struct WaveRun {
  std::vector<double> fairlead;  // tension of the last link at each second [N]
  double peak = 0;
  long steps = 0;
  bool finite = true;
};

WaveRun RunMooringInWaves(int N, bool waves, bool inextensible = false, double fairlead_y = 0.0,
                          Scheme kind = Scheme::kImplicit, double duration = 60,
                          double tolerance = 1e-6 * 500) {
  const double rho = 1025, mu = 115, area = 0.01465, EA = 5.4e8, bed_y = -100;
  EnvironmentSpec env;
  env.fluid_density = rho;
  env.seabed.present = true;
  env.seabed.y = bed_y;
  env.current_profile.y = {-100, 0};
  env.current_profile.speed = {0.1, 0.6};
  if (waves) {
    env.waves = Spec(4.0, 10.0, 105.0, 0.0);
    env.waves.surface_y = 5.0;
    env.waves.ramp_rate = 0.4;
  }
  SectionSpec s{500.0, N, 0.137, area, mu, EA / area, 2.4, 1.0};
  const EndMotion ship =
      EndMotion::Trochoid(InPlane(450, fairlead_y), InPlane(3.0, 0.0), InPlane(0.0, 1.0), 2 * kPi / 12.0, 0.3);
  const LineModel m =
      MakeLineModel({s}, {}, env, EndMotion::Fixed(InPlane(0.0, bed_y)), ship,
                      inextensible ? LinkLaw::kInextensible : LinkLaw::kElastic);
  State st = SolveLineEquilibrium(m);
  std::unique_ptr<testing::Stepper> integ =
      kind == Scheme::kExplicit
          ? std::make_unique<testing::Stepper>(Scheme::kExplicit, 0.5, 0, 0.8)  // "auto": 0.8 of the limit
          : testing::MakeStepper(inextensible ? Scheme::kInextensible : kind, m, 0.5,
                           tolerance);
  integ->Initialize(m, st);
  WaveRun r;
  for (int i = 0; i < duration; ++i) {
    integ->Step(m, st, 1.0);
    const double T = integ->tensions()[m.line.links - 1];
    r.finite = r.finite && std::isfinite(T) && st.x.allFinite() && st.v.allFinite();
    r.fairlead.push_back(T);
    r.peak = std::max(r.peak, T);
  }
  r.steps = integ->stats().steps;
  return r;
}

double RmsDifference(const WaveRun& a, const WaveRun& b) {
  double s = 0;
  for (size_t i = 0; i < a.fairlead.size(); ++i)
    s += (a.fairlead[i] - b.fairlead[i]) * (a.fairlead[i] - b.fairlead[i]);
  return std::sqrt(s / a.fairlead.size());
}

// No NaN; the fairlead tension's time series converges as N doubles: the RMS differences
// between successive N fall by at least 0.6 each time (first order, 1/2, is what the touchdown
// moving across the stations allows: a station lands or lifts off at once; measured 0.44 and
// 0.55), to under 2 % of the peak between 100 and 200 links (1.5 %); and the implicit scheme takes
// no more than twice the steps of the same line in calm water.
TEST(WaveMooring, GroundedLineDrivenByShipInWavesConvergesWithN) {
  const WaveRun r25 = RunMooringInWaves(25, true), r50 = RunMooringInWaves(50, true),
                r100 = RunMooringInWaves(100, true), r200 = RunMooringInWaves(200, true),
                calm = RunMooringInWaves(100, false);
  EXPECT_TRUE(r25.finite && r50.finite && r100.finite && r200.finite);
  const double d1 = RmsDifference(r25, r50), d2 = RmsDifference(r50, r100),
               d3 = RmsDifference(r100, r200);
  const double effect = RmsDifference(r100, calm);
  std::printf("[ mooring ] peak fairlead tension N = 25, 50, 100, 200: %.1f, %.1f, %.1f, %.1f kN "
              "(no waves, N = 100: %.1f kN); RMS differences 25-50 %.3f kN, 50-100 %.3f kN, "
              "100-200 %.3f kN; the waves' own effect %.3f kN; implicit steps %ld, %ld, %ld, %ld "
              "(no waves %ld)\n",
              r25.peak / 1e3, r50.peak / 1e3, r100.peak / 1e3, r200.peak / 1e3, calm.peak / 1e3,
              d1 / 1e3, d2 / 1e3, d3 / 1e3, effect / 1e3, r25.steps, r50.steps, r100.steps,
              r200.steps, calm.steps);
  EXPECT_LT(d2, 0.6 * d1);
  EXPECT_LT(d3, 0.6 * d2);
  EXPECT_LT(d3, 0.02 * r200.peak);
  EXPECT_LT(r100.steps, 2 * calm.steps);
}

// The inextensible model in the same sea: runs through (no NaN) and its fairlead tension stays
// close to the elastic line's (the chain stretches by 0.03 %: the two models differ by the
// stretch's effect on the geometry, a few per cent of the dynamic tension at most).
TEST(WaveMooring, InextensibleModelRunsInWaves) {
  const WaveRun e = RunMooringInWaves(50, true), i = RunMooringInWaves(50, true, true);
  EXPECT_TRUE(i.finite);
  std::printf("[ mooring ] inextensible, N = 50: peak fairlead tension %.1f kN (elastic %.1f "
              "kN), RMS difference %.3f kN\n", i.peak / 1e3, e.peak / 1e3,
              RmsDifference(e, i) / 1e3);
  EXPECT_NEAR(i.peak / e.peak, 1.0, 0.05);
}

// The line pierces the surface: its fairlead 9 m above the still water level (5 m), heaving
// 1 m, in waves of 4 m, so that the stations near it go in and out of the water (each over its
// band, 10 m of line at N = 50). The implicit scheme (its Jacobian has the wet fractions'
// gradients) runs through at its automatic step, with no more than twice the steps of the same
// line in calm water, and agrees with the explicit scheme (an independent scheme, at 0.8 of its
// stability limit) as well as it does in calm water: on this grounded line the two schemes
// differ by 3.6 kN RMS of the fairlead tension over 30 s without waves (1.5 % of the peak; 2.4
// kN with the implicit tolerance at 1e-4 of its default), and the waves must not add to that
// beyond 20 % (measured 3.8 kN; 1.5 kN at 1e-4 of the tolerance).
TEST(WaveMooring, LinePiercingTheSurfaceRunsThroughInBothSchemes) {
  const WaveRun imp = RunMooringInWaves(50, true, false, 14.0, Scheme::kImplicit, 30);
  const WaveRun exp = RunMooringInWaves(50, true, false, 14.0, Scheme::kExplicit, 30);
  const WaveRun imp_calm = RunMooringInWaves(50, false, false, 14.0, Scheme::kImplicit, 30);
  const WaveRun exp_calm = RunMooringInWaves(50, false, false, 14.0, Scheme::kExplicit, 30);
  EXPECT_TRUE(imp.finite && exp.finite);
  const double d = RmsDifference(imp, exp), d_calm = RmsDifference(imp_calm, exp_calm);
  std::printf("[ piercing ] fairlead 9 m above the surface: peak %.1f kN implicit (%ld steps), "
              "%.1f kN explicit (%ld steps), RMS difference %.3f kN; calm water: %ld implicit "
              "steps, RMS difference %.3f kN\n",
              imp.peak / 1e3, imp.steps, exp.peak / 1e3, exp.steps, d / 1e3, imp_calm.steps,
              d_calm / 1e3);
  EXPECT_LT(d, 1.2 * d_calm);
  EXPECT_LT(d, 0.02 * exp.peak);
  EXPECT_LT(imp.steps, 2 * imp_calm.steps);
}

// The static equilibrium counts the surface: 30 m of wire hanging from a point 5 m above the
// still water level, its lower end free. Each link carries the weight of the line below it,
// in air above the surface and submerged below it, so the top link (its midpoint 0.25 m below
// the top) carries w_air 4.75 m + w_sub 25 m. The lumped line has station 10 at the surface,
// half wet over its 0.5 m share of line (the wet fraction is symmetric about the surface): the
// midpoint rule of that integral, exact for a step in the weight. The stretch of the top 5 m
// (T / EA, 9.5e-5 m) sinks station 10 below the surface by that much, wetting 1.5 (9.5e-5 / 0.5)
// more of its buoyancy (6.3 N): 1.8e-3 N, 6.9e-7 of the tension, within the bound of 1e-6.
// Ignoring the surface (as the equilibrium did before) gives w_sub 29.75 m, 2.3 % less. From that equilibrium, under a still
// surface (H = 0), the line stays at rest: no start transient.
TEST(WaveEquilibrium, LinePiercingTheSurfaceHangsWithItsDryPartInAir) {
  const double mu = 10.0, area = 1.2566e-3, E = 1e11, rho = 1025;
  EnvironmentSpec env;
  env.fluid_density = rho;
  env.waves = Spec(2.0, 8.0, 100.0);
  env.waves.ramp_rate = 0.2;
  SectionSpec s{30.0, 60, 0.04, area, mu, E, 1.2, 1.0};
  auto build = [&](const EnvironmentSpec& e) {
    return MakeLineModel({s}, {}, e, EndMotion::Fixed(InPlane(0, 5)), EndMotion::Free(InPlane(0, -25)),
                           LinkLaw::kElastic);
  };
  const LineModel m = build(env);
  const State st = SolveLineEquilibrium(m);
  ForceWorkspace ws(m.line.links);
  ComputeGeometry(m, SceneWater(m), 0.0, st.x, ws.geometry);
  ComputeHookeTensions(m, ws.geometry, ws.tension);
  const double w_air = mu * kG, w_sub = (mu - rho * area) * kG;
  const double expected = w_air * 4.75 + w_sub * 25.0;
  std::printf("[ surface statics ] top link %.6f N, expected %.6f N (relative %.2e; ignoring "
              "the surface: %.6f N); station 10 at y = %.3e m\n",
              ws.tension[0], expected, ws.tension[0] / expected - 1, w_sub * 29.75, st.x(1, 10));
  EXPECT_NEAR(ws.tension[0], expected, 1e-6 * expected);

  EnvironmentSpec still = env;
  still.waves.height = 0;
  const LineModel calm = build(still);
  State run = SolveLineEquilibrium(calm);
  const Points start = run.x;
  auto integ = testing::MakeStepper(Scheme::kImplicit, calm, 0.5, 1e-6 * 30);
  integ->Initialize(calm, run);
  double fastest = 0;
  for (int i = 0; i < 200; ++i) {  // 20 s
    integ->Step(calm, run, 0.1);
    fastest = std::max(fastest, run.v.cwiseAbs().maxCoeff());
  }
  const double moved = (run.x - start).cwiseAbs().maxCoeff();
  std::printf("[ surface statics ] still surface, 20 s from the equilibrium: fastest station "
              "%.2e m/s, moved %.2e m\n", fastest, moved);
  EXPECT_LT(fastest, 1e-6);  // at rest (the buoyancy lost at t = 0 moved it by cm/s)
  EXPECT_LT(moved, 1e-6);
}

// ---------------------------------------------------------------------------------------------
// The surface: a station in the air has its weight, no buoyancy, no drag and no added mass; one
// deep in the water all of them; still water (H = 0) far above the line gives the forces and
// inertia of the model without waves (to round-off: a different sum).
TEST(WaveForces, StationsAboveTheSurfaceAreDryAndStillWaterChangesNothing) {
  EnvironmentSpec env;
  env.fluid_density = 1025;
  env.current = 0.4;
  SectionSpec s{10.0, 10, 0.05, 1e-3, 8.0, 1e9, 1.2, 1.0};
  auto build = [&](const EnvironmentSpec& e) {
    return MakeLineModel({s}, {}, e, EndMotion::Fixed(InPlane(0, -12)), EndMotion::Fixed(InPlane(6, 0)),
                           LinkLaw::kElastic);
  };
  const LineModel plain = build(env);
  EnvironmentSpec still = env;
  still.waves = Spec(0.0, 5.0, 100.0);
  still.waves.surface_y = 50.0;
  const LineModel calm = build(still);
  Points x(kDim, 11), v(kDim, 11);
  for (int j = 0; j <= 10; ++j) {
    x.col(j) = InPlane(0.6 * j, -12.0 + 1.2 * j);
    v.col(j) = InPlane(0.1 * std::sin(j), 0.2 * std::cos(j));
  }
  ForceWorkspace a(10), b(10);
  ComputeGeometry(x, a.geometry);
  ComputeGeometry(calm, SceneWater(calm), 0.0, x, b.geometry);
  ComputeTensions(plain, a.geometry, v, a.tension);
  ComputeTensions(calm, b.geometry, v, b.tension);
  ComputeStationForces(plain, SceneWater(plain), a.geometry, a.tension, v, a.force);
  ComputeStationForces(calm, SceneWater(calm), b.geometry, b.tension, v, b.force);
  EXPECT_LT((a.force - b.force).cwiseAbs().maxCoeff(), 1e-12 * a.force.cwiseAbs().maxCoeff());
  for (int j = 0; j <= 10; ++j)
    EXPECT_LT((StationInertia(plain, a.geometry, j) - StationInertia(calm, b.geometry, j))
                  .cwiseAbs().maxCoeff(), 1e-12);
  // The surface at y = -6 m: stations 0-4 (y <= -7.2) wet, 6-10 (y >= -4.8) dry, station 5 at
  // the surface itself half wet (its band is its 1 m share of the line).
  EnvironmentSpec cut = env;
  cut.waves = Spec(0.0, 5.0, 100.0);
  cut.waves.surface_y = -6.0;
  const LineModel half = build(cut);
  ComputeGeometry(half, SceneWater(half), 0.0, x, b.geometry);
  ComputeTensions(half, b.geometry, v, b.tension);
  ComputeStationForces(half, SceneWater(half), b.geometry, b.tension, v, b.force);
  const double buoyancy = 1025 * kG * 1e-3 * 1.0;  // rho g sigma l_j of an inner station [N]
  for (int j = 1; j <= 9; ++j) {
    const double wet = b.geometry.sea.wet[j];
    EXPECT_EQ(wet, j < 5 ? 1.0 : j > 5 ? 0.0 : 0.5) << "station " << j;
    // Same tensions, so the difference is the external force alone. Stations 4 and 6 share a
    // link with the half-wet station 5 (its drag and added mass are a quarter dry or wet).
    const Vec diff = b.force.col(j) - a.force.col(j);
    if (j < 4) {
      EXPECT_LT(diff.norm(), 1e-9);
    }
    if (j > 6) {
      // In the air: the buoyancy lost, and no drag (the plain model's drag on it removed).
      Points drag_only = Points::Zero(kDim, 11);
      AddExternalForces(plain, SceneWater(plain), a.geometry, v, drag_only);
      drag_only(1, j) += plain.line.net_weight[j];  // leave the drag
      EXPECT_NEAR(diff.y(), -buoyancy - drag_only(1, j), 1e-9) << "station " << j;
      EXPECT_NEAR(diff.x(), -drag_only(0, j), 1e-9) << "station " << j;
      const Mat M = StationInertia(half, b.geometry, j);
      EXPECT_LT((M - plain.line.cable_mass[j] * Mat::Identity()).cwiseAbs().maxCoeff(),
                1e-12) << "station " << j;
    }
  }
}

// Still water over a whole line is no surface at all (SeaState::still_under): a line driven in
// surge and heave 2 m below a still surface steps exactly as the same line without one, step
// for step (the same numbers: the forces go through the same code); and with its top end
// heaving through the surface the sea's own forces act (its stations' shares of line are 1 m:
// the band reaches 0.5 m below the surface): it differs.
TEST(WaveForces, StillSurfaceOverTheWholeLineIsNoSurface) {
  EnvironmentSpec env;
  env.fluid_density = 1025;
  SectionSpec s{20.0, 20, 0.05, 2e-3, 20.0, 1e9, 1.2, 1.0};
  auto run = [&](const EnvironmentSpec& e, double top, double seconds, long* steps) {
    const LineModel m = MakeLineModel(
        {s}, {}, e, EndMotion::Fixed(InPlane(0, -15)),
        EndMotion::Trochoid(InPlane(12, top), InPlane(1.0, 0.5), InPlane(0, 0), 2 * kPi / 8, 0.5),
        LinkLaw::kElastic);
    State st = SolveLineEquilibrium(m);
    auto integ = testing::MakeStepper(Scheme::kImplicit, m, 0.5, 1e-6 * 20);
    integ->Initialize(m, st);
    for (int i = 0; i < static_cast<int>(seconds / 0.1 + 0.5); ++i) integ->Step(m, st, 0.1);
    *steps = integ->stats().steps;
    return st;
  };
  EnvironmentSpec still = env;
  still.waves = Spec(0.0, 10.0, 100.0);  // height 0
  long plain_steps = 0, still_steps = 0;
  // Top end 2.5 m below the surface, heaving 0.5 m: at least 2 m under, outside the band.
  const State a = run(env, -2.5, 20.0, &plain_steps);
  const State b = run(still, -2.5, 20.0, &still_steps);
  EXPECT_EQ(still_steps, plain_steps);
  EXPECT_EQ((a.x - b.x).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((a.v - b.v).cwiseAbs().maxCoeff(), 0.0);
  // Top end 0.5 m above the surface, heaving 0.5 m: the stations below it in and out of the
  // water (the line rises at about 40 degrees: the next station 0.6 m lower). In air a 1 m
  // station weighs its 20 kg with no buoyancy (2 kg lost): the line sags further, by
  // millimetres.
  const State c = run(env, 0.5, 20.0, &plain_steps);
  const State d = run(still, 0.5, 20.0, &still_steps);
  std::printf("[ still surface ] top end through the surface: stations moved apart by %.3e m\n",
              (c.x - d.x).cwiseAbs().maxCoeff());
  EXPECT_GT((c.x - d.x).cwiseAbs().maxCoeff(), 1e-3);
}

}  // namespace
}  // namespace cablefilm
