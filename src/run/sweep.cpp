#include "run/sweep.h"

#include <algorithm>
#include <iterator>
#include <system_error>

#include "core/error.h"
#include "scene/text_escape.h"

namespace cablefilm {

CaseOutcome OutcomeOf(const RunSummary& s, bool stopped) {
  CaseOutcome o;
  if (s.completed) {
    o.status = "ok";
    o.has_summary = true;
    o.summary = s;
    if (!s.warnings.empty()) o.message = s.warnings.front();
  } else if (!s.failure.empty()) {
    o.status = "blow-up";
    o.message = s.failure;
  } else {
    o.status = stopped ? "interrupted" : "error";
  }
  return o;
}

void RunCases(CaseExecutor& executor, int jobs, const CancelFlag* stop,
              std::vector<CaseOutcome>& outcomes,
              const std::function<void(std::size_t, const SweepProgress&)>& on_end,
              const std::function<void(const SweepProgress&)>& on_wait,
              std::chrono::milliseconds tick) {
  SweepProgress p;
  p.cases = outcomes.size();
  std::size_t next = 0;
  while (true) {
    if (stop && *stop != 0 && !p.stopping) {
      p.stopping = true;
      executor.StopAll();
    }
    while (!p.stopping && next < p.cases && p.running < jobs) {
      outcomes[next].status = "running";
      executor.Start(next++);
      ++p.running;
    }
    if (p.running == 0 && (p.stopping || next >= p.cases)) break;
    std::size_t index = 0;
    CaseOutcome outcome;
    if (!executor.WaitAny(tick, &index, &outcome)) {
      if (on_wait) on_wait(p);
      continue;
    }
    --p.running;
    ++p.done;
    if (outcome.status != "ok" && outcome.status != "interrupted") ++p.failed;
    outcomes[index] = std::move(outcome);
    if (on_end) on_end(index, p);
  }
}

ThreadExecutor::ThreadExecutor(int threads, RunCase run)
    : run_(std::move(run)), threads_(static_cast<std::size_t>(std::max(1, threads))) {}

ThreadExecutor::~ThreadExecutor() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    quit_ = true;
  }
  stop_ = 1;
  work_.notify_all();
  for (std::thread& t : pool_) t.join();
}

void ThreadExecutor::Start(std::size_t index) {
  std::lock_guard<std::mutex> lock(mutex_);
  queue_.push_back(index);
  // A thread a case while fewer than `threads` run: no idle pool for a short sweep. A thread
  // the system refuses is not an error while another works (the queue waits for it).
  if (pool_.size() < threads_) {
    try {
      pool_.emplace_back([this] { Work(); });
    } catch (const std::system_error& e) {
      if (pool_.empty())
        throw Error(std::string("cannot start a thread for the sweep's cases: ") + e.what());
    }
  }
  work_.notify_one();
}

void ThreadExecutor::Work() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    work_.wait(lock, [&] { return quit_ || !queue_.empty(); });
    if (quit_) return;
    const std::size_t index = queue_.front();
    queue_.pop_front();
    lock.unlock();
    CaseOutcome outcome;
    const auto start = std::chrono::steady_clock::now();
    try {
      outcome = run_(index, &stop_);
    } catch (const std::exception& e) {
      outcome.status = "error";
      outcome.message = e.what();
    }
    outcome.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    lock.lock();
    done_.emplace_back(index, std::move(outcome));
    ended_.notify_all();
  }
}

bool ThreadExecutor::WaitAny(std::chrono::milliseconds timeout, std::size_t* index,
                             CaseOutcome* outcome) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (!ended_.wait_for(lock, timeout, [&] { return !done_.empty(); })) return false;
  *index = done_.front().first;
  *outcome = std::move(done_.front().second);
  done_.pop_front();
  return true;
}

void ThreadExecutor::StopAll() {
  stop_ = 1;
  std::lock_guard<std::mutex> lock(mutex_);
  // Cases started but not taken by a thread end at once, as cases that never ran.
  for (std::size_t index : queue_) done_.emplace_back(index, CaseOutcome{});
  queue_.clear();
  ended_.notify_all();
}

std::string SweepHeader(const SweepCases& cases) {
  std::string header = "case,folder";
  for (const std::string& k : cases.keys) header += "," + CsvCell(k);
  header += ",status,message";
  for (const SummaryColumn& c : kSummaryColumns) header += std::string(",") + c.name;
  return header;
}

std::string SweepRow(const SweepCases& cases, std::size_t index, const std::string& folder,
                     const CaseOutcome& o) {
  std::string line = std::to_string(index) + "," + folder;
  for (const std::string& v : cases.rows[index]) line += "," + CsvCell(v);
  line += "," + o.status + "," + CsvCell(o.message);
  if (o.has_summary) {
    for (const std::string& cell : SummaryCells(o.summary)) line += "," + CsvCell(cell);
  } else {
    for (std::size_t c = 0; c < std::size(kSummaryColumns); ++c) line += ",";
  }
  return line;
}

std::string DescribeCase(const SweepCases& cases, std::size_t i) {
  std::string text;
  for (std::size_t k = 0; k < cases.keys.size(); ++k)
    text += (k ? ", " : "") + EscapeText(cases.keys[k]) + " = " + EscapeText(cases.rows[i][k]);
  return text;
}

}  // namespace cablefilm
