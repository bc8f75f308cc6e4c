#pragma once
// The time series of a live session, every frame's row, kept in an anonymous temporary file
// (gone when the program ends) rather than in memory: hours of rows cost disk, not memory, and
// at most `max_bytes` of it. Past that the rows are thinned to every second one, and from
// then on only every second (then fourth, ...) frame's row is kept: the whole session stays,
// ever more coarsely, as a large system's rows of 1 MB/s would otherwise fill the disk.
// Not thread-safe: the session guards it (but Read, below).
#include <Eigen/Core>
#include <atomic>
#include <cstdio>
#include <functional>
#include <string>


namespace cablefilm {

class RowLog {
 public:
  // `header`: the CSV's first line, with its newline. Throws Error if no temporary file can be
  // made.
  explicit RowLog(std::string header, long max_bytes = kMaxBytes);
  static constexpr long kMaxBytes = 256L << 20;  // [bytes]
  ~RowLog();
  RowLog(const RowLog&) = delete;
  RowLog& operator=(const RowLog&) = delete;

  void Clear();  // a restart
  // One frame's row: `write` prints it, with its newline (unless thinning skips it).
  void Append(const std::function<void(std::FILE*)>& write);
  long rows() const { return rows_; }      // kept
  long stride() const { return stride_; }  // one frame's row kept of every `stride`
  // The bytes written so far (flushed): call under the session's lock...
  long Flush();
  // ...then read them without it (the rows keep being appended meanwhile): the CSV in pieces,
  // `sink` returns false to stop early. A restart or a thinning meanwhile ends the read short.
  void Read(long size, const std::function<bool(const char* data, std::size_t size)>& sink) const;

 private:
  void Thin();
  std::FILE* file_ = nullptr;
  std::string header_;
  long max_bytes_;
  long rows_ = 0;
  long frames_ = 0;  // rows offered since the restart
  long stride_ = 1;
  std::atomic<long> generation_{0};  // changes as the file is rewritten (a reader stops)
};

}  // namespace cablefilm
