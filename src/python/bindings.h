#pragma once
// What the module's files share (module.cpp binds a single line's runs, system_bindings.cpp a
// system's, body_tools.cpp the quasi-static tools of a body): the Result of a line's run, the
// scene of a Python argument, read-only numpy views of a run's rows.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/line_model.h"
#include "python/scene_handle.h"
#include "run/memory_run.h"
#include "run/memory_system_run.h"
#ifdef CABLEFILM_PYTHON_RENDER
#include "view/film_pass.h"
#endif

namespace cablefilm::python {

// A run held by Python: its rows stay where the run wrote them, and the arrays handed out are
// read-only views of them that keep the Result alive. A line of a system's run is one too (its
// `run` then kept alive by the system's), marked `of_system`: it cannot be run again alone.
struct Result {
  std::shared_ptr<const MemoryRun> run;
  pybind11::object scene;  // the Scene it ran (a copy, unchanged by later edits)
  bool of_system = false;
};

// The static equilibrium of a line: x, y, z, tension and arc lengths as arrays (copies).
struct Equilibrium {
  pybind11::array x, y, z, tension, s, s_link;
  pybind11::array position;  // [stations, 3]: x, y, z
  int iterations = 0;
  double residual = 0;
  bool fallback = false;
};

// A line's equilibrium from its state and tensions (the solver's report set by the caller).
Equilibrium LineEquilibrium(const LineModel& m, const Points& x, const Eigen::VectorXd& tension);

// A Scene from a Python argument: a Scene (copied), a dict, or a path.
SceneHandle SceneOf(const pybind11::handle& source, const std::optional<std::string>& name);

// A read-only view of `data` (shape, strides in elements) kept alive by `owner`.
pybind11::array View(const pybind11::object& owner, const double* data,
                     std::vector<pybind11::ssize_t> shape, std::vector<pybind11::ssize_t> strides);

pybind11::array Copy(const Eigen::VectorXd& v);

// Raises cablefilm.BlowUpError(message) with `result` (the rows so far) as its .result.
[[noreturn]] void RaiseBlowUp(const std::string& message, const pybind11::object& result);

// The system's bindings (system_bindings.cpp): SystemResult, SystemEquilibrium, and the run
// and equilibrium of a system scene, which cablefilm.run and cablefilm.equilibrium call.
void BindSystems(pybind11::module_& m);
pybind11::object RunSystemScene(const SceneHandle& scene);
pybind11::object MakeSystemResult(std::shared_ptr<const MemorySystemRun> run,
                                  const SceneHandle& scene);
pybind11::object SystemSceneEquilibrium(const SceneHandle& scene);
// A SystemResult; a SystemResult or a scene argument (a Scene, a dict, a path) of a system.
bool IsSystemResult(const pybind11::handle& obj);
bool IsSystemRun(const pybind11::handle& obj);
// The run of a SystemResult.
const MemorySystemRun& SystemRunOf(const pybind11::object& result);
#ifdef CABLEFILM_PYTHON_RENDER
// The film of a SystemResult into the folder `out_dir` (system_bindings.cpp); false if
// interrupted.
bool RenderSystemResultFilm(const pybind11::object& result, const std::string& out_dir,
                            std::optional<int> width, std::optional<int> height,
                            std::optional<double> fps, std::optional<double> speed,
                            std::optional<std::string> colormap,
                            std::optional<std::pair<double, double>> tension_range);
#endif

#ifdef CABLEFILM_PYTHON_RENDER
// The film's options: the scene's [film], with those given (each checked as the loader and the
// command line check theirs); a whole film's frame count too (module.cpp).
FilmRequest FilmOptions(const SceneDef& scene, std::optional<int> width, std::optional<int> height,
                        std::optional<double> fps, std::optional<double> speed,
                        std::optional<std::string> colormap,
                        std::optional<std::pair<double, double>> tension_range, bool whole_film);
#endif

// The quasi-static tools of a body (body_tools.cpp): stiffness, offset_curve.
void BindBodyTools(pybind11::module_& m);

}  // namespace cablefilm::python
