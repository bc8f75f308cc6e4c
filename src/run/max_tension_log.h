#pragma once
// The largest link tension of every output row of a run (the tension_max column of
// timeseries.csv, as exact doubles), and the tensions of its two end links (tension_start,
// tension_end), kept in an anonymous temporary file (32 bytes a row, gone when the program
// ends: memory stays bounded however long the run), made once the rows reach kMemoryRows: a
// short run of many lines holds no file per line. The one source of max_tension.png and of the
// film's time plot, so that both agree with the CSV and the run's reported peak (RunSummary,
// from the same rows); and of the second pass of the end tensions' statistics
// (run/end_tension_pass.h), which needs their mean before it counts its up-crossings.
#include <cstdio>
#include <limits>
#include <vector>

namespace cablefilm {

class MaxTensionLog {
 public:
  // Rows kept in memory: the temporary file is made when rows() reaches it.
  static constexpr long kMemoryRows = 4096;

  MaxTensionLog() = default;
  ~MaxTensionLog();
  MaxTensionLog(MaxTensionLog&& other) noexcept;
  MaxTensionLog& operator=(MaxTensionLog&&) = delete;
  MaxTensionLog(const MaxTensionLog&) = delete;
  MaxTensionLog& operator=(const MaxTensionLog&) = delete;

  // One output row: its time t [s] (increasing), its largest link tension and its end links'
  // tensions [N]. Throws Error if the temporary file cannot be made or written.
  void Append(double t, double tension_max, double tension_start = 0, double tension_end = 0);

  long rows() const { return rows_; }

  // Reads the rows in order, from the first. Appending meanwhile is allowed (a cursor sees the
  // rows appended before each call).
  class Cursor {
   public:
    explicit Cursor(const MaxTensionLog& log) : log_(&log) {}
    // The next row (true) if there is one and its time is at most `t_until` [s]; else false and
    // the cursor stays. Throws Error on a read error.
    bool Next(double t_until, double* t, double* tension_max);
    // The same with the end links' tensions [N] (tension_start, tension_end) of the row.
    bool Next(double t_until, double* t, double* tension_max, double* tension_start,
              double* tension_end);
    long position() const { return next_; }  // rows read so far

   private:
    const MaxTensionLog* log_;
    long next_ = 0;             // the next row to hand out
    long block_first_ = 0;      // the row held at block_[0]
    std::vector<double> block_; // rows read ahead (kWidth numbers each)
  };

  // The numbers of a row: t, tension_max, tension_start, tension_end.
  static constexpr long kWidth = 4;

 private:
  void WritePending();
  std::FILE* file_ = nullptr;
  long rows_ = 0;
  long written_ = 0;             // rows in the file; the rest are in pending_
  std::vector<double> pending_;  // rows not yet written (kWidth numbers each)
};

}  // namespace cablefilm
