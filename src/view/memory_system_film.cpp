#include "view/memory_system_film.h"

#include <string>

#include "core/error.h"
#include "view/colormap.h"
#include "view/frame_builder.h"
#include "view/history.h"
#include "view/renderer.h"
#include "view/scene_view.h"
#include "view/scene_view_builder.h"
#include "view/snapshot.h"
#include "view/system_film.h"
#include "view/world_box.h"

namespace cablefilm {

Image DrawMemorySystemFrame(const MemorySystemRun& run, long row, const FilmRequest& request) {
  const long rows = run.lines.front().rows.rows;  // every line's rows alike
  if (row < 0 || row >= rows)
    throw Error("row " + std::to_string(row) + ": expected a row from 0 to " +
                std::to_string(rows - 1));
  const SystemModel& sys = run.run.sys;
  const std::size_t nl = sys.lines.size();
  const SceneView scene = MakeSystemFilmScene(run.scene, run.run, request.view);
  const FixedPolicy policy = MakeSystemFilmPolicy(scene, run.run, request, run.run.grid.end());
  const Model& any = sys.lines.front();  // one environment: any line's is the scene's
  const Vec current = TopCurrent(any, SceneWater(any));
  const Colormap colormap(request.colormap);
  History history(scene, policy);
  Snapshot snap;
  snap.lines.resize(nl);
  for (long r = 0; r <= row; ++r) {
    // Each row a snapshot carrying itself (every line's), as a line's frame is drawn
    // (memory_film.cpp): the time plot and the envelope cover every row.
    snap.t = run.lines.front().rows.time[r];
    snap.row_t.assign(1, snap.t);
    for (std::size_t i = 0; i < nl; ++i) {
      const MemoryRows& m = run.lines[i].rows;
      const Eigen::Index stations = sys.lines[i].stations();
      const Eigen::Index links = sys.lines[i].line.links;
      const Points x = Eigen::Map<const Points>(m.x.data() + r * stations * kDim, kDim, stations);
      const Eigen::Map<const Eigen::VectorXd> T(m.tension.data() + r * links, links);
      LineSnapshot& line = snap.lines[i];
      SetLineState(x, T, &line);
      line.row_max.assign(1, T.maxCoeff());
      line.row_link_min = line.tension;
      line.row_link_max = line.tension;
    }
    if (scene.sea.surface) {
      AddWaterSurface(any.env.wave, policy.box, &snap);
      snap.wave = any.env.wave;
    }
    snap.current = current;
    history.Add(snap);
  }
  const FrameLayout layout = MakeFrameLayout(scene, history, request.width, request.height);
  RenderOptions options;
  options.width = request.width;
  options.height = request.height;
  options.shader_dir = request.shader_dir;
  Renderer renderer(options);
  return renderer.Draw(MakeFrame(scene, history, snap, layout, colormap));
}

}  // namespace cablefilm
