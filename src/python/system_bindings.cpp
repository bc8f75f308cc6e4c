// The module's systems of lines: cablefilm.run of a system scene returns a SystemResult (each
// line a Result, the points' and bodies' rows as points.csv and body.csv print them, as
// doubles), cablefilm.equilibrium a SystemEquilibrium. The run is the command line's
// (run/memory_system_run.h: PrepareSystemRun, ExecuteSystemRun), so the numbers are those of
// `cablefilm run`'s files.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "python/bindings.h"
#include "python/interruptible.h"
#include "run/memory_system_run.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"
#ifdef CABLEFILM_PYTHON_RENDER
#include "view/system_film.h"
#endif

namespace py = pybind11;

namespace cablefilm::python {
namespace {

// A system's run held by Python; `lines` are Results sharing the run.
struct SystemResult {
  std::shared_ptr<const MemorySystemRun> run;
  py::object scene;  // the Scene it ran (a copy)
  py::dict lines;    // line name -> Result
};

// The static equilibrium of a system.
struct SystemEquilibrium {
  py::dict lines;  // line name -> Equilibrium
  std::vector<std::string> point_names, body_names;
  py::array point_position, point_force;  // [points, 3] (m, N)
  py::array body_pose, body_load;         // [bodies, 6] (m, rad; N, N m)
  int iterations = 0;
  double residual = 0;
};

std::vector<std::string> PointNames(const Model& sys) {
  std::vector<std::string> names;
  for (const Point& p : sys.points) names.push_back(p.name);
  return names;
}

std::vector<std::string> BodyNames(const Model& sys) {
  std::vector<std::string> names;
  for (const BodySpec& b : sys.bodies) names.push_back(b.name);
  return names;
}

// Rows x items x width doubles of `data` as a read-only view [rows, items, width].
py::array Rows3(const py::object& self, const std::vector<double>& data, long rows, size_t items,
                int width) {
  const auto n = static_cast<py::ssize_t>(items);
  return View(self, data.data(), {rows, n, width}, {n * width, width, 1});
}

// The first row's items x width doubles as a new array [items, width].
py::array FirstRow(const std::vector<double>& data, size_t items, int width) {
  py::array_t<double> a({static_cast<py::ssize_t>(items), py::ssize_t{width}});
  if (!data.empty()) std::memcpy(a.mutable_data(), data.data(), sizeof(double) * items * width);
  return std::move(a);
}

// The run of a system scene, the GIL released; an Error (no equilibrium) is a SceneError.
std::shared_ptr<const MemorySystemRun> Simulate(const SceneHandle& scene, bool equilibrium_only) {
  CancelFlag cancel{0};
  try {
    return RunInterruptible(cancel, [&] {
      return std::make_shared<const MemorySystemRun>(
          equilibrium_only ? SystemEquilibriumInMemory(scene.def(), scene.system(), &cancel)
                           : RunSystemInMemory(scene.def(), scene.system(), &cancel));
    });
  } catch (const CancelledError&) {
    throw;
  } catch (const Error& e) {
    throw SceneProblem(SceneErrorMessage(scene.path(), e.what()));
  }
}

py::dict SystemStats(const MemorySystemRun& r) {
  const RunSummary& s = r.run.summary;
  py::dict d;
  d["integrator"] = s.scheme;
  d["steps"] = s.stats.steps;
  d["rejected"] = s.stats.rejected;
  d["newton_iterations"] = s.stats.newton_iterations;
  d["snaps"] = s.stats.record.snaps;
  d["unresolved_snaps"] = s.stats.record.unresolved_snaps;
  d["equilibrium_iterations"] = r.run.equilibrium.iterations;
  d["equilibrium_residual"] = r.run.equilibrium.residual;
  d["equilibrium_relaxed"] = r.run.equilibrium.relaxed;
  return d;
}

const MemorySystemRun& RunOf(const py::object& self) { return *self.cast<SystemResult&>().run; }

}  // namespace

const MemorySystemRun& SystemRunOf(const py::object& result) { return RunOf(result); }

py::object MakeSystemResult(std::shared_ptr<const MemorySystemRun> run, const SceneHandle& scene) {
  SystemResult r{run, py::cast(scene), py::dict()};
  for (size_t i = 0; i < run->lines.size(); ++i) {
    // Each line's Result keeps the whole run alive (an aliasing pointer to its part).
    std::shared_ptr<const MemoryRun> line(run, &run->lines[i]);
    r.lines[py::str(run->run.sys.line_names[i])] = py::cast(Result{line, r.scene, true});
  }
  return py::cast(std::move(r));
}

py::object RunSystemScene(const SceneHandle& scene) {
  const std::shared_ptr<const MemorySystemRun> run = Simulate(scene, false);
  py::object result = MakeSystemResult(run, scene);
  if (!run->run.summary.failure.empty()) RaiseBlowUp(run->run.summary.failure, result);
  return result;
}

py::object SystemSceneEquilibrium(const SceneHandle& scene) {
  const std::shared_ptr<const MemorySystemRun> run = Simulate(scene, true);
  const Model& sys = run->run.sys;
  SystemEquilibrium e;
  for (size_t i = 0; i < sys.lines.size(); ++i) {
    const LineData& d = run->run.initial.lines[i];
    Equilibrium line = LineEquilibrium(sys.lines[i], d.state.x, d.tension());
    line.iterations = run->run.equilibrium.iterations;
    line.residual = run->run.equilibrium.residual;
    e.lines[py::str(sys.line_names[i])] = py::cast(std::move(line));
  }
  e.point_names = PointNames(sys);
  e.body_names = BodyNames(sys);
  e.point_position = FirstRow(run->rows.point_position, sys.points.size(), kDim);
  e.point_force = FirstRow(run->rows.point_force, sys.points.size(), kDim);
  e.body_pose = FirstRow(run->rows.body_pose, sys.bodies.size(), 6);
  e.body_load = FirstRow(run->rows.body_load, sys.bodies.size(), 6);
  e.iterations = run->run.equilibrium.iterations;
  e.residual = run->run.equilibrium.residual;
  return py::cast(std::move(e));
}

bool IsSystemResult(const py::handle& obj) { return py::isinstance<SystemResult>(obj); }

bool IsSystemRun(const py::handle& obj) {
  if (IsSystemResult(obj)) return true;
  if (py::isinstance<Result>(obj)) return false;
  return SceneOf(obj, std::nullopt).is_system();
}

#ifdef CABLEFILM_PYTHON_RENDER
bool RenderSystemResultFilm(const py::object& result, const std::string& out_dir,
                            std::optional<int> width, std::optional<int> height,
                            std::optional<double> fps, std::optional<double> speed,
                            std::optional<std::string> colormap,
                            std::optional<std::pair<double, double>> tension_range) {
  const MemorySystemRun& run = RunOf(result);
  if (!run.run.summary.completed)
    throw py::value_error("the run did not complete: its film is not drawn (the command line "
                          "draws max_tension.partial.png only)");
  FilmRequest request =
      FilmOptions(run.scene, width, height, fps, speed, colormap, tension_range, true);
  request.out_dir = out_dir;
  request.say_written = false;
  CancelFlag cancel{0};
  return RunInterruptible(cancel, [&] {
    return RenderSystemFilm(run.scene, run.run, request, cancel);
  });
}
#endif

void BindSystems(py::module_& m) {
  py::class_<SystemResult>(m, "SystemResult", R"(The rows of a system's run, as `cablefilm run`
writes them (the same doubles as lines/<name>/results.nc; points.csv and body.csv print these
to 10 to 12 digits): time [n] (s); lines {name: Result} (each line's rows as a single line's
Result: x, y, z, position, tension, s, ...); point_names and point_position, point_force
[n, points, 3] (m, N: the force the lines exert on the point); body_names and body_pose
[n, bodies, 6] (x, y, z in m, then the angles about x, y, z in rad; body.csv prints degrees),
body_load [n, bodies, 6] (the lines' force in N and moment about the reference point in N m).
The arrays are read-only views of the run.)")
      .def_property_readonly("time", [](const py::object& self) {
        const MemoryRows& r = RunOf(self).lines.front().rows;  // every line's rows alike
        return View(self, r.time.data(), {r.rows}, {1});
      })
      .def_property_readonly("lines", [](const SystemResult& r) { return r.lines; },
                             "{line name: Result}, in the scene's order")
      .def_property_readonly("line_names", [](const SystemResult& r) {
        return r.run->run.sys.line_names;
      })
      .def_property_readonly("point_names", [](const SystemResult& r) {
        return PointNames(r.run->run.sys);
      })
      .def_property_readonly("body_names", [](const SystemResult& r) {
        return BodyNames(r.run->run.sys);
      })
      .def_property_readonly("point_position", [](const py::object& self) {
        const MemorySystemRun& r = RunOf(self);
        return Rows3(self, r.rows.point_position, r.rows.rows, r.run.sys.points.size(), kDim);
      }, "[n, points, 3] (m)")
      .def_property_readonly("point_force", [](const py::object& self) {
        const MemorySystemRun& r = RunOf(self);
        return Rows3(self, r.rows.point_force, r.rows.rows, r.run.sys.points.size(), kDim);
      }, "[n, points, 3] (N): the lines' pull on the point (what an anchor or fairlead holds)")
      .def_property_readonly("body_pose", [](const py::object& self) {
        const MemorySystemRun& r = RunOf(self);
        return Rows3(self, r.rows.body_pose, r.rows.rows, r.run.sys.bodies.size(), 6);
      }, "[n, bodies, 6]: x, y, z (m), angles about x, y, z (rad)")
      .def_property_readonly("body_load", [](const py::object& self) {
        const MemorySystemRun& r = RunOf(self);
        return Rows3(self, r.rows.body_load, r.rows.rows, r.run.sys.bodies.size(), 6);
      }, "[n, bodies, 6]: force (N), moment about the reference point (N m)")
      .def_property_readonly("scene", [](const SystemResult& r) { return r.scene; })
      .def_property_readonly("completed", [](const SystemResult& r) {
        return r.run->run.summary.completed;
      })
      .def_property_readonly("failure", [](const SystemResult& r) {
        return r.run->run.summary.failure;
      })
      .def_property_readonly("peak_tension", [](const SystemResult& r) {
        return r.run->run.summary.peak;
      }, "The largest tension of any line's row [N] (the run's printed peak).")
      .def_property_readonly("peak_time", [](const SystemResult& r) {
        return r.run->run.summary.peak_t;
      })
      .def_property_readonly("peak_line", [](const SystemResult& r) -> py::object {
        const int i = r.run->run.peak_line;
        if (i < 0) return py::none();
        return py::str(r.run->run.sys.line_names[i]);
      }, "The name of the line holding the peak (None before any row).")
      .def_property_readonly("peak_link", [](const SystemResult& r) {
        return r.run->run.summary.peak_link;
      }, "The peak's link in that line.")
      .def_property_readonly("min_tension", [](const SystemResult& r) {
        return r.run->run.summary.min_tension;
      })
      .def_property_readonly("stats", [](const SystemResult& r) { return SystemStats(*r.run); })
      .def_property_readonly("warnings", [](const SystemResult& r) {
        return r.run->run.summary.warnings;
      }, "Why the peak cannot be trusted (empty: converged), as run_report.toml says.")
      .def("__repr__", [](const SystemResult& r) {
        const MemorySystemRun& s = *r.run;
        return "<cablefilm.SystemResult " + std::to_string(s.rows.rows) + " rows, " +
               std::to_string(s.lines.size()) + " lines, peak " +
               FormatNumber(s.run.summary.peak) + " N" +
               (s.run.summary.completed ? "" : ", cut short") + ">";
      });

  py::class_<SystemEquilibrium>(m, "SystemEquilibrium", R"(The static equilibrium of a system
(the first row of its run, its free bodies at their equilibrium poses whatever their initial
offsets): lines {name: Equilibrium}; point_names, point_position, point_force [points, 3]
(m, N); body_names, body_pose [bodies, 6] (m, rad), body_load [bodies, 6] (N, N m);
iterations and residual (N) of the system's Newton solve.)")
      .def_readonly("lines", &SystemEquilibrium::lines)
      .def_readonly("point_names", &SystemEquilibrium::point_names)
      .def_readonly("point_position", &SystemEquilibrium::point_position)
      .def_readonly("point_force", &SystemEquilibrium::point_force)
      .def_readonly("body_names", &SystemEquilibrium::body_names)
      .def_readonly("body_pose", &SystemEquilibrium::body_pose)
      .def_readonly("body_load", &SystemEquilibrium::body_load)
      .def_readonly("iterations", &SystemEquilibrium::iterations)
      .def_readonly("residual", &SystemEquilibrium::residual, "largest out-of-balance force [N]");
}

}  // namespace cablefilm::python
