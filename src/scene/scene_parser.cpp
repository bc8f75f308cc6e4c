#include "scene/scene_parser.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <toml++/toml.h>
#include <unordered_map>

#include "core/error.h"
#include "core/waves.h"
#include "scene/film_settings.h"
#include "scene/film_view.h"
#include "scene/number_table.h"
#include "scene/recorded_sea.h"
#include "scene/scene_checks.h"
#include "scene/scene_limits.h"
#include "scene/table_file.h"
#include "scene/text_escape.h"
#include "scene/toml_reader.h"

namespace cablefilm {
namespace {

std::string Quote(const std::string& s) { return QuoteText(s); }

// Names to their indices: a file may name 1e5 points, so lookups must not scan.
using NameIndex = std::unordered_map<std::string, int>;

template <class Named>
NameIndex IndexByName(const std::vector<Named>& named) {
  NameIndex index;
  for (std::size_t k = 0; k < named.size(); ++k) index.emplace(named[k].name, static_cast<int>(k));
  return index;
}

// The index of `name` in `index`, or -1.
int Find(const NameIndex& index, const std::string& name) {
  const auto found = index.find(name);
  return found == index.end() ? -1 : found->second;
}

// [[y, speed], ...]: elevations strictly increasing, each within the stated ranges.
void ReadCurrentProfile(TableReader& r, const toml::array& a, CurrentProfile& profile) {
  const std::string what = "a profile [[y, speed], ...]: from 1 to " +
                           std::to_string(kMaxCurrentPoints) +
                           " pairs of an elevation in m (" + TableReader::Fmt(-kMaxLength) +
                           " to " + TableReader::Fmt(kMaxLength) + ", increasing) and a speed "
                           "in m/s (" + TableReader::Fmt(-kMaxCurrent) + " to " +
                           TableReader::Fmt(kMaxCurrent) + ")";
  if (a.empty() || a.size() > static_cast<size_t>(kMaxCurrentPoints))
    r.Fail(&a, "current", "expected " + what + ", got " + std::to_string(a.size()) + " pairs");
  for (size_t i = 0; i < a.size(); ++i) {
    const std::string key = "current[" + std::to_string(i) + "]";
    const toml::node* n = a.get(i);
    const toml::array* pair = n->as_array();
    if (!pair || pair->size() != 2) r.Fail(n, key, "expected [y, speed] in " + what);
    const double y = r.Number(key, pair->get(0), "an elevation in m");
    const double c = r.Number(key, pair->get(1), "a speed in m/s");
    if (!(std::abs(y) <= kMaxLength))
      r.Fail(n, key, "expected an elevation in m from " + TableReader::Fmt(-kMaxLength) + " to " +
                         TableReader::Fmt(kMaxLength) + ", got " + TableReader::Fmt(y));
    if (!(std::abs(c) <= kMaxCurrent))
      r.Fail(n, key, "expected a speed in m/s from " + TableReader::Fmt(-kMaxCurrent) + " to " +
                         TableReader::Fmt(kMaxCurrent) + ", got " + TableReader::Fmt(c));
    if (!profile.empty() && !(y > profile.y.back()))
      r.Fail(n, key, "expected the elevations to increase strictly, got y = " +
                         TableReader::Fmt(y) + " m after " + TableReader::Fmt(profile.y.back()) +
                         " m");
    profile.y.push_back(y);
    profile.speed.push_back(c);
  }
}

// environment.current_file: the current over time, rows t,speed,heading (a uniform current
// of that speed; no `current` beside it) or t,scale,heading (the scene's current scaled; not the
// vector [u, w], whose direction is its own); either way the heading column turns it (no
// current_heading beside it).
void ReadCurrentFile(TableReader& r, const toml::table* t, EnvironmentDef& env,
                     const std::string& file, bool current_given, bool vector) {
  const std::string name = r.String("current_file", "", true);
  if (name.empty() || name.find('\0') != std::string::npos)
    r.Fail(t->get("current_file"), "current_file",
           "expected the name of a CSV file t,speed,heading or t,scale,heading, got " +
               Quote(name));
  if (r.Has("current_heading"))
    r.Fail(t->get("current_heading"), "current_heading",
           "the current_file's heading column turns the current; expected no current_heading "
           "beside it");
  env.current_file = (std::filesystem::path(file).parent_path() / name).string();
  auto history = std::make_shared<CurrentHistory>();
  bool speeds = false;
  try {
    int form = 0;
    const auto rows = ReadNumberTableOfForms(
        env.current_file, {{"t", "speed", "heading"}, {"t", "scale", "heading"}},
        "the current over time", "(t in s, the speed in m/s or the scale, heading in degrees)",
        1, &form);
    speeds = form == 0;
    double base = std::abs(env.current);  // the largest speed the table scales [m/s]
    for (double v : env.current_profile.speed) base = std::max(base, std::abs(env.current + v));
    if (speeds) base = 1.0;
    for (const auto& row : rows) {
      const double limit = speeds ? kMaxCurrent : (base > 0 ? kMaxCurrent / base : kMaxCurrent);
      if (!(std::abs(row[0]) <= kMaxTime) || !(std::abs(row[1]) <= limit) ||
          !(std::abs(row[2]) <= 2 * kMaxPhase) ||
          (!history->t.empty() && !(row[0] > history->t.back())))
        throw Error(EscapeText(env.current_file) + ": expected t increasing within " +
                    TableReader::Fmt(kMaxTime) + " s, " +
                    (speeds ? "a speed within " + TableReader::Fmt(kMaxCurrent) + " m/s"
                            : "a scale within " + TableReader::Fmt(limit) +
                                  " (the current at most " + TableReader::Fmt(kMaxCurrent) +
                                  " m/s)") +
                    " and a heading within " + TableReader::Fmt(2 * kMaxPhase) +
                    " degrees, got t = " + TableReader::Fmt(row[0]) + ", " +
                    (speeds ? "speed = " : "scale = ") + TableReader::Fmt(row[1]) +
                    ", heading = " + TableReader::Fmt(row[2]));
      history->t.push_back(row[0]);
      history->factor.push_back(row[1]);
      history->heading.push_back(row[2] * M_PI / 180.0);
    }
  } catch (const Error& e) {
    r.Fail(t->get("current_file"), "current_file", e.what());
  }
  if (speeds && current_given)
    r.Fail(t->get("current"), "current",
           "the current_file's rows t,speed,heading give the current; expected no current "
           "beside them (or rows t,scale,heading to scale this one)");
  if (vector)
    r.Fail(t->get("current"), "current",
           "the current [u, w] has its direction already, and the current_file turns it; "
           "expected a speed or a profile [[y, speed], ...] with a current_file");
  if (speeds) env.current = 1.0;  // the table's speed is its factor on 1 m/s
  env.current_history = std::move(history);
}

void ReadEnvironment(TableReader& top, SceneDef& scene, const std::string& file) {
  const toml::table* t = top.SubTable("environment", false);
  if (!t) return;
  TableReader r = top.Child(*t, "environment");
  scene.environment.gravity =
      r.OptionalNonNegative("gravity", 9.80665, " in m/s^2", kMaxGravity);
  scene.environment.fluid_density =
      r.OptionalNonNegative("fluid_density", 1025.0, " in kg/m^3", kMaxFluidDensity);
  // A number (along +x, or current_heading), a horizontal vector [u, w] (along +x and +z), or a
  // profile [[y, speed], ...] (along +x, or current_heading): told apart by their types.
  EnvironmentDef& env = scene.environment;
  const toml::node* current = t->get("current");
  const toml::array* array = current ? current->as_array() : nullptr;
  const bool profile = array && (array->empty() || array->get(0)->is_array());
  const bool vector = array && !profile;
  if (profile) {
    r.Get("current");
    ReadCurrentProfile(r, *array, env.current_profile);
  } else if (vector) {
    if (array->size() != 2)
      r.Fail(current, "current",
             "expected a horizontal current [u, w] in m/s along +x and +z (two numbers), a "
             "speed, or a profile [[y, speed], ...], got an array of " +
                 std::to_string(array->size()) + " numbers");
    const std::array<double, 3> uw = r.Triple("current", {0, 0, 0}, true, false,
                                              " (m/s along +x and +z)", kMaxCurrent,
                                              TableReader::TwoValues::kZeroZ);
    env.current = std::hypot(uw[0], uw[1]);
    if (env.current > 0) env.current_direction = Vec(uw[0], 0.0, uw[1]) / env.current;
  } else if (current && !current->is_number()) {
    r.Fail(current, "current",
           "expected a speed in m/s from " + TableReader::Fmt(-kMaxCurrent) + " to " +
               TableReader::Fmt(kMaxCurrent) + ", a horizontal vector [u, w] in m/s, or a "
               "profile [[y, speed], ...] (elevation in m, speed in m/s)");
  } else {
    env.current =
        r.Ranged("current", 0.0, false, -kMaxCurrent, kMaxCurrent, " (a speed in m/s)");
  }
  if (r.Has("current_heading") && vector)
    r.Fail(t->get("current_heading"), "current_heading",
           "the current [u, w] has its direction already; expected no current_heading with it");
  const double heading = r.Ranged("current_heading", 0.0, false, -kMaxPhase, kMaxPhase,
                                  " (degrees from +x towards +z)");
  if (heading != 0) env.current_direction = Horizontal(heading * M_PI / 180.0);
  if (r.Has("current_file")) ReadCurrentFile(r, t, env, file, current != nullptr, vector);
  r.Finish();
}

void ReadSeabed(TableReader& top, SceneDef& scene) {
  const toml::table* t = top.SubTable("seabed", false);
  if (!t) return;
  TableReader r = top.Child(*t, "seabed");
  SeabedDef& b = scene.seabed;
  b.present = true;
  b.y = r.Ranged("y", 0.0, true, -kMaxLength, kMaxLength, " (the seabed's elevation in m)");
  b.stiffness = r.OptionalPositive("stiffness", b.stiffness, " in N/m per m of line (N/m^2)",
                                   kMinSeabedStiffness, kMaxSeabedStiffness);
  if (r.Has("damping"))
    b.damping = r.OptionalNonNegative("damping", 0.0, " in N s/m per m of line (N s/m^2)",
                                      kMaxSeabedDamping);
  else
    r.Get("damping");
  b.friction = r.OptionalNonNegative("friction", 0.0, " (Coulomb coefficient)", kMaxFriction);
  // Stick-slip unless the scene asks for the smoothed law, by name or by giving its
  // friction_velocity (scenes written before the stick-slip law keep theirs).
  const bool smoothed_asked = r.Has("friction_velocity");
  b.friction_velocity = r.OptionalPositive("friction_velocity", b.friction_velocity, " in m/s",
                                           kMinFrictionVelocity, kMaxFrictionVelocity);
  b.friction_model =
      r.Choice("friction_model", smoothed_asked ? "smoothed" : "stick_slip",
               {"stick_slip", "smoothed"}) == "smoothed"
          ? FrictionModel::kSmoothed
          : FrictionModel::kStickSlip;
  if (r.Has("friction_stiffness"))
    b.friction_stiffness = r.OptionalPositive("friction_stiffness", b.stiffness,
                                              " in N/m per m of line (N/m^2)",
                                              kMinSeabedStiffness, kMaxSeabedStiffness);
  else
    r.Get("friction_stiffness");
  r.Finish();
}

// [waves]: read after [environment] and [seabed] (the default depth is the seabed's). The wave
// is checked against breaking: H / L at most tanh(k h) / 7 (Miche 1944: 1/7 in deep water,
// H <= 0.88 h in shallow water), an error naming waves.height.
// An irregular sea's keys (spectrum != "regular"): the spectrum's, or a table's or record's
// file, and how its components are drawn; the sea made into components (its Hs and Tp into
// height and period).
void ReadSea(TableReader& r, const toml::table* t, SceneDef& scene, const std::string& file,
             const std::string& spectrum) {
  WavesDef& w = scene.waves;
  for (const char* regular : {"height", "period", "phase"})
    if (r.Has(regular))
      r.Fail(t->get(regular), regular,
             std::string(regular) + " is the regular wave's; a sea of spectrum = " +
                 QuoteText(spectrum) +
                 " takes hs and tp (jonswap, pierson-moskowitz) or a file (table, record)");
  const bool drawn = w.sea != SeaKind::kRecord;  // the components are drawn from a spectrum
  if (!drawn)
    for (const char* key : {"seed", "components", "spreading"})
      if (r.Has(key))
        r.Fail(t->get(key), key,
               std::string(key) + " draws a spectrum's components; a record's are its own");
  const bool formula = w.sea == SeaKind::kJonswap || w.sea == SeaKind::kPiersonMoskowitz;
  SpectrumSpec spec;
  if (formula) {
    spec.kind = w.sea == SeaKind::kJonswap ? SpectrumKind::kJonswap
                                           : SpectrumKind::kPiersonMoskowitz;
    spec.hs = r.Positive("hs", " (significant wave height, in m)", 1e-6, kMaxWaveHeight);
    spec.tp = r.Ranged("tp", 0.0, true, kMinWavePeriod, kMaxWavePeriod, " (peak period, in s)");
    spec.gamma = 1.0;
    if (w.sea == SeaKind::kJonswap)
      spec.gamma = r.Has("gamma")
                       ? r.Ranged("gamma", 0.0, true, 1.0, 10.0,
                                  " (JONSWAP's peak enhancement; DNV's rule if left out)")
                       : DnvJonswapGamma(spec.hs, spec.tp);
    w.gamma = spec.gamma;
  } else {
    for (const char* formula_key : {"hs", "tp", "gamma"})
      if (r.Has(formula_key))
        r.Fail(t->get(formula_key), formula_key,
               std::string(formula_key) + " belongs to spectrum = \"jonswap\" or " +
                   "\"pierson-moskowitz\"; a sea of spectrum = " + QuoteText(spectrum) +
                   " is its file's");
    const std::string name = r.String("file", "", true);
    if (name.empty() || name.find('\0') != std::string::npos)
      r.Fail(t->get("file"), "file",
             std::string("expected the name of a CSV file ") +
                 (w.sea == SeaKind::kTable ? "omega,S" : "t,eta") + ", got " + Quote(name));
    w.file = (std::filesystem::path(file).parent_path() / name).string();
    try {
      if (w.sea == SeaKind::kTable) {
        for (const auto& row : ReadNumberTable(w.file, {"omega", "S"}, "the spectrum table",
                                               "(omega in rad/s, S in m^2 s/rad)")) {
          if (!(row[0] > 0 && row[0] <= 1e3) || !(row[1] >= 0 && row[1] <= 1e9) ||
              (!w.table_omega.empty() && !(row[0] > w.table_omega.back())))
            throw Error(EscapeText(w.file) + ": expected omega increasing from above 0 to 1000 "
                        "rad/s and S from 0 to 1e9 m^2 s/rad, got omega = " +
                        TableReader::Fmt(row[0]) + ", S = " + TableReader::Fmt(row[1]));
          w.table_omega.push_back(row[0]);
          w.table_density.push_back(row[1]);
        }
      } else {
        for (const auto& row : ReadNumberTable(w.file, {"t", "eta"}, "the recorded elevation",
                                               "(t in s, eta in m)", 4)) {
          if (!(std::abs(row[0]) <= kMaxTime) || !(std::abs(row[1]) <= kMaxWaveHeight) ||
              (!w.record_t.empty() && !(row[0] > w.record_t.back())))
            throw Error(EscapeText(w.file) + ": expected t increasing, within " +
                        TableReader::Fmt(kMaxTime) + " s, and |eta| at most " +
                        TableReader::Fmt(kMaxWaveHeight) + " m, got t = " +
                        TableReader::Fmt(row[0]) + ", eta = " + TableReader::Fmt(row[1]));
          w.record_t.push_back(row[0]);
          w.record_eta.push_back(row[1]);
        }
      }
    } catch (const Error& e) {
      r.Fail(t->get("file"), "file", e.what());
    }
  }
  w.band = r.Pair("band", {0, 0}, false, false, " ([lowest, highest] omega in rad/s)", 1e3);
  if (r.Has("band") && !(w.band[0] > 0 && w.band[1] > w.band[0]))
    r.Fail(t->get("band"), "band",
           "expected [lowest, highest] omega in rad/s with 0 < lowest < highest, got [" +
               TableReader::Fmt(w.band[0]) + ", " + TableReader::Fmt(w.band[1]) + "]");
  if (drawn) {
    w.seed = static_cast<std::uint64_t>(r.Integer("seed", 1, 0, 2147483647, false));
    w.components = r.Integer("components", 200, 1, kMaxSeaComponents, false);
    w.spreading = r.Ranged("spreading", 0.0, false, 0.0, 1000.0,
                           " (s of the cos-2s spreading function; 0: long-crested)");
  } else {
    w.record_point = r.Pair("record_point", {0, 0}, false, false,
                            " ([x, z] in m, where the record was measured)", kMaxLength);
  }
  const double g = scene.environment.gravity;
  if (!(g > 0)) r.Fail(t, "spectrum", "expected gravity > 0 for waves (environment.gravity = 0)");
  SeaComponents sea;
  try {
    if (w.sea == SeaKind::kRecord) {
      sea = RecordComponents(w.record_t, w.record_eta, w.record_point[0], w.record_point[1],
                             w.heading * M_PI / 180.0, g, w.depth, w.band[0], w.band[1]);
    } else {
      if (w.sea == SeaKind::kTable) {
        spec.kind = SpectrumKind::kTable;
        spec.omega = w.table_omega;
        spec.density = w.table_density;
        if (!(SpectrumArea(spec, spec.omega.front(), spec.omega.back(), 20000) > 0))
          throw Error(EscapeText(w.file) + ": the spectrum's area is 0; expected S > 0 somewhere");
      }
      SeaDiscretization d;
      d.components = w.components;
      d.band_lo = w.band[0];
      d.band_hi = w.band[1];
      d.seed = w.seed;
      d.heading = w.heading * M_PI / 180.0;
      d.spreading = w.spreading;
      sea = SpectrumComponents(spec, d, g, w.depth);
    }
  } catch (const Error& e) {
    r.Fail(t->get("file"), w.sea == SeaKind::kRecord ? "file" : "spectrum", e.what());
  }
  if (sea.size() == 0)
    r.Fail(t->get("band"), "band", "the band holds none of the spectrum: expected a band where "
                                   "its density is above 0");
  // Hs and Tp: the formulas' as given; a table's and a record's from their components (4 sqrt(m0),
  // and the period of the largest).
  int largest = 0;
  for (int i = 1; i < sea.size(); ++i)
    if (sea.amplitude[i] > sea.amplitude[largest]) largest = i;
  w.height = formula ? spec.hs : sea.SignificantHeight();
  w.period = formula ? spec.tp : 2.0 * M_PI / sea.omega[largest];
  if (w.sea == SeaKind::kTable) {  // the table's own peak
    std::size_t peak = 0;
    for (std::size_t i = 1; i < w.table_density.size(); ++i)
      if (w.table_density[i] > w.table_density[peak]) peak = i;
    w.period = 2.0 * M_PI / w.table_omega[peak];
  }
  w.components_made = std::make_shared<const SeaComponents>(std::move(sea));
}

void ReadWaves(TableReader& top, SceneDef& scene, const std::string& file) {
  const toml::table* t = top.SubTable("waves", false);
  if (!t) return;
  TableReader r = top.Child(*t, "waves");
  WavesDef& w = scene.waves;
  w.present = true;
  const std::string spectrum = r.Choice(
      "spectrum", "regular", {"regular", "jonswap", "pierson-moskowitz", "table", "record"});
  w.sea = spectrum == "jonswap"             ? SeaKind::kJonswap
          : spectrum == "pierson-moskowitz" ? SeaKind::kPiersonMoskowitz
          : spectrum == "table"             ? SeaKind::kTable
          : spectrum == "record"            ? SeaKind::kRecord
                                            : SeaKind::kRegular;
  const bool regular = w.sea == SeaKind::kRegular;
  if (regular) {
    for (const char* sea_key : {"hs", "tp", "gamma", "file", "seed", "components", "band",
                                "spreading", "record_point"})
      if (r.Has(sea_key))
        r.Fail(t->get(sea_key), sea_key,
               std::string(sea_key) + " belongs to an irregular sea: expected spectrum = "
               "\"jonswap\", \"pierson-moskowitz\", \"table\" or \"record\" with it (the "
               "regular wave takes height and period)");
    w.height = r.Ranged("height", 0.0, true, 0.0, kMaxWaveHeight,
                        " (crest to trough, in m; 0: still water with a surface)");
    w.period = r.Ranged("period", 0.0, true, kMinWavePeriod, kMaxWavePeriod, " in s");
  }
  w.surface_y = r.Ranged("surface_y", 0.0, false, -kMaxLength, kMaxLength,
                         " (the still water level's elevation in m)");
  // With a [seabed], the depth is the water's over it: given, it must be surface_y - seabed.y
  // (to kWaveDepthTolerance), and the surface at least kMinWaveDepth above the bed.
  const double over_bed = w.surface_y - scene.seabed.y;
  if (scene.seabed.present && !(over_bed >= kMinWaveDepth))
    r.Fail(t->get("surface_y"), "surface_y",
           "expected the still water level at least " + TableReader::Fmt(kMinWaveDepth) +
               " m above the seabed (seabed.y = " + TableReader::Fmt(scene.seabed.y) +
               " m), got y = " + TableReader::Fmt(w.surface_y) + " m, " +
               TableReader::Fmt(std::abs(over_bed)) + " m " + (over_bed < 0 ? "below" : "above") +
               " it");
  if (r.Has("depth") || !scene.seabed.present) {
    w.depth = r.Positive("depth", " in m (still water level to the bed)", kMinWaveDepth,
                         kMaxLength);
    if (scene.seabed.present &&
        !(std::abs(w.depth - over_bed) <= kWaveDepthTolerance * std::max(w.depth, over_bed)))
      r.Fail(t->get("depth"), "depth",
             "expected the still water level's height over the seabed, surface_y - seabed.y = " +
                 TableReader::Fmt(w.surface_y) + " - (" + TableReader::Fmt(scene.seabed.y) +
                 ") = " + TableReader::Fmt(over_bed) + " m (to " +
                 TableReader::Fmt(kWaveDepthTolerance) + " of it), got " +
                 TableReader::Fmt(w.depth) + " m; or leave depth out (it is surface_y - seabed.y "
                 "by default)");
  } else {
    r.Get("depth");
    w.depth = over_bed;
  }
  if (regular) w.phase = r.Ranged("phase", 0.0, false, -kMaxPhase, kMaxPhase, " in degrees");
  w.heading = r.Ranged("heading", 0.0, false, -kMaxPhase, kMaxPhase,
                       regular ? " (the direction they travel, degrees from +x towards +z)"
                               : " (the sea's mean direction, degrees from +x towards +z)");
  if (!regular) ReadSea(r, t, scene, file, spectrum);
  w.ramp_rate =
      r.OptionalPositive("ramp_rate", 4.0 / w.period, " in 1/s", kMinRampRate, kMaxRampRate);
  const std::string kinematics =
      r.Choice("kinematics", "wheeler", {"wheeler", "linear", "extrapolated"});
  w.kinematics = kinematics == "linear"         ? WaveKinematics::kLinear
                 : kinematics == "extrapolated" ? WaveKinematics::kExtrapolated
                                                : WaveKinematics::kWheeler;
  if (!(scene.environment.gravity > 0))
    r.Fail(t, "period", "expected gravity > 0 for waves (environment.gravity = 0)");
  WaveSpec spec;  // the wave number and the breaking height need the period and depth only
  spec.period = w.period;
  spec.depth = w.depth;
  const Wave wave = MakeWave(spec, scene.environment.gravity);
  const double k = wave.k, L = wave.length(), limit = wave.breaking_height();
  if (!(std::isfinite(k * w.depth) && k > 0 && std::isfinite(limit)))  // a gravity near 0
    r.Fail(t->get("period"), "period",
           "no finite wave length for T = " + TableReader::Fmt(w.period) + " s in " +
               TableReader::Fmt(w.depth) + " m of water at environment.gravity = " +
               TableReader::Fmt(scene.environment.gravity) +
               " m/s^2; expected a period, depth and gravity whose deep-water wave length "
               "g T^2 / (2 pi) is finite and above 0");
  if (!regular && !(w.height <= limit))
    r.Fail(t->get(w.sea == SeaKind::kJonswap || w.sea == SeaKind::kPiersonMoskowitz ? "hs"
                                                                                   : "file"),
           "hs",
           "the sea breaks: Hs / L = " + TableReader::Fmt(w.height / L) + " at Tp = " +
               TableReader::Fmt(w.period) + " s (L = " + TableReader::Fmt(L) + " m in " +
               TableReader::Fmt(w.depth) + " m of water); expected Hs of at most " +
               TableReader::Fmt(limit) + " m (Miche's limit at the peak period), got " +
               TableReader::Fmt(w.height) + " m");
  if (!(w.height <= limit))
    r.Fail(t->get("height"), "height",
           "the wave breaks: H / L = " + TableReader::Fmt(w.height / L) + " (L = " +
               TableReader::Fmt(L) + " m at T = " + TableReader::Fmt(w.period) + " s in " +
               TableReader::Fmt(w.depth) + " m of water, k h = " + TableReader::Fmt(k * w.depth) +
               "); expected a height of at most " + TableReader::Fmt(limit) +
               " m (H / L <= tanh(k h) / 7, Miche's limit; 1/7 in deep water)");
  r.Finish();
}

void ReadMaterials(TableReader& top, SceneDef& scene, bool elastic) {
  const toml::array* arr = top.TableArray("material", true);
  NameIndex names;
  for (size_t i = 0; i < arr->size(); ++i) {
    const std::string prefix = "material[" + std::to_string(i) + "]";
    TableReader r = top.Child(*arr->get(i)->as_table(), prefix);
    MaterialDef m;
    m.name = r.String("name", "", true);
    if (!names.emplace(m.name, static_cast<int>(i)).second)
      r.Fail(arr->get(i)->as_table()->get("name"), "name",
             "expected a unique name, " + Quote(m.name) + " is defined twice");
    m.diameter = r.Positive("diameter", " in m", kMinDiameter, kMaxDiameter);
    m.area = r.Positive("area", " in m^2", kMinArea, kMaxArea);
    m.mass_per_length =
        r.Positive("mass_per_length", " in kg/m", kMinMassPerLength, kMaxMassPerLength);
    const toml::table* t = arr->get(i)->as_table();
    if (t->contains("axial_stiffness")) {
      // EA itself [N] (MoorDyn's EA, a rope's catalogue figure): E = EA / area, the area still
      // setting the buoyancy.
      if (t->contains("youngs_modulus"))
        r.Fail(t->get("axial_stiffness"), "axial_stiffness",
               "expected either youngs_modulus (Pa) or axial_stiffness (N, E times area), not both");
      const double ea = r.Positive("axial_stiffness", " in N", kMinModulus * m.area,
                                   kMaxModulus * m.area);
      m.youngs_modulus = ea / m.area;
    } else if (elastic) {
      if (!t->contains("youngs_modulus"))
        r.Fail(nullptr, "youngs_modulus",
               "missing; expected youngs_modulus (Pa) or axial_stiffness (N, E times area)");
      m.youngs_modulus = r.Positive("youngs_modulus", " in Pa", kMinModulus, kMaxModulus);
    } else {
      m.youngs_modulus =
          r.OptionalPositive("youngs_modulus", 0.0, " in Pa", kMinModulus, kMaxModulus);
    }
    m.drag_coefficient = r.OptionalNonNegative("drag_coefficient", 1.2, "", kMaxCoefficient);
    m.added_mass_coefficient =
        r.OptionalNonNegative("added_mass_coefficient", 1.0, "", kMaxCoefficient);
    m.tangential_drag_coefficient =
        r.OptionalNonNegative("tangential_drag_coefficient", 0.0, "", kMaxCoefficient);
    m.tangential_added_mass_coefficient =
        r.OptionalNonNegative("tangential_added_mass_coefficient", 0.0, "", kMaxCoefficient);
    m.axial_froude_krylov = r.Bool("axial_froude_krylov", true);
    m.axial_damping = r.OptionalNonNegative("axial_damping", 0.0, " in Pa s", kMaxAxialDamping);
    m.axial_damping_ratio =
        r.OptionalNonNegative("axial_damping_ratio", 0.0, " (of critical)", kMaxDampingRatio);
    if (m.axial_damping > 0 && m.axial_damping_ratio > 0)
      r.Fail(arr->get(i)->as_table()->get("axial_damping_ratio"), "axial_damping_ratio",
             "expected either axial_damping (Pa s) or axial_damping_ratio, not both");
    m.moordyn_axial_damping_ratio = r.OptionalNonNegative(
        "moordyn_axial_damping_ratio", 0.0, " (MoorDyn's -BA)", kMaxDampingRatio);
    if (m.moordyn_axial_damping_ratio > 0 && (m.axial_damping > 0 || m.axial_damping_ratio > 0))
      r.Fail(arr->get(i)->as_table()->get("moordyn_axial_damping_ratio"),
             "moordyn_axial_damping_ratio",
             "expected one of axial_damping (Pa s), axial_damping_ratio and "
             "moordyn_axial_damping_ratio, not two");
    m.minimum_breaking_load = r.OptionalPositive("minimum_breaking_load", 0.0, " in N",
                                                 kMinBreakingLoad, kMaxBreakingLoad);
    r.Finish();
    scene.materials.push_back(m);
  }
}

// A suspended prism's own physics (a weight's, a free point's): mass (required when
// `mass_required`), volume, added volumes, drag coefficients and areas.
void ReadPrism(TableReader& w, double& mass, double& volume, std::array<double, 3>& added_volume,
               std::array<double, 3>& drag_coefficient, std::array<double, 3>& drag_area,
               bool mass_required = true) {
  mass = mass_required ? w.Positive("mass", " in kg", 0, kMaxWeightMass)
                       : w.OptionalNonNegative("mass", 0.0, " in kg", kMaxWeightMass);
  volume = w.OptionalNonNegative("volume", 0.0, " in m^3", kMaxVolume);
  // [x, y] or [x, y, z]: two values are the same across both horizontal axes.
  const auto horizontal_alike = TableReader::TwoValues::kZLikeX;
  added_volume =
      w.Triple("added_volume", {0, 0, 0}, false, true, " in m^3", kMaxVolume, horizontal_alike);
  drag_coefficient = w.Triple("drag_coefficient", {0, 0, 0}, false, true, "", kMaxCoefficient,
                              horizontal_alike);
  drag_area =
      w.Triple("drag_area", {0, 0, 0}, false, true, " in m^2", kMaxDragArea, horizontal_alike);
}

// The sections and weights of a line, from the reader `r` of its table (`name`: "cable" or
// "line[i]", as messages show it).
void ReadSections(TableReader& r, const std::string& name, const NameIndex& materials,
                  std::vector<SectionDef>& out_sections, std::vector<WeightDef>& out_weights) {
  const toml::array* sections = r.TableArray("section", true);
  if (sections->empty())
    r.Fail(nullptr, "section", "expected at least one [[" + name + ".section]]");
  for (size_t i = 0; i < sections->size(); ++i) {
    const std::string prefix = name + ".section[" + std::to_string(i) + "]";
    TableReader s = r.Child(*sections->get(i)->as_table(), prefix);
    SectionDef sec;
    const std::string material = s.String("material", "", true);
    sec.material = Find(materials, material);
    if (sec.material < 0)
      s.Fail(sections->get(i)->as_table()->get("material"), "material",
             "expected the name of a [[material]], no material is named " + Quote(material));
    sec.length = s.Positive("length", " in m", kMinSectionLength, kMaxLength);
    sec.segments = s.Integer("segments", 0, 1, static_cast<int>(kMaxLinks), true);
    s.Finish();
    out_sections.push_back(sec);
  }
  double total = 0, segment_length_min = 1e300, links = 0;
  for (size_t i = 0; i < out_sections.size(); ++i) {
    const SectionDef& sec = out_sections[i];
    total += sec.length;
    links += sec.segments;
    segment_length_min = std::min(segment_length_min, sec.length / sec.segments);
    // The whole cable's limits, named by the section that goes beyond them.
    const toml::table* section = sections->get(i)->as_table();
    const std::string prefix = "section[" + std::to_string(i) + "].";
    if (links > kMaxLinks)
      r.Fail(section->get("segments"), prefix + "segments",
             "the cable has " + TableReader::Fmt(links) + " links up to here; expected at most " +
                 TableReader::Fmt(kMaxLinks) + " in all");
    if (total > kMaxLength)
      r.Fail(section->get("length"), prefix + "length",
             "the cable is " + TableReader::Fmt(total) + " m long up to here; expected at most " +
                 TableReader::Fmt(kMaxLength) + " m in all");
  }
  const toml::array* weights = r.TableArray("weight", false);
  for (size_t i = 0; weights && i < weights->size(); ++i) {
    const std::string prefix = name + ".weight[" + std::to_string(i) + "]";
    const toml::table* wt = weights->get(i)->as_table();
    TableReader w = r.Child(*wt, prefix);
    WeightDef def;
    def.at = w.Required("at", "an arc length in m from station 0");
    // The station arc lengths, section by section.
    bool on_station = false;
    double start = 0;
    for (const SectionDef& sec : out_sections) {
      const double l = sec.length / sec.segments;
      const double k = std::round((def.at - start) / l);
      if (k >= 0 && k <= sec.segments && std::abs(def.at - start - k * l) <= 1e-6 * l)
        on_station = true;
      start += sec.length;
    }
    if (def.at < -1e-6 * segment_length_min || def.at > total * (1 + 1e-9) || !on_station)
      w.Fail(wt->get("at"), "at",
             "expected the arc length of a station (0 to " + TableReader::Fmt(total) +
                 " m, on a segment boundary), got " + TableReader::Fmt(def.at));
    ReadPrism(w, def.mass, def.volume, def.added_volume, def.drag_coefficient, def.drag_area);
    w.Finish();
    out_weights.push_back(def);
  }
}

// [cable]: the one line of its scene, from the point "start" to the point "end" ([ends]).
void ReadCable(TableReader& top, SceneDef& scene, CableModelKind model) {
  const toml::table* t = top.SubTable("cable", true);
  TableReader r = top.Child(*t, "cable");
  // The model is read first by the caller (materials depend on it); mark it used here.
  r.Get("model");
  LineDef line;
  line.name = line.key = "cable";
  line.model = model;
  line.start = 0;
  line.end = 1;
  ReadSections(r, "cable", IndexByName(scene.materials), line.sections, line.weights);
  r.Finish();
  scene.lines.push_back(line);
}

// motion = "wave": [ratio, phase in degrees], the ratio at most kMaxRao; `unit` the ratio's
// (m/m for an offset, deg/m for a body's angle).
std::array<double, 2> ReadRao(TableReader& r, const std::string& key,
                              const std::string& unit = "m/m") {
  const std::array<double, 2> rao = r.Pair(
      key, {0, 0}, false, false, " ([amplitude ratio in " + unit + ", phase in degrees])", kMaxRao);
  if (!(rao[0] >= 0) || !(std::abs(rao[1]) <= kMaxPhase))
    r.Fail(r.Get(key), key,
           "expected [amplitude ratio in " + unit + " from 0 to " + TableReader::Fmt(kMaxRao) +
               ", phase in degrees from " + TableReader::Fmt(-kMaxPhase) + " to " +
               TableReader::Fmt(kMaxPhase) + "], got [" + TableReader::Fmt(rao[0]) + ", " +
               TableReader::Fmt(rao[1]) + "]");
  return rao;
}

// The end's motion following the waves at its rest x, as eq. (3)'s trochoid: for each
// component a response r a cos(theta(x0, t) + p) with theta = k e . x0 - omega t + phase, which
// is r a (cos(beta) cos(omega t) + sin(beta) sin(omega t)), beta = k e . x0 + phase + p; r and
// p the RAO's at the component's frequency and heading (the end's table's, or its x_rao ...
// pairs at every frequency). The regular wave: one component, written as the trochoid's
// amplitudes; an irregular sea: one harmonic a component.
void FollowWave(const WavesDef& w, double gravity, EndDef& end) {
  const double deg = M_PI / 180.0;
  const std::array<double, 2>* pairs[6] = {&end.x_rao,  &end.y_rao,  &end.z_rao,
                                           &end.rx_rao, &end.ry_rao, &end.rz_rao};
  // The six responses [m or deg] to a component of amplitude a [m], frequency omega [rad/s]
  // and direction `heading` [rad], as (cos, sin) amplitudes: r a (cos(beta), sin(beta)),
  // beta(axis) its phase at the end's rest point with the RAO's phase added.
  using Responses = std::array<std::array<double, 2>, 6>;
  auto respond = [&](double a, double omega, double heading, auto beta) {
    Responses r{};
    if (end.rao_table) {
      r = RaoAt(*end.rao_table, omega, heading / deg);
    } else {
      for (int axis = 0; axis < 6; ++axis) r[axis] = *pairs[axis];
    }
    Responses out;
    for (int axis = 0; axis < 6; ++axis) {
      const double b = beta(r[axis][1]);
      out[axis] = {r[axis][0] * a * std::cos(b), r[axis][0] * a * std::sin(b)};
    }
    return out;
  };
  end.period = w.period;
  end.ramp_rate = w.ramp_rate;
  if (w.sea != SeaKind::kRegular) {  // one harmonic a component
    const SeaComponents& sea = *w.components_made;
    end.harmonics.clear();
    for (int i = 0; i < sea.size(); ++i) {
      const double along = sea.dir_x[i] * end.position[0] + sea.dir_z[i] * end.position[2];
      const Responses r =
          respond(sea.amplitude[i], sea.omega[i], std::atan2(sea.dir_z[i], sea.dir_x[i]),
                  [&](double p) { return sea.k[i] * along + sea.phase[i] + p * deg; });
      std::array<double, 13> h{};
      h[0] = sea.omega[i];
      for (int axis = 0; axis < 6; ++axis) {
        h[1 + 2 * axis] = r[axis][0];
        h[2 + 2 * axis] = r[axis][1];
      }
      end.harmonics.push_back(h);
    }
    return;
  }
  // The regular wave: its one component as the trochoid's amplitudes, the offsets [m] and a
  // body's angles [deg].
  const double omega = 2.0 * M_PI / w.period;
  const double k = WaveNumber(omega, gravity, w.depth);
  const Vec e = Horizontal(w.heading * deg);  // theta at the rest point: k e . x0
  const double along = e.x() * end.position[0] + e.z() * end.position[2];
  const Responses r = respond(0.5 * w.height, omega, w.heading * deg,
                              [&](double p) { return k * along + (w.phase + p) * deg; });
  std::array<double, 2>* amps[6] = {&end.x_amplitudes,  &end.y_amplitudes,  &end.z_amplitudes,
                                    &end.rx_amplitudes, &end.ry_amplitudes, &end.rz_amplitudes};
  for (int axis = 0; axis < 6; ++axis) *amps[axis] = r[axis];
}

// A motion table named by `key` ("file": a table motion's; "drift_file": the table added to a
// wave-following end's motion) into end.table_file, end.table and end.interpolation.
void ReadMotionFile(TableReader& r, const toml::table* t, EndDef& end, const std::string& file,
                    bool body, const char* key) {
  const std::string name = r.String(key, "", true);
  if (name.empty() || name.find('\0') != std::string::npos)
    r.Fail(t->get(key), key,
           std::string("expected the name of a CSV file t,x,y") +
               (body ? " (or t,x,y,z,rx,ry,rz)" : "") + ", got " + Quote(name));
  const std::filesystem::path base = std::filesystem::path(file).parent_path();
  end.table_file = (base / name).string();
  try {
    end.table = ReadMotionTable(end.table_file, body);
  } catch (const Error& e) {
    r.Fail(t->get(key), key, e.what());
  }
  end.interpolation = r.Choice("interpolation", "spline", {"spline", "linear"}) == "linear"
                          ? TableInterpolation::kLinear
                          : TableInterpolation::kSpline;
}

// An end's (or a point's, or a body's: `body`, whose angles may move too) position and motion
// from its table `t` read by `r`; returns the motion's name. The caller finishes the reader.
std::string ReadMotion(TableReader& r, const toml::table* t, EndDef& end, const std::string& file,
                       const SceneDef& scene, bool body = false) {
  end.position = r.Triple("position", {0, 0, 0}, true, false, " in m ([x, y] or [x, y, z])",
                          kMaxLength, TableReader::TwoValues::kZeroZ);
  const std::string motion =
      r.Choice("motion", "fixed", {"fixed", "free", "trochoid", "table", "wave"});
  if (motion == "wave") {
    if (!scene.waves.present)
      r.Fail(t->get("motion"), "motion",
             "motion = \"wave\" follows the waves: expected a [waves] table");
    end.motion = EndMotionKind::kTrochoid;
    end.follows_wave = true;
    if (r.Has("rao_file")) {
      for (const char* pair : {"x_rao", "y_rao", "z_rao", "rx_rao", "ry_rao", "rz_rao"})
        if (r.Has(pair))
          r.Fail(t->get(pair), pair,
                 std::string(pair) + " and rao_file both give the RAOs: expected one of them");
      const std::string name = r.String("rao_file", "", true);
      if (name.empty() || name.find('\0') != std::string::npos)
        r.Fail(t->get("rao_file"), "rao_file",
               "expected the name of a CSV file of RAOs, got " + Quote(name));
      end.rao_file = (std::filesystem::path(file).parent_path() / name).string();
      try {
        end.rao_table = std::make_shared<const RaoTable>(ReadRaoTable(end.rao_file, body));
      } catch (const Error& e) {
        r.Fail(t->get("rao_file"), "rao_file", e.what());
      }
    }
    end.x_rao = ReadRao(r, "x_rao");
    end.y_rao = ReadRao(r, "y_rao");
    end.z_rao = ReadRao(r, "z_rao");
    if (body) {
      end.rx_rao = ReadRao(r, "rx_rao", "deg/m");
      end.ry_rao = ReadRao(r, "ry_rao", "deg/m");
      end.rz_rao = ReadRao(r, "rz_rao", "deg/m");
    }
    FollowWave(scene.waves, scene.environment.gravity, end);
    if (r.Has("drift_file")) ReadMotionFile(r, t, end, file, body, "drift_file");
  }
  if (motion == "fixed") end.motion = EndMotionKind::kFixed;
  if (motion == "free") end.motion = EndMotionKind::kFree;
  if (motion == "trochoid") {
    end.motion = EndMotionKind::kTrochoid;
    end.x_amplitudes = r.Pair("x_amplitudes", {0, 0}, false, false, " in m", kMaxLength);
    end.y_amplitudes = r.Pair("y_amplitudes", {0, 0}, false, false, " in m", kMaxLength);
    end.z_amplitudes = r.Pair("z_amplitudes", {0, 0}, false, false, " in m", kMaxLength);
    if (body) {
      const std::string deg = " in degrees";
      end.rx_amplitudes = r.Pair("rx_amplitudes", {0, 0}, false, false, deg, kMaxPhase);
      end.ry_amplitudes = r.Pair("ry_amplitudes", {0, 0}, false, false, deg, kMaxPhase);
      end.rz_amplitudes = r.Pair("rz_amplitudes", {0, 0}, false, false, deg, kMaxPhase);
    }
    end.period = r.Positive("period", " in s", kMinPeriod, kMaxPeriod);
    end.ramp_rate = r.Positive("ramp_rate", " in 1/s", kMinRampRate, kMaxRampRate);
  }
  if (motion == "table") {
    end.motion = EndMotionKind::kTable;
    ReadMotionFile(r, t, end, file, body, "file");
  }
  return motion;
}

// [ends.start] or [ends.end]: the point `which` of a [cable] scene.
void ReadEnd(TableReader& ends, const std::string& which, const std::string& file,
             SceneDef& scene) {
  const toml::table* t = ends.SubTable(which, true);
  PointDef p;
  p.name = which;
  p.key = "ends." + which;
  p.label = which + " end";
  TableReader r = ends.Child(*t, p.key);
  const std::string motion = ReadMotion(r, t, p.motion, file, scene);
  r.Finish(" (motion = " + Quote(motion) + " uses only the keys it needs)");
  scene.points.push_back(p);
}

// A name of a point or a line: used in file names (lines/<name>/) and in points.csv.
std::string ReadName(TableReader& r, const toml::table* t) {
  const std::string name = r.String("name", "", true);
  const bool plain = !name.empty() && name.size() <= 64 && name != "." && name != ".." &&
                     std::all_of(name.begin(), name.end(), [](unsigned char c) {
                       return std::isalnum(c) || c == '_' || c == '-' || c == '.';
                     });
  if (!plain)
    r.Fail(t->get("name"), "name",
           "expected 1 to 64 letters, digits, '_', '-' or '.' (it names files), got " +
               Quote(name));
  return name;
}

// A point's, body's or line's name not yet taken by one of `earlier`, added to it as `index`.
void CheckUnique(TableReader& r, const toml::table* t, const std::string& name, int index,
                 NameIndex& earlier, const char* what) {
  if (!earlier.emplace(name, index).second)
    r.Fail(t->get("name"), "name", "expected a unique name, " + Quote(name) + " names two " + what);
}

// [[point]]: the points of a system.
void ReadPoints(TableReader& top, SceneDef& scene, const std::string& file) {
  const toml::array* arr = top.TableArray("point", true);
  const NameIndex bodies = IndexByName(scene.bodies);
  NameIndex names;
  for (size_t i = 0; i < arr->size(); ++i) {
    const toml::table* t = arr->get(i)->as_table();
    PointDef p;
    p.key = "point[" + std::to_string(i) + "]";
    TableReader r = top.Child(*t, p.key);
    p.name = ReadName(r, t);
    p.label = "point " + Quote(p.name);
    CheckUnique(r, t, p.name, static_cast<int>(i), names, "points");
    if (t->contains("body")) {  // fixed to a body: its position in the body's axes
      const std::string body = r.String("body", "", true);
      p.body = Find(bodies, body);
      if (p.body < 0)
        r.Fail(t->get("body"), "body", "expected the name of a [[body]], no body is named " +
                                           Quote(body));
      p.motion.position = r.Triple("position", {0, 0, 0}, true, false,
                                   " in m, in the body's axes ([x, y] or [x, y, z])", kMaxLength,
                                   TableReader::TwoValues::kZeroZ);
      r.Finish(" (a point on a body moves with it: it takes name, body and position)");
      scene.points.push_back(p);
      continue;
    }
    const std::string motion = ReadMotion(r, t, p.motion, file, scene);
    if (motion == "free") {
      ReadPrism(r, p.mass, p.volume, p.added_volume, p.drag_coefficient, p.drag_area, false);
      p.force = r.Triple("force", {0, 0, 0}, false, false, " in N", kMaxTension,
                         TableReader::TwoValues::kZeroZ);
    }
    r.Finish(" (motion = " + Quote(motion) + " uses only the keys it needs)");
    scene.points.push_back(p);
  }
}

// Six numbers per degree of freedom of a body (x, y, z, about x, y, z), each >= 0 when
// `non_negative`, within `limit`.
std::array<double, 6> ReadSix(TableReader& r, const std::string& key, bool non_negative,
                              const std::string& units, double limit) {
  std::array<double, 6> out{};
  const toml::node* n = r.Get(key);
  if (!n) return out;
  const std::string what = "an array of six " +
                           std::string(non_negative ? "numbers >= 0" : "numbers") + " (x, y, z, "
                           "about x, y, z) " + units + " up to " + TableReader::Fmt(limit);
  const toml::array* a = n->as_array();
  if (!a || a->size() != 6) r.Fail(n, key, "expected " + what);
  for (size_t i = 0; i < 6; ++i) {
    out[i] = r.Number(key, a->get(i), what);
    if (!(std::abs(out[i]) <= limit) || (non_negative && out[i] < 0))
      r.Fail(n, key, "expected " + what + ", got " + TableReader::Fmt(out[i]));
  }
  return out;
}

// Exactly three numbers (along x, y, z), each within [0, limit] (non_negative) or
// [-limit, limit]; `fallback` when the key is absent.
std::array<double, 3> ReadThree(TableReader& r, const std::string& key,
                                std::array<double, 3> fallback, bool non_negative,
                                const std::string& units, double limit) {
  const toml::node* n = r.Get(key);
  if (!n) return fallback;
  const std::string what = "an array of three " +
                           std::string(non_negative ? "numbers >= 0" : "numbers") + " " + units +
                           " up to " + TableReader::Fmt(limit);
  const toml::array* a = n->as_array();
  if (!a || a->size() != 3) r.Fail(n, key, "expected " + what);
  std::array<double, 3> out{};
  for (size_t i = 0; i < 3; ++i) {
    out[i] = r.Number(key, a->get(i), what);
    if (!(std::abs(out[i]) <= limit) || (non_negative && out[i] < 0))
      r.Fail(n, key, "expected " + what + ", got " + TableReader::Fmt(out[i]));
  }
  return out;
}

// [[body]]: the rigid bodies of a system.
void ReadBodies(TableReader& top, SceneDef& scene, const std::string& file) {
  const toml::array* arr = top.TableArray("body", false);
  NameIndex names;
  for (size_t i = 0; arr && i < arr->size(); ++i) {
    const toml::table* t = arr->get(i)->as_table();
    TableReader r = top.Child(*t, "body[" + std::to_string(i) + "]");
    BodyDef b;
    b.name = ReadName(r, t);
    CheckUnique(r, t, b.name, static_cast<int>(i), names, "bodies");
    const std::string motion = ReadMotion(r, t, b.motion, file, scene, true);
    b.free = motion == "free";
    b.orientation = r.Triple("orientation", {0, 0, 0}, false, false,
                             " in degrees, about x, y and z", kMaxPhase,
                             TableReader::TwoValues::kZeroZ);
    b.has_box = t->contains("box");  // drawn only, whatever its motion
    b.box = ReadThree(r, "box", {0, 0, 0}, true,
                      "(length along x, height along y, width along z, in m)", kMaxBodyBox);
    b.box_center = ReadThree(r, "box_center", {0, 0, 0}, false,
                             "(x, y, z in m, in the body's axes from its reference point)",
                             kMaxLength);
    if (b.free) {
      b.mass = r.OptionalNonNegative("mass", 0.0, " in kg", kMaxBodyMass);
      b.center_of_gravity = r.Triple("center_of_gravity", {0, 0, 0}, false, false,
                                     " in m, in the body's axes", kMaxLength,
                                     TableReader::TwoValues::kZeroZ);
      b.volume = r.OptionalNonNegative("volume", 0.0, " in m^3", kMaxBodyVolume);
      b.center_of_buoyancy = r.Triple("center_of_buoyancy", {0, 0, 0}, false, false,
                                      " in m, in the body's axes", kMaxLength,
                                      TableReader::TwoValues::kZeroZ);
      b.waterplane_area = r.OptionalNonNegative("waterplane_area", 0.0, " in m^2", kMaxArea2D);
      b.waterplane_inertia = r.Pair("waterplane_inertia", {0, 0}, false, true,
                                    " in m^4, about the body's x and z axes", kMaxWaterplaneInertia);
      b.force = r.Triple("force", {0, 0, 0}, false, false, " in N", kMaxTension,
                         TableReader::TwoValues::kZeroZ);
      b.moment = r.Triple("moment", {0, 0, 0}, false, false, " in N m", kMaxTension,
                          TableReader::TwoValues::kZeroZ);
      b.inertia = r.Triple("inertia", {0, 0, 0}, false, true,
                           " in kg m^2, about its centre of gravity along its x, y, z axes",
                           kMaxBodyInertia, TableReader::TwoValues::kZLikeX);
      b.added_mass = ReadSix(r, "added_mass", true, "in kg and kg m^2", kMaxBodyInertia);
      b.linear_damping =
          ReadSix(r, "linear_damping", true, "in N s/m and N m s", kMaxBodyInertia);
      b.quadratic_damping =
          ReadSix(r, "quadratic_damping", true, "in N s^2/m^2 and N m s^2", kMaxBodyInertia);
      b.initial_offset =
          ReadSix(r, "initial_offset", false, "in m and degrees", kMaxPhase);
    }
    r.Finish(" (motion = " + Quote(motion) + " uses only the keys it needs)");
    scene.bodies.push_back(b);
  }
}

// [[line]]: the lines of a system, each between two [[point]]s.
void ReadLines(TableReader& top, SceneDef& scene) {
  const toml::array* arr = top.TableArray("line", true);
  const NameIndex points = IndexByName(scene.points), materials = IndexByName(scene.materials);
  NameIndex names;
  for (size_t i = 0; i < arr->size(); ++i) {
    const toml::table* t = arr->get(i)->as_table();
    const std::string name = "line[" + std::to_string(i) + "]";
    TableReader r = top.Child(*t, name);
    LineDef line;
    line.key = name;
    line.name = ReadName(r, t);
    CheckUnique(r, t, line.name, static_cast<int>(i), names, "lines");
    // An inextensible line between points that hold it (the coupled step is the elastic
    // lines': the model refuses one joined to others, naming it).
    line.model = r.Choice("model", "elastic", {"elastic", "inextensible"}) == "inextensible"
                     ? CableModelKind::kInextensible
                     : CableModelKind::kElastic;
    for (const char* key : {"start", "end"}) {
      const std::string point = r.String(key, "", true);
      const int index = Find(points, point);
      if (index < 0)
        r.Fail(t->get(key), key, "expected the name of a [[point]], no point is named " +
                                     Quote(point));
      (std::string(key) == "start" ? line.start : line.end) = index;
    }
    // A line from a point back to itself has no chord to hang along (its statics' motion took
    // a fuzzed one through seconds of steps a millisecond long).
    if (line.start == line.end)
      r.Fail(t->get("end"), "end",
             "expected another point than its start, " + Quote(scene.points[line.start].name) +
                 ": a line runs between two points");
    ReadSections(r, name, materials, line.sections, line.weights);
    if (const std::string far = LineReachProblem(line, scene); !far.empty())
      r.Fail(t->get("end"), "end", far);
    r.Finish();
    scene.lines.push_back(line);
  }
}

}  // namespace

SceneDef ParseScene(const std::string& text, const std::string& file, KeyLog* keys) {
  const toml::table root = ParseToml(text, file);
  SceneDef scene;
  scene.path = file;
  scene.name = std::filesystem::path(file).stem().string();
  TableReader top(root, file, keys);
  scene.title = top.String("title", scene.name, false);
  if (const toml::node* title = root.get("title")) {
    std::size_t characters = 0;  // UTF-8 lead bytes
    for (const unsigned char c : scene.title) characters += (c & 0xC0) != 0x80;
    if (characters > kMaxTitleLength)
      top.Fail(title, "title",
               "expected a title of at most " + std::to_string(kMaxTitleLength) +
                   " characters (it is drawn on one line of the film), got " +
                   std::to_string(characters));
  }
  ReadEnvironment(top, scene, file);
  ReadSeabed(top, scene);
  ReadWaves(top, scene, file);

  bool elastic = true;
  if (const toml::table* cable = root.get_as<toml::table>("cable")) {
    TableReader r = top.Child(*cable, "cable");
    const std::string model = r.Choice("model", "elastic", {"elastic", "inextensible"});
    elastic = model == "elastic";
  }
  ReadMaterials(top, scene, elastic);
  if (root.contains("line") || root.contains("point") || root.contains("body")) {
    // A system: [[point]] and [[line]] in place of [cable] and [ends].
    for (const char* single : {"cable", "ends"})
      if (const toml::node* n = root.get(single))
        top.Fail(n, single,
                 "a scene is either one line ([cable] and [ends]) or a system ([[line]] and "
                 "[[point]]); this one has both");
    ReadBodies(top, scene, file);
    ReadPoints(top, scene, file);
    ReadLines(top, scene);
  } else {
    ReadCable(top, scene, elastic ? CableModelKind::kElastic : CableModelKind::kInextensible);
    const toml::table* ends = top.SubTable("ends", true);
    TableReader r = top.Child(*ends, "ends");
    ReadEnd(r, "start", file, scene);
    ReadEnd(r, "end", file, scene);
    if (scene.points[0].motion.motion == EndMotionKind::kFree &&
        scene.points[1].motion.motion == EndMotionKind::kFree)
      r.Fail(ends, "end.motion",
             "expected at least one end that is not \"free\" (a cable with two free ends has no "
             "equilibrium)");
    if (const std::string far = LineReachProblem(scene.lines[0], scene); !far.empty())
      r.Fail(ends->get("end")->as_table()->get("position"), "end.position", far);
    r.Finish();
  }
  if (const toml::table* t = top.SubTable("initial", false)) {
    TableReader r = top.Child(*t, "initial");
    scene.initial = r.Choice("state", "equilibrium", {"equilibrium", "straight"}) == "straight"
                        ? InitialStateKind::kStraight
                        : InitialStateKind::kEquilibrium;
    r.Finish();
  }
  if (const toml::table* t = top.SubTable("simulation", false)) {
    TableReader r = top.Child(*t, "simulation");
    scene.simulation.duration =
        r.OptionalPositive("duration", 60.0, " of seconds", 0, kMaxTime);
    if (const toml::node* n = r.Get("time_step")) {
      if (n->is_string()) {
        if (n->value<std::string>().value() != "auto")
          r.Fail(n, "time_step", "expected \"auto\" or a positive number of seconds");
      } else {
        scene.simulation.time_step = r.Number("time_step", n, "\"auto\" or a positive number of seconds");
        if (!(scene.simulation.time_step > 0))
          r.Fail(n, "time_step", "expected \"auto\" or a positive number of seconds");
      }
    }
    scene.simulation.tolerance =
        r.OptionalPositive("tolerance", 0.0, " in m (local error per step)", 0, kMaxLength);
    scene.simulation.start_tolerance = r.OptionalPositive(
        "start_tolerance", 0.0, " in m (local error per step while the motion starts)", 0,
        kMaxLength);
    if (const toml::node* n = r.Get("start_duration")) {
      constexpr const char* kExpected = "\"auto\" or a number of seconds from 0 to 1e9";
      if (n->is_string()) {
        if (n->value<std::string>().value() != "auto")
          r.Fail(n, "start_duration", std::string("expected ") + kExpected + ", got " +
                                          Quote(n->value<std::string>().value()));
      } else {
        const double s = r.Number("start_duration", n, kExpected);
        if (!(s >= 0 && s <= kMaxTime))
          r.Fail(n, "start_duration", std::string("expected ") + kExpected + ", got " + TableReader::Fmt(s));
        scene.simulation.start_duration = s;
      }
    }
    scene.simulation.safety_factor = r.OptionalPositive(
        "safety_factor", 0.8, " (fraction of the stability limit)", 0, 1.0);
    scene.simulation.integrator =
        r.Choice("integrator", "implicit", {"explicit", "implicit"}) == "explicit"
            ? IntegratorChoice::kExplicit
            : IntegratorChoice::kImplicit;
    scene.simulation.rho_infinity = r.Ranged("rho_infinity", 0.5, false, 0.0, 1.0, "");
    scene.simulation.explicit_snaps =
        r.Choice("snap_steps", "explicit", {"explicit", "implicit"}) == "explicit";
    r.Finish();
  }
  if (const toml::table* t = top.SubTable("film", false)) {
    TableReader r = top.Child(*t, "film");
    FilmDef& f = scene.film;
    f.width = r.Integer("width", f.width, kMinFilmSize, kMaxFilmWidth, false);
    f.height = r.Integer("height", f.height, kMinFilmSize, kMaxFilmHeight, false);
    if (f.width % 2) r.Fail(t->get("width"), "width", "expected an even number of pixels");
    if (f.height % 2) r.Fail(t->get("height"), "height", "expected an even number of pixels");
    f.fps = r.Ranged("fps", f.fps, false, kMinFps, kMaxFps, " of frames per second");
    f.speed = r.OptionalPositive("speed", f.speed, " (simulated seconds per second of film)", 0,
                                 kMaxTime);
    f.crf = r.Integer("crf", f.crf, 0, 51, false);
    f.colormap = r.Choice("colormap", f.colormap, ColormapNames());
    f.view = r.Choice("view", f.view, FilmViewNames());
    if (r.Has("tension_range")) {
      const auto range = r.Pair("tension_range", {0, 0}, true, true, " in N", kMaxTension);
      if (!(range[1] > range[0]))
        r.Fail(t->get("tension_range"), "tension_range", "expected [min, max] with max > min");
      f.tension_min = range[0];
      f.tension_max = range[1];
    }
    // "peak:60" or "whole", or [T0, T1]; its fit to the run is checked where a film is made.
    if (r.Has("window") && t->get("window")->is_array()) {
      const auto span = r.Pair("window", {0, 0}, true, true, " of seconds", kMaxTime);
      if (!(span[1] > span[0]))
        r.Fail(t->get("window"), "window", "expected [T0, T1] with T1 > T0, in seconds");
      f.window.start = span[0];
      f.window.end = span[1];
    } else if (r.Has("window")) {
      const toml::node* n = r.Get("window");
      const std::string text = n->is_string() ? n->value<std::string>().value() : "";
      const std::string problem = FilmWindowProblem(text, &f.window);
      if (!n->is_string() || !problem.empty())
        r.Fail(n, "window",
               "expected \"peak:SECONDS\" (the film of that many seconds around the run's "
               "peak), [T0, T1] or \"T0,T1\" (from T0 to T1 seconds) or \"whole\"" +
                   (n->is_string() ? ", got " + QuoteText(text) : std::string()));
    }
    r.Finish();
  }
  if (const toml::table* t = top.SubTable("output", false)) {
    TableReader r = top.Child(*t, "output");
    scene.output.interval = r.OptionalPositive("interval", 0.0, " of seconds", 0, kMaxTime);
    scene.output.film = r.Bool("film", true);
    scene.output.frames = r.Bool("frames", false);
    r.Finish();
  }
  const bool interval_given = scene.output.interval > 0;
  if (!interval_given) scene.output.interval = scene.film.speed / scene.film.fps;
  top.Finish();
  CheckSeabed(root, scene, file);
  CheckRunCounts(root, scene, file, interval_given);
  CheckStaticsSize(root, scene, file);
  return scene;
}

}  // namespace cablefilm
