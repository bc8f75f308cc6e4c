#include "run/memory_system_run.h"

#include <optional>

#include "core/point_loads.h"

namespace cablefilm {
namespace {

// Appends each row's points and bodies (PointLoads, as points.csv and body.csv compute them).
class PointRows : public SystemRowSink {
 public:
  PointRows(const SystemRun& run, MemorySystemRows& rows)
      : run_(run), rows_(rows), loads_(run.sys) {}
  bool Row(const Data& sd) override {
    loads_.Compute(run_.sys, sd, run_.inputs);
    const Points& x = loads_.positions();
    const Points& f = loads_.forces();
    rows_.point_position.insert(rows_.point_position.end(), x.data(), x.data() + x.size());
    rows_.point_force.insert(rows_.point_force.end(), f.data(), f.data() + f.size());
    for (size_t b = 0; b < run_.sys.bodies.size(); ++b) {
      const Vec6& q = loads_.body_poses()[b];
      const Vec6& l = loads_.body_loads()[b];
      rows_.body_pose.insert(rows_.body_pose.end(), q.data(), q.data() + 6);
      rows_.body_load.insert(rows_.body_load.end(), l.data(), l.data() + 6);
    }
    ++rows_.rows;
    return true;
  }

 private:
  const SystemRun& run_;
  MemorySystemRows& rows_;
  PointLoads loads_;
};

// Line i of the run as a single line's run (its rows filled later).
MemoryRun LineRun(const SceneDef& scene, const SystemRun& run, size_t i) {
  MemoryRun line;
  line.scene = scene;
  line.run.label = "elastic";  // a system's lines are elastic (core/model.h)
  line.run.model = run.sys.lines[i];
  line.run.grid = run.grid;
  line.run.inputs = run.inputs;
  line.run.equilibrium.iterations = run.equilibrium.iterations;
  line.run.equilibrium.residual = run.equilibrium.residual;
  line.run.equilibrium_ms = run.equilibrium_ms;
  line.run.initial = run.initial.lines[i];
  return line;
}

MemorySystemRun Execute(const SceneDef& scene, SystemRun prepared, long rows) {
  MemorySystemRun out{scene, std::move(prepared), {}, {}};
  SystemRun& run = out.run;
  const size_t nl = run.sys.lines.size();
  std::vector<std::vector<RowSink*>> line_sinks(nl);
  for (size_t i = 0; i < nl; ++i) {
    out.lines.push_back(LineRun(scene, run, i));
    const LineModel& m = run.sys.lines[i];
    out.lines[i].rows.Reserve(m, run.inputs, rows);
  }
  for (size_t i = 0; i < nl; ++i) line_sinks[i] = {&out.lines[i].rows};
  const size_t n = static_cast<size_t>(rows);
  out.rows.point_position.reserve(n * run.sys.points.size() * kDim);
  out.rows.point_force.reserve(n * run.sys.points.size() * kDim);
  out.rows.body_pose.reserve(n * run.sys.bodies.size() * 6);
  out.rows.body_load.reserve(n * run.sys.bodies.size() * 6);
  PointRows points(run, out.rows);
  ExecuteSystemRun(run, line_sinks, {&points});
  for (size_t i = 0; i < nl; ++i) {
    out.lines[i].run.summary = run.lines[i];
    out.lines[i].run.extent = run.extents[i];
    // row_max stays the system's (run.row_max[i]: a log is not copied); a line is not drawn
    // alone.
  }
  return out;
}

}  // namespace

MemorySystemRun RunSystemInMemory(const SceneDef& scene, Model sys, const CancelFlag* stop) {
  SystemRun run = PrepareSystemRun(scene, std::move(sys), stop);
  const long rows = run.grid.outputs + 1;
  return Execute(scene, std::move(run), rows);
}

MemorySystemRun SystemEquilibriumInMemory(const SceneDef& scene, Model sys,
                                          const CancelFlag* stop) {
  for (BodySpec& b : sys.bodies) b.initial_offset = Vec6::Zero();
  SystemRun run = PrepareSystemRun(scene, std::move(sys), stop);
  run.grid.outputs = 0;  // the first row only: no step
  return Execute(scene, std::move(run), 1);
}

}  // namespace cablefilm
