#pragma once
// The pictures of a system of lines (run/system_run.h), as film_pass.h draws a line's:
// max_tension.png with a curve a line, and the film, a second deterministic pass over the
// system (SystemRowStepper from its initial LineData: a frame's state is its row's) that pushes a
// snapshot of every line each frame, on the colour range and world box of all the lines' rows
// (the first pass's), memory bounded whatever the film's length. Every line is drawn alike
// (SceneView::lines_alike): in full, named, its ends marked as the system's points.
#include <atomic>
#include <string>

#include "run/system_run.h"
#include "scene/scene_def.h"
#include "view/film_pass.h"
#include "view/history.h"
#include "view/scene_view.h"

namespace cablefilm {

// The system's scene view: a line a line of the system, named by its name, drawn alike, its
// points named where their first line end is (a point no line is attached to is not drawn), in
// space or in the plane as `view` says (scene/film_view.h). `run` has been run once.
SceneView MakeSystemFilmScene(const SceneDef& scene, const SystemRun& run,
                              const std::string& view = "auto");

// What stays fixed over the film lasting `duration` [s]: the colour range over every line's
// rows (or the request's range) and the box of every line, reaching to the seabed and the
// crests.
FixedPolicy MakeSystemFilmPolicy(const SceneView& view, const SystemRun& run,
                                 const FilmRequest& request, double duration);

// Renders film.mp4 of the system (frames as film_clock.h places them). Returns false if `stop`
// was raised (the film then closed at the last frame drawn, as film.partial.mp4). `report`
// (optional): the film's time plot at its last frame, over all the lines (its peak the largest
// row of any line). Throws Error (a blow-up in this pass: the film up to it stays partial).
bool RenderSystemFilm(const SceneDef& scene, const SystemRun& run, const FilmRequest& request,
                      const std::atomic<int>& stop, PictureReport* report = nullptr);

}  // namespace cablefilm
