#include "view/memory_film.h"

#include <algorithm>
#include <string>
#include <vector>

#include "core/error.h"
#include "view/colormap.h"
#include "view/frame_builder.h"
#include "view/renderer.h"

namespace cablefilm {

bool RenderMemoryRunFilm(const MemoryRun& run, const FilmRequest& request,
                         const std::atomic<int>& stop) {
  const RunSummary& s = run.run.summary;
  if (!s.completed)
    throw Error("the run did not reach its end" +
                (s.failure.empty() ? std::string() : ": " + s.failure) +
                "; a film is made of a whole run");
  return RenderFilm(run.scene, {&run.run}, request, stop);
}

Image DrawMemoryRunFrame(const MemoryRun& run, long row, const FilmRequest& request) {
  const MemoryRows& rows = run.rows;
  if (row < 0 || row >= rows.rows)
    throw Error("row " + std::to_string(row) + ": expected a row from 0 to " +
                std::to_string(rows.rows - 1));
  const Model& model = run.run.model;
  const FilmSpec spec = MakeFilmSpec(run.scene, {&run.run}, request, run.run.grid.end());
  const Colormap colormap(request.colormap);
  const FrameLayout layout = MakeFrameLayout(spec, request.width, request.height);
  FilmHistory history(spec);
  const std::size_t stations = static_cast<std::size_t>(model.stations());
  const std::size_t links = static_cast<std::size_t>(model.line.links);
  CableSnapshot snap;
  for (long r = 0; r <= row; ++r) {
    // Each row a snapshot carrying itself: the time plot and the envelope cover every row.
    const double* x = rows.x[0].data() + r * stations;
    const double* y = rows.x[1].data() + r * stations;
    const double* T = rows.tension.data() + r * links;
    snap.t = rows.time[r];
    snap.x.assign(x, x + stations);
    snap.y.assign(y, y + stations);
    snap.tension.assign(T, T + links);
    snap.row_t.assign(1, snap.t);
    snap.row_max.assign(1, *std::max_element(T, T + links));
    snap.row_link_min = snap.tension;
    snap.row_link_max = snap.tension;
    AddWaterSurface(spec, model, &snap);
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
