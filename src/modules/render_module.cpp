// cablefilm_render.so: the films and the live view behind one table (module_api.h).
#include "modules/module_api.h"
#include "view/memory_film.h"

extern "C" __attribute__((visibility("default"))) const void* cablefilm_render_module() {
  using namespace cablefilm;
  static const RenderModuleApi api{ModuleAbiText(), &RenderFilm, &LiveCommand,
                                   &RenderMemoryRunFilm, &DrawMemoryRunFrame,
                                   &RecordOutputsThrough};
  return &api;
}
