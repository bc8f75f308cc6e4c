#include "core/waves.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {
namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

double WaveNumber(double omega, double g, double h) {
  // x tanh x = y with y = omega^2 h / g. Fenton & McKee (1990): x0 = y (1 - e^{-y^{5/4}})^{-2/5},
  // within 1.7 % of the root for every y (-> sqrt(y) shallow, -> y deep); f(x) = x tanh x - y is
  // increasing and convex in x > 0, so Newton from there converges monotonically, in 2-4
  // iterations to the last bit.
  const double y = omega * omega * h / g;
  double x = y * std::pow(-std::expm1(-std::pow(y, 1.25)), -0.4);
  for (int it = 0; it < 50; ++it) {
    const double th = std::tanh(x);
    const double f = x * th - y;
    const double df = th + x * (1.0 - th * th);
    const double dx = f / df;
    x -= dx;
    if (std::abs(dx) <= 1e-15 * x) break;
  }
  return x / h;
}

WaveRamp RampAt(const WaveSpec& w, double t) {
  WaveRamp r;
  if (w.ramp_rate == 0) return r;
  if (t <= 0) return WaveRamp{0.0, 0.0};
  // Eq. (3)'s ramp, as the end motion's (end_motion.cpp): R = 1 - (1 + nu t) e^{-nu t},
  // R' = nu^2 t e^{-nu t}.
  const double nu = w.ramp_rate, e = std::exp(-nu * t);
  r.value = 1.0 - (1.0 + nu * t) * e;
  r.rate = nu * nu * t * e;
  return r;
}

double Wave::length() const { return 2.0 * kPi / k; }

double Wave::breaking_steepness() const { return std::tanh(k * spec.depth) / 7.0; }

Wave MakeWave(const WaveSpec& spec, double gravity) {
  Wave w;
  w.spec = spec;
  w.omega = 2.0 * kPi / spec.period;
  w.k = WaveNumber(w.omega, gravity, spec.depth);
  w.amplitude = 0.5 * spec.height;
  w.direction = Horizontal(spec.heading);
  w.decay = std::exp(-2.0 * w.k * spec.depth);
  w.decay_gap = -std::expm1(-2.0 * w.k * spec.depth);
  return w;
}

double SurfaceAt(const Wave& wave, const Vec& position, double t) {
  const double R = RampAt(wave.spec, t).value;
  return wave.spec.surface_y + R * wave.amplitude * std::cos(wave.k * wave.direction.dot(
                                                                 HorizontalPart(position)) -
                                                             wave.omega * t + wave.spec.phase);
}

void SurfaceProfile(const Wave& wave, double t, double x0, double x1, std::vector<double>& xs,
                    std::vector<double>& ys) {
  const double waves = std::abs(x1 - x0) / wave.length();
  const int n = static_cast<int>(std::clamp(std::ceil(24.0 * waves), 63.0, 4095.0)) + 1;
  xs.resize(n);
  ys.resize(n);
  for (int i = 0; i < n; ++i) {
    xs[i] = x0 + (x1 - x0) * i / (n - 1);
    ys[i] = SurfaceAt(wave, Vec(xs[i], 0.0, 0.0), t);
  }
}

WaterKinematics KinematicsAt(const Wave& wave, const Vec& position, double t) {
  return KinematicsAt(wave, position, t, RampAt(wave.spec, t));
}

WaterKinematics KinematicsAt(const Wave& wave, const Vec& position, double t,
                             const WaveRamp& ramp) {
  WaterKinematics out;
  const double a = wave.amplitude, w = wave.omega, k = wave.k, h = wave.spec.depth;
  const Vec& e = wave.direction;
  const double theta = k * e.dot(HorizontalPart(position)) - w * t + wave.spec.phase;
  const double co = std::cos(theta), si = std::sin(theta);
  const double R = ramp.value, dR = ramp.rate;
  out.eta = R * a * co;
  const Vec dtheta = k * e;  // d theta / d position
  out.eta_gradient = (-R * a * si) * dtheta;
  if (a == 0) return out;
  // The evaluation point z_e [m] (elevation above the still water level) and its gradient
  // dz_e / d position [1], by the spec's kinematics; then the depth profiles at it:
  //   C = cosh(k (z_e + h)) / sinh(k h),  S = sinh(k (z_e + h)) / sinh(k h)
  // written without overflow at any k h as [e^{k z_e} +- e^{-k (z_e + 2h)}] / (1 - e^{-2 k h}),
  // e^{-k (z_e + 2h)} = e^{-2 k h} / e^{k z_e} (both 0 when e^{k z_e} underflows: k h > 700).
  // dC/dz_e = k S_slope and dS/dz_e = k C_slope [1/m]: S and C themselves, but for the Taylor
  // extension above the still water level, whose slopes are those at z_e = 0.
  const double z = position[kVertical] - wave.spec.surface_y, eta = out.eta;
  double ze = 0, C = 0, S = 0, C_slope = 0, S_slope = 0;
  Vec dze = Vec::Zero();
  const auto profiles = [&](double at) {
    const double e1 = std::exp(k * at), e2 = e1 > 0 ? wave.decay / e1 : 0.0;
    C = (e1 + e2) / wave.decay_gap;
    S = (e1 - e2) / wave.decay_gap;
    C_slope = C;
    S_slope = S;
  };
  if (wave.spec.kinematics == WaveKinematics::kWheeler) {
    // z_s = h (z - eta) / (h + eta) on [-h, 0]; held at the ends beyond.
    ze = h * (z - eta) / (h + eta);
    dze = -h * (h + z) / ((h + eta) * (h + eta)) * out.eta_gradient;
    dze[kVertical] = h / (h + eta);
    if (ze > 0 || ze < -h) {
      ze = std::clamp(ze, -h, 0.0);
      dze.setZero();
    }
    profiles(ze);
  } else {
    // z itself on [-h, eta]: above the surface the surface's own point (moving with eta), below
    // the bed the bed.
    ze = z;
    dze[kVertical] = 1.0;
    if (z > eta) {
      ze = eta;
      dze = out.eta_gradient;
    } else if (z < -h) {
      ze = -h;
      dze.setZero();
    }
    if (wave.spec.kinematics == WaveKinematics::kExtrapolated && ze > 0) {
      // q(0) + z_e dq/dz(0): C(0) + z_e k S(0), S(0) + z_e k C(0).
      profiles(0.0);
      const double C0 = C, S0 = S;
      C = C0 + ze * k * S0;
      S = S0 + ze * k * C0;
      C_slope = C0;
      S_slope = S0;
    } else {
      profiles(ze);
    }
  }
  // Each component q = A(z_e) trig(theta): dq/dx = A'(z_e) dz_e/dx trig + A trig' dtheta/dx,
  // with C' = k S_slope and S' = k C_slope. The horizontal part along e, the vertical along y.
  const double aw = a * w;
  const double uh = R * aw * C * co, uv = R * aw * S * si;
  const double uh_z = R * aw * k * S_slope * co, uh_th = -R * aw * C * si;
  const double uv_z = R * aw * k * C_slope * si, uv_th = R * aw * S * co;
  // Acceleration d(R u)/dt at fixed z_e: dR/dt u + R du/dt, d theta/dt = -omega.
  const double ah = aw * C * (R * w * si + dR * co);
  const double av = aw * S * (-R * w * co + dR * si);
  const double ah_z = aw * k * S_slope * (R * w * si + dR * co);
  const double ah_th = aw * C * (R * w * co - dR * si);
  const double av_z = aw * k * C_slope * (-R * w * co + dR * si);
  const double av_th = aw * S * (R * w * si + dR * co);
  Vec up = Vec::Zero();
  up[kVertical] = 1.0;
  out.velocity = uh * e + uv * up;
  out.acceleration = ah * e + av * up;
  out.velocity_gradient = e * (uh_z * dze + uh_th * dtheta).transpose() +
                          up * (uv_z * dze + uv_th * dtheta).transpose();
  out.acceleration_gradient = e * (ah_z * dze + ah_th * dtheta).transpose() +
                              up * (av_z * dze + av_th * dtheta).transpose();
  return out;
}

}  // namespace cablefilm
