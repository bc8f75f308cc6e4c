#include "run/memory_run.h"

namespace cablefilm {

bool MemoryRows::Row(const LineData& d) {
  time.push_back(d.state.t);
  const Points& p = d.state.x;  // column-major: x, y, z of station 0, then of station 1, ...
  x.insert(x.end(), p.data(), p.data() + p.size());
  const Eigen::VectorXd& T = d.tension();
  tension.insert(tension.end(), T.data(), T.data() + T.size());
  if (model_) {  // rows reserved for a model (Reserve)
    ends_.Compute(*model_, d, *inputs_);
    for (int e = 0; e < 2; ++e)
      end_load.insert(end_load.end(), ends_.at(e).data(), ends_.at(e).data() + kDim);
  }
  ++rows;
  return true;
}

void MemoryRows::Reserve(const LineModel& m, const Inputs& in, long rows) {
  model_ = &m;
  inputs_ = &in;
  ends_ = EndLoads(m);
  const std::size_t n = static_cast<std::size_t>(rows);
  time.reserve(n);
  x.reserve(n * static_cast<std::size_t>(m.stations()) * kDim);
  tension.reserve(n * static_cast<std::size_t>(m.line.links));
  end_load.reserve(n * 2 * kDim);
}

MemoryRun RunInMemory(const SceneDef& scene, const LineModel& model, const CancelFlag* stop) {
  MemoryRun out{scene, PrepareRun(scene, model, LawName(model.line.law), stop), MemoryRows()};
  out.rows.Reserve(out.run.model, out.run.inputs, out.run.grid.outputs + 1);
  ExecuteRun(out.run, {&out.rows});
  return out;
}

}  // namespace cablefilm
