#pragma once
// What the program reaches through the modules it loads on demand (module_loader.h): the
// films and the live view (cablefilm_render.so: OSMesa, LLVM, libav*, about 0.2 s of loading)
// and results.nc (cablefilm_netcdf.so: libnetcdf and HDF5, 25 ms). A process that writes
// neither, such as `cablefilm --version` or `check`, loads neither.
//
// The Python module reaches the render module the same way (so that `import cablefilm` does
// not load OpenGL and the video encoder either).
//
// A module is built from the same sources as the program, its own copy of the libraries
// linked in and hidden, so the two share no symbol: only these tables of functions, checked
// by ModuleAbi() before use.
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "core/version.h"
#include "io/output_ledger.h"
#include "io/results_nc.h"
#include "live/live_command.h"
#include "encode/image.h"
#include "run/memory_run.h"
#include "run/run.h"
#include "scene/scene_def.h"
#include "view/film_pass.h"

namespace cablefilm {

// The build a table belongs to: the version and the sizes of the structures that cross, so
// that a module from another build is refused rather than misread.
inline std::string ModuleAbi() {
  return std::string(kVersion) + " " + kGitDescribe + " " + std::to_string(sizeof(SceneDef)) +
         "/" + std::to_string(sizeof(Run)) + "/" + std::to_string(sizeof(MemoryRun)) + "/" +
         std::to_string(sizeof(FilmRequest)) + "/" + std::to_string(sizeof(Model)) + "/" +
         std::to_string(sizeof(LiveCommandOptions));
}

// ModuleAbi() kept for the process's life: what a module's table points to.
inline const char* ModuleAbiText() {
  static const std::string abi = ModuleAbi();
  return abi.c_str();
}

struct RenderModuleApi {
  const char* abi;  // ModuleAbi() of the module's build
  bool (*render_film)(const SceneDef&, const std::vector<const Run*>&, const FilmRequest&,
                      const std::atomic<int>&, PictureReport*);
  int (*live_command)(const std::string& scene_path, const LiveCommandOptions&);
  // The Python module's films and frames of runs kept in memory (view/memory_film.h).
  bool (*render_memory_run_film)(const MemoryRun&, const FilmRequest&, const std::atomic<int>&);
  Image (*draw_memory_run_frame)(const MemoryRun&, long row, const FilmRequest&);
  void (*record_outputs_through)(OutputRecorder);  // the program's ledgers (io/output_ledger.h)
};

struct NetcdfModuleApi {
  const char* abi;
  std::unique_ptr<LineResultsNc> (*open_line)(const std::string&, const NetcdfResultsInfo&,
                                              const LineModel&, const State&,
                                              const Eigen::VectorXd&, int);
  std::unique_ptr<ModelResultsNc> (*open_model)(const std::string&, const NetcdfResultsInfo&,
                                                  const Model&, const Inputs&);
  void (*record_outputs_through)(OutputRecorder);
};

// The modules' entry points (extern "C": looked up by name).
constexpr const char* kRenderModuleFile = "cablefilm_render.so";
constexpr const char* kRenderModuleEntry = "cablefilm_render_module";
constexpr const char* kNetcdfModuleFile = "cablefilm_netcdf.so";
constexpr const char* kNetcdfModuleEntry = "cablefilm_netcdf_module";

}  // namespace cablefilm
