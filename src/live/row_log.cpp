#include "live/row_log.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include "core/error.h"

namespace cablefilm {

RowLog::RowLog(std::string header) : file_(std::tmpfile()), header_(std::move(header)) {
  if (!file_) throw Error(std::string("live: cannot create a temporary file for the time series: ") +
                          std::strerror(errno));
  Clear();
}

RowLog::~RowLog() { std::fclose(file_); }

void RowLog::Clear() {
  std::fflush(file_);
  if (ftruncate(fileno(file_), 0) != 0) { /* the rewind below still restarts the rows */ }
  std::rewind(file_);
  std::fputs(header_.c_str(), file_);
  rows_ = 0;
}

void RowLog::Append(const std::function<void(std::FILE*)>& write) {
  write(file_);
  ++rows_;
}

long RowLog::Flush() {
  std::fflush(file_);
  return std::ftell(file_);
}

void RowLog::Read(long end, const std::function<bool(const char*, std::size_t)>& sink) const {
  char buffer[1 << 16];
  long offset = 0;
  while (offset < end) {
    const ssize_t want = static_cast<ssize_t>(std::min<long>(sizeof buffer, end - offset));
    const ssize_t got = pread(fileno(file_), buffer, want, offset);  // leaves the append position
    if (got <= 0) break;
    if (!sink(buffer, static_cast<std::size_t>(got))) break;
    offset += got;
  }
}

}  // namespace cablefilm
