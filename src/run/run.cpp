#include "run/run.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>

#include "core/end_loads.h"
#include "run/initial_state.h"

namespace cablefilm {
namespace {

// The run's own record of every row, line by line.
class RecordSink : public RowSink {
 public:
  explicit RecordSink(Run& run) : run_(run) {
    for (std::size_t i = 0; i < run.lines.size(); ++i)
      run.lines[i].row_ends = EndLoads(run.model.lines[i]);
  }
  bool Row(const Data& d) override {
    for (std::size_t i = 0; i < run_.lines.size(); ++i) {
      const LineModel& m = run_.model.lines[i];
      const LineData& line = d.lines[i];
      LineRecord& r = run_.lines[i];
      const Eigen::VectorXd& T = line.tension();
      r.extent.Add(line.state, T);
      const double tension_start = T[0], tension_end = T[m.line.links - 1];  // [N]
      r.row_max.Append(line.state.t, T.maxCoeff(), tension_start, tension_end);
      r.end_moments[0].Add(tension_start);
      r.end_moments[1].Add(tension_end);
      r.summary.AddRow(line.state.t, T, m.line.breaking_load);
      r.row_ends.Compute(m, line, run_.inputs);
      r.summary.AddEndLoads(line.state.t, r.row_ends.at(0), r.row_ends.at(1));
    }
    return true;
  }

 private:
  Run& run_;
};

// run's initial data (the lines at `states`, the bodies where run.model has them) and its
// records, empty, for the grid's step options.
void StartFrom(const SceneDef& scene, Run& run, const std::vector<State>& states,
               const std::vector<Points>* friction_anchors = nullptr) {
  run.initial = MakeData(run.model, run.inputs, run.grid.options, states, friction_anchors);
  run.lines.clear();
  run.lines.resize(run.model.lines.size());
  for (std::size_t i = 0; i < run.lines.size(); ++i) {
    LineRecord& r = run.lines[i];
    if (i < scene.lines.size()) r.section_materials = SectionMaterials(scene, scene.lines[i].sections);
    r.extent = RunExtent(run.initial.lines[i].state);
    RunSummary& s = r.summary;
    s.scheme = SchemeName(run.model.lines[i], run.initial.lines[i].options);
    s.tolerance = run.grid.automatic ? run.grid.options.tolerance : 0.0;
    const bool implicit = run.initial.lines[i].options.scheme == Scheme::kImplicit;
    if (run.grid.automatic && implicit && run.grid.options.start_end > 0) {  // its step's
      s.start_tolerance = run.grid.options.start_tolerance;
      s.start_end = run.grid.options.start_end;
    }
  }
  run.summary = run.lines.front().summary;
}

// The run's summary of several lines from theirs: the largest peak and utilisation and the
// least tension of any line (the first line holding each), the end tensions' statistics of the
// line holding the peak, every line's warnings named.
void MergeLines(Run& run) {
  RunSummary& s = run.summary;
  for (std::size_t i = 0; i < run.lines.size(); ++i) {
    const RunSummary& l = run.lines[i].summary;
    const std::string& name = run.model.line_names[i];
    for (const std::string& w : l.warnings) s.warnings.push_back("line \"" + name + "\": " + w);
    if (!(l.peak <= s.peak)) {  // the first line with the largest peak (NaN: none yet)
      s.peak = l.peak;
      s.peak_t = l.peak_t;
      s.peak_link = l.peak_link;
      s.peak_line = name;
      run.peak_line = static_cast<int>(i);
      s.ends[0] = l.ends[0];
      s.ends[1] = l.ends[1];
      s.ends_line = name;
    }
    if (l.utilisation_link >= 0 && !(l.utilisation <= s.utilisation)) {  // the first largest
      s.utilisation = l.utilisation;
      s.utilisation_t = l.utilisation_t;
      s.utilisation_link = l.utilisation_link;
      s.utilisation_tension = l.utilisation_tension;
      s.utilisation_mbl = l.utilisation_mbl;
      s.utilisation_material = l.utilisation_material;
      s.utilisation_line = name;
    }
    if (!(l.min_tension >= s.min_tension)) {
      s.min_tension = l.min_tension;
      s.min_tension_t = l.min_tension_t;
      s.min_tension_link = l.min_tension_link;
      s.min_tension_line = name;
    }
  }
}

}  // namespace

std::vector<std::string> SectionMaterials(const SceneDef& scene,
                                          const std::vector<SectionDef>& sections) {
  std::vector<std::string> names;
  for (const SectionDef& s : sections) names.push_back(scene.materials.at(s.material).name);
  return names;
}

const char* LawName(LinkLaw law) {
  return law == LinkLaw::kElastic ? "elastic" : "inextensible";
}

const char* ModelLawName(const Model& model) {
  for (const LineModel& m : model.lines)
    if (m.line.law == LinkLaw::kElastic) return "elastic";
  return "inextensible";
}

Run PrepareRun(const SceneDef& scene, Model model, std::string label, const CancelFlag* stop,
               const StaticsCallbacks& progress) {
  Run run;
  run.label = std::move(label);
  run.model = std::move(model);
  run.grid = ChooseTimeGrid(run.model, scene.simulation, scene.output.interval);
  run.inputs = SceneInputs(run.model);
  run.inputs.stop = stop;
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<State> states =
      MakeInitialState(scene, run.model, run.grid, &run.equilibrium, stop, progress);
  run.equilibrium_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  StartFrom(scene, run, states);
  return run;
}

Run RestartRun(const SceneDef& scene, const Run& run) {
  Run again;
  again.label = run.label;
  again.model = run.model;  // its bodies where the run starts them
  again.grid = ChooseTimeGrid(again.model, scene.simulation, scene.output.interval);
  again.inputs = run.inputs;
  again.equilibrium = run.equilibrium;
  again.equilibrium_ms = run.equilibrium_ms;
  std::vector<State> states;
  for (const LineData& d : run.initial.lines) states.push_back(d.state);
  StartFrom(scene, again, states);
  return again;
}

Run WindowRun(const SceneDef& scene, const Run& run, const std::vector<State>& states,
              const std::vector<Points>& friction_anchors, long first_row, long last_row) {
  Run again;
  again.label = run.label;
  again.model = run.model;
  again.grid = ChooseTimeGrid(again.model, scene.simulation, scene.output.interval);
  again.grid.first_output = first_row;
  again.grid.outputs = std::min(last_row, again.grid.outputs);
  again.inputs = run.inputs;
  again.equilibrium = run.equilibrium;
  again.equilibrium_ms = run.equilibrium_ms;
  StartFrom(scene, again, states, &friction_anchors);
  return again;
}

void ExecuteRun(Run& run, const std::vector<RowSink*>& sinks) {
  RecordSink record(run);
  std::vector<RowSink*> all{&record};
  all.insert(all.end(), sinks.begin(), sinks.end());
  Data d = run.initial;
  // The wall time drifts with the machine's load; the stepping thread's CPU time does not.
  auto cpu_now = [] {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);  // [s]
  };
  const double cpu0 = cpu_now();
  const auto t0 = std::chrono::steady_clock::now();
  const RunEnd end = Drive(run.model, d, run.inputs, run.grid, all);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = cpu_now() - cpu0;
  const RunSummary& first = run.lines.front().summary;
  std::string failure;
  if (!end.failure.empty())
    failure = end.failure + " (" + first.scheme + ", time step " + std::to_string(run.grid.dt) +
              " s)";
  for (std::size_t i = 0; i < run.lines.size(); ++i) {
    RunSummary& l = run.lines[i].summary;
    l.wall = wall;
    l.cpu = cpu;
    l.duration = d.t;
    l.completed = end.completed;
    l.failure = failure;
    l.stats = LineStepStats(run.model, d, static_cast<int>(i));
    l.warnings = TrustWarnings(run.model.lines[i], l.stats);
    LineRecord& r = run.lines[i];
    EndTensionPass(r.row_max, r.end_moments, run.grid.interval, l.ends, &r.spectrum);
    const std::vector<std::string>& materials = run.lines[i].section_materials;
    if (l.utilisation_link >= 0 && !materials.empty())
      l.utilisation_material =
          materials.at(run.model.lines[i].line.link_section[l.utilisation_link]);
  }
  if (run.lines.size() == 1) {
    run.summary = first;
    run.peak_line = 0;
    return;
  }
  RunSummary& s = run.summary;
  s.wall = wall;
  s.cpu = cpu;
  s.duration = d.t;
  s.rows = first.rows;
  s.completed = end.completed;
  s.failure = failure;
  s.stats = ModelStepStats(run.model, d);
  MergeLines(run);
}

}  // namespace cablefilm
