#include "run/system_run.h"

#include <algorithm>
#include <chrono>

#include "core/cancel.h"
#include "core/error.h"
#include "core/step.h"
#include "run/initial_state.h"
#include "run/run.h"

namespace cablefilm {
namespace {

// The grid of the system: each line's own (ChooseTimeGrid); the finest step asked, and with
// "auto" the longest line's tolerance (1e-6 of its length: the system's scale; the shortest
// line's would make a short pendant set the steps of the whole mooring).
TimeGrid SystemGrid(const SceneDef& scene, const Model& sys) {
  TimeGrid grid;
  double longest = -1, tolerance = 0, start_tolerance = 0, start_end = 0;
  for (size_t i = 0; i < sys.lines.size(); ++i) {
    const TimeGrid g = ChooseTimeGrid(sys.lines[i], scene.simulation, scene.output.interval);
    if (i == 0 || g.dt < grid.dt) grid = g;
    if (sys.lines[i].line.total_length() > longest) {
      longest = sys.lines[i].line.total_length();
      tolerance = g.options.tolerance;
      start_tolerance = g.options.start_tolerance;
    }
    start_end = std::max(start_end, g.options.start_end);  // every line's moving ends
  }
  grid.options.tolerance = tolerance;
  grid.options.start_tolerance = start_tolerance;
  grid.options.start_end = start_end;
  return grid;
}

// run's initial data (the lines at `states`, the bodies where run.sys has them) and its
// summaries, empty, for the grid's step options.
void StartFrom(const SceneDef& scene, SystemRun& run, const std::vector<State>& states) {
  run.initial = MakeData(run.sys, run.inputs, run.grid.options, states);
  run.lines.resize(run.sys.lines.size());
  for (size_t i = 0; i < run.lines.size(); ++i) {
    for (const LineDef& def : scene.lines)
      if (def.name == run.sys.line_names[i])
        run.section_materials.push_back(SectionMaterials(scene, def.sections));
    if (run.section_materials.size() != i + 1) run.section_materials.emplace_back();
    run.lines[i].scheme = SchemeName(run.sys.lines[i], run.grid.options);
    run.extents.emplace_back(run.initial.lines[i].state);
    run.row_max.emplace_back();
  }
  run.summary.scheme = run.lines[0].scheme;
  run.summary.tolerance = run.grid.automatic ? run.grid.options.tolerance : 0.0;
  if (run.grid.automatic && run.grid.options.start_end > 0) {
    run.summary.start_tolerance = run.grid.options.start_tolerance;
    run.summary.start_end = run.grid.options.start_end;
  }
}

}  // namespace

void SystemRowStepper::Next() {
  // grid.dt is interval / steps_per_output (time_grid.cpp): the same steps as ever.
  StepSpan(sys_, sd_, in_, grid_.interval, grid_.steps_per_output);
  // Each row at exactly row x interval (no round-off drift over long runs).
  sd_.t = ++row_ * grid_.interval;
  for (LineData& d : sd_.lines) d.state.t = sd_.t;
}

std::vector<State> SystemStatics(const SceneDef& scene, const Model& sys,
                                 EquilibriumReport* report, const CancelFlag* stop,
                                 const std::function<void(double)>& relaxing,
                                 const std::function<void(double)>& solving) {
  if (sys.lines.empty()) throw Error(scene.path + ": a system needs at least one [[line]]");
  Inputs in = SceneInputs(sys.lines[0]);
  in.stop = stop;
  EquilibriumOptions options;
  options.cancel = stop;
  options.relaxing = relaxing;
  options.solving = solving;
  options.relaxation = SystemGrid(scene, sys).options;
  options.inputs = in;
  return SolveEquilibrium(sys, report, options);
}

SystemRun PrepareSystemRun(const SceneDef& scene, Model sys, const CancelFlag* stop,
                           const std::function<void(double)>& relaxing,
                           const std::function<void(double)>& solving) {
  SystemRun run;
  run.sys = std::move(sys);
  if (run.sys.lines.empty()) throw Error(scene.path + ": a system needs at least one [[line]]");
  run.grid = SystemGrid(scene, run.sys);
  run.inputs = SceneInputs(run.sys.lines[0]);  // one environment: any line's inputs
  run.inputs.stop = stop;
  EquilibriumOptions options;
  options.cancel = stop;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<State> states = SystemStatics(scene, run.sys, &run.equilibrium, stop, relaxing, solving);
  // A free body given an initial offset starts there, its lines in equilibrium with it held
  // (a decay test); the others at their equilibrium.
  Model held = run.sys;
  bool offset = false;
  for (int b : run.sys.free_bodies) {
    const Vec6 start = run.equilibrium.body_poses[b] + run.sys.bodies[b].initial_offset;
    PlaceBody(run.sys, b, start);
    if (run.sys.bodies[b].initial_offset == Vec6::Zero()) continue;
    held = HoldBody(held, b, start);
    offset = true;
  }
  if (offset) {
    try {
      states = SolveEquilibrium(held, nullptr, options);
    } catch (const CancelledError&) {
      throw;
    } catch (const Error& e) {
      throw Error(scene.path + ": with the bodies at their initial offsets: " + e.what());
    }
  }
  CheckSystemInitialStretch(scene, run.sys, states);
  run.equilibrium_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  StartFrom(scene, run, states);
  return run;
}

SystemRun RestartSystemRun(const SceneDef& scene, const SystemRun& run) {
  SystemRun again;
  again.sys = run.sys;  // its bodies where the run's start them
  again.grid = SystemGrid(scene, again.sys);
  again.inputs = run.inputs;
  again.equilibrium = run.equilibrium;
  again.equilibrium_ms = run.equilibrium_ms;
  std::vector<State> states;
  for (const LineData& d : run.initial.lines) states.push_back(d.state);
  StartFrom(scene, again, states);
  return again;
}

void ExecuteSystemRun(SystemRun& run, const std::vector<std::vector<RowSink*>>& line_sinks,
                      const std::vector<SystemRowSink*>& sinks) {
  Data sd = run.initial;
  const int nl = static_cast<int>(sd.lines.size());
  auto hand = [&] {
    bool go_on = true;
    for (int i = 0; i < nl; ++i) {
      const LineData& d = sd.lines[i];
      const Eigen::VectorXd& T = d.tension();
      run.lines[i].AddRow(d.state.t, T, run.sys.lines[i].line.breaking_load);
      run.extents[i].Add(d.state, T);
      run.row_max[i].Append(d.state.t, T.maxCoeff());
      if (i < static_cast<int>(line_sinks.size()))
        for (RowSink* s : line_sinks[i]) go_on = s->Row(d) && go_on;
    }
    for (SystemRowSink* s : sinks) go_on = s->Row(sd) && go_on;
    ++run.summary.rows;
    return go_on;
  };
  RunSummary& s = run.summary;
  const auto t0 = std::chrono::steady_clock::now();
  bool completed = hand();
  SystemRowStepper rows(run.sys, sd, run.inputs, run.grid);
  while (completed && !rows.done()) {
    try {
      rows.Next();
    } catch (const CancelledError&) {
      completed = false;
      break;
    } catch (const BlowUpError& e) {
      s.failure = std::string(e.what()) + " (" + s.scheme + ")";
      completed = false;
      break;
    }
    completed = hand();
  }
  s.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  s.duration = sd.t;
  s.completed = completed && sd.t >= run.grid.end() - 1e-9 * run.grid.interval;
  s.stats = ModelStepStats(run.sys, sd);
  for (int i = 0; i < nl; ++i) {
    RunSummary& l = run.lines[i];
    l.tolerance = s.tolerance;
    l.duration = s.duration;
    l.wall = s.wall;
    l.rows = s.rows;
    l.completed = s.completed;
    l.failure = s.failure;
    l.stats = LineStepStats(run.sys, sd, i);
    l.warnings = TrustWarnings(run.sys.lines[i], l.stats, true);
    for (const std::string& w : l.warnings)
      s.warnings.push_back("line \"" + run.sys.line_names[i] + "\": " + w);
    if (!(l.peak <= s.peak)) {  // the first line with the largest peak (NaN: none yet)
      s.peak = l.peak;
      s.peak_t = l.peak_t;
      s.peak_link = l.peak_link;
      s.peak_line = run.sys.line_names[i];
      run.peak_line = i;
    }
    const std::vector<std::string>& materials = run.section_materials.at(i);
    if (l.utilisation_link >= 0 && !materials.empty())
      l.utilisation_material =
          materials.at(run.sys.lines[i].line.link_section[l.utilisation_link]);
    if (l.utilisation_link >= 0 && !(l.utilisation <= s.utilisation)) {  // the first largest
      s.utilisation = l.utilisation;
      s.utilisation_t = l.utilisation_t;
      s.utilisation_link = l.utilisation_link;
      s.utilisation_tension = l.utilisation_tension;
      s.utilisation_mbl = l.utilisation_mbl;
      s.utilisation_material = l.utilisation_material;
      s.utilisation_line = run.sys.line_names[i];
    }
    if (!(l.min_tension >= s.min_tension)) {
      s.min_tension = l.min_tension;
      s.min_tension_t = l.min_tension_t;
      s.min_tension_link = l.min_tension_link;
      s.min_tension_line = run.sys.line_names[i];
    }
  }
}

}  // namespace cablefilm
