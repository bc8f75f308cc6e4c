#pragma once
// The stated limits on a scene and on what a run of it may produce (README.md, "Limits").
// The loader checks every number of a scene against them; CheckModelLimits checks what needs
// the built model. `check` and `run` share both, so `check` refuses whatever `run` would.
#include <cstdint>
#include <string>
#include <vector>

#include "core/model.h"
#include "scene/scene_def.h"

namespace cablefilm {

// Numbers of a scene: ranges that keep every product of the model's arithmetic (weights,
// stiffnesses, drag, the equilibrium's force scale) finite, with room to spare.
constexpr double kMaxLength = 1e6;          // m: a section, the cable, |positions|, amplitudes,
                                            //    a table's offsets
constexpr double kMinSectionLength = 1e-6;  // m
constexpr double kMaxLinks = 1e7;           // links of the whole cable
constexpr double kMinDiameter = 1e-6, kMaxDiameter = 100;     // m
constexpr double kMinArea = 1e-12, kMaxArea = 100;            // m^2
constexpr double kMinMassPerLength = 1e-9, kMaxMassPerLength = 1e6;  // kg/m
constexpr double kMinModulus = 1, kMaxModulus = 1e13;         // Pa
constexpr double kMaxCoefficient = 1e3;     // drag and added-mass coefficients
constexpr double kMaxAxialDamping = 1e15;   // Pa s (MoorDyn's BA)
constexpr double kMaxDampingRatio = 100;    // of critical, the link's axial mode
constexpr double kMinBreakingLoad = 1e-6, kMaxBreakingLoad = 1e15;  // N, a material's MBL
constexpr double kMaxGravity = 1e3;         // m/s^2
constexpr double kMaxFluidDensity = 1e5;    // kg/m^3
constexpr double kMaxCurrent = 1e3;         // m/s, either way
constexpr int kMaxCurrentPoints = 10000;    // points of a current profile
constexpr double kMinSeabedStiffness = 1, kMaxSeabedStiffness = 1e12;  // N/m per m of line
constexpr double kMaxSeabedDamping = 1e12;  // N s/m per m of line
constexpr double kMaxFriction = 10;         // Coulomb coefficient
constexpr double kMinFrictionVelocity = 1e-9, kMaxFrictionVelocity = 1e3;  // m/s
constexpr double kMaxWaveHeight = 1e3;     // m
constexpr double kMinWavePeriod = 1e-3, kMaxWavePeriod = 1e6;  // s
constexpr double kMinWaveDepth = 1e-3;      // m (below it the dispersion relation underflows)
constexpr double kWaveDepthTolerance = 1e-6;  // waves.depth against surface_y - seabed.y,
                                              // relative to the larger
constexpr double kMaxBodyBox = 1e4;         // m: a body's drawn box, each size
constexpr double kMaxPhase = 360;           // deg, either way
constexpr double kMaxRao = 1e3;             // m of motion per m of wave amplitude
constexpr double kMaxWeightMass = 1e9;      // kg
constexpr double kMaxVolume = 1e6;          // m^3 (volumes, added volumes)
constexpr double kMaxDragArea = 1e6;        // m^2
constexpr double kMaxBodyMass = 1e12;       // kg: a body (the largest ships: 1e9)
constexpr double kMaxBodyVolume = 1e10;     // m^3: its displacement
constexpr double kMaxArea2D = 1e8;          // m^2: a waterplane
constexpr double kMaxWaterplaneInertia = 1e16;  // m^4
constexpr double kMaxBodyInertia = 1e18;    // kg m^2 (and a body's added mass and damping)
constexpr double kMinPeriod = 1e-6, kMaxPeriod = 1e9;  // s
constexpr double kMaxRampRate = 1e6;        // 1/s
constexpr double kMaxTime = 1e9;            // s: a duration, |a table's times|
// 1/s: a slower ramp never starts within the longest run, and its start (5 / nu) stays finite.
constexpr double kMinRampRate = 1 / kMaxTime;
constexpr double kMaxTension = 1e15;         // N: a film's colour range
constexpr double kMaxStartStretch = 2.0;    // an elastic link at t = 0, L / l (the integrators
                                            // call a link beyond it a blow-up)

constexpr std::size_t kMaxTitleLength = 200;  // characters of a given title (one line of film)

// What a run produces.
constexpr double kMaxOutputRows = 1e7;      // rows of timeseries.csv (about 1 GB)
constexpr double kMaxSteps = 1e9;           // time steps of a fixed-step run
constexpr double kMaxFilmFrames = 1e6;      // about 9 hours of film at 30 frames/s
constexpr double kMinFps = 1, kMaxFps = 240;
constexpr int kMinFilmSize = 16, kMaxFilmWidth = 7680, kMaxFilmHeight = 4320;  // pixels (8K UHD)

// Input files.
constexpr std::uintmax_t kMaxSceneBytes = 16u << 20;   // 16 MiB
constexpr std::uintmax_t kMaxTableBytes = 64u << 20;   // 64 MiB
constexpr long kMaxTableRows = 1000000;
constexpr std::size_t kMaxTableLineLength = 1024;      // characters

// The colour maps a film can use.
const std::vector<std::string>& ColormapNames();

// A number for a message: %.6g without the exponent's padding (1e6, 2.5e-7, 91.44).
std::string FormatNumber(double v);

// The simulated span of a run: the whole output intervals within its duration (as the run
// counts them). May be 0.
double RunSpan(double duration, double interval);

// The film of a run of `span` simulated seconds at `fps` frames per second of film and `speed`
// simulated seconds per second of film: "" if it has from 1 to kMaxFilmFrames frames after
// the first, else why not, with the speeds that would do (for a message after the key).
std::string FilmFramesProblem(double span, double fps, double speed);



// What needs the built model, as `check` and `run` see it: the ends at t = 0 within the
// cable's reach (inextensible: less than its length apart; elastic: no link stretched beyond
// kMaxStartStretch), and the explicit scheme's automatic step giving at most kMaxSteps.
// Throws Error naming the scene file and the key.
void CheckModelLimits(const SceneDef& scene, const Model& model);

}  // namespace cablefilm
