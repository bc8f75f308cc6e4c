#pragma once
// Long work (the step loops, the equilibrium solver) polls a flag that a signal handler sets, so
// that Ctrl-C or SIGTERM is seen within one step or one Newton iteration however large the
// cable: the work then throws CancelledError and the caller keeps what it has.
#include <atomic>
#include <string>

#include "core/error.h"

namespace cablefilm {

using CancelFlag = std::atomic<int>;  // non-zero: stop (the signal's number, say)

class CancelledError : public Error {
 public:
  explicit CancelledError(const std::string& what) : Error(what) {}
};

inline void ThrowIfCancelled(const CancelFlag* flag, const char* what) {
  if (flag && flag->load(std::memory_order_relaxed) != 0)
    throw CancelledError(std::string("interrupted during ") + what);
}

}  // namespace cablefilm
