#include "view/memory_film.h"

#include <algorithm>
#include <string>
#include <vector>

#include "run/max_tension_log.h"
#include "core/error.h"
#include "view/colormap.h"
#include "view/frame_builder.h"
#include "view/renderer.h"

namespace cablefilm {
namespace {

// The largest tension of every row, as `run` logs them (the first link holding it).
MaxTensionLog RowMaxima(const MemoryRun& run) {
  MaxTensionLog log;
  const Eigen::Index links = run.model.links;
  for (long r = 0; r < run.rows; ++r) {
    Eigen::Map<const Eigen::VectorXd> T(run.tension.data() + r * links, links);
    Eigen::Index link = 0;
    const double tmax = T.maxCoeff(&link);
    log.Append(run.time[r], tmax, static_cast<int>(link));
  }
  return log;
}

FilmRun ToFilmRun(const MemoryRun& run, const MaxTensionLog& rows) {
  return FilmRun{run.model.law == LinkLaw::kElastic ? "elastic" : "inextensible", &run.model,
                 run.grid, run.initial, run.initial_tension, run.extent, &rows};
}

}  // namespace

bool RenderMemoryRunFilm(const MemoryRun& run, const FilmRequest& request,
                         const std::atomic<int>& stop) {
  if (!run.completed)
    throw Error("the run did not reach its end" +
                (run.failure.empty() ? std::string() : ": " + run.failure) +
                "; a film is made of a whole run");
  const MaxTensionLog rows = RowMaxima(run);
  return RenderFilm(run.scene, {ToFilmRun(run, rows)}, request, stop);
}

Image DrawMemoryRunFrame(const MemoryRun& run, long row, const FilmRequest& request) {
  if (row < 0 || row >= run.rows)
    throw Error("row " + std::to_string(row) + ": expected a row from 0 to " +
                std::to_string(run.rows - 1));
  const MaxTensionLog rows = RowMaxima(run);
  const FilmSpec spec = MakeFilmSpec(run.scene, {ToFilmRun(run, rows)}, request,
                                     run.grid.outputs * run.grid.interval);
  const Colormap colormap(request.colormap);
  const FrameLayout layout = MakeFrameLayout(spec, request.width, request.height);
  FilmHistory history(spec);
  const std::size_t stations = static_cast<std::size_t>(run.model.stations());
  const std::size_t links = static_cast<std::size_t>(run.model.links);
  CableSnapshot snap;
  for (long r = 0; r <= row; ++r) {
    // Each row a snapshot carrying itself: the time plot and the envelope cover every row.
    const double* x = run.x.data() + r * stations;
    const double* y = run.y.data() + r * stations;
    const double* T = run.tension.data() + r * links;
    snap.t = run.time[r];
    snap.x.assign(x, x + stations);
    snap.y.assign(y, y + stations);
    snap.tension.assign(T, T + links);
    snap.row_t.assign(1, snap.t);
    snap.row_max.assign(1, *std::max_element(T, T + links));
    snap.row_link_min = snap.tension;
    snap.row_link_max = snap.tension;
    AddWaterSurface(spec, run.model, &snap);
    history.Add(snap);
  }
  RenderOptions options;
  options.width = request.width;
  options.height = request.height;
  options.shader_dir = request.shader_dir;
  Renderer renderer(options);
  return renderer.Draw(MakeFrame(spec, history, snap, layout, colormap));
}

}  // namespace cablefilm
