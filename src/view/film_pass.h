#pragma once
// The pictures of a run. max_tension.png (the paper's Figure 1) is drawn from every output row
// of the simulation (MaxTensionLog: the tension_max column of timeseries.csv), for every run,
// film or not. The film is a second, deterministic pass over the simulation that pushes a
// snapshot every film frame to the renderer, so the colour range and the world box found by the
// first pass hold for every frame while memory stays bounded whatever the film's length; each
// snapshot carries the output rows since the previous frame, so the film's time plot shows
// every row too: the run's reported peak, the CSV, the figure and the film agree on the peak.
#include <Eigen/Core>
#include <atomic>
#include <limits>
#include <string>
#include <vector>

#include "run/film_checkpoint.h"
#include "run/run.h"
#include "scene/film_settings.h"
#include "scene/scene_def.h"

namespace cablefilm {

struct FilmRequest {
  std::string out_dir;
  bool frames = false;          // frames/frame_000000.png ...
  int width = 1920, height = 1080;
  double fps = 30, speed = 1;   // film frames per second; simulated seconds per film second
  int crf = 20;
  std::string colormap = "viridis";
  double tension_min = -1, tension_max = -1;  // [N]; negative: from the runs
  std::string view = "auto";    // "auto", "2d", "3d" (scene/film_view.h)
  std::string shader_dir;       // empty: CABLEFILM_SHADERS or the built-in shaders
  bool say_written = true;      // print "wrote DIR/film.mp4" (the Python module names its own file)
  FilmWindow window;            // the span of the runs it shows (the first run's peak's)
  // Per run, the states kept during it that its window's pass starts from (run/
  // film_checkpoint.h); absent or null: it steps from the run's start to the window.
  std::vector<const FilmCheckpoint*> starts;
};

// The film of `settings` (scene/film_settings.h) into `out_dir`.
FilmRequest MakeFilmRequest(const FilmSettings& settings, const std::string& out_dir,
                            const std::string& shader_dir);

// What a picture shows: the largest value drawn [N] and its time [s] (NaN: nothing drawn).
struct PictureReport {
  double peak = std::numeric_limits<double>::quiet_NaN();
  double peak_t = std::numeric_limits<double>::quiet_NaN();
  long frames = 0;              // the film's frames
  double last_frame_max = std::numeric_limits<double>::quiet_NaN();  // its cable's largest
                                // tension at the last frame [N] (the "now" of the plot)
  double last_frame_t = std::numeric_limits<double>::quiet_NaN();    // that frame's time [s]
  double last_row_max = std::numeric_limits<double>::quiet_NaN();    // the time plot's newest
                                // point: the last row's tension_max [N]
};

struct SceneView;    // view/scene_view.h
struct FixedPolicy;  // view/history.h

// The film's scene view of `runs` (each run once: run/run.h, ExecuteRun), in space or in the
// plane as `view` says (scene/film_view.h). A run of one line: its line, its sections named;
// several runs of one line (compare): a line a run, named by its label, the first drawn in
// full and the others over it. A model of several lines: every line of every run drawn alike
// (SceneView::lines_alike), named (a second run's lines by their name and its label), the
// first run's points named where their first line end is (a point no line is attached to is
// not drawn) and its bodies. Used by RenderFilm, and to draw a frame on its own.
SceneView MakeFilmScene(const SceneDef& scene, const std::vector<const Run*>& runs,
                        const std::string& view = "auto");

// What stays fixed over the film of `runs` from `start` to `end` simulated seconds: the colour
// range over every line's rows of every run (or the request's range) and their world box, the
// box reaching to the seabed and the crests of `view` (MakeFilmScene's).
FixedPolicy MakeFilmPolicy(const SceneView& view, const std::vector<const Run*>& runs,
                           const FilmRequest& request, double start, double end);

// Renders film.mp4 of the runs (MakeFilmScene's lines): a second, deterministic pass that steps
// each run's initial Data again through the frames (film_clock.h), in lockstep so that a run can
// be drawn over another. Frames are at k x speed / fps and, when the run's end is not on one,
// at its end. A window of the runs (request.window): its rows (WindowRows, about the first
// run's peak), each run stepped from its checkpoint (request.starts) or its start to the
// window's first row undrawn, the frames from there. Returns false if `stop` was raised (the film is then closed at the last frame
// drawn, as film.partial.mp4). `report` (optional): the film's time plot at its last frame,
// over the first run's lines (its peak the largest row of any of them). Throws Error (a
// blow-up in this pass: the film up to it stays partial).
bool RenderFilm(const SceneDef& scene, const std::vector<const Run*>& runs,
                const FilmRequest& request, const std::atomic<int>& stop,
                PictureReport* report = nullptr);

}  // namespace cablefilm
