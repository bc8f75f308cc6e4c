#include "run/memory_run.h"

namespace cablefilm {

bool MemoryRows::Row(const Data& d) {
  time.push_back(d.state.t);
  for (int i = 0; i < kDim; ++i)
    for (Eigen::Index j = 0; j < d.state.x.cols(); ++j) x[i].push_back(d.state.x(i, j));
  const Eigen::VectorXd& T = d.tension();
  tension.insert(tension.end(), T.data(), T.data() + T.size());
  ++rows;
  return true;
}

void MemoryRows::Reserve(long rows, int stations, int links) {
  const std::size_t n = static_cast<std::size_t>(rows);
  time.reserve(n);
  for (std::vector<double>& axis : x) axis.reserve(n * static_cast<std::size_t>(stations));
  tension.reserve(n * static_cast<std::size_t>(links));
}

MemoryRun RunInMemory(const SceneDef& scene, const Model& model, const CancelFlag* stop) {
  MemoryRun out{scene, PrepareRun(scene, model, LawName(model.line.law), stop), MemoryRows()};
  out.rows.Reserve(out.run.grid.outputs + 1, model.stations(), model.line.links);
  ExecuteRun(out.run, {&out.rows});
  return out;
}

}  // namespace cablefilm
