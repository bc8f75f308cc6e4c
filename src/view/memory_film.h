#pragma once
// The pictures of a run held in memory (memory_run.h), drawn by the film pass of `cablefilm
// run` (film_pass.h): the whole film, or one of its frames as an image.
#include <atomic>

#include "encode/image.h"
#include "run/memory_run.h"
#include "view/colormap.h"
#include "view/film_pass.h"
#include "view/history.h"
#include "view/scene_view.h"
#include "view/snapshot.h"

namespace cablefilm {

// <request.out_dir>/film.mp4 of a completed run (its rows give the colour range, the box and
// the time plot; the film pass repeats the simulation as `run` does). Returns false if `stop`
// was raised (film.partial.mp4 then). Throws Error (a run that did not complete, the film's
// options, the renderer).
bool RenderMemoryRunFilm(const MemoryRun& run, const FilmRequest& request,
                         const std::atomic<int>& stop);

// The film's frame showing output row `row` (0 to rows - 1) at request.width x request.height:
// every line at that row, the time plot and the tension envelope over every row up to it, on
// the colour range and the world box of the whole run, as the film draws it. Throws Error.
Image DrawMemoryRunFrame(const MemoryRun& run, long row, const FilmRequest& request);

// The steps of such a frame:
// `line` as held rows r of `rows` (a run of `model`) show it;
void SetRowLine(const MemoryRows& rows, long r, const LineModel& model, LineSnapshot* line);
// `snap` (its time and lines set) added to the history as a row of its own, with the sea and
// the current;
void AddRowSnapshot(const SceneView& scene, const FixedPolicy& policy, const Wave& wave,
                    const Vec& current, Snapshot* snap, History* history);
// and the frame of the last snapshot drawn over that history.
Image DrawRowFrame(const SceneView& scene, const History& history, const Snapshot& snap,
                   const FilmRequest& request, const Colormap& colormap);

}  // namespace cablefilm
