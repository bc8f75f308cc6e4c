#include "core/waves.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/sea_components.h"

namespace cablefilm {
namespace {
constexpr double kPi = 3.14159265358979323846;

// One Airy component of the waves: amplitude [m], omega [rad/s], k [1/m], phase [rad], the
// horizontal direction (ex, 0, ez) and its depth constants e^{-2 k h}, 1 - e^{-2 k h}.
struct Component {
  double a, w, k, phase, ex, ez, decay, decay_gap;
};

Component RegularComponent(const Wave& wave) {
  return {wave.amplitude, wave.omega, wave.k, wave.spec.phase, wave.direction[0],
          wave.direction[2], wave.decay, wave.decay_gap};
}

Component SeaComponent(const Wave& wave, int i) {
  const SeaComponents& s = *wave.sea;
  return {wave.sea_scale * s.amplitude[i], s.omega[i], s.k[i], s.phase[i], s.dir_x[i],
          s.dir_z[i], s.decay[i], s.decay_gap[i]};
}

// theta = k e . x - omega t + phase of a component at the horizontal point (x, z) [m].
double Phase(const Component& c, double x, double z, double t) {
  return c.k * (c.ex * x + c.ez * z) - c.w * t + c.phase;
}

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
  if (t <= 0) return WaveRamp{0.0, 0.0, 0.0};
  // Eq. (3)'s ramp, as the end motion's (end_motion.cpp): R = 1 - (1 + nu t) e^{-nu t},
  // R' = nu^2 t e^{-nu t}.
  const double nu = w.ramp_rate, e = std::exp(-nu * t);
  r.value = 1.0 - (1.0 + nu * t) * e;
  r.rate = nu * nu * t * e;
  r.rate2 = nu * nu * (1.0 - nu * t) * e;
  return r;
}

double Wave::length() const { return 2.0 * kPi / k; }

double Wave::shortest_length() const {
  return irregular() ? sea->ShortestLength() : length();
}

double Wave::crest() const { return irregular() ? 2.0 * amplitude : amplitude; }

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
  w.sea = spec.sea;
  return w;
}

double SurfaceAt(const Wave& wave, const Vec& position, double t) {
  const double R = RampAt(wave.spec, t).value;
  if (!wave.irregular())
    return wave.spec.surface_y + R * wave.amplitude * std::cos(wave.k * wave.direction.dot(
                                                                   HorizontalPart(position)) -
                                                               wave.omega * t + wave.spec.phase);
  double eta = 0;
  for (int i = 0; i < wave.sea->size(); ++i) {
    const Component c = SeaComponent(wave, i);
    eta += c.a * std::cos(Phase(c, position[0], position[2], t));
  }
  return wave.spec.surface_y + R * eta;
}

void SurfaceProfile(const Wave& wave, double t, double x0, double x1, std::vector<double>& xs,
                    std::vector<double>& ys) {
  const double waves = std::abs(x1 - x0) / wave.shortest_length();
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

namespace {

// The kinematics of the sum of n components (component(i)), cos and sin of each one's phase in
// trig[2 i], trig[2 i + 1] (filled here: the surface's elevation is summed before the
// velocities, which Wheeler's stretching evaluates under it).
template <class Components>
WaterKinematics SumKinematics(const WaveSpec& spec, int n, const Components& component,
                              const Vec& position, double t, const WaveRamp& ramp,
                              double* trig, double cutoff) {
  WaterKinematics out;
  const double R = ramp.value, dR = ramp.rate, ddR = ramp.rate2, h = spec.depth;
  const double px = position[0], pz = position[2];
  bool moving = false;
  for (int i = 0; i < n; ++i) {
    const Component c = component(i);
    const double theta = Phase(c, px, pz, t);
    const double co = std::cos(theta), si = std::sin(theta);
    trig[2 * i] = co;
    trig[2 * i + 1] = si;
    out.eta += R * c.a * co;
    out.eta_rate += c.a * (dR * co + R * c.w * si);
    const Vec dtheta = c.k * Vec(c.ex, 0.0, c.ez);  // d theta / d position
    out.eta_gradient += (-R * c.a * si) * dtheta;
    moving = moving || c.a != 0;
  }
  if (!moving) return out;
  // The evaluation point z_e [m] (elevation above the still water level) and its gradient
  // dz_e / d position [1], by the spec's kinematics, from the whole surface's eta (the same for
  // every component). Then each component's depth profiles at it:
  //   C = cosh(k (z_e + h)) / sinh(k h),  S = sinh(k (z_e + h)) / sinh(k h)
  // written without overflow at any k h as [e^{k z_e} +- e^{-k (z_e + 2h)}] / (1 - e^{-2 k h}),
  // e^{-k (z_e + 2h)} = e^{-2 k h} / e^{k z_e} (both 0 when e^{k z_e} underflows: k h > 700).
  // dC/dz_e = k S_slope and dS/dz_e = k C_slope [1/m]: S and C themselves, but for the Taylor
  // extension above the still water level, whose slopes are those at z_e = 0.
  const double z = position[kVertical] - spec.surface_y, eta = out.eta;
  double ze = 0;
  Vec dze = Vec::Zero();
  bool taylor = false;  // extrapolated above the still water level
  if (spec.kinematics == WaveKinematics::kWheeler) {
    // z_s = h (z - eta) / (h + eta) on [-h, 0]; held at the ends beyond.
    ze = h * (z - eta) / (h + eta);
    dze = -h * (h + z) / ((h + eta) * (h + eta)) * out.eta_gradient;
    dze[kVertical] = h / (h + eta);
    if (ze > 0 || ze < -h) {
      ze = std::clamp(ze, -h, 0.0);
      dze.setZero();
    }
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
    taylor = spec.kinematics == WaveKinematics::kExtrapolated && ze > 0;
  }
  // The sums over the components, gathered as scalars along the horizontal (x, z) and the
  // vertical, so that each component costs a few multiplications (not a 3x3 outer product):
  //   velocity = sum uh e + (sum uv) up,
  //   velocity_gradient = (sum uh_z e) dze^T + sum uh_th k e e^T + up ((sum uv_z) dze +
  //                       sum uv_th k e)^T,
  // and the same for the acceleration.
  struct Sums {
    double hx = 0, hz = 0, v = 0;          // sum q_h e, sum q_v
    double zx = 0, zz = 0, vz = 0;         // sum q_h,z e, sum q_v,z
    double txx = 0, txz = 0, tzz = 0;      // sum q_h,th k e e^T (symmetric, horizontal)
    double vtx = 0, vtz = 0;               // sum q_v,th k e
    void Add(double ex, double ez, double k, double h, double v_, double h_z, double v_z,
             double h_th, double v_th) {
      hx += h * ex;
      hz += h * ez;
      v += v_;
      zx += h_z * ex;
      zz += h_z * ez;
      vz += v_z;
      const double kt = k * h_th;
      txx += kt * ex * ex;
      txz += kt * ex * ez;
      tzz += kt * ez * ez;
      vtx += k * v_th * ex;
      vtz += k * v_th * ez;
    }
    void Write(const Vec& dze, Vec* value, Mat* gradient) const {
      *value = Vec(hx, v, hz);
      Mat g = Vec(zx, vz, zz) * dze.transpose();
      g(0, 0) += txx;
      g(0, 2) += txz;
      g(2, 0) += txz;
      g(2, 2) += tzz;
      g(kVertical, 0) += vtx;
      g(kVertical, 2) += vtz;
      *gradient = g;
    }
  };
  Sums u, acc;
  double jx = 0, jz = 0, jv = 0;  // the jerk's sums: sum j_h e, sum j_v
  // The components too deep here to matter: 2 e^{k z_e} < cutoff, k above k_cut [1/m].
  const double k_cut = cutoff > 0 && ze < 0 ? std::log(2 / cutoff) / -ze
                                            : std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const Component c = component(i);
    if (c.a == 0 || c.k > k_cut) continue;
    const double k = c.k, w = c.w;
    out.omega_max = std::max(out.omega_max, w);
    out.k_max = std::max(out.k_max, k);
    const auto profile = [&](double at, double* C, double* S) {
      const double e1 = std::exp(k * at), e2 = e1 > 0 ? c.decay / e1 : 0.0;
      *C = (e1 + e2) / c.decay_gap;
      *S = (e1 - e2) / c.decay_gap;
    };
    double C, S, C_slope, S_slope;
    if (taylor) {
      // q(0) + z_e dq/dz(0): C(0) + z_e k S(0), S(0) + z_e k C(0).
      double C0, S0;
      profile(0.0, &C0, &S0);
      C = C0 + ze * k * S0;
      S = S0 + ze * k * C0;
      C_slope = C0;
      S_slope = S0;
    } else {
      profile(ze, &C, &S);
      C_slope = C;
      S_slope = S;
    }
    const double co = trig[2 * i], si = trig[2 * i + 1];
    // Each component q = A(z_e) trig(theta): dq/dx = A'(z_e) dz_e/dx trig + A trig' dtheta/dx,
    // with C' = k S_slope and S' = k C_slope, dtheta/dx = k e. The horizontal part along e, the
    // vertical along y.
    const double aw = c.a * w;
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
    // Its rate d(acceleration)/dt at fixed z_e, for carrying the acceleration in time.
    const double jh = aw * C * (2 * dR * w * si - R * w * w * co + ddR * co);
    jx += jh * c.ex;
    jz += jh * c.ez;
    jv += aw * S * (-2 * dR * w * co - R * w * w * si + ddR * si);
    u.Add(c.ex, c.ez, k, uh, uv, uh_z, uv_z, uh_th, uv_th);
    acc.Add(c.ex, c.ez, k, ah, av, ah_z, av_z, ah_th, av_th);
  }
  u.Write(dze, &out.velocity, &out.velocity_gradient);
  acc.Write(dze, &out.acceleration, &out.acceleration_gradient);
  out.jerk = Vec(jx, jv, jz);
  return out;
}

}  // namespace

WaterKinematics KinematicsAt(const Wave& wave, const Vec& position, double t,
                             const WaveRamp& ramp) {
  if (!wave.irregular()) {
    double trig[2];
    const Component c = RegularComponent(wave);
    return SumKinematics(wave.spec, 1, [&](int) { return c; }, position, t, ramp, trig, 0.0);
  }
  // The cosines and sines of every component's phase: a buffer per thread, sized once.
  thread_local std::vector<double> trig;
  const int n = wave.sea->size();
  if (static_cast<int>(trig.size()) < 2 * n) trig.resize(2 * n);
  return SumKinematics(wave.spec, n, [&](int i) { return SeaComponent(wave, i); }, position, t,
                       ramp, trig.data(), wave.sea_cutoff);
}

}  // namespace cablefilm
