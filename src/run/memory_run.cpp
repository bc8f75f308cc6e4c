#include "run/memory_run.h"

namespace cablefilm {

bool MemoryRows::Row(const Data& d) {
  time.push_back(d.state.t);
  const Points& p = d.state.x;  // column-major: x, y, z of station 0, then of station 1, ...
  x.insert(x.end(), p.data(), p.data() + p.size());
  const Eigen::VectorXd& T = d.tension();
  tension.insert(tension.end(), T.data(), T.data() + T.size());
  ++rows;
  return true;
}

void MemoryRows::Reserve(long rows, int stations, int links) {
  const std::size_t n = static_cast<std::size_t>(rows);
  time.reserve(n);
  x.reserve(n * static_cast<std::size_t>(stations) * kDim);
  tension.reserve(n * static_cast<std::size_t>(links));
}

MemoryRun RunInMemory(const SceneDef& scene, const Model& model, const CancelFlag* stop) {
  MemoryRun out{scene, PrepareRun(scene, model, LawName(model.line.law), stop), MemoryRows()};
  out.rows.Reserve(out.run.grid.outputs + 1, model.stations(), model.line.links);
  ExecuteRun(out.run, {&out.rows});
  return out;
}

}  // namespace cablefilm
