#include "live/row_log.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>
#include <utility>

#include "core/error.h"

namespace cablefilm {

RowLog::RowLog(std::string header, long max_bytes)
    : file_(std::tmpfile()), header_(std::move(header)), max_bytes_(max_bytes) {
  if (!file_) throw Error(std::string("live: cannot create a temporary file for the time series: ") +
                          std::strerror(errno));
  Clear();
}

RowLog::~RowLog() { std::fclose(file_); }

void RowLog::Clear() {
  ++generation_;
  std::fflush(file_);
  if (ftruncate(fileno(file_), 0) != 0) { /* the rewind below still restarts the rows */ }
  std::rewind(file_);
  std::fputs(header_.c_str(), file_);
  rows_ = 0;
  frames_ = 0;
  stride_ = 1;
}

void RowLog::Append(const std::function<void(std::FILE*)>& write) {
  if (frames_++ % stride_ != 0) return;
  write(file_);
  ++rows_;
  if (std::ftell(file_) > max_bytes_ && rows_ > 1) Thin();
}

// Every second row kept, moved down in place (a row is written no further on than it was
// read), the file cut after them; then every second of the rows to come.
void RowLog::Thin() {
  ++generation_;
  std::fflush(file_);
  const int fd = fileno(file_);
  const long end = std::ftell(file_);
  char buffer[1 << 16];
  std::string line;  // a row read in pieces
  long read = 0, written = 0, row = -1;  // row -1: the header
  while (read < end) {
    const ssize_t got = pread(fd, buffer, static_cast<size_t>(std::min<long>(sizeof buffer, end - read)), read);
    if (got <= 0) break;
    read += got;
    for (ssize_t i = 0; i < got; ++i) {
      line += buffer[i];
      if (buffer[i] != '\n') continue;
      if (row < 0 || row % 2 == 0) {
        if (pwrite(fd, line.data(), line.size(), written) != static_cast<ssize_t>(line.size()))
          throw Error(std::string("live: cannot thin the time series' temporary file: ") +
                      std::strerror(errno));
        written += static_cast<long>(line.size());
      }
      ++row;
      line.clear();
    }
  }
  if (ftruncate(fd, written) != 0) { /* the rows past `written` are overwritten as they come */ }
  std::fseek(file_, written, SEEK_SET);
  rows_ = (rows_ + 1) / 2;
  stride_ *= 2;
  ++generation_;
}

long RowLog::Flush() {
  std::fflush(file_);
  return std::ftell(file_);
}

void RowLog::Read(long end, const std::function<bool(const char*, std::size_t)>& sink) const {
  char buffer[1 << 16];
  long offset = 0;
  const long generation = generation_;
  while (offset < end) {
    const ssize_t want = static_cast<ssize_t>(std::min<long>(sizeof buffer, end - offset));
    const ssize_t got = pread(fileno(file_), buffer, want, offset);  // leaves the append position
    if (got <= 0 || generation_ != generation) break;  // rewritten meanwhile: what was read may mix
    if (!sink(buffer, static_cast<std::size_t>(got))) break;
    offset += got;
  }
}

}  // namespace cablefilm
