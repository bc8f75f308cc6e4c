#include "scene/film_settings.h"

#include <algorithm>

#include "core/error.h"
#include "scene/film_view.h"
#include "scene/scene_limits.h"
#include "scene/text_escape.h"

namespace cablefilm {

const FilmKeyNames kCommandLineNames{"--size",     "--fps",           "--speed",
                                     "--colormap", "--tension-range", "--view"};
const FilmKeyNames kPythonNames{"width", "fps", "speed", "colormap", "tension_range", "view"};

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
  if (!whole_film) return s;
  // The film of the run must have from 1 to kMaxFilmFrames frames: counted here, not by the
  // loader, so that a run without its film is not refused for it.
  const std::string problem = FilmFramesProblem(
      RunSpan(scene.simulation.duration, scene.output.interval), s.look.fps, s.look.speed);
  if (!problem.empty()) {
    const std::string key = o.speed > 0 ? names.speed : o.fps > 0 ? names.fps : "film.speed";
    throw Error(EscapeText(scene.path) + ": " + key + ": " + problem);
  }
  return s;
}

}  // namespace cablefilm
