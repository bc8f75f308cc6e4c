// results.nc as the program opens it (io/results_nc.h): through cablefilm_netcdf.so, loaded on
// the first file, so that a process that writes none never loads libnetcdf and HDF5.
#include "modules/module_api.h"
#include "modules/module_loader.h"

namespace cablefilm {
namespace {

const NetcdfModuleApi& Netcdf() {
  const auto* table = static_cast<const NetcdfModuleApi*>(
      LoadModuleTable(kNetcdfModuleFile, kNetcdfModuleEntry, ModuleAbi(), "results.nc"));
  table->record_outputs_through(&RecordOutputOrSay);  // what it writes is the run's
  return *table;
}

}  // namespace

std::unique_ptr<LineResultsNc> OpenLineResultsNc(const std::string& path,
                                                 const NetcdfResultsInfo& info, const LineModel& m,
                                                 const State& initial,
                                                 const Eigen::VectorXd& initial_tension,
                                                 int line) {
  return Netcdf().open_line(path, info, m, initial, initial_tension, line);
}

std::unique_ptr<ModelResultsNc> OpenModelResultsNc(const std::string& path,
                                                     const NetcdfResultsInfo& info,
                                                     const Model& sys, const Inputs& in) {
  return Netcdf().open_model(path, info, sys, in);
}

}  // namespace cablefilm
