// The films and the live view as the program and the Python module call them
// (view/film_pass.h, view/memory_film.h, live/live_command.h): forwarded to cablefilm_render.so, loaded on the first call, so that a
// run without a film never loads OSMesa or libav*.
#include "modules/module_api.h"
#include "modules/module_loader.h"
#include "view/memory_film.h"

namespace cablefilm {
namespace {

const RenderModuleApi& Render(const std::string& what) {
  const auto* table = static_cast<const RenderModuleApi*>(
      LoadModuleTable(kRenderModuleFile, kRenderModuleEntry, ModuleAbi(), what));
  table->record_outputs_through(&RecordOutputOrSay);  // what the film writes is the run's
  return *table;
}

}  // namespace

bool RenderFilm(const SceneDef& scene, const std::vector<const Run*>& runs,
                const FilmRequest& request, const std::atomic<int>& stop, PictureReport* report) {
  return Render("film").render_film(scene, runs, request, stop, report);
}

int LiveCommand(const std::string& scene_path, const LiveCommandOptions& options) {
  return Render("live").live_command(scene_path, options);
}

bool RenderMemoryRunFilm(const MemoryRun& run, const FilmRequest& request,
                         const std::atomic<int>& stop) {
  return Render("film").render_memory_run_film(run, request, stop);
}

Image DrawMemoryRunFrame(const MemoryRun& run, long row, const FilmRequest& request) {
  return Render("frame").draw_memory_run_frame(run, row, request);
}

}  // namespace cablefilm
