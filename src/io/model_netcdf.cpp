#include "io/model_netcdf.h"

#include <netcdf.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/error.h"
#include "io/output_ledger.h"

namespace cablefilm {
namespace {

constexpr int kPointSeries = 6;  // point_x, _y, _z, _fx, _fy, _fz
constexpr int kLineSeries = 4;   // tension_start, tension_end, tension_max, link_max
constexpr int kBodySeries = 12;  // body_x .. body_mz

}  // namespace

ModelResultsWriter::ModelResultsWriter(const std::string& path, const NetcdfResultsInfo& info,
                                         const Model& model, const Inputs& in)
    : model_(model), in_(in), loads_(model), path_(path),
      temp_path_(path + ".tmp" + std::to_string(::getpid())) {
  KeepFreedMemoryForTheCompressor();
  SkipHdf5CleanupAtExit();
  RecordOutput(path_);
  try {
    Define(info);
  } catch (...) {
    if (ncid_ >= 0) nc_close(ncid_);
    std::remove(temp_path_.c_str());
    throw;
  }
}

ModelResultsWriter::~ModelResultsWriter() {
  if (ncid_ >= 0) nc_close(ncid_);
  if (!committed_) std::remove(temp_path_.c_str());
}

void ModelResultsWriter::Define(const NetcdfResultsInfo& info) {
  const std::string& f = temp_path_;
  errno = 0;  // NetcdfCheck reads it
  int created = -1;
  NetcdfCheck(nc_create(f.c_str(), NC_NETCDF4 | NC_CLOBBER, &created), f, "create");
  ncid_ = created;
  const int nc = ncid_;
  const int lines = static_cast<int>(model_.lines.size());
  const int points = static_cast<int>(model_.points.size());
  const int bodies = static_cast<int>(model_.bodies.size());

  int dim_time = -1, dim_line = -1, dim_point = -1, dim_body = -1;
  NetcdfCheck(nc_def_dim(nc, "time", NC_UNLIMITED, &dim_time), f, "time");
  NetcdfCheck(nc_def_dim(nc, "line", static_cast<size_t>(lines), &dim_line), f, "line");
  NetcdfCheck(nc_def_dim(nc, "point", static_cast<size_t>(points), &dim_point), f, "point");
  if (bodies > 0)
    NetcdfCheck(nc_def_dim(nc, "body", static_cast<size_t>(bodies), &dim_body), f, "body");

  // A row: time, the points' 6 series, the lines' 4, the bodies' 12.
  const bool deflate = DeflateResults(
      info, sizeof(double) *
                (1 + kPointSeries * points + kLineSeries * lines + kBodySeries * bodies));
  // A variable with its units and long name; over time: chunked by kChunkRows rows and, when
  // the file is large (DeflateResults), deflated (level 1, shuffle), as a line's results.nc.
  auto define = [&](const char* name, nc_type type, std::vector<int> dims, const char* units,
                    const std::string& long_name) {
    int var = -1;
    NetcdfCheck(nc_def_var(nc, name, type, static_cast<int>(dims.size()), dims.data(), &var), f,
                name);
    if (dims[0] == dim_time) {
      size_t width = 1;
      if (dims.size() == 2) NetcdfCheck(nc_inq_dimlen(nc, dims[1], &width), f, name);
      const size_t chunks[2] = {static_cast<size_t>(kChunkRows), width};
      NetcdfCheck(nc_def_var_chunking(nc, var, NC_CHUNKED, chunks), f, name);
      if (deflate) NetcdfCheck(nc_def_var_deflate(nc, var, 1, 1, 1), f, name);
    }
    if (units[0] != '\0') NetcdfText(nc, var, "units", units, f);
    NetcdfText(nc, var, "long_name", long_name, f);
    return var;
  };
  auto series = [&](const char* name, nc_type type, int dim, int width, const char* units,
                    const std::string& long_name) {
    series_.push_back({define(name, type, {dim_time, dim}, units, long_name), width, {}});
    series_.back().rows.reserve(static_cast<size_t>(kChunkRows * width));
  };

  var_time_ = define("time", NC_DOUBLE, {dim_time}, "s", "simulated time");
  NetcdfText(nc, var_time_, "axis", "T", f);
  const int var_line_name = define("line_name", NC_STRING, {dim_line}, "", "the line's name");
  const int var_point_name = define("point_name", NC_STRING, {dim_point}, "", "the point's name");
  const int var_start = define("line_start_point", NC_INT, {dim_line}, "1",
                               "index of the point at the line's station 0");
  const int var_end = define("line_end_point", NC_INT, {dim_line}, "1",
                             "index of the point at the line's station s");
  int var_body_name = -1;
  if (bodies > 0) var_body_name = define("body_name", NC_STRING, {dim_body}, "", "the body's name");

  const char* axes = "xyz";
  for (int c = 0; c < 3; ++c)
    series((std::string("point_") + axes[c]).c_str(), NC_DOUBLE, dim_point, points, "m",
           std::string("position ") + axes[c] + " of the point (y up)");
  for (int c = 0; c < 3; ++c)
    series((std::string("point_f") + axes[c]).c_str(), NC_DOUBLE, dim_point, points, "N",
           std::string("force along ") + axes[c] +
               " the lines exert on the point (points.csv's)");
  series("tension_start", NC_DOUBLE, dim_line, lines, "N",
         "tension of the line's first link (at station 0)");
  series("tension_end", NC_DOUBLE, dim_line, lines, "N",
         "tension of the line's last link (at station s)");
  series("tension_max", NC_DOUBLE, dim_line, lines, "N", "largest tension of the line's links");
  series("link_max", NC_INT, dim_line, lines, "1", "the link j+1/2 of the line carrying it");
  if (bodies > 0) {
    for (int c = 0; c < 3; ++c)
      series((std::string("body_") + axes[c]).c_str(), NC_DOUBLE, dim_body, bodies, "m",
             std::string("position ") + axes[c] + " of the body's reference point");
    for (int c = 0; c < 3; ++c)
      series((std::string("body_r") + axes[c]).c_str(), NC_DOUBLE, dim_body, bodies, "degree",
             std::string("the body's angle about ") + axes[c] +
                 " (turned about x, then y, then z)");
    for (int c = 0; c < 3; ++c)
      series((std::string("body_f") + axes[c]).c_str(), NC_DOUBLE, dim_body, bodies, "N",
             std::string("force along ") + axes[c] + " the lines exert on the body");
    for (int c = 0; c < 3; ++c)
      series((std::string("body_m") + axes[c]).c_str(), NC_DOUBLE, dim_body, bodies, "N m",
             std::string("moment about ") + axes[c] +
                 " of the lines' forces, about the body's reference point");
  }
  time_.reserve(kChunkRows);
  NetcdfGlobalAttributes(nc, info, f);
  NetcdfSceneAttribute(nc, info.scene, f);
  NetcdfCheck(nc_enddef(nc), f, "enddef");

  auto names = [&](int var, std::vector<const char*>& text) {
    if (!text.empty()) NetcdfCheck(nc_put_var_string(nc, var, text.data()), f, "names");
  };
  std::vector<const char*> text;
  for (const std::string& n : model_.line_names) text.push_back(n.c_str());
  names(var_line_name, text);
  text.clear();
  for (const Point& p : model_.points) text.push_back(p.name.c_str());
  names(var_point_name, text);
  if (bodies > 0) {
    text.clear();
    for (const BodySpec& b : model_.bodies) text.push_back(b.name.c_str());
    names(var_body_name, text);
  }
  std::vector<int> start(static_cast<size_t>(lines)), end(static_cast<size_t>(lines));
  for (int i = 0; i < lines; ++i) {
    start[static_cast<size_t>(i)] = model_.line_points[i][0];
    end[static_cast<size_t>(i)] = model_.line_points[i][1];
  }
  if (lines > 0) {
    NetcdfCheck(nc_put_var_int(nc, var_start, start.data()), f, "line_start_point");
    NetcdfCheck(nc_put_var_int(nc, var_end, end.data()), f, "line_end_point");
  }
}

bool ModelResultsWriter::Row(const Data& d) {
  loads_.Compute(model_, d, in_);
  time_.push_back(d.t);
  std::vector<Series>::iterator s = series_.begin();
  for (int c = 0; c < 3; ++c, ++s)
    for (int p = 0; p < s->width; ++p) s->rows.push_back(loads_.positions()(c, p));
  for (int c = 0; c < 3; ++c, ++s)
    for (int p = 0; p < s->width; ++p) s->rows.push_back(loads_.forces()(c, p));
  for (const LineData& d : d.lines) {
    const Eigen::VectorXd& T = d.tension();
    Eigen::Index link = 0;
    const double t_max = T.maxCoeff(&link);
    s[0].rows.push_back(T[0]);
    s[1].rows.push_back(T[T.size() - 1]);
    s[2].rows.push_back(t_max);
    s[3].rows.push_back(static_cast<double>(link));
  }
  s += kLineSeries;
  if (!model_.bodies.empty()) {
    const double deg = 180.0 / M_PI;
    for (int k = 0; k < 6; ++k)
      for (const Vec6& q : loads_.body_poses()) s[k].rows.push_back(k < 3 ? q[k] : q[k] * deg);
    for (int k = 0; k < 6; ++k)
      for (const Vec6& load : loads_.body_loads()) s[6 + k].rows.push_back(load[k]);
  }
  if (static_cast<int>(time_.size()) == kChunkRows) Flush();
  return true;
}

void ModelResultsWriter::Flush() {
  if (time_.empty()) return;
  const std::string& f = temp_path_;
  errno = 0;
  const size_t start[2] = {static_cast<size_t>(written_), 0};
  const size_t rows = time_.size();
  NetcdfCheck(nc_put_vara_double(ncid_, var_time_, start, &rows, time_.data()), f, "time");
  for (const Series& s : series_) {
    if (s.width == 0) continue;
    const size_t count[2] = {rows, static_cast<size_t>(s.width)};
    // link_max is whole: netCDF converts the doubles (exact small integers) to its type.
    NetcdfCheck(nc_put_vara_double(ncid_, s.var, start, count, s.rows.data()), f, "rows");
  }
  written_ += static_cast<long>(rows);
  time_.clear();
  for (Series& s : series_) s.rows.clear();
}

void ModelResultsWriter::Commit() { CommitPartial(path_); }

void ModelResultsWriter::CommitPartial(const std::string& path) {
  if (committed_ || ncid_ < 0) throw Error("internal: " + path_ + " committed twice");
  Flush();
  const int id = ncid_;
  ncid_ = -1;
  errno = 0;
  NetcdfCheck(nc_close(id), temp_path_, "close");
  RecordOutput(path);
  if (std::rename(temp_path_.c_str(), path.c_str()) != 0)
    throw Error("cannot rename " + temp_path_ + " to " + path + ": " + std::strerror(errno));
  committed_ = true;
}

}  // namespace cablefilm
