#include "run/max_tension_log.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <string>

#include "core/error.h"

namespace cablefilm {

MaxTensionLog::~MaxTensionLog() {
  if (file_) std::fclose(file_);
}

MaxTensionLog::MaxTensionLog(MaxTensionLog&& o) noexcept
    : file_(o.file_),
      rows_(o.rows_),
      written_(o.written_),
      pending_(std::move(o.pending_)) {
  o.file_ = nullptr;
  o.rows_ = o.written_ = 0;
  o.pending_.clear();
}

void MaxTensionLog::Append(double t, double tension_max, double tension_start,
                           double tension_end) {
  pending_.push_back(t);
  pending_.push_back(tension_max);
  pending_.push_back(tension_start);
  pending_.push_back(tension_end);
  ++rows_;
  if (static_cast<long>(pending_.size()) >= kWidth * kMemoryRows) WritePending();
}

void MaxTensionLog::WritePending() {
  if (!file_ && !(file_ = std::tmpfile()))
    throw Error(std::string("cannot create a temporary file for the maximum tension: ") +
                std::strerror(errno));
  const char* data = reinterpret_cast<const char*>(pending_.data());
  std::size_t left = pending_.size() * sizeof(double);
  off_t at = static_cast<off_t>(written_) * kWidth * sizeof(double);
  while (left > 0) {
    const ssize_t n = ::pwrite(fileno(file_), data, left, at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw Error(std::string("cannot write the temporary file of the maximum tension: ") +
                  std::strerror(n < 0 ? errno : ENOSPC));
    data += n;
    at += n;
    left -= static_cast<std::size_t>(n);
  }
  written_ += static_cast<long>(pending_.size() / kWidth);
  pending_.clear();
}

bool MaxTensionLog::Cursor::Next(double t_until, double* t, double* tension_max) {
  double start = 0, end = 0;
  return Next(t_until, t, tension_max, &start, &end);
}

bool MaxTensionLog::Cursor::Next(double t_until, double* t, double* tension_max,
                                 double* tension_start, double* tension_end) {
  const MaxTensionLog& log = *log_;
  if (next_ >= log.rows_) return false;
  const long in_block = next_ - block_first_;
  if (in_block < 0 || kWidth * in_block >= static_cast<long>(block_.size())) {
    // Read ahead: from the file while the rows are there, else from the pending rows.
    block_first_ = next_;
    if (next_ < log.written_) {
      const long n = std::min(kMemoryRows, log.written_ - next_);
      block_.resize(static_cast<std::size_t>(kWidth * n));
      char* data = reinterpret_cast<char*>(block_.data());
      std::size_t left = block_.size() * sizeof(double);
      off_t at = static_cast<off_t>(next_) * kWidth * sizeof(double);
      while (left > 0) {
        const ssize_t r = ::pread(fileno(log.file_), data, left, at);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0)
          throw Error(std::string("cannot read the temporary file of the maximum tension: ") +
                      (r < 0 ? std::strerror(errno) : "it ends early"));
        data += r;
        at += r;
        left -= static_cast<std::size_t>(r);
      }
    } else {
      const std::size_t from = static_cast<std::size_t>(kWidth * (next_ - log.written_));
      block_.assign(log.pending_.begin() + static_cast<std::ptrdiff_t>(from), log.pending_.end());
    }
  }
  const std::size_t i = static_cast<std::size_t>(kWidth * (next_ - block_first_));
  if (!(block_[i] <= t_until)) return false;
  *t = block_[i];
  *tension_max = block_[i + 1];
  *tension_start = block_[i + 2];
  *tension_end = block_[i + 3];
  ++next_;
  return true;
}

}  // namespace cablefilm
