// Issue 11, "make it stay fixed": a scene fuzzer. An input is a scene file (TOML), optionally
// followed by a motion table, after a line exactly
//     # ---- motion.csv ----
// which is written beside the scene as motion.csv (a scene reads it with file = "motion.csv").
// Each input goes the way `check`, `run` and `compare` take it:
//   1. the loader, then `check` itself (CheckCommand: the limits, the model, the time grid, the
//      summary, the static equilibrium) for a scene of at most kMaxLinksCheckedWithEquilibrium
//      links or a straight start; for larger ones (up to kMaxLinksChecked) what `check` does
//      before the equilibrium (the equilibrium then runs in 2., within the time budget);
//   2. for a scene of at most kMaxLinksSimulated links: the initial state (the static
//      equilibrium) and the first kMaxOutputs outputs of the run, with its result files (each
//      line's equilibrium.csv and timeseries.csv, points.csv of several lines), for the
//      scene's model and, when compare would accept it, for the other model too.
// Every cablefilm::Error is a clean answer. Anything else fails: a sanitizer report, another
// exception (std::bad_alloc, std::out_of_range, ...; main() would abort on them), a hang
// (libFuzzer -timeout; the replay driver's alarm). Runs long by design (a stiff explicit scene)
// are stopped by a time budget through the program's own cancel flag (as Ctrl-C would).
#include "scene_fuzzer.h"

#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <new>
#include <string>
#include <thread>
#include <vector>

#include <toml++/toml.h>

#include "app/commands.h"
#include "core/cancel.h"
#include "core/error.h"
#include "io/points_file.h"
#include "io/result_files.h"
#include "run/run.h"
#include "run/time_grid.h"
#include "scene/build_model.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"

namespace cablefilm_fuzz {
namespace {

namespace fs = std::filesystem;
using namespace cablefilm;

constexpr char kTableSeparator[] = "\n# ---- motion.csv ----\n";
constexpr long kMaxLinksChecked = 200000;  // `check` builds the model: memory and time O(links)
// `check`'s equilibrium takes up to 5500 iterations of O(links) (no budget reaches it here).
constexpr long kMaxLinksCheckedWithEquilibrium = 100;
constexpr long kMaxLinksSimulated = 1000;
constexpr long kMaxOutputs = 20;          // outputs simulated after t = 0, per model
constexpr double kBudgetSeconds = 0.3;    // wall time for the runs of an input
                                          // (CABLEFILM_FUZZ_BUDGET)
constexpr double kCoupledEquilibriumBudgets = 5;  // statics of lines joined at points or
                                                  // bodies: 5 budgets

Counts g_counts;

// Raises a cancel flag when the time given to a run is over: the run then stops within one step
// or one Newton iteration (cancel.h), the way a signal stops it.
class Watchdog {
 public:
  Watchdog() : thread_([this] { Loop(); }) {}
  ~Watchdog() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      quit_ = true;
    }
    wake_.notify_all();
    thread_.join();
  }
  const CancelFlag* Arm(double seconds) {
    std::lock_guard<std::mutex> lock(mutex_);
    flag_ = 0;
    armed_ = true;
    deadline_ = std::chrono::steady_clock::now() +
                std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                    std::chrono::duration<double>(seconds));
    wake_.notify_all();
    return &flag_;
  }
  void Disarm() {
    std::lock_guard<std::mutex> lock(mutex_);
    armed_ = false;
  }

 private:
  void Loop() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!quit_) {
      if (!armed_) {
        wake_.wait(lock);
      } else if (wake_.wait_until(lock, deadline_) == std::cv_status::timeout && armed_ &&
                 std::chrono::steady_clock::now() >= deadline_) {
        flag_ = 1;
        armed_ = false;
      }
    }
  }
  std::mutex mutex_;
  std::condition_variable wake_;
  bool quit_ = false, armed_ = false;
  std::chrono::steady_clock::time_point deadline_;
  CancelFlag flag_{0};
  std::thread thread_;
};

struct Setup {
  fs::path dir;        // this process's own folder
  fs::path scene, table, out;
  double budget = kBudgetSeconds;
  bool verbose = false;  // CABLEFILM_FUZZ_VERBOSE=1: each clean error's message on stderr
  Watchdog* watchdog = nullptr;
};
Setup* g_setup = nullptr;

[[noreturn]] void Fail(const char* what, const char* detail) {
  std::fprintf(stderr, "\nscene_fuzzer: FAILURE: %s: %s\n", what, detail);
  std::fflush(stderr);
  std::abort();
}

void WriteFile(const fs::path& p, const char* data, std::size_t size) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(data, static_cast<std::streamsize>(size));
  if (!out) Fail("cannot write", p.c_str());
}

void Explain(const char* what, const Error& e) {
  if (g_setup->verbose) std::fprintf(stderr, "  %s: %s\n", what, e.what());
}

long Links(const SceneDef& scene) {
  long links = 0;
  for (const LineDef& line : scene.lines)
    for (const SectionDef& s : line.sections) links += s.segments;
  return links;
}

enum class Outcome { kFinished, kError, kBudget };

// Whether the model has lines joined at points or bodies: its statics take longer.
bool Coupled(const Model& model) {
  for (const Island& island : model.islands)
    if (island.coupled()) return true;
  return false;
}

// What `run` and `compare` do (SimulateToFiles), on the first kMaxOutputs outputs: the initial
// state, each line's equilibrium.csv and timeseries.csv, points.csv of several lines. The
// statics of lines joined at points get kCoupledEquilibriumBudgets budgets, the steps one.
Outcome RunModel(const SceneDef& scene, const std::string& suffix) {
  const CancelFlag* cancel = g_setup->watchdog->Arm(g_setup->budget);
  try {
    const Model model = BuildModel(scene);
    CheckModelLimits(scene, model);
    if (Coupled(model)) cancel = g_setup->watchdog->Arm(g_setup->budget * kCoupledEquilibriumBudgets);
    Run run = PrepareRun(scene, model, ModelLawName(model), cancel);
    g_setup->watchdog->Arm(g_setup->budget);  // the steps: the budget of a run
    const std::string out = g_setup->out.string();
    const std::size_t nl = run.model.lines.size();
    std::vector<std::unique_ptr<TimeseriesWriter>> series(nl);
    std::vector<RowSink*> sinks;
    for (std::size_t i = 0; i < nl; ++i) {
      const LineData& d = run.initial.lines[i];
      const std::string name = out + "/line" + std::to_string(i) + suffix;
      WriteEquilibriumCsv(name + "_equilibrium.csv", run.model.lines[i], d.state, d.tension());
      series[i] = std::make_unique<TimeseriesWriter>(name + "_timeseries.csv", run.model.lines[i],
                                                     static_cast<int>(i), run.inputs,
                                                     &run.lines[i].row_ends);
      sinks.push_back(series[i].get());
    }
    std::unique_ptr<PointsWriter> points;
    if (nl > 1) {
      points = std::make_unique<PointsWriter>(out + "/points" + suffix + ".csv", run.model, run.inputs);
      sinks.push_back(points.get());
    }
    long outputs = 0;
    RowFunction enough([&](const Data&) { return outputs++ < kMaxOutputs; });
    sinks.push_back(&enough);
    ExecuteRun(run, sinks);
    for (std::size_t i = 0; i < nl; ++i) {
      if (run.summary.completed)
        series[i]->Commit();
      else
        series[i]->CommitPartial(out + "/line" + std::to_string(i) + suffix + "_timeseries.partial.csv");
    }
    if (points && run.summary.completed) points->Commit();
    if (points && !run.summary.completed) points->CommitPartial(out + "/points" + suffix + ".partial.csv");
  } catch (const Error& e) {
    Explain("run", e);
    return *cancel != 0 ? Outcome::kBudget : Outcome::kError;
  }
  return *cancel != 0 ? Outcome::kBudget : Outcome::kFinished;
}

// Whether the scene text is TOML at all (the counts tell the parser's rejections apart).
bool IsToml(const char* data, std::size_t size) {
  try {
    (void)toml::parse(std::string_view(data, size));
  } catch (const toml::parse_error&) {
    return false;
  }
  return true;
}

void RunOne(const char* data, std::size_t size) {
  // The scene and its table, written afresh: nothing of an earlier input may be read.
  const std::string input(data, size);
  const std::size_t cut = input.find(kTableSeparator);
  std::error_code ec;
  fs::remove_all(g_setup->out, ec);
  fs::create_directories(g_setup->out, ec);
  if (ec) Fail("cannot create", g_setup->out.c_str());
  if (cut == std::string::npos) {
    WriteFile(g_setup->scene, data, size);
    fs::remove(g_setup->table, ec);
  } else {
    WriteFile(g_setup->scene, data, cut + 1);  // the scene keeps its last newline
    const std::size_t table = cut + sizeof kTableSeparator - 1;
    WriteFile(g_setup->table, data + table, size - table);
  }

  // 1. The loader, then `check` as the command line runs it.
  SceneDef scene;
  try {
    scene = LoadScene(g_setup->scene.string());
    const long links = Links(scene);
    if (links > kMaxLinksChecked) {
      ++g_counts.loaded_only;
      return;
    }
    if (links <= kMaxLinksCheckedWithEquilibrium || scene.initial != InitialStateKind::kEquilibrium) {
      CheckCommand(g_setup->scene.string());
    } else {  // what `check` does before the equilibrium (which runs in 2., within the budget)
      const Model model = BuildModel(scene);
      CheckModelLimits(scene, model);
      ChooseTimeGrid(model, scene.simulation, scene.output.interval);
    }
  } catch (const Error& e) {
    Explain("rejected", e);
    ++g_counts.rejected;
    if (!IsToml(data, cut == std::string::npos ? size : cut + 1)) ++g_counts.not_toml;
    return;
  }
  if (Links(scene) > kMaxLinksSimulated) {
    ++g_counts.checked_only;
    return;
  }

  // 2. The run, and compare's second model (every line the other) when it can be built.
  ++g_counts.simulated;
  if (scene.lines.size() > 1) ++g_counts.systems;
  Outcome end = RunModel(scene, "");
  SceneDef other = scene;
  for (LineDef& line : other.lines)
    line.model = line.model == CableModelKind::kElastic ? CableModelKind::kInextensible
                                                        : CableModelKind::kElastic;
  bool other_ok = true;
  try {
    CheckModelLimits(other, BuildModel(other));
  } catch (const Error&) {
    other_ok = false;  // compare refuses the scene: nothing more to run
  }
  if (other_ok && end != Outcome::kBudget) {
    const Outcome second = RunModel(other, "_other");
    if (second != Outcome::kFinished) end = second;
  }
  g_setup->watchdog->Disarm();
  if (end == Outcome::kError) ++g_counts.run_errors;
  if (end == Outcome::kBudget) ++g_counts.budget_cut;
}

}  // namespace

const Counts& GetCounts() { return g_counts; }

void PrintCounts() {
  const Counts& c = g_counts;
  std::fprintf(stderr,
               "scene_fuzzer: %ld inputs: %ld rejected cleanly (%ld of them not TOML: %.1f %% of "
               "the inputs pass the TOML parser); accepted: %ld too large to check here, %ld too "
               "large to simulate here, %ld simulated (%ld systems of lines; %ld ended in a "
               "clean run error, %ld stopped at the time budget)\n",
               c.inputs, c.rejected, c.not_toml,
               c.inputs > 0 ? 100.0 * static_cast<double>(c.inputs - c.not_toml) /
                                  static_cast<double>(c.inputs)
                            : 0.0,
               c.loaded_only, c.checked_only, c.simulated, c.systems, c.run_errors,
               c.budget_cut);
}

}  // namespace cablefilm_fuzz

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  using namespace cablefilm_fuzz;
  // The commands print their summaries on stdout: not wanted here. Nothing reads a terminal.
  if (!std::freopen("/dev/null", "w", stdout)) Fail("cannot reopen", "stdout");
  if (!std::freopen("/dev/null", "r", stdin)) Fail("cannot reopen", "stdin");
  static Setup setup;
  static Watchdog watchdog;
  setup.watchdog = &watchdog;
  if (const char* b = std::getenv("CABLEFILM_FUZZ_BUDGET")) setup.budget = std::atof(b);
  if (const char* v = std::getenv("CABLEFILM_FUZZ_VERBOSE")) setup.verbose = *v && *v != '0';
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/cablefilm_fuzz_XXXXXX";
  if (!::mkdtemp(pattern.data())) Fail("cannot create a folder", pattern.c_str());
  setup.dir = pattern;
  setup.scene = setup.dir / "scene.toml";
  setup.table = setup.dir / "motion.csv";
  setup.out = setup.dir / "out";
  g_setup = &setup;
  std::atexit([] {
    PrintCounts();
    std::error_code ec;
    fs::remove_all(g_setup->dir, ec);
  });
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cablefilm_fuzz;
  ++g_counts.inputs;
  try {
    RunOne(reinterpret_cast<const char*>(data), size);
  } catch (const std::bad_alloc& e) {
    Fail("std::bad_alloc (memory beyond the stated limits)", e.what());
  } catch (const std::exception& e) {
    Fail("an exception that is not a cablefilm::Error", e.what());
  } catch (...) {
    Fail("an exception that is not a std::exception", "?");
  }
  return 0;
}
