#include "run/run.h"

#include <chrono>

#include "core/end_loads.h"
#include "run/initial_state.h"

namespace cablefilm {
namespace {

// The run's own record of every row.
class RecordSink : public RowSink {
 public:
  explicit RecordSink(Run& run) : run_(run) { run_.row_ends = EndLoads(run.model); }
  bool Row(const LineData& d) override {
    const Eigen::VectorXd& T = d.tension();
    run_.extent.Add(d.state, T);
    run_.row_max.Append(d.state.t, T.maxCoeff());
    run_.summary.AddRow(d.state.t, T, run_.model.line.breaking_load);
    EndLoads& ends = run_.row_ends;
    ends.Compute(run_.model, d, run_.inputs);
    run_.summary.AddEndLoads(d.state.t, ends.at(0), ends.at(1));
    return true;
  }

 private:
  Run& run_;
};

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

Run PrepareRun(const SceneDef& scene, LineModel model, std::string label, const CancelFlag* stop) {
  Run run;
  run.label = std::move(label);
  run.model = std::move(model);
  const LineModel& m = run.model;
  run.grid = ChooseTimeGrid(m, scene.simulation, scene.output.interval);
  run.inputs = SceneInputs(m);
  run.inputs.stop = stop;
  const auto t0 = std::chrono::steady_clock::now();
  const State initial = MakeInitialState(scene, m, &run.equilibrium, stop);
  run.equilibrium_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  run.initial = MakeLineData(m, run.inputs, run.grid.options, initial);
  run.extent = RunExtent(initial);
  run.summary.scheme = SchemeName(m, run.grid.options);
  run.summary.tolerance = run.grid.automatic ? run.grid.options.tolerance : 0.0;
  if (run.grid.automatic && run.grid.options.start_end > 0) {
    run.summary.start_tolerance = run.grid.options.start_tolerance;
    run.summary.start_end = run.grid.options.start_end;
  }
  run.section_materials = SectionMaterials(scene, scene.sections);
  return run;
}

void ExecuteRun(Run& run, const std::vector<RowSink*>& sinks) {
  RecordSink record(run);
  std::vector<RowSink*> all{&record};
  all.insert(all.end(), sinks.begin(), sinks.end());
  LineData d = run.initial;
  const auto t0 = std::chrono::steady_clock::now();
  const RunEnd end = Drive(run.model, d, run.inputs, run.grid, all);
  RunSummary& s = run.summary;
  s.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  s.duration = d.state.t;
  s.stats = d.step_stats();
  s.completed = end.completed;
  if (!end.failure.empty())
    s.failure = end.failure + " (" + s.scheme + ", time step " + std::to_string(run.grid.dt) +
                " s)";
  s.warnings = TrustWarnings(run.model, s.stats);
  if (s.utilisation_link >= 0)
    s.utilisation_material =
        run.section_materials.at(run.model.line.link_section[s.utilisation_link]);
}

}  // namespace cablefilm
