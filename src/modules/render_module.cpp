// cablefilm_render.so: the films and the live view behind one table (module_api.h).
#include "modules/module_api.h"
#include "view/memory_film.h"
#include "view/memory_system_film.h"
#include "view/system_film.h"

namespace cablefilm {
namespace {

const std::string& Abi() {
  static const std::string abi = ModuleAbi();
  return abi;
}

}  // namespace
}  // namespace cablefilm

extern "C" __attribute__((visibility("default"))) const void* cablefilm_render_module() {
  using namespace cablefilm;
  static const RenderModuleApi api{Abi().c_str(),        &RenderFilm,         &RenderSystemFilm,
                                   &LiveCommand,         &RenderMemoryRunFilm, &DrawMemoryRunFrame,
                                   &DrawMemorySystemFrame};
  return &api;
}
