#pragma once
// What the module's files share (module.cpp binds scenes, runs, pictures and sweeps,
// result_bindings.cpp the results of a run and of the statics, body_tools.cpp the quasi-static
// tools of a body): the Result of a run and its lines, the equilibrium, the scene of a Python
// argument, read-only numpy views of a run's rows.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "python/scene_handle.h"
#include "run/memory_run.h"

namespace cablefilm::python {

// A run held by Python: its rows stay where the run wrote them, and the arrays handed out are
// read-only views of them that keep the run alive. One type for every model: its lines are
// `lines`, and a model of one line has that line's arrays on the Result too.
struct Result {
  std::shared_ptr<const MemoryRun> run;
  pybind11::object scene;  // the Scene it ran (a copy, unchanged by later edits)
  pybind11::dict lines;    // line name -> Line, in the model's order
};

// Line `index` of a run: its rows and its own summary. It holds the run (not the Result,
// which holds it: a cycle the collector could not see through).
struct Line {
  std::shared_ptr<const MemoryRun> run;
  int index = 0;
};

// A line's static equilibrium: positions, tensions and arc lengths as arrays (copies), and its
// own solve's figures.
struct LineEquilibrium {
  std::string name;
  pybind11::array x, y, z, tension, s, s_link;
  pybind11::array position;  // [stations, 3]: x, y, z
  int iterations = 0;
  double residual = 0;
  bool fallback = false;
};

// A model's static equilibrium (a run's first row, its free bodies at their equilibrium
// poses).
struct Equilibrium {
  pybind11::dict lines;  // line name -> LineEquilibrium
  std::vector<std::string> point_names, body_names;
  pybind11::array point_position, point_force;  // [points, 3] (m, N)
  pybind11::array body_pose, body_load;         // [bodies, 6] (m, rad; N, N m)
  int iterations = 0;
  double residual = 0;
  bool fallback = false;
};

// A Scene from a Python argument: a Scene (copied), a dict, or a path.
SceneHandle SceneOf(const pybind11::handle& source, const std::optional<std::string>& name);

// A read-only view of `data` (shape, strides in elements) kept alive by `owner`.
pybind11::array View(const pybind11::object& owner, const double* data,
                     std::vector<pybind11::ssize_t> shape, std::vector<pybind11::ssize_t> strides);

pybind11::array Copy(const Eigen::VectorXd& v);

// Raises cablefilm.BlowUpError(message) with `result` (the rows so far) as its .result.
[[noreturn]] void RaiseBlowUp(const std::string& message, const pybind11::object& result);

// The results' bindings (result_bindings.cpp): Result, Line, Equilibrium, LineEquilibrium.
void BindResults(pybind11::module_& m);
// A Result of `run` of `scene`.
pybind11::object MakeResult(std::shared_ptr<const MemoryRun> run, const SceneHandle& scene);
// The static equilibrium of a scene, whatever its [initial] state says, the GIL released; a
// scene with none is a SceneError.
pybind11::object SceneEquilibrium(const SceneHandle& scene);

// The quasi-static tools of a body (body_tools.cpp): stiffness, offset_curve.
void BindBodyTools(pybind11::module_& m);

}  // namespace cablefilm::python
