#include "app/sweep_command.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "app/command.h"
#include "app/open_files.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "io/out_dir_lock.h"
#include "io/output_ledger.h"
#include "io/result_files.h"
#include "scene/option_values.h"
#include "io/run_report_file.h"
#include "run/run.h"
#include "run/sweep.h"
#include "run/sweep_maxima.h"
#include "scene/build_model.h"
#include "scene/scene_edit.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"
#include "scene/text_escape.h"

namespace cablefilm {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxJobs = kMaxSweepJobs;

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

const char* SignalName(int sig) {
  return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "signal";
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
  if (!o.view.empty()) args.insert(args.end(), {"--view", o.view});
  if (o.tension_min >= 0)
    args.insert(args.end(), {"--tension-range", number(o.tension_min) + "," + number(o.tension_max)});
  if (!o.shader_dir.empty()) args.insert(args.end(), {"--shaders", o.shader_dir});
  if (o.window_given)
    args.insert(args.end(), {"--film-window", o.window.peak_width > 0 ? "peak:" + number(o.window.peak_width)
                                              : o.window.end < 0 ? std::string("whole")
                                              : number(o.window.start) + "," + number(o.window.end)});
  return args;
}

// What `check` refuses of a case, refused before anything runs: the loader (every key known,
// every value in range), the built model's limits, the files its run keeps open when it writes
// them (`files`), and the film's settings when on.
void ValidateCase(const std::string& text, const std::string& path, const RunOptions& o,
                  bool files) {
  const SceneDef scene = ParseScene(text, path);
  const Model model = BuildModel(scene);
  CheckModelLimits(scene, model);
  if (files) CheckOpenFiles(scene, model);
  if (o.film == 1) ResolveFilm(scene, o, kCommandLineNames);
}

// Case `path`'s scene text run in this process with no file written: its summary, as
// `cablefilm run` would report it (a blow-up's ends the run with its failure).
CaseOutcome RunCaseInProcess(const std::string& text, const std::string& path,
                             const CancelFlag* stop) {
  const SceneDef scene = ParseScene(text, path);
  const Model model = BuildModel(scene);
  CheckModelLimits(scene, model);
  Run run = PrepareRun(scene, model, ModelLawName(model), stop);
  ExecuteRun(run, {});
  return OutcomeOf(run.summary, *stop != 0);
}

// The cases as child processes: each `cablefilm run` of its folder's scene.toml, in a process
// group of its own, its output in the folder's run.log; its row from its run_report.toml (or
// from how it ended).
class ProcessExecutor : public CaseExecutor {
 public:
  ProcessExecutor(const fs::path& dir, std::size_t cases, const RunOptions& options,
                  const sigset_t& original_mask, const sigset_t& waiting_mask)
      : dir_(dir), cases_(cases), options_(options), original_mask_(original_mask),
        waiting_mask_(waiting_mask), children_(std::make_unique<std::atomic<pid_t>[]>(kMaxJobs)) {
    for (int k = 0; k < kMaxJobs; ++k) children_[k] = 0;
    g_children = children_.get();
  }
  ~ProcessExecutor() override { g_children = nullptr; }

  void Start(std::size_t index) override {
    int slot = 0;
    while (slot < kMaxJobs && children_[slot] != 0) ++slot;
    if (slot == kMaxJobs) throw Error("the sweep runs too many cases at once");
    const pid_t pid = Launch(index);
    children_[slot] = pid;
    running_.push_back({pid, index, slot, std::chrono::steady_clock::now()});
  }

  bool WaitAny(std::chrono::milliseconds timeout, std::size_t* index,
               CaseOutcome* outcome) override {
    for (int pass = 0; pass < 2; ++pass) {
      for (std::size_t k = 0; k < running_.size(); ++k) {
        int status = 0;
        const pid_t r = ::waitpid(running_[k].pid, &status, WNOHANG);
        if (r == 0 || (r < 0 && errno == EINTR)) continue;
        *index = running_[k].index;
        *outcome = Finish(*index, r < 0 ? 0x7f00 : status);
        outcome->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                                         running_[k].start).count();
        children_[running_[k].slot] = 0;
        running_.erase(running_.begin() + static_cast<std::ptrdiff_t>(k));
        return true;
      }
      if (pass == 0) {  // wakes on SIGCHLD, SIGINT, SIGTERM
        const timespec t{static_cast<time_t>(timeout.count() / 1000),
                         static_cast<long>(timeout.count() % 1000) * 1000000L};
        ::ppoll(nullptr, 0, &t, &waiting_mask_);
      }
    }
    return false;
  }

  void StopAll() override {
    stopping_ = true;
    for (const Child& c : running_) ::kill(c.pid, g_signal != 0 ? g_signal.load() : SIGTERM);
  }

 private:
  struct Child {
    pid_t pid;
    std::size_t index;
    int slot;
    std::chrono::steady_clock::time_point start;
  };

  pid_t Launch(std::size_t i) {
    const fs::path folder = dir_ / CaseFolderName(i, cases_);
    std::vector<std::string> args = {"cablefilm", "run", (folder / "scene.toml").string(),
                                     "--out", folder.string()};
    for (const std::string& a : ChildRunOptions(options_)) args.push_back(a);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const std::string log = (folder / "run.log").string();
    RecordOutput(log);
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
    return pid;
  }

  // The outcome of case i from how its process ended.
  CaseOutcome Finish(std::size_t i, int wait_status) const {
    const fs::path folder = dir_ / CaseFolderName(i, cases_);
    std::error_code ec;
    const int code = WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : -1;
    RunSummary summary;
    if (code == 0 && ReadRunReport((folder / "run_report.toml").string(), &summary))
      return OutcomeOf(summary, false);
    CaseOutcome o;
    const bool partial = fs::exists(folder / "timeseries.partial.csv", ec);
    if (stopping_) {
      o.status = "interrupted";
      o.message = std::string("stopped by the sweep's ") + SignalName(g_signal.load()) +
                  (partial ? "; its rows so far are in timeseries.partial.csv"
                           : " before its first row");
      return o;
    }
    const std::string said = LastMessage(folder / "run.log");
    if (code == 1 && partial) {
      o.status = "blow-up";
      o.message = said;
      return o;
    }
    o.status = "error";
    if (!said.empty()) o.message = said;
    else if (code == 0) o.message = "no run_report.toml";
    else if (code > 0) o.message = "exit status " + std::to_string(code);
    else
      o.message = "killed by signal " + std::to_string(WTERMSIG(wait_status)) + " (" +
                  strsignal(WTERMSIG(wait_status)) + ")";
    return o;
  }

  fs::path dir_;
  std::size_t cases_;
  RunOptions options_;
  sigset_t original_mask_, waiting_mask_;
  std::unique_ptr<std::atomic<pid_t>[]> children_;
  std::vector<Child> running_;
  bool stopping_ = false;
};

class Sweep {
 public:
  Sweep(std::string scene_path, const SweepOptions& o)
      : scene_path_(std::move(scene_path)), options_(o) {}

  int Run() {
    // A MoorDyn file is swept through its equivalent scene: the keys are the scene's.
    std::vector<std::string> warnings;
    const std::string text = EditableSceneText(scene_path_, &warnings);
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
          EscapeText(scene_path_) + " with " + DescribeCase(cases_, i) + "\n\n";
      try {
        scenes[i] = EditSceneText(text, scene_path_, cases_.keys, cases_.rows[i], comment);
        ValidateCase(scenes[i], path, options_.run, !options_.summary_only);
      } catch (const Error& e) {
        throw Error(EscapeText(scene_path_) + ": case " + std::to_string(i) + " (" +
                    DescribeCase(cases_, i) + ") is refused, so no case was run: " + e.what());
      }
    }
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec)
      throw Error("cannot create the sweep folder " + EscapeText(dir_.string()) + ": " +
                  ec.message());
    // One sweep at a time in it; what an earlier sweep wrote (its case folders and what their
    // runs wrote) is removed, so that no stale case sits beside this sweep's.
    lock_.Lock(dir_.string(), "sweep folder");
    for (std::size_t i = 0; i < n && !options_.summary_only; ++i) {
      const fs::path folder = dir_ / CaseFolderName(i, n);
      CreateOutputFolder(folder.string());
      AtomicFile scene((folder / "scene.toml").string());
      std::fputs(scenes[i].c_str(), scene.stream());
      scene.Commit();
    }
    if (options_.summary_only) {
      scenes_ = std::move(scenes);
      for (std::size_t i = 0; i < n; ++i)
        scene_paths_.push_back((dir_ / CaseFolderName(i, n) / "scene.toml").string());
    }
    outcomes_.assign(n, CaseOutcome());
    WriteSummary();
    for (const std::string& w : warnings) std::printf("warning: %s\n", w.c_str());
    std::printf("sweep: %zu case%s of %s (%s) in %s\n", n, n == 1 ? "" : "s",
                EscapeText(scene_path_).c_str(), KeysText().c_str(),
                EscapeText(dir_.string()).c_str());
    if (options_.prepare) {
      std::printf("prepared: each case folder holds its scene.toml; nothing run\nwrote %s\n",
                  EscapeText((dir_ / "sweep.csv").string()).c_str());
      return 0;
    }
    return RunAll();
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
    std::fprintf(f, "%s\n", SweepHeader(cases_).c_str());
    const std::size_t n = outcomes_.size();
    for (std::size_t i = 0; i < n; ++i)
      std::fprintf(f, "%s\n",
                   SweepRow(cases_, i, options_.summary_only ? "" : CaseFolderName(i, n),
                            outcomes_[i])
                       .c_str());
    file.Commit();
  }

  int RunAll() {
    const std::size_t n = outcomes_.size();
    const int jobs = static_cast<int>(std::min<std::size_t>(
        n, static_cast<std::size_t>(options_.jobs > 0 ? options_.jobs : CoreCount())));
    if (options_.summary_only)
      std::printf("running %d case%s at a time in this process; no case folders\n", jobs,
                  jobs == 1 ? "" : "s");
    else
      std::printf("running %d case%s at a time; each case's output in its folder's run.log\n",
                  jobs, jobs == 1 ? "" : "s");
    std::fflush(stdout);

    // Processes: the signals blocked but while waiting (ProcessExecutor). Threads: they come
    // through at any time, and their handler only raises the stop flag the cases poll.
    sigset_t blocked, original, waiting;
    sigemptyset(&blocked);
    if (!options_.summary_only)
      for (int s : {SIGINT, SIGTERM, SIGCHLD}) sigaddset(&blocked, s);
    ::sigprocmask(SIG_BLOCK, &blocked, &original);
    struct sigaction action {};
    action.sa_handler = OnSweepSignal;  // no SA_RESTART: the wait wakes
    sigemptyset(&action.sa_mask);
    ::sigaction(SIGINT, &action, nullptr);
    ::sigaction(SIGTERM, &action, nullptr);
    action.sa_handler = OnChild;
    action.sa_flags = SA_NOCLDSTOP;
    ::sigaction(SIGCHLD, &action, nullptr);
    waiting = original;  // the mask while waiting: these signals come through
    for (int s : {SIGINT, SIGTERM, SIGCHLD}) sigdelset(&waiting, s);

    const bool tty = ::isatty(STDERR_FILENO) != 0;
    const auto t0 = std::chrono::steady_clock::now();
    bool status_shown = false, unsaved = false, said_stop = false;
    auto saved = t0;
    auto clear_status = [&] {
      if (status_shown) std::fprintf(stderr, "\r\033[K");
      status_shown = false;
    };
    // The summary as the cases end, at most once a second (a sweep of many short cases
    // would otherwise rewrite it in full for each), and whole at the end.
    auto save_when_due = [&] {
      if (unsaved && std::chrono::steady_clock::now() - saved >= std::chrono::seconds(1)) {
        WriteSummary();
        saved = std::chrono::steady_clock::now();
        unsaved = false;
      }
    };
    // `ending`: said as a case ends (it was running when the stop came, and is no more).
    auto say_stop = [&](const SweepProgress& p, int ending) {
      if (said_stop || !p.stopping) return;
      said_stop = true;
      clear_status();
      const int running = p.running + ending;
      std::fprintf(stderr, "sweep: %s: stopping the %d running case%s; the finished ones stay\n",
                   SignalName(g_signal.load()), running, running == 1 ? "" : "s");
    };
    {
      std::unique_ptr<CaseExecutor> executor;
      if (options_.summary_only)
        executor = std::make_unique<ThreadExecutor>(
            jobs, [this](std::size_t i, const CancelFlag* stop) {
              return RunCaseInProcess(scenes_[i], scene_paths_[i], stop);
            });
      else
        executor = std::make_unique<ProcessExecutor>(dir_, n, options_.run, original, waiting);
      RunCases(
          *executor, jobs, &g_signal, outcomes_,
          [&](std::size_t i, const SweepProgress& p) {
            say_stop(p, 1);
            const CaseOutcome& o = outcomes_[i];
            clear_status();
            if (o.status == "ok")
              std::printf("case %zu (%s): ok in %.2f s, peak %.10g N at t = %.10g s in link %d "
                          "[%zu/%zu done, %d running, %zu failed]\n",
                          i, DescribeCase(cases_, i).c_str(), o.seconds, o.summary.peak,
                          o.summary.peak_t, o.summary.peak_link, p.done, n, p.running, p.failed);
            else
              std::printf("case %zu (%s): %s%s%s [%zu/%zu done, %d running, %zu failed]\n", i,
                          DescribeCase(cases_, i).c_str(), o.status.c_str(),
                          o.message.empty() ? "" : ": ", o.message.c_str(), p.done, n,
                          p.running, p.failed);
            std::fflush(stdout);
            unsaved = true;
            save_when_due();
          },
          [&](const SweepProgress& p) {
            say_stop(p, 0);
            save_when_due();
            if (!tty || p.stopping) return;
            const double elapsed =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            std::fprintf(stderr, "\rsweep: %zu/%zu done, %d running, %zu failed, %.0f s   ",
                         p.done, n, p.running, p.failed, elapsed);
            std::fflush(stderr);
            status_shown = true;
          },
          tty ? std::chrono::milliseconds(250) : std::chrono::milliseconds(1000));
    }
    clear_status();
    WriteSummary();
    const std::vector<SweepMaxima> maxima = CollectSweepMaxima(outcomes_);
    {
      AtomicFile file((dir_ / "sweep_maxima.toml").string());
      std::fputs(SweepMaximaToml(maxima).c_str(), file.stream());
      file.Commit();
    }
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    std::signal(SIGCHLD, SIG_DFL);
    ::sigprocmask(SIG_SETMASK, &original, nullptr);

    std::size_t ok = 0, blowups = 0, errors = 0, interrupted = 0, not_run = 0;
    for (const CaseOutcome& o : outcomes_) {
      ok += o.status == "ok";
      blowups += o.status == "blow-up";
      errors += o.status == "error";
      interrupted += o.status == "interrupted";
      not_run += o.status == "not run";
    }
    const bool stopped = g_signal != 0;
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("sweep: %zu case%s in %.3g s: %zu ok, %zu blow-up, %zu error", n,
                n == 1 ? "" : "s", wall, ok, blowups, errors);
    if (stopped) std::printf(", %zu interrupted, %zu not run", interrupted, not_run);
    std::printf("\n");
    for (const std::string& line : DescribeSweepMaxima(maxima)) std::printf("%s\n", line.c_str());
    std::printf("wrote %s and %s\n", EscapeText((dir_ / "sweep.csv").string()).c_str(),
                EscapeText((dir_ / "sweep_maxima.toml").string()).c_str());
    std::fflush(stdout);
    if (stopped) return 128 + g_signal.load();
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
  OutDirLock lock_;
  std::vector<CaseOutcome> outcomes_;
  std::vector<std::string> scenes_, scene_paths_;  // --summary-only: each case's scene
};

}  // namespace

int SweepCommand(const std::string& scene_path, const SweepOptions& options) {
  if (options.jobs < 0 || options.jobs > kMaxJobs)
    throw Error("--jobs: expected 1 to " + std::to_string(kMaxJobs));
  if (options.summary_only && (options.run.film == 1 || options.prepare))
    throw Error(std::string("--summary-only writes sweep.csv and sweep_maxima.toml alone: ") +
                (options.prepare ? "--prepare" : "a film") + " is not made with it");
  return Sweep(scene_path, options).Run();
}

Command DeclareSweepCommand(CLI::App& program, std::string* scene) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* cmd = AddSceneCommand(program, "sweep",
                                  "run a scene over the cross product of values of its keys", scene);
  Value(cmd, "--set", "KEY=V1,V2,...",
        "a scene key (e.g. environment.current, ends.end.period, material[0].youngs_modulus) "
        "and its values (TOML: 0.5, \"explicit\" or explicit, [1, 2]; A..B: the whole numbers "
        "from A to B); repeat for more keys: the cases are their cross product",
        [o](const std::string& v) {
          try {
            o->sets.push_back(ParseSetOption(v));
          } catch (const Error& e) {
            Bad(std::string("--set: ") + e.what());
          }
        })
      ->trigger_on_parse();
  Value(cmd, "--cases", "CASES.csv",
        "a CSV of cases: a header naming the keys, a row of values per case (times the --set "
        "values)",
        [o](const std::string& v) { o->cases_csv = v; });
  Value(cmd, "--jobs", "N", "cases at a time (default: one per core)", [o](const std::string& v) {
    const double jobs = ParseNumber("--jobs", v, 1, 1024, false, " cases at a time");
    if (jobs != std::floor(jobs))
      Bad("--jobs: expected a whole number from 1 to 1024, got " + Shown(v));
    o->jobs = static_cast<int>(jobs);
  });
  Flag(cmd, "--prepare", "write the case folders (scene.toml) and sweep.csv, run nothing",
       [o] { o->prepare = true; });
  Flag(cmd, "--summary-only",
       "run the cases in this process and write sweep.csv and sweep_maxima.toml alone: no case "
       "folders, no per-case files (the fastest for many short cases)",
       [o] { o->summary_only = true; });
  AddRunOptions(cmd, &o->run, "sweep folder (default output/<scene name>_sweep)");
  cmd->footer(
      "Each case is 'cablefilm run' in a process of its own (the film off unless --film), in\n"
      "DIR/case_NNN/ with its scene.toml; every case's scene is checked as 'check' would before\n"
      "any runs. The summary: DIR/sweep.csv (case, folder, the values, status, message, peak\n"
      "tension, its time and link, minimum tension, its time and link, snaps, peak_converged,\n"
      "each end tension's mean, std, min, max, up-crossings and most probable maximum), and\n"
      "DIR/sweep_maxima.toml (the cases' maxima; from 3 cases their Gumbel fit). A value A..B\n"
      "(whole numbers) stands for A, A+1, ..., B: --set waves.seed=1..10.\n"
      "Ctrl-C stops the running cases and leaves the finished ones.");
  return {cmd, [scene, o] {
            if (o->sets.empty() && o->cases_csv.empty())
              Bad("nothing to sweep: give --set KEY=V1,V2,... or --cases CASES.csv");
            return SweepCommand(*scene, *o);
          }};
}

}  // namespace cablefilm
