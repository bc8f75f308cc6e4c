#pragma once
// Long C++ work called from Python: run with the GIL released (other Python threads go on, and
// run cases of their own in parallel), on a thread of its own while the calling thread waits
// and looks at Python's signal handlers every 0.1 s, so Ctrl-C stops it: the work polls
// `cancel` (core/cancel.h) and, once it has stopped, KeyboardInterrupt is raised. An exception
// of the work is rethrown in the calling thread. The work must not touch Python objects.
#include <pybind11/pybind11.h>

#include <chrono>
#include <csignal>
#include <future>
#include <utility>

#include "core/cancel.h"

namespace cablefilm::python {

template <class Work>
auto RunInterruptible(CancelFlag& cancel, Work&& work) -> decltype(work()) {
  auto future = std::async(std::launch::async, std::forward<Work>(work));
  for (;;) {
    std::future_status status;
    {
      pybind11::gil_scoped_release release;
      status = future.wait_for(std::chrono::milliseconds(100));
    }
    if (status == std::future_status::ready) break;
    // Python's handlers run here (in the main thread only; elsewhere this returns 0).
    if (PyErr_CheckSignals() != 0) {
      cancel = SIGINT;
      {
        pybind11::gil_scoped_release release;
        future.wait();
      }
      throw pybind11::error_already_set();
    }
  }
  return future.get();
}

}  // namespace cablefilm::python
