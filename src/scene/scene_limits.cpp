#include "scene/scene_limits.h"

#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/error.h"
#include "core/stability.h"
#include "scene/key_source.h"
#include "scene/text_escape.h"

namespace cablefilm {

const std::vector<std::string>& ColormapNames() {
  static const std::vector<std::string> names{"viridis", "cividis", "magma", "inferno", "plasma"};
  return names;
}

std::string FormatNumber(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  std::string s = buf;
  const std::size_t e = s.find('e');
  if (e == std::string::npos) return s;
  std::string exponent = s.substr(e + 1);
  const bool negative = !exponent.empty() && exponent[0] == '-';
  if (!exponent.empty() && (exponent[0] == '+' || exponent[0] == '-')) exponent.erase(0, 1);
  while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
  return s.substr(0, e) + "e" + (negative ? "-" : "") + exponent;
}

double RunSpan(double duration, double interval) {
  // As ChooseTimeGrid counts the outputs (floor with the same slack), without the cast.
  return std::floor(duration / interval + 1e-9) * interval;
}

std::string FilmFramesProblem(double span, double fps, double speed) {
  // As RenderFilm counts its frames: whole frame intervals (speed / fps) within the span.
  const double frames = std::floor(span / (speed / fps) + 1e-9);
  if (frames >= 1 && frames <= kMaxFilmFrames) return "";
  const double hours = kMaxFilmFrames / fps / 3600.0;
  std::string why = FormatNumber(span) + " s simulated at " + FormatNumber(fps) +
                    " frames per second of film and " + FormatNumber(speed) +
                    " simulated seconds per second of film make ";
  why += std::isfinite(frames) ? FormatNumber(frames) + " frames" : "too many frames";
  why += "; expected 1 to " + FormatNumber(kMaxFilmFrames) + " frames (a film of at most " +
         FormatNumber(std::round(hours * 10) / 10) + " h at this frame rate)";
  const double fastest = span * fps, slowest = span * fps / kMaxFilmFrames;
  if (std::isfinite(fastest) && fastest > 0)
    why += ": a speed from " + FormatNumber(slowest) + " to " + FormatNumber(fastest);
  return why;
}

void CheckModelLimits(const SceneDef& scene, const Model& model) {
  auto fail = [&](const std::string& key, const std::string& message) {
    throw Error(KeyPlace(scene, key) + ": " + message);
  };
  for (std::size_t i = 0; i < model.lines.size(); ++i) {
    const LineModel& m = model.lines[i];
    // The key of the line's end point's position, as the scene names it.
    const int end = model.line_points[i][1];
    const std::string key = (end < static_cast<int>(scene.points.size())
                                 ? scene.points[end].key
                                 : "line[" + std::to_string(i) + "].end") + ".position";
    const std::string cable = model.lines.size() > 1 ? "line \"" + model.line_names[i] + "\"" : "cable";
    if (m.ends.start.prescribed() && m.ends.end.prescribed()) {
      const double chord = (m.ends.end.Position(0) - m.ends.start.Position(0)).norm();
      const double length = m.line.total_length();
      // The same comparison as the inextensible equilibrium (chord >= length fails there).
      if (m.line.law == LinkLaw::kInextensible && chord >= length)
        fail(key, "expected the ends less than the inextensible " + cable + "'s length (" +
                      FormatNumber(length) + " m) apart at t = 0, they are " +
                      FormatNumber(chord) + " m apart (an inextensible cable cannot reach)");
      if (m.line.law == LinkLaw::kElastic && chord > length) {
        // The most stretched link at t = 0: a straight start stretches every link alike; the
        // equilibrium shares one tension, stretching the most compliant link most.
        double stretch = chord / length;
        if (scene.initial == InitialStateKind::kEquilibrium) {
          const double compliance =
              (m.line.rest_length.array() / m.line.axial_stiffness.array()).sum();
          const double tension = (chord - length) / compliance;
          stretch = 1.0 + tension / m.line.axial_stiffness.minCoeff();
        }
        if (!(stretch <= kMaxStartStretch))
          fail(key, "the ends are " + FormatNumber(chord) + " m apart at t = 0, which stretches the " +
                        FormatNumber(length) + " m " + cable + "'s links up to " +
                        FormatNumber(stretch) + " times their rest length; expected at most " +
                        FormatNumber(kMaxStartStretch) +
                        " times (beyond it Hooke's law has no meaning and the run stops as a "
                        "numerical blow-up): bring the ends closer or lengthen the cable");
      }
    }
    const SimulationDef& sim = scene.simulation;
    if (m.line.law == LinkLaw::kElastic && sim.integrator == IntegratorChoice::kExplicit &&
        sim.time_step <= 0) {
      const StabilityLimit limit = ComputeStabilityLimit(m);
      const double dt = sim.safety_factor * limit.time_step;
      const double steps = RunSpan(sim.duration, scene.output.interval) / dt;
      if (!(steps <= kMaxSteps))
        fail("simulation.time_step",
             "\"auto\" with integrator = \"explicit\" is " + FormatNumber(sim.safety_factor) +
                 " x the stability limit of the stiffest link, " + FormatNumber(dt) +
                 " s, which makes " + FormatNumber(steps) + " steps of the " +
                 FormatNumber(sim.duration) + " s run; expected at most " +
                 FormatNumber(kMaxSteps) +
                 " steps (use integrator = \"implicit\", fewer segments or a shorter duration)");
    }
  }
}

}  // namespace cablefilm
