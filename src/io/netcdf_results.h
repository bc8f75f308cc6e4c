#pragma once
// results.nc: every station and every link over time, NetCDF-4 following the CF-1.8
// conventions, streamed to disk as the rows come (bounded memory however long the run), written
// whole or not at all like the CSV files (a temporary name beside it, then a rename).
//
//   dimensions  time (unlimited), station (s + 1), link (s: link j+1/2 is link j)
//   time(time) [s]; station(station), link(link): the indices j
//   s(station), s_link(link) [m]: unstretched arc length of the stations, of the link midpoints
//   x(time, station), y(time, station), z(time, station) [m]; tension(time, link) [N]
//   x_start, y_start, z_start, x_end, y_end, z_end (time) [m]: the ends' motion
//   x_equilibrium, y_equilibrium, z_equilibrium (station) [m], tension_equilibrium (link) [N]:
//   the initial state
//   tension_start_mean, _std, _min, _max, _upcrossings, _mpm, _psd_m0 and the same of
//   tension_end (scalars) [N, 1, N^2]: the end links' tensions' statistics over the rows, when
//   the run set them (a complete run; run/end_tension_pass.h)
// (z is 0 throughout for a cable in the x-y plane: a 2D scene.)
//
// Time-dependent variables are chunked by time: a chunk is up to kChunkRows rows of all
// stations (fewer for a cable whose row is large); deflated (level 1, with the shuffle filter)
// when the file is large (DeflateResults, io/netcdf_support.h). The rows are gathered a chunk
// at a time and handed to a thread of the writer's own, which alone calls the library and
// writes each chunk as it comes (deflating doubles costs about as much as simulating a 60-link
// cable, and the other core is idle during the simulation); at most kQueuedChunks wait for it,
// so memory stays a few chunks however long the run, and a run that outpaces the disk waits.
#include <Eigen/Core>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "core/line_model.h"
#include "core/line_data.h"
#include "io/netcdf_support.h"
#include "run/driver.h"

namespace cablefilm {

class NetcdfResultsWriter : public LineResultsNc {
 public:
  static constexpr int kChunkRows = 64;            // rows of a chunk, at most
  static constexpr long kChunkBytes = 4L << 20;    // bytes of a chunk of x, at most (about)
  static constexpr size_t kQueuedChunks = 2;       // waiting for the writer's thread, at most

  // Creates `path`'s temporary file and writes what does not change over time. Throws Error.
  NetcdfResultsWriter(const std::string& path, const NetcdfResultsInfo& info,
                      const LineModel& m, const State& initial,
                      const Eigen::VectorXd& initial_tension, int line = 0);
  ~NetcdfResultsWriter() override;  // uncommitted: the rows not yet written are dropped, the
                           // file removed
  NetcdfResultsWriter(const NetcdfResultsWriter&) = delete;
  NetcdfResultsWriter& operator=(const NetcdfResultsWriter&) = delete;

  // One output row. Throws Error on a write error (of this row or of an earlier chunk).
  void Append(const State& state, const Eigen::VectorXd& tension) override;
  // Writes the rows still waiting, closes and renames; throws Error on a write error.
  void Commit() override;                                // the complete file, under its name
  void CommitPartial(const std::string& path) override;  // an incomplete run, another name

  long rows() const { return rows_; }
  int chunk_rows() const { return chunk_rows_; }

 private:
  // Defines the end tensions' statistics (ends_) as scalar variables, in define mode: each
  // variable and the value to put once out of it; none when not set.
  std::vector<std::pair<int, double>> DefineEndStatistics();
  // Up to a chunk of rows, row-major, from row `first`.
  struct Block {
    long first = 0;
    int rows = 0;
    std::vector<double> time, tension;
    std::vector<double> x[kDim];     // by axis: x, y, z
    std::vector<double> ends[2 * kDim];  // x_start, y_start, z_start, x_end, y_end, z_end
  };
  void Define(const NetcdfResultsInfo& info, const LineModel& m, const State& initial,
              const Eigen::VectorXd& initial_tension);  // the file and what is fixed
  void StartWriter();
  std::unique_ptr<Block> NewBlock();  // a free one, or a new one
  void Hand(std::unique_ptr<Block> block);  // to the writer's thread; throws its error
  void WriterLoop();                        // the thread: writes the blocks handed to it
  void Write(const Block& b);               // throws Error
  void StopWriter(bool drop);               // joins the thread (dropping what waits)
  void Close();                             // the rest written, the file closed; throws Error

  std::string path_, temp_path_;
  std::shared_ptr<const std::string> scene_;  // written as the file closes
  int ncid_ = -1;
  int stations_ = 0, links_ = 0, chunk_rows_ = 1;
  int var_time_ = -1, var_tension_ = -1;
  int var_x_[kDim] = {-1, -1, -1};        // x, y, z
  int var_end_[2 * kDim] = {-1, -1, -1, -1, -1, -1};
  long rows_ = 0;
  std::unique_ptr<Block> filling_;  // the rows not yet handed over
  bool committed_ = false;

  std::mutex mutex_;                // guards what follows
  std::condition_variable changed_;
  std::deque<std::unique_ptr<Block>> queue_;  // handed over, not yet written
  std::vector<std::unique_ptr<Block>> free_;
  bool stopping_ = false;
  std::string error_;               // the writer's first error; nothing is written after it
  std::thread writer_;
};

}  // namespace cablefilm
