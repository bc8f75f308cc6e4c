#include "app/sweep_command.h"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <toml++/toml.h>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io/result_files.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "scene/build_model.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"
#include "scene/text_escape.h"

namespace cablefilm {

const char* const kSweepResultColumns[] = {
    "status",      "message",          "peak_tension",     "peak_time",
    "peak_link",   "min_tension",      "min_tension_time", "min_tension_link",
    "snaps",       "peak_converged",   nullptr};

namespace {

namespace fs = std::filesystem;

constexpr int kMaxJobs = 1024;

// The sweep's signals: the first stops the cases (each keeps what it has, as `run` does) and
// leaves the finished ones; a second kills the running cases at once.
std::atomic<int> g_signal{0};
std::atomic<pid_t>* g_children = nullptr;  // kMaxJobs slots, 0: free
extern "C" void OnSweepSignal(int sig) {
  if (g_signal != 0) {
    for (int i = 0; g_children && i < kMaxJobs; ++i)
      if (const pid_t pid = g_children[i].load(); pid > 0) ::kill(pid, SIGKILL);
    ::_exit(128 + sig);
  }
  g_signal = sig;
}
extern "C" void OnChild(int) {}  // only wakes the wait

int CoreCount() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return std::max(1L, sysconf(_SC_NPROCESSORS_ONLN));
}

// "environment.current = 0.5, ends.end.period = 8"
std::string DescribeValues(const SweepCases& cases, std::size_t i) {
  std::string text;
  for (std::size_t k = 0; k < cases.keys.size(); ++k)
    text += (k ? ", " : "") + EscapeText(cases.keys[k]) + " = " + EscapeText(cases.rows[i][k]);
  return text;
}

// A number as printed in sweep.csv: 10 significant digits, as run_report.toml has them.
std::string Num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

// The columns from run_report.toml: kSweepResultColumns after status and message.
constexpr std::size_t kReportColumns = 8;
constexpr std::size_t kConvergedColumn = 7;  // peak_converged

struct CaseRow {
  std::string status = "not run";
  std::string message;
  std::vector<std::string> results;  // kReportColumns cells; empty: not finished
};

// The results of a finished run, from its run_report.toml; false when it has none.
bool ReadRunReport(const fs::path& path, CaseRow* row) {
  toml::table report;
  try {
    report = toml::parse_file(path.string());
  } catch (const std::exception&) {
    return false;
  }
  row->results.clear();
  for (const char* key : {"peak_tension", "peak_time", "peak_link", "min_tension",
                          "min_tension_time", "min_tension_link", "snaps", "peak_converged"}) {
    const toml::node* n = report.get(key);
    std::string cell;
    if (n && n->is_boolean()) cell = n->as_boolean()->get() ? "true" : "false";
    else if (n && n->is_integer() && std::string(key).find("link") != std::string::npos)
      cell = std::to_string(n->as_integer()->get());
    else if (n && n->is_integer() && std::string(key) == "snaps")
      cell = std::to_string(n->as_integer()->get());
    else if (n && n->is_number()) cell = Num(n->value<double>().value());
    row->results.push_back(cell);
  }
  return true;
}

// The last line the run printed about what stopped it ("cablefilm: error: ..."), without the
// program's name; "" if none.
std::string LastMessage(const fs::path& log) {
  std::ifstream in(log, std::ios::binary);
  std::string line, last;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.rfind("cablefilm: ", 0) == 0) last = line.substr(11);
  }
  if (last.rfind("error: ", 0) == 0) last.erase(0, 7);
  return last;
}

// The options of `run` that the sweep hands to every case (the film off unless --film).
std::vector<std::string> ChildRunOptions(const RunOptions& o) {
  std::vector<std::string> args;
  auto number = [](double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return std::string(buf);
  };
  if (o.frames == 1) args.push_back("--frames");
  args.push_back(o.film == 1 ? "--film" : "--no-film");
  if (o.width > 0)
    args.insert(args.end(), {"--size", std::to_string(o.width) + "x" + std::to_string(o.height)});
  if (o.fps > 0) args.insert(args.end(), {"--fps", number(o.fps)});
  if (o.speed > 0) args.insert(args.end(), {"--speed", number(o.speed)});
  if (!o.colormap.empty()) args.insert(args.end(), {"--colormap", o.colormap});
  if (o.tension_min >= 0)
    args.insert(args.end(), {"--tension-range", number(o.tension_min) + "," + number(o.tension_max)});
  if (!o.shader_dir.empty()) args.insert(args.end(), {"--shaders", o.shader_dir});
  return args;
}

// What `check` refuses of a case, refused before anything runs: the loader (every key known,
// every value in range), the built model's limits, and the film's frame count when on.
void ValidateCase(const std::string& text, const std::string& path, const RunOptions& o) {
  const SceneDef scene = ParseScene(text, path);
  CheckModelLimits(scene, BuildModel(scene));
  if (o.film != 1) return;
  const double fps = o.fps > 0 ? o.fps : scene.film.fps;
  const double speed = o.speed > 0 ? o.speed : scene.film.speed;
  const std::string problem =
      FilmFramesProblem(RunSpan(scene.simulation.duration, scene.output.interval), fps, speed);
  if (!problem.empty())
    throw Error(EscapeText(path) + ": " +
                (o.speed > 0 ? "--speed" : o.fps > 0 ? "--fps" : "film.speed") + ": " + problem);
}

// Case folders of an earlier, larger sweep: emptied of what a sweep writes and removed, so that
// no stale case sits beside this sweep's.
void RemoveStaleCases(const fs::path& dir, const std::set<std::string>& keep) {
  static const std::regex name("case_[0-9]+");
  std::error_code ec;
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string n = entry.path().filename().string();
    if (entry.is_directory(ec) && std::regex_match(n, name) && !keep.count(n))
      stale.push_back(entry.path());
  }
  for (const fs::path& p : stale) {
    RemoveEarlierResults(p.string());
    for (const char* n : {"scene.toml", "run.log"}) fs::remove(p / n, ec);
    fs::remove(p / "frames", ec);  // only when empty
    fs::remove(p, ec);
  }
}

class Sweep {
 public:
  Sweep(std::string scene_path, const SweepOptions& o)
      : scene_path_(std::move(scene_path)), options_(o) {}

  int Run() {
    const std::string text = ReadSceneFile(scene_path_);
    SweepCases listed;
    if (!options_.cases_csv.empty()) listed = ReadCasesCsv(options_.cases_csv);
    cases_ = ExpandCases(listed, options_.sets);
    const std::size_t n = cases_.rows.size();
    dir_ = options_.run.out_dir.empty()
               ? fs::path("output") / (fs::path(scene_path_).stem().string() + "_sweep")
               : fs::path(options_.run.out_dir);

    // Every case's scene, checked as `check` would before anything is written or run.
    std::vector<std::string> scenes(n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::string path = (dir_ / CaseFolderName(i, n) / "scene.toml").string();
      const std::string comment =
          "# cablefilm sweep, case " + std::to_string(i) + " of " + std::to_string(n) + ": " +
          EscapeText(scene_path_) + " with " + DescribeValues(cases_, i) + "\n\n";
      try {
        scenes[i] = EditSceneText(text, scene_path_, cases_.keys, cases_.rows[i], comment);
        ValidateCase(scenes[i], path, options_.run);
      } catch (const Error& e) {
        throw Error(EscapeText(scene_path_) + ": case " + std::to_string(i) + " (" +
                    DescribeValues(cases_, i) + ") is refused, so no case was run: " + e.what());
      }
    }

    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec)
      throw Error("cannot create the sweep folder " + EscapeText(dir_.string()) + ": " +
                  ec.message());
    std::set<std::string> names;
    for (std::size_t i = 0; i < n; ++i) names.insert(CaseFolderName(i, n));
    RemoveStaleCases(dir_, names);
    for (std::size_t i = 0; i < n; ++i) {
      const fs::path folder = dir_ / CaseFolderName(i, n);
      fs::create_directories(folder, ec);
      if (ec)
        throw Error("cannot create the case folder " + EscapeText(folder.string()) + ": " +
                    ec.message());
      RemoveEarlierResults(folder.string());  // no result of an earlier sweep beside the scene
      fs::remove(folder / "run.log", ec);
      AtomicFile scene((folder / "scene.toml").string());
      std::fputs(scenes[i].c_str(), scene.stream());
      scene.Commit();
    }
    rows_.assign(n, CaseRow());
    WriteSummary();
    std::printf("sweep: %zu case%s of %s (%s) in %s\n", n, n == 1 ? "" : "s",
                EscapeText(scene_path_).c_str(), KeysText().c_str(),
                EscapeText(dir_.string()).c_str());
    if (options_.prepare) {
      std::printf("prepared: each case folder holds its scene.toml; nothing run\nwrote %s\n",
                  EscapeText((dir_ / "sweep.csv").string()).c_str());
      return 0;
    }
    return RunCases();
  }

 private:
  std::string KeysText() const {
    std::string text;
    for (const std::string& k : cases_.keys) text += (text.empty() ? "" : ", ") + EscapeText(k);
    return text;
  }

  void WriteSummary() {
    AtomicFile file((dir_ / "sweep.csv").string());
    std::FILE* f = file.stream();
    std::string header = "case,folder";
    for (const std::string& k : cases_.keys) header += "," + CsvCell(k);
    for (int c = 0; kSweepResultColumns[c]; ++c) header += std::string(",") + kSweepResultColumns[c];
    std::fprintf(f, "%s\n", header.c_str());
    const std::size_t n = rows_.size();
    for (std::size_t i = 0; i < n; ++i) {
      std::string line = std::to_string(i) + "," + CaseFolderName(i, n);
      for (const std::string& v : cases_.rows[i]) line += "," + CsvCell(v);
      line += "," + rows_[i].status + "," + CsvCell(rows_[i].message);
      for (std::size_t c = 0; c < kReportColumns; ++c)
        line += "," + (c < rows_[i].results.size() ? CsvCell(rows_[i].results[c]) : "");
      std::fprintf(f, "%s\n", line.c_str());
    }
    file.Commit();
  }

  pid_t Launch(std::size_t i) {
    const fs::path folder = dir_ / CaseFolderName(i, rows_.size());
    std::vector<std::string> args = {"cablefilm", "run", (folder / "scene.toml").string(),
                                     "--out", folder.string()};
    for (const std::string& a : ChildRunOptions(options_.run)) args.push_back(a);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const std::string log = (folder / "run.log").string();
    const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (out < 0) throw Error("cannot create " + EscapeText(log) + ": " + std::strerror(errno));
    const int in = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    const pid_t parent = ::getpid();
    std::fflush(nullptr);
    const pid_t pid = ::fork();
    if (pid == 0) {
      // Only async-signal-safe calls until exec. Its own process group: a Ctrl-C at the
      // terminal reaches the sweep, which stops its cases once each (a second signal would
      // stop a case at once, without its partial results). It ends with the sweep.
      ::setpgid(0, 0);
      ::prctl(PR_SET_PDEATHSIG, SIGTERM);
      if (::getppid() != parent) ::_exit(128 + SIGTERM);
      if (in >= 0) ::dup2(in, STDIN_FILENO);
      ::dup2(out, STDOUT_FILENO);
      ::dup2(out, STDERR_FILENO);
      ::sigprocmask(SIG_SETMASK, &original_mask_, nullptr);
      ::execv("/proc/self/exe", argv.data());
      static const char message[] = "cablefilm: error: cannot start /proc/self/exe\n";
      [[maybe_unused]] const ssize_t w = ::write(STDERR_FILENO, message, sizeof message - 1);
      ::_exit(127);
    }
    const int fork_errno = errno;
    ::close(out);
    if (in >= 0) ::close(in);
    if (pid < 0) throw Error(std::string("cannot start a case (fork): ") + std::strerror(fork_errno));
    rows_[i].status = "running";
    return pid;
  }

  // The row of case i from how its process ended.
  void Finish(std::size_t i, int wait_status, bool stopped) {
    const fs::path folder = dir_ / CaseFolderName(i, rows_.size());
    CaseRow& row = rows_[i];
    row.results.clear();
    row.message.clear();
    std::error_code ec;
    const int code = WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : -1;
    if (code == 0 && ReadRunReport(folder / "run_report.toml", &row)) {
      row.status = "ok";
      if (row.results.size() == kReportColumns && row.results[kConvergedColumn] == "false")
        row.message = "the peak tension is not converged (see run_report.toml)";
      return;
    }
    if (stopped) {
      row.status = "interrupted";
      row.message = std::string("stopped by the sweep's ") + sigabbrev(g_signal.load()) +
                    "; its rows so far are in timeseries.partial.csv";
      return;
    }
    const std::string said = LastMessage(folder / "run.log");
    if (code == 1 && fs::exists(folder / "timeseries.partial.csv", ec)) {
      row.status = "blow-up";
      row.message = said;
      return;
    }
    row.status = "error";
    if (!said.empty()) row.message = said;
    else if (code == 0) row.message = "no run_report.toml";
    else if (code > 0) row.message = "exit status " + std::to_string(code);
    else
      row.message = "killed by signal " + std::to_string(WTERMSIG(wait_status)) + " (" +
                    strsignal(WTERMSIG(wait_status)) + ")";
  }

  static const char* sigabbrev(int sig) {
    return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "signal";
  }

  int RunCases() {
    const std::size_t n = rows_.size();
    const int jobs = static_cast<int>(std::min<std::size_t>(
        n, static_cast<std::size_t>(options_.jobs > 0 ? options_.jobs : CoreCount())));
    std::printf("running %d case%s at a time; each case's output in its folder's run.log\n",
                jobs, jobs == 1 ? "" : "s");
    std::fflush(stdout);

    auto children = std::make_unique<std::atomic<pid_t>[]>(kMaxJobs);
    for (int k = 0; k < kMaxJobs; ++k) children[k] = 0;
    g_children = children.get();
    sigset_t blocked;
    sigemptyset(&blocked);
    for (int s : {SIGINT, SIGTERM, SIGCHLD}) sigaddset(&blocked, s);
    ::sigprocmask(SIG_BLOCK, &blocked, &original_mask_);
    struct sigaction action {};
    action.sa_handler = OnSweepSignal;  // no SA_RESTART: the wait below wakes
    sigemptyset(&action.sa_mask);
    ::sigaction(SIGINT, &action, nullptr);
    ::sigaction(SIGTERM, &action, nullptr);
    action.sa_handler = OnChild;
    action.sa_flags = SA_NOCLDSTOP;
    ::sigaction(SIGCHLD, &action, nullptr);
    sigset_t waiting = original_mask_;  // the mask while waiting: these signals come through
    for (int s : {SIGINT, SIGTERM, SIGCHLD}) sigdelset(&waiting, s);

    struct Slot {
      pid_t pid = 0;
      std::size_t index = 0;
      std::chrono::steady_clock::time_point start;
    };
    std::vector<Slot> slots(jobs);
    const bool tty = ::isatty(STDERR_FILENO) != 0;
    const auto t0 = std::chrono::steady_clock::now();
    std::size_t next = 0, done = 0, failed = 0;
    int running = 0;
    bool stopping = false, status_shown = false, unsaved = false;
    auto saved = t0;
    auto clear_status = [&] {
      if (status_shown) std::fprintf(stderr, "\r\033[K");
      status_shown = false;
    };
    auto show_status = [&] {
      if (!tty) return;
      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::fprintf(stderr, "\rsweep: %zu/%zu done, %d running, %zu failed, %.0f s   ", done, n,
                   running, failed, elapsed);
      std::fflush(stderr);
      status_shown = true;
    };

    while (true) {
      if (g_signal != 0 && !stopping) {
        stopping = true;
        clear_status();
        std::fprintf(stderr, "sweep: %s: stopping the %d running case%s; the finished ones stay\n",
                     sigabbrev(g_signal.load()), running, running == 1 ? "" : "s");
        for (const Slot& s : slots)
          if (s.pid > 0) ::kill(s.pid, g_signal.load());
      }
      bool changed = false;
      for (int k = 0; k < jobs && !stopping; ++k) {
        if (slots[k].pid != 0 || next >= n) continue;
        slots[k].index = next;
        slots[k].start = std::chrono::steady_clock::now();
        slots[k].pid = Launch(next++);
        children[k] = slots[k].pid;
        ++running;
        changed = true;
      }
      for (int k = 0; k < jobs; ++k) {
        if (slots[k].pid == 0) continue;
        int status = 0;
        const pid_t r = ::waitpid(slots[k].pid, &status, WNOHANG);
        if (r == 0) continue;
        if (r < 0 && errno == EINTR) continue;
        children[k] = 0;
        slots[k].pid = 0;
        --running;
        ++done;
        const std::size_t i = slots[k].index;
        Finish(i, r < 0 ? 0x7f00 : status, stopping);
        const CaseRow& row = rows_[i];
        if (row.status != "ok" && row.status != "interrupted") ++failed;
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                                          slots[k].start).count();
        clear_status();
        if (row.status == "ok")
          std::printf("case %zu (%s): ok in %.2f s, peak %s N at t = %s s in link %s "
                      "[%zu/%zu done, %d running, %zu failed]\n",
                      i, DescribeValues(cases_, i).c_str(), wall, row.results[0].c_str(),
                      row.results[1].c_str(), row.results[2].c_str(), done, n, running, failed);
        else
          std::printf("case %zu (%s): %s%s%s [%zu/%zu done, %d running, %zu failed]\n", i,
                      DescribeValues(cases_, i).c_str(), row.status.c_str(),
                      row.message.empty() ? "" : ": ", row.message.c_str(), done, n, running,
                      failed);
        std::fflush(stdout);
        changed = true;
      }
      // The summary as the cases end, at most once a second (a sweep of many short cases
      // would otherwise rewrite it in full for each), and whole at the end.
      unsaved = unsaved || changed;
      if (unsaved && std::chrono::steady_clock::now() - saved >= std::chrono::seconds(1)) {
        WriteSummary();
        saved = std::chrono::steady_clock::now();
        unsaved = false;
      }
      if (running == 0 && (stopping || next >= n)) break;
      if (changed) continue;  // launch into the freed slots first
      show_status();
      const timespec timeout = tty ? timespec{0, 250000000L} : timespec{1, 0};
      ::ppoll(nullptr, 0, &timeout, &waiting);  // wakes on SIGCHLD, SIGINT, SIGTERM
    }
    clear_status();
    WriteSummary();
    g_children = nullptr;
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    std::signal(SIGCHLD, SIG_DFL);
    ::sigprocmask(SIG_SETMASK, &original_mask_, nullptr);

    std::size_t ok = 0, blowups = 0, errors = 0, interrupted = 0;
    for (const CaseRow& r : rows_) {
      ok += r.status == "ok";
      blowups += r.status == "blow-up";
      errors += r.status == "error";
      interrupted += r.status == "interrupted";
    }
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("sweep: %zu case%s in %.3g s: %zu ok, %zu blow-up, %zu error", n,
                n == 1 ? "" : "s", wall, ok, blowups, errors);
    if (stopping) std::printf(", %zu interrupted, %zu not run", interrupted, n - done);
    std::printf("\nwrote %s\n", EscapeText((dir_ / "sweep.csv").string()).c_str());
    std::fflush(stdout);
    if (stopping) return 128 + g_signal.load();
    if (ok < n) {
      std::fprintf(stderr, "cablefilm: %zu of %zu cases did not finish: see the status and message "
                   "columns of %s and each case's run.log\n",
                   n - ok, n, EscapeText((dir_ / "sweep.csv").string()).c_str());
      return 1;
    }
    return 0;
  }

  std::string scene_path_;
  SweepOptions options_;
  SweepCases cases_;
  fs::path dir_;
  std::vector<CaseRow> rows_;
  sigset_t original_mask_{};
};

}  // namespace

int SweepCommand(const std::string& scene_path, const SweepOptions& options) {
  if (options.jobs < 0 || options.jobs > kMaxJobs)
    throw Error("--jobs: expected 1 to " + std::to_string(kMaxJobs));
  return Sweep(scene_path, options).Run();
}

}  // namespace cablefilm
