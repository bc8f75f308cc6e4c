#include "scene/film_settings.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "scene/film_view.h"
#include "scene/option_values.h"
#include "scene/scene_limits.h"
#include "scene/text_escape.h"

namespace cablefilm {

const FilmKeyNames kCommandLineNames{"--size",     "--fps",           "--speed",
                                     "--colormap", "--tension-range", "--view",
                                     "--film-window"};
const FilmKeyNames kPythonNames{"width", "fps",  "speed", "colormap", "tension_range",
                                "view",  "window"};

std::string FilmSizeProblem(int width, int height) {
  auto bad = [](int v, int hi) { return v < kMinFilmSize || v > hi || v % 2 != 0; };
  if (!bad(width, kMaxFilmWidth) && !bad(height, kMaxFilmHeight)) return "";
  return "expected an even number of pixels, " + std::to_string(kMinFilmSize) + "x" +
         std::to_string(kMinFilmSize) + " to " + std::to_string(kMaxFilmWidth) + "x" +
         std::to_string(kMaxFilmHeight) + ", got " + std::to_string(width) + "x" +
         std::to_string(height);
}

std::string FpsProblem(double fps) {
  if (fps >= kMinFps && fps <= kMaxFps) return "";
  return "expected a number from " + FormatNumber(kMinFps) + " to " + FormatNumber(kMaxFps) +
         " frames per second, got " + FormatNumber(fps);
}

std::string SpeedProblem(double speed) {
  if (speed > 0 && speed <= kMaxTime) return "";
  return "expected a number above 0 to " + FormatNumber(kMaxTime) +
         " simulated seconds per second of film, got " + FormatNumber(speed);
}

std::string ColormapProblem(const std::string& name) {
  const std::vector<std::string>& names = ColormapNames();
  if (std::find(names.begin(), names.end(), name) != names.end()) return "";
  std::string known;
  for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
  return "expected one of " + known + ", got " + QuoteText(name);
}

std::string TensionRangeProblem(double lo, double hi) {
  if (lo >= 0 && hi > lo && hi <= kMaxTension) return "";
  return "expected MIN,MAX in N with " + FormatNumber(kMaxTension) +
         " >= MAX > MIN >= 0, got " + FormatNumber(lo) + "," + FormatNumber(hi);
}

std::string ViewProblem(const std::string& view) {
  const std::vector<std::string>& names = FilmViewNames();
  if (std::find(names.begin(), names.end(), view) != names.end()) return "";
  std::string known;
  for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
  return "expected one of " + known + ", got " + QuoteText(view);
}

std::string FilmWindowProblem(const std::string& text, FilmWindow* window) {
  const std::string expected =
      "expected peak:SECONDS (the film of that many seconds around the run's peak), T0,T1 (from "
      "T0 to T1 seconds) or whole, got " + QuoteText(text);
  FilmWindow w;
  if (text == "whole") {
    *window = w;
    return "";
  }
  if (text.rfind("peak:", 0) == 0) {
    if (!ParseDouble(text.substr(5), &w.peak_width) || !(w.peak_width > 0) ||
        w.peak_width > kMaxTime)
      return expected;
    *window = w;
    return "";
  }
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos || !ParseDouble(text.substr(0, comma), &w.start) ||
      !ParseDouble(text.substr(comma + 1), &w.end) || !(w.start >= 0) || !(w.end > w.start) ||
      w.end > kMaxTime)
    return expected;
  *window = w;
  return "";
}

std::string FilmWindowFitProblem(const FilmWindow& w, double span) {
  if (w.whole() || w.peak_width > 0) return "";
  if (w.start >= 0 && w.end > w.start && w.end <= span * (1 + 1e-9)) return "";
  return "expected a window within the run, from 0 to " + FormatNumber(span) + " s, got " +
         FormatNumber(w.start) + " to " + FormatNumber(w.end) + " s";
}

double FilmWindowLength(const FilmWindow& w, double span, double interval) {
  if (w.peak_width > 0) return std::min(2 * std::round(0.5 * w.peak_width / interval) * interval, span);
  if (w.end < 0) return span;
  const double first = std::floor(w.start / interval + 1e-9) * interval;
  const double last = std::ceil(w.end / interval - 1e-9) * interval;
  return std::min(last, span) - std::min(first, span);
}

FilmSettings ResolveFilm(const SceneDef& scene, const FilmOverrides& o,
                         const FilmKeyNames& names, bool whole_film) {
  auto check = [](const std::string& key, const std::string& problem) {
    if (!problem.empty()) throw Error(key + ": " + problem);
  };
  FilmSettings s;
  s.look = scene.film;
  s.frames = o.frames >= 0 ? o.frames == 1 : scene.output.frames;
  if (o.width > 0 || o.height > 0) {
    const int w = o.width > 0 ? o.width : s.look.width, h = o.height > 0 ? o.height : s.look.height;
    check(names.size, FilmSizeProblem(w, h));
    s.look.width = w;
    s.look.height = h;
  }
  if (o.fps > 0) check(names.fps, FpsProblem(s.look.fps = o.fps));
  if (o.speed > 0) check(names.speed, SpeedProblem(s.look.speed = o.speed));
  if (!o.colormap.empty()) check(names.colormap, ColormapProblem(s.look.colormap = o.colormap));
  if (!o.view.empty()) check(names.view, ViewProblem(s.look.view = o.view));
  if (o.tension_min >= 0 || o.tension_max >= 0) {
    check(names.tension_range, TensionRangeProblem(o.tension_min, o.tension_max));
    s.look.tension_min = o.tension_min;
    s.look.tension_max = o.tension_max;
  }
  if (o.window_given) s.look.window = o.window;
  if (!whole_film) return s;
  // The window must fit the run and the film have from 1 to kMaxFilmFrames frames: counted
  // here, not by the loader, so that a run without its film is not refused for it.
  const double span = RunSpan(scene.simulation.duration, scene.output.interval);
  const std::string misfit = FilmWindowFitProblem(s.look.window, span);
  if (!misfit.empty())
    throw Error(EscapeText(scene.path) + ": " + (o.window_given ? names.window : "film.window") +
                ": " + misfit);
  const std::string problem =
      FilmFramesProblem(FilmWindowLength(s.look.window, span, scene.output.interval), s.look.fps,
                        s.look.speed);
  if (!problem.empty()) {
    const std::string key = o.speed > 0 ? names.speed : o.fps > 0 ? names.fps : "film.speed";
    throw Error(EscapeText(scene.path) + ": " + key + ": " + problem);
  }
  return s;
}

}  // namespace cablefilm
