#pragma once
// The largest link tension of every output row of a run (the tension_max column of
// timeseries.csv, as exact doubles), kept in an anonymous temporary file (16 bytes a row, gone
// when the program ends: memory stays bounded however long the run) with the peak over the
// rows. The one source of the run's reported peak, of max_tension.png and of the film's time
// plot, so that all of them agree with the CSV.
#include <cstdio>
#include <limits>
#include <vector>

namespace cablefilm {

class MaxTensionLog {
 public:
  MaxTensionLog();  // throws Error if no temporary file can be made
  ~MaxTensionLog();
  MaxTensionLog(MaxTensionLog&& other) noexcept;
  MaxTensionLog& operator=(MaxTensionLog&&) = delete;
  MaxTensionLog(const MaxTensionLog&) = delete;
  MaxTensionLog& operator=(const MaxTensionLog&) = delete;

  // One output row: its time t [s] (increasing), the largest link tension [N] and its link.
  // Throws Error if the temporary file cannot be written.
  void Append(double t, double tension_max, int link);

  long rows() const { return rows_; }
  // The largest tension_max of the rows [N], the first row's time holding it [s] and its link;
  // NaN (link -1) before any row.
  double peak() const { return peak_; }
  double peak_t() const { return peak_t_; }
  int peak_link() const { return peak_link_; }

  // Reads the rows in order, from the first. Appending meanwhile is allowed (a cursor sees the
  // rows appended before each call).
  class Cursor {
   public:
    explicit Cursor(const MaxTensionLog& log) : log_(&log) {}
    // The next row (true) if there is one and its time is at most `t_until` [s]; else false and
    // the cursor stays. Throws Error on a read error.
    bool Next(double t_until, double* t, double* tension_max);
    long position() const { return next_; }  // rows read so far

   private:
    const MaxTensionLog* log_;
    long next_ = 0;             // the next row to hand out
    long block_first_ = 0;      // the row held at block_[0]
    std::vector<double> block_; // rows read ahead (t, tension pairs)
  };

 private:
  static constexpr long kBlockRows = 4096;
  void WritePending();
  std::FILE* file_ = nullptr;
  long rows_ = 0;
  long written_ = 0;             // rows in the file; the rest are in pending_
  std::vector<double> pending_;  // (t, tension) pairs not yet written
  double peak_ = std::numeric_limits<double>::quiet_NaN();
  double peak_t_ = std::numeric_limits<double>::quiet_NaN();
  int peak_link_ = -1;
};

}  // namespace cablefilm
