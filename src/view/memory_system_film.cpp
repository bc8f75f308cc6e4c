#include "view/memory_system_film.h"

#include <string>

#include "core/error.h"
#include "view/colormap.h"
#include "view/memory_film.h"
#include "view/scene_view.h"
#include "view/scene_view_builder.h"
#include "view/snapshot.h"
#include "view/system_film.h"

namespace cablefilm {

Image DrawMemorySystemFrame(const MemorySystemRun& run, long row, const FilmRequest& request) {
  const long rows = run.lines.front().rows.rows;  // every line's rows alike
  if (row < 0 || row >= rows)
    throw Error("row " + std::to_string(row) + ": expected a row from 0 to " +
                std::to_string(rows - 1));
  const Model& sys = run.run.sys;
  const std::size_t nl = sys.lines.size();
  const SceneView scene = MakeSystemFilmScene(run.scene, run.run, request.view);
  const FixedPolicy policy = MakeSystemFilmPolicy(scene, run.run, request, run.run.grid.end());
  const LineModel& any = sys.lines.front();  // one environment: any line's is the scene's
  const Vec current = TopCurrent(any, SceneWater(any));
  const Colormap colormap(request.colormap);
  History history(scene, policy);
  Snapshot snap;
  snap.lines.resize(nl);
  for (long r = 0; r <= row; ++r) {
    snap.t = run.lines.front().rows.time[r];
    for (std::size_t i = 0; i < nl; ++i)
      SetRowLine(run.lines[i].rows, r, sys.lines[i], &snap.lines[i]);
    AddRowSnapshot(scene, policy, any.env.wave, current, &snap, &history);
  }
  return DrawRowFrame(scene, history, snap, request, colormap);
}

}  // namespace cablefilm
