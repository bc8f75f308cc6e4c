#include "view/memory_film.h"

#include <algorithm>
#include <string>
#include <vector>

#include "core/error.h"
#include "view/colormap.h"
#include "view/frame_builder.h"
#include "view/history.h"
#include "view/renderer.h"
#include "view/scene_view.h"
#include "view/scene_view_builder.h"
#include "view/snapshot.h"
#include "view/world_box.h"

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
  const long rows = run.lines.front().rows;  // every line's rows alike
  if (row < 0 || row >= rows)
    throw Error("row " + std::to_string(row) + ": expected a row from 0 to " +
                std::to_string(rows - 1));
  const Model& model = run.run.model;
  const std::size_t nl = model.lines.size();
  const SceneView scene = MakeFilmScene(run.scene, {&run.run}, request.view);
  const FixedPolicy policy = MakeFilmPolicy(scene, {&run.run}, request, 0, run.run.grid.end());
  const LineModel& any = model.lines.front();  // one environment: any line's is the scene's
  const Vec current = TopCurrent(any, SceneWater(any));
  const Colormap colormap(request.colormap);
  History history(scene, policy);
  Snapshot snap;
  snap.lines.resize(nl);
  for (long r = 0; r <= row; ++r) {
    snap.t = run.lines.front().time[r];
    for (std::size_t i = 0; i < nl; ++i) SetRowLine(run.lines[i], r, model.lines[i], &snap.lines[i]);
    AddRowSnapshot(scene, policy, any.env.wave, current, &snap, &history);
  }
  return DrawRowFrame(scene, history, snap, request, colormap);
}

void SetRowLine(const MemoryRows& rows, long r, const LineModel& model, LineSnapshot* line) {
  const Eigen::Index stations = model.stations(), links = model.line.links;
  const Points x = Eigen::Map<const Points>(rows.x.data() + r * stations * kDim, kDim, stations);
  const Eigen::Map<const Eigen::VectorXd> T(rows.tension.data() + r * links, links);
  SetLineState(x, T, line);
  line->row_max.assign(1, T.maxCoeff());
  line->row_link_min = line->tension;
  line->row_link_max = line->tension;
}

void AddRowSnapshot(const SceneView& scene, const FixedPolicy& policy, const Wave& wave,
                    const Vec& current, Snapshot* snap, History* history) {
  // Each row a snapshot carrying itself: the time plot and the envelope cover every row.
  snap->row_t.assign(1, snap->t);
  if (scene.sea.surface) {
    AddWaterSurface(wave, policy.box, snap);
    snap->wave = wave;
  }
  snap->current = current;
  history->Add(*snap);
}

Image DrawRowFrame(const SceneView& scene, const History& history, const Snapshot& snap,
                   const FilmRequest& request, const Colormap& colormap) {
  const FrameLayout layout = MakeFrameLayout(scene, history, request.width, request.height);
  RenderOptions options;
  options.width = request.width;
  options.height = request.height;
  options.shader_dir = request.shader_dir;
  Renderer renderer(options);
  return renderer.Draw(MakeFrame(scene, history, snap, layout, colormap));
}

}  // namespace cablefilm
