#pragma once
// results.nc (NetCDF-4) as the runs see it: a sink of rows, committed whole or under a partial
// name. The writers (io/netcdf_results.h, a line's; io/model_netcdf.h, a system's) link
// libnetcdf and HDF5, which take 25 ms to load: the program reaches them through a module it
// loads when a run writes results.nc (src/modules/), the tests and the Python module directly
// (io/results_nc_direct.cpp). Either way the Open functions below.
#include <Eigen/Core>
#include <memory>
#include <string>

#include "core/data.h"
#include "core/inputs.h"
#include "core/model.h"
#include "run/driver.h"
#include "run/tension_statistics.h"

namespace cablefilm {

// The global attributes beside Conventions = "CF-1.8".
struct NetcdfResultsInfo {
  std::string title;          // the scene's title
  std::string scene_file;     // its path, as given
  // Its text, shared: each line's file of a system writes it as the file closes, and a copy
  // per line would grow with the square of the lines.
  std::shared_ptr<const std::string> scene;
  std::string version;        // the program's: "0.1 (git 1a2b3c4)"
  std::string model;          // "elastic" or "inextensible"
  std::string initial_state;  // "equilibrium" or "straight"
  // Not an attribute: the rows a complete run writes (0: not known), which decide whether the
  // variables over time are deflated (DeflateResults, io/netcdf_support.h).
  long rows = 0;
  // Not an attribute: the scene stays in the plane z = 0, so z is zeros throughout (the one
  // variable along the cable that deflates for next to nothing, DeflateResults).
  bool planar = false;
};

// A line's results.nc: every row's positions and tensions (of the Data's line `line`).
class LineResultsNc : public RowSink {
 public:
  explicit LineResultsNc(int line = 0) : line_(line) {}
  // One output row. Throws Error on a write error (of this row or of an earlier chunk).
  virtual void Append(const State& state, const Eigen::VectorXd& tension) = 0;
  bool Row(const Data& d) override {
    Append(d.lines[line_].state, d.lines[line_].tension());
    return true;
  }
  // The statistics of the end links' tensions over the rows (RunSummary::ends), written as
  // scalar variables (tension_start_mean, ...) when the file closes; none unless set.
  void SetEndStatistics(const TensionStatistics ends[2]) {
    ends_[0] = ends[0];
    ends_[1] = ends[1];
  }
  // Writes the rows still waiting, closes and renames; throws Error on a write error.
  virtual void Commit() = 0;                                // the complete file, under its name
  virtual void CommitPartial(const std::string& path) = 0;  // an incomplete run, another name

 protected:
  TensionStatistics ends_[2];

 private:
  int line_;
};

// The results.nc of a model of several lines: points, lines' end tensions, bodies.
class ModelResultsNc : public RowSink {
 public:
  virtual void Commit() = 0;
  virtual void CommitPartial(const std::string& path) = 0;
};

// Create `path`'s temporary file and write what does not change over time. Throw Error. The
// objects keep references to `model` and `in`, which must outlive them. A line's file holds
// line `line` of the rows' Data (`m` its model).
std::unique_ptr<LineResultsNc> OpenLineResultsNc(const std::string& path,
                                                 const NetcdfResultsInfo& info, const LineModel& m,
                                                 const State& initial,
                                                 const Eigen::VectorXd& initial_tension,
                                                 int line = 0);
std::unique_ptr<ModelResultsNc> OpenModelResultsNc(const std::string& path,
                                                     const NetcdfResultsInfo& info,
                                                     const Model& model, const Inputs& in);

}  // namespace cablefilm
