// cablefilm_netcdf.so: the results.nc writers behind one table (module_api.h).
#include "modules/module_api.h"

namespace cablefilm {
namespace {

const std::string& Abi() {
  static const std::string abi = ModuleAbi();
  return abi;
}

}  // namespace
}  // namespace cablefilm

extern "C" __attribute__((visibility("default"))) const void* cablefilm_netcdf_module() {
  using namespace cablefilm;
  static const NetcdfModuleApi api{Abi().c_str(), &OpenLineResultsNc, &OpenSystemResultsNc};
  return &api;
}
