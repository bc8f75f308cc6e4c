#pragma once
// What the NetCDF-4 result files share: the error check, text attributes, the global
// attributes, and the process settings HDF5 and zlib need (io/netcdf_results.h, a line's file;
// io/system_netcdf.h, a system's).
#include <string>

namespace cablefilm {

// The global attributes beside Conventions = "CF-1.8".
struct NetcdfResultsInfo {
  std::string title;          // the scene's title
  std::string scene_file;     // its path, as given
  std::string scene;          // its text
  std::string version;        // the program's: "0.1 (git 1a2b3c4)"
  std::string model;          // "elastic" or "inextensible"
  std::string initial_state;  // "equilibrium" or "straight"
};

// Throws Error naming `file` and `what` unless status is NC_NOERR (a full disk said as such).
void NetcdfCheck(int status, const std::string& file, const char* what);
// A text attribute of variable `var` (NC_GLOBAL: of the file).
void NetcdfText(int ncid, int var, const char* name, const std::string& value,
                const std::string& file);
// Conventions, title, source, references, cablefilm_version, model, initial_state, scene_file,
// scene.
void NetcdfGlobalAttributes(int ncid, const NetcdfResultsInfo& info, const std::string& file);

// Before the first file is created (both idempotent): zlib's churn of freed memory avoided,
// and HDF5's exit handler (which follows a freed pointer after a failed close) turned off.
void KeepFreedMemoryForTheCompressor();
void SkipHdf5CleanupAtExit();

}  // namespace cablefilm
