#include "scene/build_model.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "core/error.h"
#include "scene/text_escape.h"

namespace cablefilm {

namespace {

// The table's offsets [m] (`angles` false) or angles [rad] about `rest` (of a wave-following
// end: zero, the table added to the waves' motion); nothing when the table has none that move
// (its angles all 0).
std::optional<EndMotion> TableMotion(const EndDef& e, const Vec& rest, bool angles) {
  if (e.table.empty()) return std::nullopt;
  const double deg = M_PI / 180.0;
  std::vector<double> times;
  std::vector<Vec> values;
  bool moves = !angles;
  for (const auto& r : e.table) {
    times.push_back(r[0]);
    values.push_back(angles ? Vec(r[4], r[5], r[6]) * deg : Vec(r[1], r[2], r[3]));
    moves = moves || r[4] != 0 || r[5] != 0 || r[6] != 0;
  }
  if (!moves) return std::nullopt;
  return EndMotion::Table(rest, times, values, e.interpolation);
}

// A wave-following end's motion (`own`) with its drift table added, if it has one.
EndMotion WithDrift(const EndDef& e, const EndMotion& own, bool angles) {
  const std::optional<EndMotion> drift = TableMotion(e, Vec::Zero(), angles);
  return drift ? own.WithAdded(*drift) : own;
}

}  // namespace

EndMotion MakeEndMotion(const EndDef& e) {
  const Vec rest(e.position[0], e.position[1], e.position[2]);
  switch (e.motion) {
    case EndMotionKind::kFixed:
      return EndMotion::Fixed(rest);
    case EndMotionKind::kFree:
      return EndMotion::Free(rest);
    case EndMotionKind::kTrochoid:
      if (!e.harmonics.empty()) {  // following an irregular sea
        std::vector<EndMotion::Harmonic> h;
        for (const auto& row : e.harmonics)
          h.push_back({row[0], Vec(row[1], row[3], row[5]), Vec(row[2], row[4], row[6])});
        return WithDrift(e, EndMotion::Harmonics(rest, std::move(h), e.ramp_rate), false);
      }
      return WithDrift(
          e,
          EndMotion::Trochoid(rest, Vec(e.x_amplitudes[0], e.y_amplitudes[0], e.z_amplitudes[0]),
                              Vec(e.x_amplitudes[1], e.y_amplitudes[1], e.z_amplitudes[1]),
                              2.0 * M_PI / e.period, e.ramp_rate),
          false);
    case EndMotionKind::kTable:
      return *TableMotion(e, rest, false);
  }
  throw Error("unknown end motion");
}

EndMotion MakeTurnMotion(const EndDef& e, const Vec& rest_angles) {
  const double deg = M_PI / 180.0;
  switch (e.motion) {
    case EndMotionKind::kTrochoid: {
      std::optional<EndMotion> waves;  // the waves' angles, if they turn it
      if (!e.harmonics.empty()) {  // following an irregular sea: the angles' columns
        std::vector<EndMotion::Harmonic> h;
        bool turns = false;
        for (const auto& row : e.harmonics) {
          h.push_back({row[0], Vec(row[7], row[9], row[11]) * deg,
                       Vec(row[8], row[10], row[12]) * deg});
          turns = turns || !h.back().cos.isZero(0) || !h.back().sin.isZero(0);
        }
        if (turns) waves = EndMotion::Harmonics(rest_angles, std::move(h), e.ramp_rate);
      } else {
        const Vec cos_amplitudes(e.rx_amplitudes[0], e.ry_amplitudes[0], e.rz_amplitudes[0]);
        const Vec sin_amplitudes(e.rx_amplitudes[1], e.ry_amplitudes[1], e.rz_amplitudes[1]);
        if (!cos_amplitudes.isZero(0) || !sin_amplitudes.isZero(0))
          waves = EndMotion::Trochoid(rest_angles, cos_amplitudes * deg, sin_amplitudes * deg,
                                      2.0 * M_PI / e.period, e.ramp_rate);
      }
      if (waves) return WithDrift(e, *waves, true);
      if (auto drift = TableMotion(e, rest_angles, true)) return *drift;  // the drift's alone
      break;
    }
    case EndMotionKind::kTable:
      if (auto table = TableMotion(e, rest_angles, true)) return *table;
      break;
    case EndMotionKind::kFixed:
    case EndMotionKind::kFree:
      break;
  }
  return EndMotion::Fixed(rest_angles);
}

namespace {

// A speed below this is taken as at rest [m/s] (a micrometre a second).
constexpr double kRestSpeed = 1e-6;
// A rate of turn below this is taken as at rest [rad/s] (a micrometre a second at 1 m).
constexpr double kRestTurnRate = 1e-6;

std::string Figure(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

void DescribeTable(const std::string& what, const EndDef& e, double run_end,
                   std::vector<std::string>* notes, std::vector<std::string>* warnings) {
  const bool drift = e.motion == EndMotionKind::kTrochoid && !e.table.empty();
  if (e.motion != EndMotionKind::kTable && !drift) return;
  // The table's own motion: a drift's alone, about a rest of zero.
  const EndMotion m = drift ? MakeEndMotion(e).added() : MakeEndMotion(e);
  const bool linear = m.interpolation() == TableInterpolation::kLinear;
  const double first = m.Velocity(m.table_start()).norm(), last = m.EndSpeed();
  if (notes)
    notes->push_back(what + ": " + (drift ? "drift table " : "table ") +
                     EscapeText(std::filesystem::path(e.table_file).filename().string()) +
                     ", " + std::to_string(e.table.size()) + " rows from t = " +
                     Figure(m.table_start()) + " to " + Figure(m.table_end()) + " s, " +
                     (linear ? "linear between rows" : "natural cubic spline") +
                     " (interpolation = \"" + (linear ? "linear" : "spline") +
                     "\"), speed " + Figure(first) + " m/s at its first row and " +
                     Figure(last) + " m/s at its last; held still before and after" +
                     (drift ? ", added to the waves' motion" : ""));
  if (warnings && run_end > m.table_end() && last > kRestSpeed)
    warnings->push_back(what + ": the run goes on to t = " + Figure(run_end) +
                        " s, past the " + (drift ? "drift " : "") + "table's last row at t = " +
                        Figure(m.table_end()) + " s, where it still moves at " + Figure(last) +
                        " m/s: after that row " + (drift ? "its drift" : "the end") +
                        " holds still, stopping dead (a jump in velocity no recorded motion "
                        "has). End the run at the table's last row, or the table at rest");
}

// A body's table that turns it: its rates of turn [deg/s] at the first and last rows, and the
// same warning for a turn still going at the last row.
void DescribeTurn(const std::string& what, const EndDef& e, double run_end,
                  std::vector<std::string>* notes, std::vector<std::string>* warnings) {
  if (e.motion != EndMotionKind::kTable) return;
  const EndMotion m = MakeTurnMotion(e, Vec::Zero());
  if (!m.moves()) return;
  const double deg = 180.0 / M_PI;
  const double first = m.Velocity(m.table_start()).norm() * deg, last = m.EndSpeed() * deg;
  if (notes)
    notes->push_back(what + ": its table turns it too, at " + Figure(first) +
                     " deg/s at its first row and " + Figure(last) + " deg/s at its last");
  if (warnings && run_end > m.table_end() && m.EndSpeed() > kRestTurnRate)
    warnings->push_back(what + ": the run goes on to t = " + Figure(run_end) +
                        " s, past the table's last row at t = " + Figure(m.table_end()) +
                        " s, where it still turns at " + Figure(last) +
                        " deg/s: after that row it holds still, stopping dead. End the run at "
                        "the table's last row, or the table at rest");
}

}  // namespace

void DescribeTables(const SceneDef& scene, std::vector<std::string>* notes,
                    std::vector<std::string>* warnings) {
  // The run's last row (run/time_grid.cpp, ChooseTimeGrid).
  const double interval = scene.output.interval;
  const double run_end =
      interval > 0 ? std::floor(scene.simulation.duration / interval + 1e-9) * interval
                   : scene.simulation.duration;
  for (const PointDef& p : scene.points)
    DescribeTable(PointTitle(p), p.motion, run_end, notes, warnings);
  for (const BodyDef& b : scene.bodies) {
    DescribeTable("body " + QuoteText(b.name), b.motion, run_end, notes, warnings);
    DescribeTurn("body " + QuoteText(b.name), b.motion, run_end, notes, warnings);
  }
  const WavesDef& w = scene.waves;
  if (warnings && w.present && w.sea == SeaKind::kRecord && w.components_made &&
      run_end > w.components_made->repeat_period)
    warnings->push_back("waves.file " + EscapeText(w.file) + ": the record spans " +
                        Figure(w.components_made->repeat_period) + " s and the run " +
                        Figure(run_end) + " s: the sea repeats the record after " +
                        Figure(w.components_made->repeat_period) +
                        " s (its components are the record's Fourier series)");
}

WaveSpec MakeWaveSpec(const SceneDef& scene) {
  WaveSpec w;
  const WavesDef& d = scene.waves;
  if (!d.present) return w;
  w.present = true;
  w.height = d.height;
  w.period = d.period;
  w.depth = d.depth;
  w.surface_y = d.surface_y;
  w.phase = d.phase * M_PI / 180.0;
  w.heading = d.heading * M_PI / 180.0;
  w.ramp_rate = d.ramp_rate;
  w.kinematics = d.kinematics;
  if (d.sea != SeaKind::kRegular) w.sea = d.components_made;
  return w;
}

int StationAt(const std::vector<SectionDef>& sections, double arc_length, const std::string& path) {
  int station = 0;
  double start = 0;
  for (const SectionDef& sec : sections) {
    const double l = sec.length / sec.segments;
    const double k = std::round((arc_length - start) / l);
    if (k >= 0 && k <= sec.segments && std::abs(arc_length - start - k * l) <= 1e-6 * l)
      return station + static_cast<int>(k);
    station += sec.segments;
    start += sec.length;
  }
  throw Error(path + ": a weight at " + std::to_string(arc_length) +
              " m is not on a station");
}

namespace {

std::vector<SectionSpec> MakeSections(const SceneDef& scene, const std::vector<SectionDef>& defs) {
  std::vector<SectionSpec> sections;
  for (const SectionDef& def : defs) {
    const MaterialDef& mat = scene.materials.at(def.material);
    SectionSpec s;
    s.length = def.length;
    s.segments = def.segments;
    s.diameter = mat.diameter;
    s.area = mat.area;
    s.mass_per_length = mat.mass_per_length;
    s.youngs_modulus = mat.youngs_modulus;
    s.drag_coefficient = mat.drag_coefficient;
    s.added_mass_coefficient = mat.added_mass_coefficient;
    s.axial_damping = mat.axial_damping;
    s.axial_damping_ratio = mat.axial_damping_ratio;
    s.moordyn_axial_damping_ratio = mat.moordyn_axial_damping_ratio;
    s.minimum_breaking_load = mat.minimum_breaking_load;
    s.tangential_drag_coefficient = mat.tangential_drag_coefficient;
    s.tangential_added_mass_coefficient = mat.tangential_added_mass_coefficient;
    s.axial_froude_krylov = mat.axial_froude_krylov;
    sections.push_back(s);
  }
  return sections;
}

Vec ToVec(const std::array<double, 3>& a) { return Vec(a[0], a[1], a[2]); }

std::vector<PrismSpec> MakePrisms(const std::vector<SectionDef>& sections,
                                  const std::vector<WeightDef>& weights, const std::string& path) {
  std::vector<PrismSpec> prisms;
  for (const WeightDef& w : weights) {
    PrismSpec p;
    p.station = StationAt(sections, w.at, path);
    p.mass = w.mass;
    p.volume = w.volume;
    p.added_volume = ToVec(w.added_volume);
    p.drag_coefficient = ToVec(w.drag_coefficient);
    p.drag_area = ToVec(w.drag_area);
    prisms.push_back(p);
  }
  return prisms;
}

EnvironmentSpec MakeEnvironment(const SceneDef& scene) {
  EnvironmentSpec env;
  env.gravity = scene.environment.gravity;
  env.fluid_density = scene.environment.fluid_density;
  env.current = scene.environment.current;
  env.current_profile = scene.environment.current_profile;
  env.current_direction = scene.environment.current_direction;
  env.current_history = scene.environment.current_history;
  env.seabed = scene.seabed;
  env.waves = MakeWaveSpec(scene);
  return env;
}

}  // namespace

Model BuildModel(const SceneDef& scene) {
  const double deg = M_PI / 180.0;
  std::vector<BodySpec> bodies;
  for (const BodyDef& d : scene.bodies) {
    BodySpec b;
    b.name = d.name;
    b.kind = d.free ? BodyKind::kFree
                    : d.motion.motion == EndMotionKind::kFixed ? BodyKind::kHeld : BodyKind::kDriven;
    b.motion = MakeEndMotion(d.motion);
    b.angles = ToVec(d.orientation) * deg;
    if (b.kind == BodyKind::kDriven) b.turn = MakeTurnMotion(d.motion, b.angles);
    b.mass = d.mass;
    b.center_of_gravity = ToVec(d.center_of_gravity);
    b.volume = d.volume;
    b.center_of_buoyancy = ToVec(d.center_of_buoyancy);
    b.waterplane_area = d.waterplane_area;
    b.waterplane_inertia_x = d.waterplane_inertia[0];
    b.waterplane_inertia_z = d.waterplane_inertia[1];
    b.force = ToVec(d.force);
    b.moment = ToVec(d.moment);
    b.inertia = ToVec(d.inertia);
    for (int k = 0; k < 6; ++k) {
      b.added_mass[k] = d.added_mass[k];
      b.linear_damping[k] = d.linear_damping[k];
      b.quadratic_damping[k] = d.quadratic_damping[k];
      b.initial_offset[k] = d.initial_offset[k] * (k < 3 ? 1.0 : deg);
    }
    bodies.push_back(b);
  }
  std::vector<PointSpec> points;
  for (const PointDef& d : scene.points) {
    PointSpec p;
    p.name = d.name;
    p.on_body = d.body;
    if (d.body >= 0) {
      p.local = ToVec(d.motion.position);
      points.push_back(p);
      continue;
    }
    p.motion = MakeEndMotion(d.motion);
    p.body.mass = d.mass;
    p.body.volume = d.volume;
    p.body.added_volume = ToVec(d.added_volume);
    p.body.drag_coefficient = ToVec(d.drag_coefficient);
    p.body.drag_area = ToVec(d.drag_area);
    p.body.force = ToVec(d.force);
    points.push_back(p);
  }
  std::vector<LineSpec> lines;
  for (const LineDef& d : scene.lines) {
    LineSpec l;
    l.name = d.name;
    l.law = d.model == CableModelKind::kElastic ? LinkLaw::kElastic : LinkLaw::kInextensible;
    l.sections = MakeSections(scene, d.sections);
    l.prisms = MakePrisms(d.sections, d.weights, scene.path);
    l.start_point = d.start;
    l.end_point = d.end;
    lines.push_back(l);
  }
  try {
    return MakeModel(lines, points, MakeEnvironment(scene), bodies);
  } catch (const Error& e) {
    throw Error(scene.path + ": " + e.what());
  }
}

}  // namespace cablefilm
