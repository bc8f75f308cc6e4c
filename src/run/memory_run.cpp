#include "run/memory_run.h"

#include <cmath>

namespace cablefilm {

MemoryRun RunInMemory(const SceneDef& scene, const CableModel& model, const CancelFlag* cancel,
                      const std::function<bool()>& keep_going) {
  // The calls of commands.cpp's SimulateToFiles, in its order, so the rows are its rows.
  const TimeGrid grid = ChooseTimeGrid(model, scene.simulation, scene.output.interval);
  EquilibriumReport eq;
  CableState initial = MakeInitialState(scene, model, &eq, cancel);
  auto integrator = MakeIntegrator(model, grid);
  integrator->Initialize(model, initial);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  MemoryRun run{scene, model,  grid, eq, initial, integrator->tensions(), RunExtent(initial),
                integrator->name(), {}, false, "", nan, nan, -1, nan, nan, -1, 0, {}, {}, {}, {}};
  const std::size_t stations = static_cast<std::size_t>(model.stations());
  const std::size_t links = static_cast<std::size_t>(model.links);
  const std::size_t expected = static_cast<std::size_t>(grid.outputs) + 1;
  run.time.reserve(expected);
  run.x.reserve(expected * stations);
  run.y.reserve(expected * stations);
  run.tension.reserve(expected * links);
  CableState state = initial;
  try {
    run.completed =
        Simulate(model, *integrator, state, grid,
                 [&](const CableState& s, const Eigen::VectorXd& T) {
                   run.time.push_back(s.t);
                   for (Eigen::Index j = 0; j < s.x.cols(); ++j) {
                     run.x.push_back(s.x(0, j));
                     run.y.push_back(s.x(1, j));
                   }
                   run.tension.insert(run.tension.end(), T.data(), T.data() + T.size());
                   run.extent.Add(s, T);
                   Eigen::Index link = 0;
                   const double tmax = T.maxCoeff(&link);  // as MaxTensionLog::Append keeps it
                   if (!std::isnan(tmax) && !(tmax <= run.peak)) {
                     run.peak = tmax;
                     run.peak_t = s.t;
                     run.peak_link = static_cast<int>(link);
                   }
                   const double tmin = T.minCoeff(&link);  // as SimulateToFiles keeps it
                   if (std::isnan(run.min_tension) || tmin < run.min_tension) {
                     run.min_tension = tmin;
                     run.min_tension_t = s.t;
                     run.min_tension_link = static_cast<int>(link);
                   }
                   ++run.rows;
                   return !keep_going || keep_going();
                 },
                 cancel);
  } catch (const BlowUpError& e) {
    // The message `run` gives, without the names of the files it would have written.
    run.failure = std::string(e.what()) + " (" + integrator->name() + ", time step " +
                  std::to_string(grid.dt) + " s)";
  }
  run.stats = integrator->stats();
  return run;
}

}  // namespace cablefilm
