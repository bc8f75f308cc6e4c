#include "io/netcdf_support.h"

#include <H5public.h>
#include <malloc.h>
#include <netcdf.h>

#include <cerrno>
#include <cstring>

#include "core/error.h"

namespace cablefilm {

// A failed call's message. HDF5 reports a full disk as "HDF error" (or, at nc_create, as
// "Permission denied"): the system's own reason, left in errno by the write that failed, comes
// first when it is a full disk or quota.
void NetcdfCheck(int status, const std::string& file, const char* what) {
  if (status == NC_NOERR) return;
  std::string why = nc_strerror(status);
  if (errno == ENOSPC || errno == EDQUOT) why = std::strerror(errno) + (" (" + why + ")");
  throw Error("cannot write " + file + " (" + what + "): " + why);
}

void NetcdfText(int ncid, int var, const char* name, const std::string& value, const std::string& file) {
  NetcdfCheck(nc_put_att_text(ncid, var, name, value.size(), value.data()), file, name);
}

bool DeflateResults(const NetcdfResultsInfo& info, double row_bytes) {
  return info.rows <= 0 || static_cast<double>(info.rows) * row_bytes > kDeflateAboveBytes;
}

// zlib allocates about 270 KiB of state for every chunk it deflates and frees it at once. With
// glibc's default trim threshold (128 KiB) every free hands those pages back to the kernel and
// the next chunk faults them in again, which on this machine cost several times the compression
// itself (case P63: 0.2-0.35 s to close the file instead of 10 ms). Keeping up to 8 MiB free at
// the top of a heap ends the churn; the rest of the program allocates nothing in its loops.
void KeepFreedMemoryForTheCompressor() {
#if defined(__GLIBC__)
  static const bool once = [] {
    mallopt(M_TOP_PAD, 1 << 20);
    mallopt(M_TRIM_THRESHOLD, 8 << 20);
    return true;
  }();
  (void)once;
#endif
}

// A close that fails (a full disk: the last metadata cannot be written) leaves HDF5 1.10 with
// a file ID whose file it has already freed (HDF5's H5F__dest frees it on failure too, fixed
// only in 1.14.1). HDF5's own atexit handler then closes every ID still open and follows the
// freed pointer: the program, having printed its error, died of SIGSEGV. Without that handler
// nothing touches the stale ID: the process ends with its own status. Successful closes have
// written and released everything already, so the handler has nothing else to do at exit.
// H5dont_atexit() takes effect only before HDF5 starts, which the first nc_create does.
void SkipHdf5CleanupAtExit() {
  static const bool once = [] {
    H5dont_atexit();
    return true;
  }();
  (void)once;
}

void NetcdfGlobalAttributes(int nc, const NetcdfResultsInfo& info, const std::string& f) {
  NetcdfText(nc, NC_GLOBAL, "Conventions", "CF-1.8", f);
  NetcdfText(nc, NC_GLOBAL, "title", info.title, f);
  NetcdfText(nc, NC_GLOBAL, "source", "cablefilm " + info.version, f);
  NetcdfText(nc, NC_GLOBAL, "references",
       "Polachek, Walton, Mejia and Dawson (1963), Transient motion of an elastic cable "
       "immersed in a fluid",
       f);
  NetcdfText(nc, NC_GLOBAL, "cablefilm_version", info.version, f);
  NetcdfText(nc, NC_GLOBAL, "model", info.model, f);
  NetcdfText(nc, NC_GLOBAL, "initial_state", info.initial_state, f);
  NetcdfText(nc, NC_GLOBAL, "scene_file", info.scene_file, f);
}

void NetcdfSceneAttribute(int nc, const std::shared_ptr<const std::string>& scene,
                          const std::string& f) {
  NetcdfText(nc, NC_GLOBAL, "scene", scene ? *scene : std::string(), f);
}

}  // namespace cablefilm
