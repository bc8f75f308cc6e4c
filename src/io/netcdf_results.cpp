#include "io/netcdf_results.h"

#include <netcdf.h>
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/error.h"
#include "io/output_ledger.h"
#include "io/netcdf_support.h"

namespace cablefilm {

NetcdfResultsWriter::NetcdfResultsWriter(const std::string& path, const NetcdfResultsInfo& info,
                                         const LineModel& m, const State& initial,
                                         const Eigen::VectorXd& initial_tension, int line)
    : LineResultsNc(line),
      path_(path),
      temp_path_(path + ".tmp" + std::to_string(::getpid())),
      scene_(info.scene) {
  KeepFreedMemoryForTheCompressor();
  SkipHdf5CleanupAtExit();
  RecordOutput(path_);
  try {
    Define(info, m, initial, initial_tension);
    filling_ = NewBlock();
    StartWriter();
  } catch (...) {
    if (ncid_ >= 0) nc_close(ncid_);
    std::remove(temp_path_.c_str());
    throw;
  }
}

void NetcdfResultsWriter::Define(const NetcdfResultsInfo& info, const LineModel& m,
                                 const State& initial,
                                 const Eigen::VectorXd& initial_tension) {
  stations_ = m.stations();
  links_ = m.line.links;
  const std::string& f = temp_path_;
  errno = 0;  // Check reads it
  int created = -1;
  NetcdfCheck(nc_create(f.c_str(), NC_NETCDF4 | NC_CLOBBER, &created), f, "create");
  ncid_ = created;
  const int nc = ncid_;

  // Chunks of all stations (at most kChunkBytes of them) by up to kChunkRows rows.
  const long per_chunk = kChunkBytes / static_cast<long>(sizeof(double));
  const size_t chunk_stations = static_cast<size_t>(std::min<long>(stations_, per_chunk));
  chunk_rows_ = static_cast<int>(
      std::clamp<long>(per_chunk / static_cast<long>(chunk_stations), 1, kChunkRows));
  const size_t rows = static_cast<size_t>(chunk_rows_);

  int dim_time = -1, dim_station = -1, dim_link = -1;
  NetcdfCheck(nc_def_dim(nc, "time", NC_UNLIMITED, &dim_time), f, "time");
  NetcdfCheck(nc_def_dim(nc, "station", static_cast<size_t>(stations_), &dim_station), f, "station");
  NetcdfCheck(nc_def_dim(nc, "link", static_cast<size_t>(links_), &dim_link), f, "link");

  // A variable with its units and long name; chunked when it has a time axis, and then deflated
  // when the file is large.
  struct Cache {
    int var;
    size_t bytes;
  };
  std::vector<Cache> caches;  // of the variables over time
  // A row: x, y, z of every station, the tension of every link, time and the ends' 6.
  const bool deflate =
      DeflateResults(info, sizeof(double) * (kDim * stations_ + links_ + 1 + 2 * kDim));
  // `zeros`: a variable along the cable known to hold zeros only (z in the plane).
  auto define = [&](const char* name, nc_type type, std::vector<int> dims, const char* units,
                    const std::string& long_name, bool zeros = false) {
    int var = -1;
    NetcdfCheck(nc_def_var(nc, name, type, static_cast<int>(dims.size()), dims.data(), &var), f, name);
    if (dims[0] == dim_time) {
      std::vector<size_t> chunks{dims.size() == 1 ? rows * 16 : rows};
      if (dims.size() == 2) chunks.push_back(std::min(chunk_stations, static_cast<size_t>(links_)));
      if (dims.size() == 2 && dims[1] == dim_station) chunks[1] = chunk_stations;
      NetcdfCheck(nc_def_var_chunking(nc, var, NC_CHUNKED, chunks.data()), f, name);
      // A 2-D variable gets whole chunks, each written once: no cache, so each is (deflated and)
      // written as it comes (by the writer's thread) rather than all at the close. A 1-D one
      // gets a 16th of a chunk at a time: a cache of two chunks, the full one leaving it as the
      // next is begun. Set after nc_enddef (below): netCDF applies a variable's cache when it
      // opens the HDF5 dataset, and a cache set in define mode is not applied to the dataset
      // nc_enddef creates: every chunk stayed in the default cache and was deflated at the close.
      caches.push_back({var, dims.size() == 1 ? 2 * chunks[0] * sizeof(double) : 0});
    }
    // Level 1 when deflated: at 6000 links 2 % larger than level 4 (162 against 159 MB) and
    // 1.1 s less CPU. A file of under kDeflateAboveBytes is not (DeflateResults). Along the
    // cable only z in the plane is: positions and tensions keep most of their bits, so deflate
    // saved a quarter to a third of their bytes at 100 MB/s of one core, a tenth of the disk's
    // speed (P63 at 6000 links: 3.2 s of CPU to save 97 MB of 259); zeros deflate at 700 MB/s
    // to nothing.
    const bool along_cable = dims.size() == 2;
    if (deflate && (!along_cable || zeros))
      NetcdfCheck(nc_def_var_deflate(nc, var, 1, 1, 1), f, name);
    NetcdfCheck(nc_def_var_fill(nc, var, NC_NOFILL, nullptr), f, name);  // every value is written
    NetcdfText(nc, var, "units", units, f);
    NetcdfText(nc, var, "long_name", long_name, f);
    return var;
  };

  var_time_ = define("time", NC_DOUBLE, {dim_time}, "s", "simulated time");
  NetcdfText(nc, var_time_, "axis", "T", f);
  const int var_station = define("station", NC_INT, {dim_station}, "1",
                                 "station index j, from 0 at the start to s at the end");
  const int var_link =
      define("link", NC_INT, {dim_link}, "1", "link index j of link j+1/2 (stations j to j+1)");
  const int var_s = define("s", NC_DOUBLE, {dim_station}, "m",
                           "unstretched arc length of the station from station 0");
  const int var_s_link = define("s_link", NC_DOUBLE, {dim_link}, "m",
                                "unstretched arc length of the link midpoint from station 0");

  // The axes: x and z horizontal, y up (z = 0 throughout for a cable in the x-y plane).
  const char* axis_names[kDim] = {"x", "y", "z"};
  const char* axis_long[kDim] = {"horizontal position x", "vertical position y",
                                 "horizontal position z"};
  const char* axis_note[kDim] = {"", " (up; gravity along -y)", " (across the x-y plane)"};
  for (int c = 0; c < kDim; ++c)
    var_x_[c] = define(axis_names[c], NC_DOUBLE, {dim_time, dim_station}, "m",
                       std::string(axis_long[c]) + " of the station" + axis_note[c],
                       c == 2 && info.planar);
  var_tension_ = define("tension", NC_DOUBLE, {dim_time, dim_link}, "N",
                        "tension of the link (0 when slack)");
  for (int var : var_x_) NetcdfText(nc, var, "coordinates", "s", f);
  NetcdfText(nc, var_tension_, "coordinates", "s_link", f);

  // x_start, y_start, z_start, x_end, y_end, z_end.
  for (int k = 0; k < 2 * kDim; ++k) {
    const char* axis = axis_names[k % kDim];
    const bool start = k < kDim;
    var_end_[k] = define((std::string(axis) + (start ? "_start" : "_end")).c_str(), NC_DOUBLE,
                         {dim_time}, "m",
                         std::string(axis_long[k % kDim]) +
                             (start ? " of the start (station 0)" : " of the end (station s)"));
  }

  const bool equilibrium = info.initial_state != "straight";
  const std::string state = equilibrium ? "static equilibrium at t = 0"
                                        : "initial state at t = 0 (the straight chord at rest, "
                                          "not an equilibrium)";
  int var_eq[kDim] = {-1, -1, -1};  // x_equilibrium, y_equilibrium, z_equilibrium
  for (int c = 0; c < kDim; ++c)
    var_eq[c] = define((std::string(axis_names[c]) + "_equilibrium").c_str(), NC_DOUBLE,
                       {dim_station}, "m",
                       std::string(axis_long[c]) + " of the station, " + state);
  const int var_t_eq = define("tension_equilibrium", NC_DOUBLE, {dim_link}, "N",
                              "tension of the link, " + state);
  for (int var : var_eq) NetcdfText(nc, var, "coordinates", "s", f);
  NetcdfText(nc, var_t_eq, "coordinates", "s_link", f);
  // With a breaking load on any material: each link's (0: its material has none), so that
  // tension / minimum_breaking_load is the utilisation.
  const int var_mbl =
      m.line.has_breaking_load()
          ? define("minimum_breaking_load", NC_DOUBLE, {dim_link}, "N",
                   "minimum breaking load of the link's material (0: not given)")
          : -1;
  if (var_mbl >= 0) NetcdfText(nc, var_mbl, "coordinates", "s_link", f);

  NetcdfGlobalAttributes(nc, info, f);
  NetcdfCheck(nc_enddef(nc), f, "enddef");
  for (const Cache& c : caches)
    NetcdfCheck(nc_set_var_chunk_cache(nc, c.var, c.bytes, 101, 1.0f), f, "chunk cache");

  std::vector<int> index(static_cast<size_t>(stations_));
  for (int j = 0; j < stations_; ++j) index[static_cast<size_t>(j)] = j;
  std::vector<double> s_link(static_cast<size_t>(links_)), row(static_cast<size_t>(stations_));
  for (int j = 0; j < links_; ++j)
    s_link[static_cast<size_t>(j)] = 0.5 * (m.line.arc_length[j] + m.line.arc_length[j + 1]);
  NetcdfCheck(nc_put_var_int(nc, var_station, index.data()), f, "station");
  NetcdfCheck(nc_put_var_int(nc, var_link, index.data()), f, "link");
  NetcdfCheck(nc_put_var_double(nc, var_s, m.line.arc_length.data()), f, "s");
  NetcdfCheck(nc_put_var_double(nc, var_s_link, s_link.data()), f, "s_link");
  for (int c = 0; c < kDim; ++c) {
    for (int j = 0; j < stations_; ++j) row[static_cast<size_t>(j)] = initial.x(c, j);
    NetcdfCheck(nc_put_var_double(nc, var_eq[c], row.data()), f, "equilibrium");
  }
  NetcdfCheck(nc_put_var_double(nc, var_t_eq, initial_tension.data()), f, "tension_equilibrium");
  if (var_mbl >= 0)
    NetcdfCheck(nc_put_var_double(nc, var_mbl, m.line.breaking_load.data()), f,
                "minimum_breaking_load");
}

void NetcdfResultsWriter::StartWriter() {
  // SIGINT and SIGTERM blocked in the writer's thread: the program's handlers run on the
  // simulation's thread.
  sigset_t block, previous;
  sigemptyset(&block);
  sigaddset(&block, SIGINT);
  sigaddset(&block, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &block, &previous);
  try {
    writer_ = std::thread([this] { WriterLoop(); });
  } catch (...) {
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    throw;
  }
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
}

NetcdfResultsWriter::~NetcdfResultsWriter() {
  StopWriter(true);
  if (ncid_ >= 0) nc_close(ncid_);
  if (!committed_) std::remove(temp_path_.c_str());
}

std::unique_ptr<NetcdfResultsWriter::Block> NetcdfResultsWriter::NewBlock() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!free_.empty()) {
      std::unique_ptr<Block> b = std::move(free_.back());
      free_.pop_back();
      b->rows = 0;
      return b;
    }
  }
  auto b = std::make_unique<Block>();
  const size_t rows = static_cast<size_t>(chunk_rows_);
  b->time.resize(rows);
  for (auto& axis : b->x) axis.resize(rows * static_cast<size_t>(stations_));
  b->tension.resize(rows * static_cast<size_t>(links_));
  for (auto& e : b->ends) e.resize(rows);
  return b;
}

void NetcdfResultsWriter::Append(const State& s, const Eigen::VectorXd& tension) {
  if (!filling_) filling_ = NewBlock();  // after a failed hand-over
  Block& b = *filling_;
  if (b.rows == 0) b.first = rows_;
  const size_t r = static_cast<size_t>(b.rows);
  const size_t n = static_cast<size_t>(stations_);
  b.time[r] = s.t;
  for (int c = 0; c < kDim; ++c) {
    double* axis = b.x[c].data() + r * n;
    for (int j = 0; j < stations_; ++j) axis[j] = s.x(c, j);
    b.ends[c][r] = s.x(c, 0);
    b.ends[kDim + c][r] = s.x(c, links_);
  }
  std::copy(tension.data(), tension.data() + links_, b.tension.data() + r * links_);
  ++b.rows;
  ++rows_;
  if (b.rows == chunk_rows_) {
    Hand(std::move(filling_));
    filling_ = NewBlock();
  }
}

void NetcdfResultsWriter::Hand(std::unique_ptr<Block> block) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return queue_.size() < kQueuedChunks || !error_.empty(); });
  if (!error_.empty()) throw Error(error_);
  queue_.push_back(std::move(block));
  changed_.notify_all();
}

void NetcdfResultsWriter::WriterLoop() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return !queue_.empty() || stopping_; });
    if (queue_.empty()) return;  // stopping, and all written
    std::unique_ptr<Block> b = std::move(queue_.front());
    queue_.pop_front();
    const bool failed = !error_.empty();
    lock.unlock();
    std::string error;
    if (!failed) {
      try {
        Write(*b);
      } catch (const std::exception& e) {
        error = e.what();
      }
    }
    lock.lock();
    if (!error.empty() && error_.empty()) error_ = error;
    free_.push_back(std::move(b));
    changed_.notify_all();
  }
}

void NetcdfResultsWriter::Write(const Block& b) {
  const std::string& f = temp_path_;
  errno = 0;
  const size_t start[2] = {static_cast<size_t>(b.first), 0};
  const size_t count_x[2] = {static_cast<size_t>(b.rows), static_cast<size_t>(stations_)};
  const size_t count_t[2] = {static_cast<size_t>(b.rows), static_cast<size_t>(links_)};
  NetcdfCheck(nc_put_vara_double(ncid_, var_time_, start, count_x, b.time.data()), f, "time");
  for (int c = 0; c < kDim; ++c)
    NetcdfCheck(nc_put_vara_double(ncid_, var_x_[c], start, count_x, b.x[c].data()), f, "positions");
  NetcdfCheck(nc_put_vara_double(ncid_, var_tension_, start, count_t, b.tension.data()), f, "tension");
  for (int k = 0; k < 2 * kDim; ++k)
    NetcdfCheck(nc_put_vara_double(ncid_, var_end_[k], start, count_x, b.ends[k].data()), f, "ends");
}

void NetcdfResultsWriter::StopWriter(bool drop) {
  if (!writer_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (drop) queue_.clear();
    stopping_ = true;
    changed_.notify_all();
  }
  writer_.join();
}

void NetcdfResultsWriter::Close() {
  if (committed_ || ncid_ < 0) throw Error("internal: " + path_ + " committed twice");
  if (filling_ && filling_->rows > 0) Hand(std::move(filling_));
  StopWriter(false);  // the thread writes what waits, then ends
  if (!error_.empty()) throw Error(error_);
  errno = 0;
  // The scene's text, the last attribute, written as the file closes: netCDF keeps a copy of
  // each attribute it has written while the file is open, and a system's text grows with its
  // lines (400 lines of a 0.5 MB scene held 200 MB).
  NetcdfCheck(nc_redef(ncid_), temp_path_, "redef");
  NetcdfSceneAttribute(ncid_, scene_, temp_path_);
  const std::vector<std::pair<int, double>> statistics = DefineEndStatistics();
  NetcdfCheck(nc_enddef(ncid_), temp_path_, "enddef");
  for (const auto& [var, value] : statistics)
    NetcdfCheck(nc_put_var_double(ncid_, var, &value), temp_path_, "end tension statistics");
  const int id = ncid_;
  ncid_ = -1;
  NetcdfCheck(nc_close(id), temp_path_, "close");
}

std::vector<std::pair<int, double>> NetcdfResultsWriter::DefineEndStatistics() {
  std::vector<std::pair<int, double>> values;
  if (!ends_[0].known()) return values;
  const std::string& f = temp_path_;
  const char* names[2] = {"start", "end"};
  const char* where[2] = {"station 0", "station s"};
  for (int e = 0; e < 2; ++e) {
    const TensionStatistics& t = ends_[e];
    const std::string of = std::string(" of the tension of the end link at ") + where[e] +
                           " over the rows";
    const struct {
      const char* name;
      nc_type type;
      const char* units;
      std::string long_name;
      double value;
    } vars[] = {
        {"mean", NC_DOUBLE, "N", "mean" + of, t.mean},
        {"std", NC_DOUBLE, "N", "standard deviation" + of, t.sigma},
        {"min", NC_DOUBLE, "N", "minimum" + of, t.min},
        {"max", NC_DOUBLE, "N", "maximum" + of, t.max},
        {"upcrossings", NC_INT, "1", "upward crossings of the mean" + of,
         static_cast<double>(t.upcrossings)},
        {"mpm", NC_DOUBLE, "N",
         "most probable maximum (Rayleigh: mean + std sqrt(2 ln upcrossings))" + of, t.mpm},
        {"psd_m0", NC_DOUBLE, "N^2", "integral of the Welch spectrum" + of, t.psd_m0},
    };
    for (const auto& v : vars) {
      const std::string name = std::string("tension_") + names[e] + "_" + v.name;
      int var = -1;
      NetcdfCheck(nc_def_var(ncid_, name.c_str(), v.type, 0, nullptr, &var), f, name.c_str());
      NetcdfText(ncid_, var, "units", v.units, f);
      NetcdfText(ncid_, var, "long_name", v.long_name, f);
      values.emplace_back(var, v.value);
    }
  }
  return values;
}

void NetcdfResultsWriter::Commit() { CommitPartial(path_); }

void NetcdfResultsWriter::CommitPartial(const std::string& path) {
  Close();
  RecordOutput(path);
  if (std::rename(temp_path_.c_str(), path.c_str()) != 0)
    throw Error("cannot rename " + temp_path_ + " to " + path + ": " + std::strerror(errno));
  committed_ = true;
}

}  // namespace cablefilm
