#pragma once
// Regular linear (Airy) waves travelling along a horizontal direction e (the heading) in water
// of finite depth (not in the paper): the free surface, the water particle velocity and
// acceleration, and their gradients in space (for the implicit scheme's Jacobian). Plain data
// and pure functions; nothing allocates.
//
//   eta(x, t) = R(t) a cos(theta),  theta = k e . x - omega t + phase,  a = H / 2
//   u = R a omega cosh(k (z + h)) / sinh(k h) cos(theta)       (horizontal, along e)
//   w = R a omega sinh(k (z + h)) / sinh(k h) sin(theta)       (vertical, along +y)
//   omega^2 = g k tanh(k h)                                    (the dispersion relation)
//
// z = y - surface_y is the elevation above the still water level and R(t) = 1 - (1 + nu t)
// e^{-nu t} the ramp of eq. (3) (the end motion's own), so the sea starts calm. Where in the water
// column the formulas are evaluated is the WaveSpec's `kinematics` (WaveKinematics below):
// Wheeler-stretched by default, z mapped from [-h, eta] onto [-h, 0]. Above the instantaneous
// surface every mode holds the surface's value, and below the bed (z < -h) the bed's. The
// acceleration is the local one, d(R u)/dt at fixed evaluation point (the convective terms are
// second order in H / L).
#include <memory>
#include <vector>

#include "core/vec.h"

namespace cablefilm {

struct SeaComponents;  // sea_components.h: an irregular sea's components

// Where the Airy formulas are evaluated for a point at elevation z above the still water level
// (eta the surface's elevation there, h the depth; z first held to [-h, eta]):
enum class WaveKinematics {
  kWheeler,       // at z_s = h (z - eta) / (h + eta): the column [-h, eta] mapped onto [-h, 0],
                  // so the surface moves at the linear surface velocity (Wheeler 1970)
  kLinear,        // at z itself: the formulas as written, in a crest above the still water
                  // level too (their exponential growth, unstretched)
  kExtrapolated,  // at z below the still water level; above it (in a crest) the first-order
                  // Taylor extension from z = 0, q(0) + z dq/dz(0) (DNV's linear extrapolation)
};

struct WaveSpec {
  bool present = false;
  double height = 0;      // H [m], crest to trough (0: still water with a surface)
  double period = 1;      // T [s]
  double depth = 1;       // h [m], still water level to the bed
  double surface_y = 0;   // the still water level's elevation [m] (same y as positions)
  double phase = 0;       // [rad]: theta at x = 0, t = 0 (0: a crest at x = 0)
  double heading = 0;     // the direction they travel [rad] from +x towards +z
  double ramp_rate = 0;   // nu [1/s] of R(t); 0: no ramp (R = 1 from t = 0)
  WaveKinematics kinematics = WaveKinematics::kWheeler;  // where the formulas are evaluated
  // An irregular sea: the sum of these components in place of the one wave above (whose height
  // and period are then the sea's Hs and Tp, for summaries, the breaking check and the ramp's
  // default). Null: the regular wave.
  std::shared_ptr<const SeaComponents> sea;
};

// The wave number k [1/m] of omega^2 = g k tanh(k h): Newton's method on x tanh x = omega^2 h / g
// (x = k h) from Fenton & McKee's (1990) explicit approximation, to machine precision for any
// k h (from very shallow, 1e-6, to deep, 1e6). omega [rad/s], g [m/s^2], h [m] all > 0.
double WaveNumber(double omega, double g, double h);

// R(t), dR/dt [1/s] of the ramp (eq. 3's form); R = 1 for nu = 0; R = 0 for t <= 0 otherwise.
struct WaveRamp {
  double value = 1, rate = 0, rate2 = 0;  // R, dR/dt [1/s], d2R/dt2 [1/s^2]
};
WaveRamp RampAt(const WaveSpec& w, double t);

// The wave with its derived constants.
struct Wave {
  WaveSpec spec;
  double omega = 0;       // 2 pi / T [rad/s]
  double k = 0;           // wave number [1/m]
  double amplitude = 0;   // a = H / 2 [m]
  Vec direction = Vec(1.0, 0.0, 0.0);  // e: the horizontal unit vector of the heading
  double decay = 0;       // e^{-2 k h}: the depth profiles' constants (KinematicsAt), set by
  double decay_gap = 1;   // 1 - e^{-2 k h}  MakeWave with k
  // An irregular sea's components (spec.sea), each amplitude times sea_scale (the live view's
  // Hs over the scene's; 1 in a run). Its omega and k above are then the peak period's.
  std::shared_ptr<const SeaComponents> sea;
  double sea_scale = 1;
  bool irregular() const { return sea != nullptr; }
  // How far an irregular sea's kinematics at a station are carried from their last exact
  // evaluation by Taylor's first order in time and position (ComputeSea, wave_forces.h): while
  // omega_max |t - t_0| and k_max |x - x_0| stay below it, the error is at most about half its
  // square (5e-5 at 0.01) of the shortest component's own part. 0: every evaluation exact.
  double sea_reach = 0.01;
  // An irregular sea's components whose depth profile at a station, cosh(k (z_e + h)) /
  // cosh(k h) <= 2 e^{k z_e}, is below this fraction of its value at the surface are left out
  // of the station's velocity and acceleration (not of the surface's elevation): at 1e-8, 20 m
  // down in a JONSWAP sea of Tp 10 s every component shorter than 6.6 m (omega above 3.1
  // rad/s), 100 m down those shorter than 33 m. 0: every component everywhere.
  double sea_cutoff = 1e-8;
  // The shortest wave length present [m]: the regular wave's, or the shortest component's.
  double shortest_length() const;
  // The highest crest to expect above the still water level [m]: a, or for a sea Hs (about the
  // most probable largest crest of a 3-hour storm).
  double crest() const;
  double length() const;  // L = 2 pi / k [m]
  double steepness() const { return spec.height / length(); }  // H / L
  // Miche's (1944) breaking limit: H / L at most tanh(k h) / 7 (1/7 in deep water, H <= 0.88 h
  // in shallow water). The steepest H / L and the highest H [m] at this period and depth.
  double breaking_steepness() const;
  double breaking_height() const { return breaking_steepness() * length(); }
};
Wave MakeWave(const WaveSpec& spec, double gravity);

// The water at one point and time.
struct WaterKinematics {
  double eta = 0;                        // surface elevation above the still water level [m]
  Vec eta_gradient = Vec::Zero();        // d eta / d(x, y, z) (horizontal) [1]
  Vec velocity = Vec::Zero();            // [m/s]
  Vec acceleration = Vec::Zero();        // its local rate [m/s^2]
  Mat velocity_gradient = Mat::Zero();   // d velocity / d position [1/s]
  Mat acceleration_gradient = Mat::Zero();  // d acceleration / d position [1/s^2]
  double eta_rate = 0;                   // d eta / dt [m/s]
  Vec jerk = Vec::Zero();                // the acceleration's local rate [m/s^3]
  // An irregular sea: the highest frequency [rad/s] and wave number [1/m] of the components
  // summed into the velocity and acceleration here (Wave::sea_cutoff leaves out those too deep
  // to matter); 0 when none.
  double omega_max = 0, k_max = 0;
};
WaterKinematics KinematicsAt(const Wave& wave, const Vec& position, double t);
// The same with the ramp at t given (RampAt(wave.spec, t)): one ramp for many points.
WaterKinematics KinematicsAt(const Wave& wave, const Vec& position, double t,
                             const WaveRamp& ramp);

// The surface's elevation (absolute y [m]) under the horizontal point of `position` at t.
double SurfaceAt(const Wave& wave, const Vec& position, double t);

// The surface from x0 to x1 [m] along x (at z = 0) at time t, sampled for drawing: at least 24
// points a wave length (the polyline's sag below a crest is then under 1 % of the amplitude),
// from 64 to 4096 points.
void SurfaceProfile(const Wave& wave, double t, double x0, double x1, std::vector<double>& xs,
                    std::vector<double>& ys);

}  // namespace cablefilm
