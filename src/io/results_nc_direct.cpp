// OpenLineResultsNc and OpenModelResultsNc for what links the NetCDF writers directly (the
// tests, the Python module, the NetCDF module itself); the program has its own, through the
// module (src/modules/netcdf_client.cpp).
#include "io/netcdf_results.h"
#include "io/results_nc.h"
#include "io/model_netcdf.h"

namespace cablefilm {

std::unique_ptr<LineResultsNc> OpenLineResultsNc(const std::string& path,
                                                 const NetcdfResultsInfo& info, const LineModel& m,
                                                 const State& initial,
                                                 const Eigen::VectorXd& initial_tension,
                                                 int line) {
  return std::make_unique<NetcdfResultsWriter>(path, info, m, initial, initial_tension, line);
}

std::unique_ptr<ModelResultsNc> OpenModelResultsNc(const std::string& path,
                                                     const NetcdfResultsInfo& info,
                                                     const Model& sys, const Inputs& in) {
  return std::make_unique<ModelResultsWriter>(path, info, sys, in);
}

}  // namespace cablefilm
