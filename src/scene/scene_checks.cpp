#include "scene/scene_checks.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "core/error.h"
#include "core/line_equilibrium.h"
#include "scene/scene_limits.h"
#include "scene/text_escape.h"

namespace cablefilm {

// A prescribed end's lowest elevation over its motion [m]: its rest position less the
// trochoid's largest vertical excursion (the ramp R(t) <= 1), plus the table's lowest offset (at
// its rows: a table motion's, or the drift added to a wave-following end's).
namespace {

double LowestElevation(const EndDef& e) {
  double y = e.position[1];
  if (e.motion == EndMotionKind::kTrochoid) y -= std::hypot(e.y_amplitudes[0], e.y_amplitudes[1]);
  if (!e.table.empty()) {  // a table motion's rows, or a wave-following end's drift
    double lowest = e.table.front()[2];
    for (const auto& row : e.table) lowest = std::min(lowest, row[2]);
    y += lowest;
  }
  return y;
}

}  // namespace

// The seabed must not be above a prescribed end (an anchor in the bed, a fairlead dipping into
// it): an error naming seabed.y.
void CheckSeabed(const toml::table& root, const SceneDef& scene, const std::string& file) {
  if (!scene.seabed.present) return;
  // The points where lines end: (name, its key, its motion).
  std::vector<std::tuple<std::string, std::string, const EndDef*>> ends;
  for (const PointDef& p : scene.points)
    if (p.body < 0)  // a body's point is in its axes
      ends.emplace_back(p.label, p.key, &p.motion);
  for (const auto& [name, key, end] : ends) {
    if (end->motion == EndMotionKind::kFree) continue;
    const double lowest = LowestElevation(*end);
    if (!(lowest < scene.seabed.y)) continue;
    std::ostringstream os;
    os << EscapeText(file) << ":";
    if (const toml::node* n = root.at_path("seabed.y").node()) os << n->source().begin.line << ":";
    os << " seabed.y: the seabed at y = " << FormatNumber(scene.seabed.y)
       << " m is above the " << name << " (" << key << ".position y = "
       << FormatNumber(end->position[1]) << " m";
    if (lowest != end->position[1]) os << ", down to " << FormatNumber(lowest) << " m as it moves";
    os << "); expected a seabed at or below the cable's prescribed ends";
    throw Error(os.str());
  }
}

// A line whose statics take more than their bound at the least (kLeastStaticPasses over its
// stations; the inextensible model's two solves twice that) is refused here, before its model
// and the statics' workspaces are made (10^7 links: 3.5 GB and some 5 s before the statics
// gave up), naming its longest section's segments.
void CheckStaticsSize(const toml::table& root, const SceneDef& scene, const std::string& file) {
  if (scene.initial != InitialStateKind::kEquilibrium) return;
  for (const LineDef& line : scene.lines) {
    double links = 0;
    std::size_t longest = 0;
    for (std::size_t i = 0; i < line.sections.size(); ++i) {
      links += line.sections[i].segments;
      if (line.sections[i].segments > line.sections[longest].segments) longest = i;
    }
    const double solves = line.model == CableModelKind::kInextensible ? 2.0 : 1.0;
    const double least = solves * kLeastStaticPasses * (links + 1);
    if (line.sections.empty() || !(least > kMostLineStaticsWork)) continue;
    const double most = std::floor(kMostLineStaticsWork / (solves * kLeastStaticPasses)) - 1;
    const std::string key = line.key + ".section[" + std::to_string(longest) + "].segments";
    std::ostringstream os;
    os << EscapeText(file) << ":";
    if (const toml::node* n = root.at_path(key).node()) os << n->source().begin.line << ":";
    os << " " << key << ": the static equilibrium of " << (line.key == "cable" ? "the cable" : "line \"" + line.name + "\"")
       << " (" << static_cast<long long>(links) << " links), the initial state, takes some "
       << FormatNumber(least) << " station-passes at the least (" << FormatNumber(kLeastStaticPasses)
       << " passes over its " << static_cast<long long>(links) + 1 << " stations"
       << (solves > 1 ? ", twice for the inextensible model" : "") << "), more than the statics' bound of "
       << FormatNumber(kMostLineStaticsWork) << " (some 5 s); expected at most "
       << static_cast<long long>(most)
       << " links in all for an equilibrium start: fewer segments, or [initial] state = \"straight\"";
    throw Error(os.str());
  }
}

// The limits that involve several keys: output rows and fixed time steps, each named by the key
// most likely at fault (the one given, when the other took its default). The film's frames are
// the film's (ResolveFilm, film_settings.h): a run without its film does not count them.
void CheckRunCounts(const toml::table& root, const SceneDef& scene, const std::string& file,
                    bool interval_given) {
  auto node = [&](const char* path) { return root.at_path(path).node(); };
  auto fail = [&](const char* key, const std::string& message) {
    std::ostringstream os;
    os << EscapeText(file) << ":";
    if (const toml::node* n = node(key)) os << n->source().begin.line << ":";
    os << " " << key << ": " << message;
    throw Error(os.str());
  };
  const SimulationDef& sim = scene.simulation;
  const double interval = scene.output.interval;
  const std::string interval_text =
      FormatNumber(interval) + " s (" +
      (interval_given ? "output.interval"
                      : "output.interval not given: film.speed / film.fps, a row per film frame") +
      ")";
  const char* interval_key = interval_given      ? "output.interval"
                             : node("film.speed") ? "film.speed"
                             : node("film.fps")   ? "film.fps"
                                                  : "simulation.duration";
  const double rows = std::floor(sim.duration / interval + 1e-9);
  if (!(rows >= 1))
    fail(node("simulation.duration") ? "simulation.duration" : interval_key,
         "the duration " + FormatNumber(sim.duration) + " s is shorter than one output interval, " +
             interval_text +
             ": the run would write no row after t = 0 and simulate nothing; expected a "
             "duration of at least one output interval");
  if (!(rows <= kMaxOutputRows))
    fail(interval_key,
         "the duration " + FormatNumber(sim.duration) + " s at one row every " + interval_text +
             " makes " + FormatNumber(rows) + " rows of timeseries.csv; expected at most " +
             FormatNumber(kMaxOutputRows) + " rows (about 1 GB): an interval of at least " +
             FormatNumber(sim.duration / kMaxOutputRows) + " s or a shorter duration");
  const double span = RunSpan(sim.duration, interval);
  if (sim.time_step > 0 && !(span / sim.time_step <= kMaxSteps))
    fail("simulation.time_step",
         FormatNumber(sim.time_step) + " s makes " + FormatNumber(span / sim.time_step) +
             " steps of the " + FormatNumber(span) + " s run; expected at most " +
             FormatNumber(kMaxSteps) + " steps: a time step of at least " +
             FormatNumber(span / kMaxSteps) + " s (or \"auto\")");
}

// scene-format.md: ends further apart than the cable can reach are an error for an
// inextensible line (an elastic one starts stretched: the run warns and solves, up to
// kMaxStartStretch, which CheckModelLimits checks on the built model). The comparison is the
// run's: ends exactly the cable's length apart are refused too.
std::string LineReachProblem(const LineDef& line, const SceneDef& scene) {
  if (line.model != CableModelKind::kInextensible) return "";
  const PointDef &a = scene.points.at(line.start), &b = scene.points.at(line.end);
  for (const PointDef* p : {&a, &b})
    if (p->motion.motion == EndMotionKind::kFree || p->body >= 0) return "";
  double total = 0;
  for (const SectionDef& sec : line.sections) total += sec.length;
  const std::array<double, 3>&pa = a.motion.position, &pb = b.motion.position;
  const double chord = std::hypot(pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]);
  if (chord < total) return "";
  return "expected the ends less than the cable's length (" + FormatNumber(total) +
         " m) apart for an inextensible cable, they are " + FormatNumber(chord) + " m apart";
}

}  // namespace cablefilm
