#pragma once
// results.nc of a model of several lines: what its points, lines and bodies do over time, one
// file for the whole model (each line's stations are in lines/<name>/results.nc),
// NetCDF-4/CF-1.8, written whole or not at all (a temporary name beside it, then a rename).
//
//   dimensions  time (unlimited), line, point, and body when the system has bodies
//   line_name(line), point_name(point), body_name(body): the scene's names (strings)
//   line_start_point(line), line_end_point(line): the index of the point at station 0, at s
//   time(time) [s]
//   point_x, point_y, point_z (time, point) [m]: the point's position
//   point_fx, point_fy, point_fz (time, point) [N]: the lines' force on it (points.csv's)
//   tension_start, tension_end, tension_max (time, line) [N], link_max (time, line): each
//   line's rows of its timeseries.csv
//   body_x, body_y, body_z [m], body_rx, body_ry, body_rz [deg], body_fx, body_fy, body_fz [N],
//   body_mx, body_my, body_mz [N m] (time, body): body.csv's
//
// The rows are small (a few numbers per point and line): they are gathered kChunkRows at a
// time and each chunk written and deflated as it fills, on the simulation's thread.
#include <string>
#include <vector>

#include "core/point_loads.h"
#include "io/netcdf_support.h"
#include "io/results_nc.h"

namespace cablefilm {

class ModelResultsWriter : public ModelResultsNc {
 public:
  static constexpr int kChunkRows = 256;

  // Creates `path`'s temporary file and writes what does not change. Throws Error.
  ModelResultsWriter(const std::string& path, const NetcdfResultsInfo& info,
                      const Model& model, const Inputs& in);
  ~ModelResultsWriter() override;  // uncommitted: the temporary file removed
  ModelResultsWriter(const ModelResultsWriter&) = delete;
  ModelResultsWriter& operator=(const ModelResultsWriter&) = delete;

  bool Row(const Data& d) override;  // throws Error on a write error
  void Commit() override;                                // the complete file, under its name
  void CommitPartial(const std::string& path) override;  // an incomplete run, another name

 private:
  // A time-dependent variable: its id, values per row, and the rows gathered.
  struct Series {
    int var = -1;
    int width = 1;              // values per row (points, lines or bodies)
    std::vector<double> rows;   // row-major, up to kChunkRows rows
  };
  void Define(const NetcdfResultsInfo& info);
  void Flush();  // writes the rows gathered; throws Error

  const Model& model_;
  const Inputs& in_;
  PointLoads loads_;
  std::string path_, temp_path_;
  int ncid_ = -1;
  int var_time_ = -1;
  std::vector<double> time_;
  std::vector<Series> series_;  // in the order Row fills them
  long written_ = 0;            // rows in the file
  bool committed_ = false;
};

}  // namespace cablefilm
