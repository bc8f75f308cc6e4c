#include "app/scene_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/sea_components.h"
#include "scene/build_model.h"
#include "scene/text_escape.h"

namespace cablefilm {
namespace {

// A horizontal direction as a user gives it: "+x", or "<angle> deg from +x towards +z".
std::string HeadingText(const Vec& direction) {
  const double deg = std::atan2(direction.z(), direction.x()) * 180.0 / M_PI;
  if (deg == 0) return "+x";
  char text[64];
  std::snprintf(text, sizeof text, "%.4g deg from +x towards +z", deg);
  return text;
}

const char* KindName(PointKind kind) {
  switch (kind) {
    case PointKind::kFixed:
      return "fixed";
    case PointKind::kMoved:
      return "moved";
    case PointKind::kFree:
      return "free";
    case PointKind::kBody:
      return "on a free body";
  }
  return "";
}

// A line alone: its stations, sections, length, mass and net weight.
void PrintLine(const SceneDef& scene, const LineModel& m) {
  const LineDef& def = scene.lines.front();
  const double cable_mass = m.line.link_mass.sum();
  double weights = 0;
  for (const WeightDef& w : def.weights) weights += w.mass;
  std::printf("  %s cable: %d stations, %d links in %zu section(s), unstretched length %.6g m\n",
              m.line.law == LinkLaw::kElastic ? "elastic" : "inextensible", m.stations(),
              m.line.links, def.sections.size(), m.line.total_length());
  std::printf("  mass %.6g kg (cable %.6g kg, %zu weight(s) %.6g kg), net weight in fluid %.6g N\n",
              cable_mass + weights, cable_mass, def.weights.size(), weights,
              m.line.net_weight.sum());
}

// Several lines: each line, point and body.
void PrintLines(const Model& model) {
  std::printf("  a system of %zu line(s) and %zu point(s)\n", model.lines.size(),
              model.points.size());
  for (size_t i = 0; i < model.lines.size(); ++i) {
    const LineModel& m = model.lines[i];
    std::printf("  line %s: %s%d links, unstretched length %.6g m, mass %.6g kg, from point %s "
                "to point %s\n",
                QuoteText(model.line_names[i]).c_str(),
                m.line.law == LinkLaw::kInextensible ? "inextensible, " : "", m.line.links,
                m.line.total_length(), m.line.link_mass.sum(),
                QuoteText(model.points[model.line_points[i][0]].name).c_str(),
                QuoteText(model.points[model.line_points[i][1]].name).c_str());
  }
  for (const Point& p : model.points)
    std::printf("  point %s: %s, %zu line end(s)%s\n", QuoteText(p.name).c_str(),
                KindName(p.kind), p.ends.size(),
                p.shared >= 0 ? ", where lines meet (solved with them)" : "");
  for (const BodySpec& b : model.bodies) {
    const bool turns = b.kind == BodyKind::kDriven && b.turn.moves();
    const char* kind = b.kind == BodyKind::kFree     ? "free"
                       : turns                       ? "driven, turning"
                       : b.kind == BodyKind::kDriven ? "driven"
                                                     : "held";
    std::printf("  body %s: %s, reference point at (%.6g, %.6g, %.6g) m\n",
                QuoteText(b.name).c_str(), kind, b.motion.rest()[0], b.motion.rest()[1],
                b.motion.rest()[2]);
  }
}

// The materials beyond the paper's model: the tangential (axial) drag and added mass, one line
// per material that has them (nothing for the others); in waves, a material that leaves out the
// Froude-Krylov force along the line.
void PrintTangentialMaterials(const SceneDef& scene) {
  for (const MaterialDef& m : scene.materials) {
    const bool fk_off = scene.waves.present && !m.axial_froude_krylov;
    if (m.tangential_drag_coefficient == 0 && m.tangential_added_mass_coefficient == 0 && !fk_off)
      continue;
    std::printf("  material %s: along the line tangential_drag_coefficient %.4g (on pi d l), "
                "tangential_added_mass_coefficient %.4g%s\n",
                QuoteText(m.name).c_str(), m.tangential_drag_coefficient,
                m.tangential_added_mass_coefficient,
                fk_off ? ", no Froude-Krylov force along it in waves (axial_froude_krylov = false)"
                       : "");
  }
}

void PrintCurrent(const Environment& env) {
  if (const CurrentHistory* h = env.current_history.get()) {
    const auto [lo, hi] = std::minmax_element(h->heading.begin(), h->heading.end());
    const auto [f_lo, f_hi] = std::minmax_element(h->factor.begin(), h->factor.end());
    const bool profile = !env.current_profile.empty();
    std::printf("  current over time: %zu row(s) from t = %.6g to %.6g s, %s%.4g to %.4g%s, "
                "along %.4g to %.4g degrees from +x towards +z, linear between rows, held "
                "before and after\n",
                h->t.size(), h->t.front(), h->t.back(), profile ? "the profile below times " : "",
                profile ? *f_lo : *f_lo * env.current, profile ? *f_hi : *f_hi * env.current,
                profile ? "" : " m/s", *lo * 180.0 / M_PI, *hi * 180.0 / M_PI);
    if (!profile) return;
  }
  if (!env.current_profile.empty()) {
    const CurrentProfile& p = env.current_profile;
    const auto [lo, hi] = std::minmax_element(p.speed.begin(), p.speed.end());
    // Under a table over time the table's headings turn it (printed above).
    std::printf("  current profile: %zu point(s) from y = %.6g to %.6g m, %.4g to %.4g m/s along "
                "%s, linear between them, constant beyond\n",
                p.y.size(), p.y.front(), p.y.back(), env.current + *lo, env.current + *hi,
                env.current_history ? "the table's heading"
                                    : HeadingText(env.current_direction).c_str());
  } else if (env.current != 0) {
    std::printf("  current: %.4g m/s along %s\n", env.current,
                HeadingText(env.current_direction).c_str());
  }
}

void PrintSeabed(const Model& model) {
  const Environment& env = model.lines.front().env;
  if (!env.seabed.present) return;
  // What a station resting on it sinks: its net weight over its share of the bed's stiffness.
  double sink = 0, damping_lo = 1e300, damping_hi = 0;
  int deepest = 0, deepest_line = 0;
  for (std::size_t i = 0; i < model.lines.size(); ++i) {
    const LineModel& m = model.lines[i];
    for (int j = m.first_free(); j <= m.last_free(); ++j) {
      const double share = m.line.seabed_stiffness[j] / env.seabed.stiffness;  // [m of line]
      damping_lo = std::min(damping_lo, m.line.seabed_damping[j] / share);
      damping_hi = std::max(damping_hi, m.line.seabed_damping[j] / share);
      if (m.line.net_weight[j] / m.line.seabed_stiffness[j] > sink) {
        sink = m.line.net_weight[j] / m.line.seabed_stiffness[j];
        deepest = j;
        deepest_line = static_cast<int>(i);
      }
    }
  }
  std::printf("  seabed at y = %.6g m: stiffness %.4g N/m per m of line, damping %.4g",
              env.seabed.y, env.seabed.stiffness, damping_lo);
  if (damping_hi > damping_lo * (1 + 1e-9)) std::printf(" to %.4g", damping_hi);
  std::printf(" N s/m per m (%s), friction %.3g", env.seabed.damping < 0 ? "critical" : "given",
              env.seabed.friction);
  if (env.seabed.friction > 0 && env.seabed.friction_model == FrictionModel::kSmoothed)
    std::printf(" (smoothed over %.3g m/s)", env.seabed.friction_velocity);
  else if (env.seabed.friction > 0)
    std::printf(" (stick-slip, shear stiffness %.4g N/m per m)", env.seabed.shear_stiffness());
  if (model.lines.size() == 1)
    std::printf("; a line resting on it sinks at most %.3g mm (station %d)\n", 1e3 * sink, deepest);
  else
    std::printf("; a line resting on it sinks at most %.3g mm (line %s, station %d)\n", 1e3 * sink,
                QuoteText(model.line_names[deepest_line]).c_str(), deepest);
}

const char* KinematicsText(WaveKinematics k) {
  switch (k) {
    case WaveKinematics::kLinear: return "\"linear\" (unstretched)";
    case WaveKinematics::kExtrapolated: return "\"extrapolated\" (linearly above the still water)";
    case WaveKinematics::kWheeler: break;
  }
  return "\"wheeler\" (stretched to the surface)";
}

void PrintWaves(const SceneDef& scene, const LineModel& m) {
  if (m.has_waves() && m.env.wave.spec.height == 0) {
    std::printf("  still water with its surface at y = %.6g m (waves.height = 0): no buoyancy, "
                "drag or added mass above it\n",
                m.env.wave.spec.surface_y);
    return;
  }
  if (!m.has_waves()) return;
  const Wave& w = m.env.wave;
  const double kh = w.k * w.spec.depth;
  if (w.irregular()) {
    const SeaComponents& sea = *w.sea;
    const WavesDef& d = scene.waves;
    const char* kinds[] = {"regular", "JONSWAP", "Pierson-Moskowitz", "table", "recorded"};
    std::printf("  irregular sea (%s, linear Airy components, mean direction %s): Hs %.4g m "
                "(components' 4 sqrt(m0) %.4g m), Tp %.4g s, depth %.6g m, still water level "
                "y = %.6g m; %d components from %.4g to %.4g rad/s",
                kinds[static_cast<int>(d.sea)], HeadingText(w.direction).c_str(),
                w.spec.height, sea.SignificantHeight(), w.spec.period, w.spec.depth,
                w.spec.surface_y, sea.size(), sea.omega.empty() ? 0.0 : *std::min_element(
                    sea.omega.begin(), sea.omega.end()),
                sea.omega.empty() ? 0.0 : *std::max_element(sea.omega.begin(), sea.omega.end()));
    if (d.sea == SeaKind::kJonswap) std::printf(", gamma %.4g", d.gamma);
    if (d.sea == SeaKind::kRecord)
      std::printf(", the record's, repeating every %.6g s", sea.repeat_period);
    else
      std::printf(", seed %llu, bins %.4g rad/s wide (drawn frequencies: no repeat)%s",
                  static_cast<unsigned long long>(d.seed), sea.frequency_step,
                  d.spreading > 0 ? "" : ", long-crested");
    if (d.spreading > 0) std::printf(", short-crested (cos-2s, s = %.4g)", d.spreading);
    std::printf("; shortest wave %.4g m, ramp rate %.4g 1/s, kinematics %s\n",
                sea.ShortestLength(), w.spec.ramp_rate, KinematicsText(w.spec.kinematics));
    return;
  }
  std::printf("  waves (linear Airy, along %s): height %.4g m, period %.4g s, depth %.6g m, "
              "still water level y = %.6g m: length %.6g m, k h = %.4g (%s), steepness H/L = "
              "%.4g (breaks above %.4g), crest speed %.4g m/s, phase %.4g deg, ramp rate %.4g "
              "1/s, kinematics %s\n",
              HeadingText(w.direction).c_str(), w.spec.height, w.spec.period, w.spec.depth,
              w.spec.surface_y, w.length(), kh,
              kh > M_PI ? "deep" : kh < M_PI / 10 ? "shallow" : "intermediate depth",
              w.steepness(), w.breaking_steepness(), w.omega / w.k, scene.waves.phase,
              w.spec.ramp_rate, KinematicsText(w.spec.kinematics));
  for (const PointDef& p : scene.points) {
    const EndDef& end = p.motion;
    if (end.follows_wave)
      std::printf("  %s follows the wave: along x %.4g x [%.4g deg], heave %.4g x [%.4g deg], "
                  "along z %.4g x [%.4g deg] of the wave's amplitude at it\n",
                  PointTitle(p).c_str(), end.x_rao[0], end.x_rao[1], end.y_rao[0], end.y_rao[1],
                  end.z_rao[0], end.z_rao[1]);
  }
}

// The scheme and its step.
void PrintScheme(const Model& model, const TimeGrid& grid) {
  const long steps = grid.outputs * grid.steps_per_output;
  bool elastic = false, inextensible = false;
  for (const LineModel& m : model.lines)
    (m.line.law == LinkLaw::kElastic ? elastic : inextensible) = true;
  if (elastic)
    std::printf("  stable time step of the explicit scheme %.4g s (stiffest at station %d)\n",
                grid.limit.time_step, grid.limit.station);
  const Scheme scheme = elastic ? grid.options.scheme : Scheme::kInextensible;
  switch (scheme) {
    case Scheme::kExplicit:
      std::printf("  integrator explicit, time step %.4g s = %.2f x the stability limit%s, %ld steps\n",
                  grid.dt, grid.dt / grid.limit.time_step,
                  grid.automatic ? " (auto: safety factor)" : " (given)", steps);
      if (!grid.automatic && grid.dt > grid.limit.time_step)
        std::printf("  warning: the time step is above the stability limit; the explicit scheme "
                    "will blow up (use integrator = \"implicit\" or time_step = \"auto\")\n");
      break;
    case Scheme::kImplicit:
      if (grid.automatic)
        std::printf("  integrator implicit (generalized-alpha, rho_inf %.2f), adaptive step up to "
                    "%.4g s (%.0f x the explicit limit), tolerance %.3g m: each step's local "
                    "position error estimate kept below it (the error a step adds, not the "
                    "run's total)\n",
                    grid.options.rho_inf, grid.dt, grid.dt / grid.limit.time_step,
                    grid.options.tolerance);
      if (grid.automatic && grid.options.start_end > 0)
        std::printf("  while the motion starts, until t = %.4g s: tolerance %.3g m (the start's "
                    "free oscillations carry their phase error on)\n",
                    grid.options.start_end, grid.options.start_tolerance);
      else if (!grid.automatic)
        std::printf("  integrator implicit (generalized-alpha, rho_inf %.2f), time step %.4g s "
                    "(given) = %.0f x the explicit limit, %ld steps\n",
                    grid.options.rho_inf, grid.dt, grid.dt / grid.limit.time_step, steps);
      break;
    case Scheme::kInextensible:
      break;
  }
  if (!inextensible) return;
  if (grid.options.tolerance > 0)
    std::printf("  %sintegrator inextensible (constraint tensions), output every %.4g s, "
                "substeps below the transverse wave limit and error-controlled: tolerance "
                "%.3g m, each step's local position error estimate kept below it\n",
                elastic ? "its inextensible lines: " : "", grid.interval, grid.options.tolerance);
  else
    std::printf("  %sintegrator inextensible (constraint tensions), output every %.4g s, "
                "substeps from the transverse wave limit\n",
                elastic ? "its inextensible lines: " : "", grid.interval);
}

}  // namespace

void PrintScene(const SceneDef& scene, const Model& model, const TimeGrid& grid) {
  std::printf("scene %s: %s\n", EscapeText(scene.path).c_str(), QuoteText(scene.title).c_str());
  const bool alone = model.lines.size() == 1;
  if (alone)
    PrintLine(scene, model.lines.front());
  else
    PrintLines(model);
  PrintTangentialMaterials(scene);
  PrintCurrent(model.lines.front().env);
  PrintSeabed(model);
  PrintWaves(scene, model.lines.front());
  PrintScheme(model, grid);
  std::vector<std::string> notes, warnings;
  DescribeTables(scene, &notes, &warnings);
  for (const std::string& n : notes) std::printf("  %s\n", n.c_str());
  const FilmWindow& window = scene.film.window;
  if (scene.output.film && window.peak_width > 0)
    std::printf("  film: the %.6g s around the run's peak (film.window), from the state the run "
                "keeps there\n", window.peak_width);
  else if (scene.output.film && !window.whole())
    std::printf("  film: from %.6g to %.6g s (film.window), from the state the run keeps there\n",
                window.start, window.end);
  for (const std::string& w : scene.warnings) std::printf("  warning: %s\n", w.c_str());
  for (const std::string& w : warnings) std::printf("  warning: %s\n", w.c_str());
  for (std::size_t i = 0; i < model.lines.size(); ++i) {
    const LineModel& m = model.lines[i];
    const Vec a = m.ends.start.Position(0), b = m.ends.end.Position(0);
    if (m.line.law == LinkLaw::kElastic && m.ends.start.prescribed() && m.ends.end.prescribed() &&
        (b - a).norm() > m.line.total_length())
      std::printf("  warning: %s ends are %.3g %% further apart than %s long: it starts "
                  "stretched\n",
                  alone ? "the" : ("line " + QuoteText(model.line_names[i]) + "'s").c_str(),
                  100.0 * ((b - a).norm() / m.line.total_length() - 1.0),
                  alone ? "the cable is" : "it is");
  }
}

void PrintInitialState(const SceneDef& scene, const Run& run, const std::string& suffix) {
  const EquilibriumReport& eq = run.equilibrium;
  const Model& model = run.model;
  const bool straight = scene.initial == InitialStateKind::kStraight;
  if (model.lines.size() == 1 && !model.islands.front().coupled()) {  // a line alone
    const Eigen::VectorXd& T0 = run.initial.lines.front().tension();
    const int last = model.lines.front().line.links - 1;
    if (straight) {  // no statics, no report
      std::printf("initial state: the straight chord at rest (not an equilibrium), written to "
                  "equilibrium%s.csv; tension %.6g N at the start, %.6g N at the end\n",
                  suffix.c_str(), T0[0], T0[last]);
      return;
    }
    const LineEquilibriumReport& line = eq.lines.front();
    std::printf("equilibrium: %d Newton iterations%s, residual %.3g N (of %.4g N), %.2f ms; "
                "tension %.6g N at the start, %.6g N at the end\n",
                line.iterations,
                line.fallback ? (" (" + std::to_string(line.fallback_iterations) +
                                 " pseudo-transient after Newton stalled)").c_str()
                              : "",
                line.residual, line.force_scale, run.equilibrium_ms, T0[0], T0[last]);
    return;
  }
  if (straight) {
    std::printf("initial state: every line on the straight chord between its ends, at rest (not "
                "an equilibrium), written to equilibrium%s.csv\n",
                suffix.c_str());
    return;
  }
  std::printf("equilibrium: %d Newton iteration(s) on the shared points and free bodies, "
              "out-of-balance %.3g N (of %.4g N), %.2f ms\n",
              eq.iterations, eq.residual, eq.force_scale, run.equilibrium_ms);
  if (eq.chains > 0)
    std::printf("  first guess: %d chain(s) of lines through their joints solved as one line\n",
                eq.chains);
  if (eq.relaxed > 0)
    std::printf("  not reached from the scene's positions: found from where %.3g s of the "
                "system's own motion, damped by its fluid, brought it\n",
                eq.relaxed);
  for (int b : model.free_bodies) {
    const Vec6& q = eq.body_poses[b];
    std::printf("  body %s at (%.6g, %.6g, %.6g) m, turned (%.6g, %.6g, %.6g) deg about x, y, "
                "z\n",
                QuoteText(model.bodies[b].name).c_str(), q[0], q[1], q[2], q[3] * 180 / M_PI,
                q[4] * 180 / M_PI, q[5] * 180 / M_PI);
  }
}

}  // namespace cablefilm
