#pragma once
// The time series of a live session, every frame's row, kept in an anonymous temporary file
// (gone when the program ends) rather than in memory: hours of rows cost disk, not memory.
// Not thread-safe: the session guards it.
#include <Eigen/Core>
#include <cstdio>
#include <functional>
#include <string>


namespace cablefilm {

class RowLog {
 public:
  // `header`: the CSV's first line, with its newline. Throws Error if no temporary file can be
  // made.
  explicit RowLog(std::string header);
  ~RowLog();
  RowLog(const RowLog&) = delete;
  RowLog& operator=(const RowLog&) = delete;

  void Clear();  // a restart
  // One row: `write` prints it, with its newline.
  void Append(const std::function<void(std::FILE*)>& write);
  long rows() const { return rows_; }
  // The bytes written so far (flushed): call under the session's lock...
  long Flush();
  // ...then read them without it (the rows keep being appended meanwhile): the CSV in pieces,
  // `sink` returns false to stop early. A restart meanwhile ends the read short.
  void Read(long size, const std::function<bool(const char* data, std::size_t size)>& sink) const;

 private:
  std::FILE* file_ = nullptr;
  std::string header_;
  long rows_ = 0;
};

}  // namespace cablefilm
