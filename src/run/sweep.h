#pragma once
// A sweep: one scene run over its cases (sweep_plan.h), each case's scene the original edited
// with its values, at most `jobs` at a time on an executor: processes of `cablefilm run` for
// the command line (app/sweep_command.cpp), threads of this process for the Python module
// (ThreadExecutor). One loop starts and collects the cases for both; one row a case, with the
// columns of sweep.csv (SweepHeader, SweepRow).
#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <mutex>
#include <condition_variable>
#include <deque>
#include <string>
#include <thread>
#include <vector>

#include "core/cancel.h"
#include "run/run_summary.h"
#include "run/sweep_plan.h"

namespace cablefilm {

constexpr int kMaxSweepJobs = 1024;  // cases at a time, at most

// How a case ended.
struct CaseOutcome {
  std::string status = "not run";  // "ok", "blow-up", "error", "interrupted", "not run"
  std::string message;             // why it did not finish, or why its peak is not converged
  bool has_summary = false;        // a finished run's summary below (status "ok")
  RunSummary summary;
  double seconds = 0;              // from its start to its end, wall clock [s]
};

// The outcome of a case whose run ended (completed, or cut short by a blow-up); a run stopped
// by the sweep is "interrupted".
CaseOutcome OutcomeOf(const RunSummary& s, bool stopped);

// Runs the cases of a sweep, each on its own (a process, a thread).
class CaseExecutor {
 public:
  virtual ~CaseExecutor() = default;
  // Starts case `index`. Throws Error when it cannot.
  virtual void Start(std::size_t index) = 0;
  // Waits up to `timeout` for a started case to end: true with its index and outcome.
  virtual bool WaitAny(std::chrono::milliseconds timeout, std::size_t* index,
                       CaseOutcome* outcome) = 0;
  // Asks every running case to stop, keeping what it has.
  virtual void StopAll() = 0;
};

struct SweepProgress {
  std::size_t cases = 0, done = 0, failed = 0;  // failed: ended neither ok nor interrupted
  int running = 0;
  bool stopping = false;
};

// Runs `outcomes.size()` cases on `executor`: starts them in order, at most `jobs` at once,
// until every case has ended, or `stop` is raised (then the running ones are asked to stop and
// waited for, and say how they ended, "interrupted" as a rule; those not started stay "not
// run"). After each case ends `on_end(index, progress)`;
// while waiting, about every `tick`, `on_wait(progress)`.
void RunCases(CaseExecutor& executor, int jobs, const CancelFlag* stop,
              std::vector<CaseOutcome>& outcomes,
              const std::function<void(std::size_t, const SweepProgress&)>& on_end,
              const std::function<void(const SweepProgress&)>& on_wait,
              std::chrono::milliseconds tick = std::chrono::milliseconds(250));

// The cases of a sweep run on threads of this process: `run(index, stop)` runs case `index`
// (polling `stop`) and says how it ended; an exception it throws is the case's "error".
class ThreadExecutor : public CaseExecutor {
 public:
  using RunCase = std::function<CaseOutcome(std::size_t index, const CancelFlag* stop)>;
  // At most `threads` at once (the threads are started as cases need them).
  ThreadExecutor(int threads, RunCase run);
  ~ThreadExecutor() override;  // stops and joins every thread
  void Start(std::size_t index) override;
  bool WaitAny(std::chrono::milliseconds timeout, std::size_t* index,
               CaseOutcome* outcome) override;
  void StopAll() override;

 private:
  void Work();
  RunCase run_;
  std::size_t threads_;
  std::vector<std::thread> pool_;
  CancelFlag stop_{0};
  std::mutex mutex_;
  std::condition_variable work_, ended_;
  std::deque<std::size_t> queue_;                          // started, not yet taken
  std::deque<std::pair<std::size_t, CaseOutcome>> done_;   // ended, not yet collected
  bool quit_ = false;
};

// The first line of sweep.csv and the row of case `index` (its folder name as given).
std::string SweepHeader(const SweepCases& cases);
std::string SweepRow(const SweepCases& cases, std::size_t index, const std::string& folder,
                     const CaseOutcome& outcome);

// "environment.current = 0.5, ends.end.period = 8"
std::string DescribeCase(const SweepCases& cases, std::size_t index);

}  // namespace cablefilm
