#pragma once
// What the NetCDF-4 result files share: the error check, text attributes, the global
// attributes, and the process settings HDF5 and zlib need (io/netcdf_results.h, a line's file;
// io/model_netcdf.h, a system's).
#include <memory>
#include <string>

#include "io/results_nc.h"  // NetcdfResultsInfo

namespace cablefilm {

// Throws Error naming `file` and `what` unless status is NC_NOERR (a full disk said as such).
void NetcdfCheck(int status, const std::string& file, const char* what);
// A text attribute of variable `var` (NC_GLOBAL: of the file).
void NetcdfText(int ncid, int var, const char* name, const std::string& value,
                const std::string& file);
// Conventions, title, source, references, cablefilm_version, model, initial_state, scene_file;
// then scene, the scene's text (empty when not given), the last.
void NetcdfGlobalAttributes(int ncid, const NetcdfResultsInfo& info, const std::string& file);
void NetcdfSceneAttribute(int ncid, const std::shared_ptr<const std::string>& scene,
                          const std::string& file);

// Whether a file's variables over time are deflated (level 1, shuffle): when their data
// (info.rows rows of `row_bytes` bytes) would exceed kDeflateAboveBytes, or the rows are not
// known. Below it the deflation costs more than it saves: on case P63 (1801 rows of 61
// stations, 3.6 MB) it took 30 ms of CPU, a sixth of the process's (185 against 155 ms,
// bench/bench_startup.py), to save 1.6 MB.
constexpr double kDeflateAboveBytes = 16.0 * (1 << 20);
bool DeflateResults(const NetcdfResultsInfo& info, double row_bytes);

// Before the first file is created (both idempotent): zlib's churn of freed memory avoided,
// and HDF5's exit handler (which follows a freed pointer after a failed close) turned off.
void KeepFreedMemoryForTheCompressor();
void SkipHdf5CleanupAtExit();

}  // namespace cablefilm
