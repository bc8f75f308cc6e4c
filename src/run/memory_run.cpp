#include "run/memory_run.h"

namespace cablefilm {
namespace {

// Appends each row of every line (its end loads the run's record computed: LineRecord) and of
// the points and bodies (PointLoads, as points.csv and body.csv compute them).
class MemorySink : public RowSink {
 public:
  MemorySink(MemoryRun& out, long rows) : out_(out), loads_(out.run.model) {
    const Model& model = out.run.model;
    const std::size_t n = static_cast<std::size_t>(rows);
    out.lines.resize(model.lines.size());
    for (std::size_t i = 0; i < model.lines.size(); ++i) {
      const LineModel& m = model.lines[i];
      MemoryRows& r = out.lines[i];
      r.time.reserve(n);
      r.x.reserve(n * static_cast<std::size_t>(m.stations()) * kDim);
      r.tension.reserve(n * static_cast<std::size_t>(m.line.links));
      r.end_load.reserve(n * 2 * kDim);
    }
    MemoryPointRows& p = out.points;
    p.point_position.reserve(n * model.points.size() * kDim);
    p.point_force.reserve(n * model.points.size() * kDim);
    p.body_pose.reserve(n * model.bodies.size() * 6);
    p.body_load.reserve(n * model.bodies.size() * 6);
  }
  bool Row(const Data& d) override {
    const Run& run = out_.run;
    for (std::size_t i = 0; i < d.lines.size(); ++i) {
      const LineData& line = d.lines[i];
      MemoryRows& r = out_.lines[i];
      r.time.push_back(line.state.t);
      const Points& x = line.state.x;  // column-major: x, y, z of station 0, then station 1 ...
      r.x.insert(r.x.end(), x.data(), x.data() + x.size());
      const Eigen::VectorXd& T = line.tension();
      r.tension.insert(r.tension.end(), T.data(), T.data() + T.size());
      const EndLoads& ends = run.lines[i].row_ends;
      for (int e = 0; e < 2; ++e)
        r.end_load.insert(r.end_load.end(), ends.at(e).data(), ends.at(e).data() + kDim);
      ++r.rows;
    }
    loads_.Compute(run.model, d, run.inputs);
    MemoryPointRows& p = out_.points;
    const Points& px = loads_.positions();
    const Points& pf = loads_.forces();
    p.point_position.insert(p.point_position.end(), px.data(), px.data() + px.size());
    p.point_force.insert(p.point_force.end(), pf.data(), pf.data() + pf.size());
    for (std::size_t b = 0; b < run.model.bodies.size(); ++b) {
      const Vec6& q = loads_.body_poses()[b];
      const Vec6& l = loads_.body_loads()[b];
      p.body_pose.insert(p.body_pose.end(), q.data(), q.data() + 6);
      p.body_load.insert(p.body_load.end(), l.data(), l.data() + 6);
    }
    ++p.rows;
    return true;
  }

 private:
  MemoryRun& out_;
  PointLoads loads_;
};

MemoryRun Execute(const SceneDef& scene, Run prepared, long rows) {
  MemoryRun out{scene, std::move(prepared), {}, {}};
  MemorySink sink(out, rows);
  ExecuteRun(out.run, {&sink});
  return out;
}

}  // namespace

MemoryRun RunInMemory(const SceneDef& scene, Model model, const CancelFlag* stop) {
  const std::string label = ModelLawName(model);
  Run run = PrepareRun(scene, std::move(model), label, stop);
  const long rows = run.grid.outputs + 1;
  return Execute(scene, std::move(run), rows);
}

MemoryRun EquilibriumInMemory(const SceneDef& scene, Model model, const CancelFlag* stop) {
  for (BodySpec& b : model.bodies) b.initial_offset = Vec6::Zero();
  const std::string label = ModelLawName(model);
  Run run = PrepareRun(scene, std::move(model), label, stop);
  run.grid.outputs = 0;  // the first row only: no step
  return Execute(scene, std::move(run), 1);
}

}  // namespace cablefilm
