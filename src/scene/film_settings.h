#pragma once
// A run's film: the scene's [film] (and [output] frames) with the settings a front end gives
// over it (the command line's options, the Python module's arguments), each value checked in
// this one place against the stated limits (scene_limits.h), as the loader checks the scene's.
#include <string>

#include "scene/scene_def.h"

namespace cablefilm {

// Settings given over the scene's; a zero, negative or empty value keeps the scene's.
struct FilmOverrides {
  int width = 0, height = 0;    // [px]
  double fps = 0, speed = 0;    // frames per second of film; simulated seconds per second of film
  std::string colormap;
  double tension_min = -1, tension_max = -1;  // colour range [N]
  int frames = -1;              // 0/1: keep every frame as PNG or not
  std::string view;             // "auto", "2d", "3d" (film_view.h)
  bool window_given = false;    // window over the scene's film.window
  FilmWindow window;
};

// What each value must be, as "" (fine) or "expected ..., got ..." for a message after its key.
std::string FilmSizeProblem(int width, int height);
std::string FpsProblem(double fps);
std::string SpeedProblem(double speed);
std::string ColormapProblem(const std::string& name);
std::string TensionRangeProblem(double lo, double hi);
std::string ViewProblem(const std::string& view);
// A window from its text: "peak:W" (W seconds around the run's peak), "T0,T1" (from T0 to T1
// seconds) or "whole"; "" (then *window is it) or "expected ..., got ...".
std::string FilmWindowProblem(const std::string& text, FilmWindow* window);
// "" or "expected ..." when a window does not fit a run of `span` seconds (a span within 0 to
// the run's end, a positive width).
std::string FilmWindowFitProblem(const FilmWindow& window, double span);
// The seconds a window shows of a run of `span` seconds with rows every `interval`: its ends on
// rows as the film takes them (run/film_checkpoint.h, WindowRows), at most the run.
double FilmWindowLength(const FilmWindow& window, double span, double interval);

// The names a front end gives its settings, for its messages.
struct FilmKeyNames {
  std::string size = "film.width", fps = "film.fps", speed = "film.speed",
              colormap = "film.colormap", tension_range = "film.tension_range",
              view = "film.view", window = "film.window";
};
extern const FilmKeyNames kCommandLineNames;  // --size, --fps, --speed, ..., --view
extern const FilmKeyNames kPythonNames;       // width, fps, speed, colormap, tension_range, view

struct FilmSettings {
  FilmDef look;         // size, fps, speed, quality, colour map and range
  bool frames = false;  // every frame as PNG too
};

// The scene's film with the overrides, every value checked, and, for a whole film, its window
// against the run and its frame count (1 to kMaxFilmFrames over the window: the one place it is
// checked, so call it whenever a film will be made). Throws Error "<key named as `names` says>:
// expected ..." (led by the scene's file for the frame count).
FilmSettings ResolveFilm(const SceneDef& scene, const FilmOverrides& overrides,
                         const FilmKeyNames& names, bool whole_film = true);

}  // namespace cablefilm
