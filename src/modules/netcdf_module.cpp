// cablefilm_netcdf.so: the results.nc writers behind one table (module_api.h).
#include "modules/module_api.h"

extern "C" __attribute__((visibility("default"))) const void* cablefilm_netcdf_module() {
  using namespace cablefilm;
  static const NetcdfModuleApi api{ModuleAbiText(), &OpenLineResultsNc, &OpenModelResultsNc,
                                     &RecordOutputsThrough};
  return &api;
}
