// The Python module `cablefilm`: scenes loaded from a file or a dict and changed key by key,
// runs as numpy arrays with no file written, the static equilibrium, the film and its frames,
// sweeps over scene keys. Bindings only: the work is that of the program's libraries
// (scene_loader, run/memory_run, view/film_pass, run/sweep), called as the command line
// calls them, so a run gives the very doubles of `cablefilm run`'s results.nc. A system of
// lines goes to system_bindings.cpp (its run, its equilibrium, its film) and body_tools.cpp
// (a body's stiffness and offset curve).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "scene/film_settings.h"
#include "scene/scene_loader.h"
#include "run/initial_state.h"
#include "run/memory_run.h"
#include "run/memory_system_run.h"
#include "run/run_summary.h"
#include "run/sweep.h"
#include "run/sweep_plan.h"
#include "scene/scene_edit.h"
#include "core/version.h"
#include "core/line_equilibrium.h"
#include "python/bindings.h"
#include "python/interruptible.h"
#include "python/scene_handle.h"
#include "python/toml_values.h"
#include "scene/scene_limits.h"
#ifdef CABLEFILM_PYTHON_RENDER
#include "view/film_pass.h"
#include "view/memory_film.h"
#include "view/memory_system_film.h"
#endif

namespace py = pybind11;

namespace cablefilm::python {
namespace {

// cablefilm.BlowUpError, made with the module (a reference kept for the process's life).
PyObject* g_blow_up_error = nullptr;

}  // namespace

SceneHandle SceneOf(const py::handle& source, const std::optional<std::string>& name) {
  if (py::isinstance<SceneHandle>(source)) return source.cast<SceneHandle>();
  if (py::isinstance<py::dict>(source))
    return SceneHandle::FromText(DictToToml(py::reinterpret_borrow<py::dict>(source)),
                                 name.value_or("<dict>"));
  if (!py::isinstance<py::str>(source) && !py::hasattr(source, "__fspath__"))
    throw py::type_error("expected a scene: a path to a scene file (TOML), a dict or a Scene, "
                         "got a " + std::string(py::str(py::type::of(source).attr("__name__"))));
  const py::object path = py::module_::import("os").attr("fspath")(source);
  if (!py::isinstance<py::str>(path)) throw py::type_error("expected a path as text, got bytes");
  return SceneHandle::FromFile(path.cast<std::string>());
}

void RaiseBlowUp(const std::string& message, const py::object& result) {
  py::object error = py::reinterpret_borrow<py::object>(g_blow_up_error)(py::str(message));
  error.attr("result") = result;
  PyErr_SetObject(g_blow_up_error, error.ptr());
  throw py::error_already_set();
}

namespace {

// The run of a scene, the GIL released. A scene with no initial state found is a SceneError
// (as `check` reports it); a blow-up raises BlowUpError with the rows so far as its `result`.
py::object RunScene(const SceneHandle& scene);

py::object MakeResult(std::shared_ptr<const MemoryRun> run, const SceneHandle& scene) {
  return py::cast(Result{std::move(run), py::cast(scene)});
}

py::object RunScene(const SceneHandle& scene) {
  CancelFlag cancel{0};
  std::shared_ptr<const MemoryRun> run;
  try {
    run = RunInterruptible(cancel, [&] {
      return std::make_shared<const MemoryRun>(RunInMemory(scene.def(), scene.model(), &cancel));
    });
  } catch (const CancelledError&) {
    throw;
  } catch (const Error& e) {  // the initial state: the equilibrium not found
    throw SceneProblem(SceneErrorMessage(scene.path(), e.what()));
  }
  py::object result = MakeResult(run, scene);
  if (!run->run.summary.failure.empty()) RaiseBlowUp(run->run.summary.failure, result);
  return result;
}

}  // namespace

py::array View(const py::object& owner, const double* data, std::vector<py::ssize_t> shape,
               std::vector<py::ssize_t> strides) {
  for (py::ssize_t& s : strides) s *= static_cast<py::ssize_t>(sizeof(double));
  py::array a(py::dtype::of<double>(), std::move(shape), std::move(strides), data, owner);
  a.attr("flags").attr("writeable") = false;
  return a;
}

namespace {

// The positions along `axis` of every row [rows, stations] (station -1), or of the start (0) or
// the end (1) station [rows]. The rows hold x, y, z station by station: an axis is every
// kDim-th double.
py::array Positions(const py::object& self, int axis, int station) {
  const MemoryRun& r = *self.cast<Result&>().run;
  const int stations = r.run.model.stations();
  const double* data = r.rows.x.data() + axis;
  if (station < 0) return View(self, data, {r.rows.rows, stations}, {stations * kDim, kDim});
  return View(self, data + (station == 0 ? 0 : (stations - 1) * kDim), {r.rows.rows},
              {stations * kDim});
}

// The end load of end e (0: start, 1: end) of every row, [rows, 3] (N): a view.
py::array EndLoadRows(const py::object& self, int e) {
  const MemoryRows& r = self.cast<Result&>().run->rows;
  return View(self, r.end_load.data() + e * kDim, {r.rows, kDim}, {2 * kDim, 1});
}

// Every station's position of every row as one array [rows, stations, 3] (x, y, z).
py::array PositionVectors(const py::object& self) {
  const MemoryRun& r = *self.cast<Result&>().run;
  const int stations = r.run.model.stations();
  return View(self, r.rows.x.data(), {r.rows.rows, stations, kDim}, {stations * kDim, kDim, 1});
}

}  // namespace

py::array Copy(const Eigen::VectorXd& v) {
  py::array_t<double> a(v.size());
  std::memcpy(a.mutable_data(), v.data(), sizeof(double) * static_cast<std::size_t>(v.size()));
  return std::move(a);
}

namespace {

py::array LinkMidpoints(const LineModel& m) {
  py::array_t<double> a(m.line.links);
  double* out = a.mutable_data();
  for (int j = 0; j < m.line.links; ++j) out[j] = 0.5 * (m.line.arc_length[j] + m.line.arc_length[j + 1]);
  return std::move(a);
}

py::dict StatsDict(const MemoryRun& r) {
  const RunSummary& s = r.run.summary;
  py::dict d;
  d["integrator"] = s.scheme;
  d["steps"] = s.stats.steps;
  d["rejected"] = s.stats.rejected;
  d["newton_iterations"] = s.stats.newton_iterations;
  d["snaps"] = s.stats.record.snaps;
  d["unresolved_snaps"] = s.stats.record.unresolved_snaps;
  d["snap_windows"] = s.stats.snap_windows;
  d["explicit_steps"] = s.stats.explicit_steps;
  d["equilibrium_iterations"] = r.run.equilibrium.iterations;
  d["equilibrium_residual"] = r.run.equilibrium.residual;
  return d;
}

}  // namespace

Equilibrium LineEquilibrium(const LineModel& m, const Points& x, const Eigen::VectorXd& tension) {
  Equilibrium e;
  e.x = Copy(x.row(0).transpose());
  e.y = Copy(x.row(1).transpose());
  e.z = Copy(x.row(2).transpose());
  // column-major: station by station, x, y, z
  py::array_t<double> position({static_cast<py::ssize_t>(x.cols()), py::ssize_t{kDim}});
  std::memcpy(position.mutable_data(), x.data(), sizeof(double) * static_cast<std::size_t>(x.size()));
  e.position = std::move(position);
  e.tension = Copy(tension);
  e.s = Copy(m.line.arc_length);
  e.s_link = LinkMidpoints(m);
  return e;
}

namespace {

// The static equilibrium of a scene, whatever its [initial] state says.
Equilibrium SolveSceneEquilibrium(const SceneHandle& scene) {
  SceneDef def = scene.def();
  def.initial = InitialStateKind::kEquilibrium;
  const LineModel& m = scene.model();
  struct Solved {
    State state;
    LineEquilibriumReport report;
    Eigen::VectorXd tension;
  };
  CancelFlag cancel{0};
  Solved solved;
  try {
    solved = RunInterruptible(cancel, [&] {
      Solved s;
      s.state = MakeInitialState(def, m, &s.report, &cancel);
      // The tensions as the run's first row gives them: its scheme's, at the state.
      const TimeGrid grid = ChooseTimeGrid(m, def.simulation, def.output.interval);
      s.tension = MakeLineData(m, SceneInputs(m), grid.options, s.state).tension();
      return s;
    });
  } catch (const CancelledError&) {
    throw;
  } catch (const Error& e) {
    throw SceneProblem(SceneErrorMessage(scene.path(), e.what()));
  }
  Equilibrium e = LineEquilibrium(m, solved.state.x, solved.tension);
  e.iterations = solved.report.iterations;
  e.residual = solved.report.residual;
  e.fallback = solved.report.fallback;
  return e;
}

#ifdef CABLEFILM_PYTHON_RENDER
// The run of a Result, or of a scene (run here; `holder` keeps it).
const MemoryRun& RunOf(const py::object& obj, py::object* holder) {
  if (py::isinstance<Result>(obj)) {
    // A line of a system moves with the others: the film pass cannot step it alone.
    if (obj.cast<Result&>().of_system)
      throw py::value_error("a line of a system's run cannot be drawn alone: render_frame and "
                            "render_film take the SystemResult (its lines together)");
    *holder = obj;
  } else {
    *holder = RunScene(SceneOf(obj, std::nullopt));
  }
  return *holder->cast<Result&>().run;
}

}  // namespace

FilmRequest FilmOptions(const SceneDef& scene, std::optional<int> width, std::optional<int> height,
                        std::optional<double> fps, std::optional<double> speed,
                        std::optional<std::string> colormap,
                        std::optional<std::pair<double, double>> tension_range, bool whole_film) {
  auto check = [](const char* key, const std::string& problem) {
    if (!problem.empty()) throw py::value_error(std::string(key) + ": " + problem);
  };
  FilmOverrides o;
  if (width || height) {
    o.width = width.value_or(scene.film.width);
    o.height = height.value_or(scene.film.height);
    check(width ? "width" : "height", FilmSizeProblem(o.width, o.height));
  }
  if (fps) check("fps", FpsProblem(o.fps = *fps));
  if (speed) check("speed", SpeedProblem(o.speed = *speed));
  if (colormap) check("colormap", ColormapProblem(o.colormap = *colormap));
  if (tension_range) {
    std::tie(o.tension_min, o.tension_max) = *tension_range;
    check("tension_range", TensionRangeProblem(o.tension_min, o.tension_max));
  }
  o.frames = 0;
  try {
    return MakeFilmRequest(ResolveFilm(scene, o, kPythonNames, whole_film), "", "");
  } catch (const Error& e) {
    throw py::value_error(e.what());
  }
}

namespace {

py::array RenderFrame(const py::object& obj, std::optional<double> t, std::optional<long> row,
                      int width, int height, std::optional<std::string> colormap,
                      std::optional<std::pair<double, double>> tension_range) {
  // A system's run (a SystemResult, or a system scene run here) or a line's.
  py::object holder;
  const MemorySystemRun* system = nullptr;
  const MemoryRun* run = nullptr;
  if (IsSystemRun(obj)) {
    holder = IsSystemResult(obj) ? obj : RunSystemScene(SceneOf(obj, std::nullopt));
    system = &SystemRunOf(holder);
  } else {
    run = &RunOf(obj, &holder);
  }
  FilmRequest request = FilmOptions(system ? system->scene : run->scene, width, height,
                                    std::nullopt, std::nullopt, colormap, tension_range, false);
  const MemoryRows& rows = system ? system->lines.front().rows : run->rows;
  long chosen = rows.rows - 1;
  if (row && t) throw py::value_error("give t or row, not both");
  if (row) {
    chosen = *row < 0 ? rows.rows + *row : *row;
    if (chosen < 0 || chosen >= rows.rows)
      throw py::index_error("row " + std::to_string(*row) + ": the run has " +
                            std::to_string(rows.rows) + " rows");
  } else if (t) {  // the row nearest t (the earlier of two as near)
    chosen = 0;
    for (long r = 1; r < rows.rows; ++r)
      if (std::fabs(rows.time[r] - *t) < std::fabs(rows.time[chosen] - *t)) chosen = r;
  }
  CancelFlag cancel{0};
  const Image image = RunInterruptible(cancel, [&] {
    return system ? DrawMemorySystemFrame(*system, chosen, request)
                  : DrawMemoryRunFrame(*run, chosen, request);
  });
  py::array_t<std::uint8_t> out({image.height, image.width, 3});
  std::uint8_t* dst = out.mutable_data();
  for (std::size_t i = 0, n = static_cast<std::size_t>(image.width) * image.height; i < n; ++i) {
    dst[3 * i] = image.rgba[4 * i];
    dst[3 * i + 1] = image.rgba[4 * i + 1];
    dst[3 * i + 2] = image.rgba[4 * i + 2];
  }
  return std::move(out);
}

std::string RenderFilmTo(const py::object& obj, const std::string& path,
                         std::optional<int> width, std::optional<int> height,
                         std::optional<double> fps, std::optional<double> speed,
                         std::optional<std::string> colormap,
                         std::optional<std::pair<double, double>> tension_range) {
  namespace fs = std::filesystem;
  const bool system = IsSystemRun(obj);
  py::object holder;
  const MemoryRun* run = nullptr;
  FilmRequest request;
  if (system) {
    // The system's run (run here for a scene) is drawn after the folder is made.
    holder = IsSystemResult(obj) ? obj : RunSystemScene(SceneOf(obj, std::nullopt));
  } else {
    run = &RunOf(obj, &holder);
    request = FilmOptions(run->scene, width, height, fps, speed, colormap, tension_range, true);
  }
  // PATH.mp4: the film itself, made in a folder of its own beside it, then renamed; else a
  // folder that gets film.mp4, as `cablefilm run --out PATH` does.
  const fs::path target(path);
  const bool file = target.extension() == ".mp4";
  fs::path dir = target;
  if (file) {
    const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    fs::create_directories(parent);
    std::string pattern = (parent / ("." + target.filename().string() + ".XXXXXX")).string();
    if (!mkdtemp(pattern.data()))
      throw Error("cannot make a folder beside " + path + ": " + std::strerror(errno));
    dir = pattern;
  }
  request.out_dir = dir.string();
  request.say_written = false;
  CancelFlag cancel{0};
  bool finished = false;
  try {
    finished = system ? RenderSystemResultFilm(holder, dir.string(), width, height, fps, speed,
                                               colormap, tension_range)
                      : RunInterruptible(cancel, [&] {
                          return RenderMemoryRunFilm(*run, request, cancel);
                        });
  } catch (...) {
    if (file) fs::remove_all(dir);
    throw;
  }
  if (!file) return (dir / (finished ? "film.mp4" : "film.partial.mp4")).string();
  fs::rename(dir / "film.mp4", target);
  fs::remove_all(dir);
  return target.string();
}
#endif

// The columns of a sweep's row from a case's summary (kSummaryColumns), as Python numbers;
// None for a case that did not finish.
void AddSummaryColumns(const CaseOutcome& o, py::dict* d) {
  for (const SummaryColumn& c : kSummaryColumns) {
    py::object value = py::none();
    if (o.has_summary) {
      const double v = c.value(o.summary);
      if (c.kind == SummaryColumn::Kind::kNumber) value = py::float_(v);
      if (c.kind == SummaryColumn::Kind::kWhole) value = py::int_(static_cast<long long>(v));
      if (c.kind == SummaryColumn::Kind::kFlag) value = py::bool_(v != 0);
    }
    (*d)[py::str(c.name)] = value;
  }
}

// The sweep: every case's scene checked first (as `cablefilm sweep` does), then run on `jobs`
// threads; one dict a case with the columns of sweep.csv.
py::list Sweep(const py::object& source, const py::dict& values, std::optional<py::list> cases,
               std::optional<int> jobs, bool keep_results) {
  const SceneHandle scene = SceneOf(source, std::nullopt);
  SweepCases listed;
  std::vector<std::vector<py::object>> listed_objects;
  if (cases) {
    for (const py::handle row : *cases) {
      const py::dict d = py::reinterpret_borrow<py::dict>(row);
      if (listed.keys.empty())
        for (const auto& item : d) listed.keys.push_back(item.first.cast<std::string>());
      std::vector<std::string> texts;
      std::vector<py::object> objects;
      if (d.size() != listed.keys.size())
        throw py::value_error("cases: every case must give the same keys");
      for (const std::string& key : listed.keys) {
        if (!d.contains(key)) throw py::value_error("cases: a case lacks " + key);
        objects.push_back(d[py::str(key)]);
        texts.push_back(ValueToToml(objects.back(), key));
      }
      listed.rows.push_back(texts);
      listed_objects.push_back(objects);
    }
  }
  std::vector<SweepKey> sets;
  std::vector<std::vector<py::object>> set_objects;
  for (const auto& item : values) {
    SweepKey k;
    k.key = item.first.cast<std::string>();
    std::vector<py::object> objects;
    // The values of a key are a list (a str is one value, not its characters).
    if (py::isinstance<py::str>(item.second) || py::isinstance<py::bytes>(item.second) ||
        py::isinstance<py::dict>(item.second) || !py::hasattr(item.second, "__iter__"))
      throw py::type_error("values[\"" + k.key + "\"]: expected a list of values, got a " +
                           std::string(py::str(py::type::of(item.second).attr("__name__"))));
    for (const py::handle v : item.second) {
      objects.push_back(py::reinterpret_borrow<py::object>(v));
      k.values.push_back(ValueToToml(v, k.key));
    }
    if (k.values.empty())
      throw py::value_error("values[\"" + k.key + "\"]: expected at least one value, got none");
    sets.push_back(k);
    set_objects.push_back(objects);
  }
  const SweepCases all = ExpandCases(listed, sets);
  const std::size_t n = all.rows.size();
  // Each case's values as Python objects (the texts are unique within a key: map them back).
  auto object_of = [&](std::size_t column, const std::string& text) -> py::object {
    if (column < listed.keys.size()) {
      for (std::size_t r = 0; r < listed.rows.size(); ++r)
        if (listed.rows[r][column] == text) return listed_objects[r][column];
    } else {
      const std::size_t s = column - listed.keys.size();
      for (std::size_t v = 0; v < sets[s].values.size(); ++v)
        if (sets[s].values[v] == text) return set_objects[s][v];
    }
    return py::str(text);
  };
  std::vector<SceneHandle> scenes;
  scenes.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::string described;
    for (std::size_t k = 0; k < all.keys.size(); ++k)
      described += (k ? ", " : "") + all.keys[k] + " = " + all.rows[i][k];
    try {
      SceneHandle edited = scene;
      edited.Set(all.keys, all.rows[i]);
      scenes.push_back(std::move(edited));
    } catch (const std::exception& e) {
      throw SceneProblem(scene.path() + ": case " + std::to_string(i) + " (" + described +
                         ") is refused, so no case was run: " + e.what());
    }
  }
  if (jobs && (*jobs < 1 || *jobs > kMaxSweepJobs))
    throw py::value_error("jobs: expected 1 to " + std::to_string(kMaxSweepJobs) + ", got " +
                          std::to_string(*jobs));
  const int threads = jobs.value_or(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  // Each case's run, kept only with keep_results: a sweep of many cases holds their summaries.
  std::vector<std::shared_ptr<const MemoryRun>> kept(n);
  std::vector<std::shared_ptr<const MemorySystemRun>> kept_systems(n);
  std::vector<CaseOutcome> outcomes(n);
  CancelFlag cancel{0};
  RunInterruptible(cancel, [&] {
    ThreadExecutor executor(threads, [&](std::size_t i, const CancelFlag* stop) {
      CaseOutcome o;
      try {
        if (scenes[i].is_system()) {
          auto run = std::make_shared<const MemorySystemRun>(
              RunSystemInMemory(scenes[i].def(), scenes[i].system(), stop));
          o = OutcomeOf(run->run.summary, *stop != 0);
          if (keep_results) kept_systems[i] = std::move(run);
        } else {
          auto run = std::make_shared<const MemoryRun>(
              RunInMemory(scenes[i].def(), scenes[i].model(), stop));
          o = OutcomeOf(run->run.summary, *stop != 0);
          if (keep_results) kept[i] = std::move(run);
        }
      } catch (const std::exception& e) {
        o.status = "error";
        o.message = SceneErrorMessage(scenes[i].path(), e.what());
      }
      return o;
    });
    RunCases(executor, threads, &cancel, outcomes, {}, {});
    return 0;
  });
  py::list rows;
  for (std::size_t i = 0; i < n; ++i) {
    py::dict d;
    d["case"] = i;
    for (std::size_t k = 0; k < all.keys.size(); ++k) d[py::str(all.keys[k])] = object_of(k, all.rows[i][k]);
    const CaseOutcome& o = outcomes[i];
    d["status"] = o.status;
    d["message"] = o.message;
    AddSummaryColumns(o, &d);
    if (keep_results)
      d["result"] = kept[i]           ? MakeResult(kept[i], scenes[i])
                    : kept_systems[i] ? MakeSystemResult(kept_systems[i], scenes[i])
                                      : py::none();
    rows.append(d);
  }
  return rows;
}

}  // namespace
}  // namespace cablefilm::python

PYBIND11_MODULE(cablefilm, m) {
  using namespace cablefilm;
  using namespace cablefilm::python;
  m.doc() = "cablefilm: the lumped-mass cable of Polachek et al. (1963) from Python";
  std::string version = kVersion;
  if (*kGitDescribe) version += std::string(" (git ") + kGitDescribe + ")";
  m.attr("__version__") = version;
  py::register_exception<SceneProblem>(m, "SceneError", PyExc_ValueError);
  g_blow_up_error = PyErr_NewExceptionWithDoc(
      "cablefilm.BlowUpError",
      "The simulation stopped on a numerical blow-up; .result holds the rows up to then.",
      PyExc_RuntimeError, nullptr);
  if (!g_blow_up_error) throw py::error_already_set();
  m.attr("BlowUpError") = py::reinterpret_borrow<py::object>(g_blow_up_error);

  py::class_<SceneHandle>(m, "Scene", R"(A scene (the TOML schema of scene-format.md), always valid.
scene["environment.current"] reads a value by its dotted key (as the loader's messages and
`cablefilm sweep --set` spell it); scene["environment.current"] = 0.5 sets it, read again by
the loader: a bad key or value raises SceneError and leaves the scene as it was.)")
      .def(py::init([](const py::object& source, std::optional<std::string> name) {
             return SceneOf(source, name);
           }),
           py::arg("source"), py::arg("name") = py::none(),
           "A scene file's path, a dict of the TOML schema, or a Scene (copied). `name` names "
           "a dict's scene in messages (default \"<dict>\").")
      .def("__getitem__",
           [](const SceneHandle& s, const std::string& key) {
             try {
               return TomlDocumentValue(s.ValueDocument(key));
             } catch (const Error& e) {
               throw py::key_error(e.what());
             }
           })
      .def("__setitem__",
           [](SceneHandle& s, const std::string& key, const py::object& value) {
             s.Set({key}, {ValueToToml(value, key)});
           })
      .def("update",
           [](SceneHandle& s, const py::dict& values) {
             std::vector<std::string> keys, texts;
             for (const auto& item : values) {
               keys.push_back(item.first.cast<std::string>());
               texts.push_back(ValueToToml(item.second, keys.back()));
             }
             s.Set(keys, texts);
           },
           py::arg("values"),
           "Sets several keys at once ({key: value}), checked together: the scene changes only "
           "if the whole is valid.")
      .def("copy", [](const SceneHandle& s) { return s; })
      .def("to_dict", [](const SceneHandle& s) { return TomlToDict(s.text()); },
           "The scene as nested dicts and lists (what `cablefilm.Scene(d)` takes).")
      .def_property_readonly("text", &SceneHandle::text, "The scene's TOML text.")
      .def_property_readonly("path", &SceneHandle::path,
                             "The file it came from (or the name given to a dict).")
      .def_property_readonly("title", [](const SceneHandle& s) { return s.def().title; })
      .def_property_readonly("is_system", &SceneHandle::is_system,
                             "True for a system of lines ([[line]], [[point]], [[body]]).")
      .def_property_readonly("lines", [](const SceneHandle& s) {
        return s.is_system() ? s.system().line_names : std::vector<std::string>{};
      }, "A system's line names (in the scene's order, line[0] first); [] for a single line.")
      .def_property_readonly("points", [](const SceneHandle& s) {
        std::vector<std::string> names;
        for (const PointDef& p : s.def().points) names.push_back(p.name);
        return names;
      }, "A system's point names (point[0] first); [] for a single line.")
      .def_property_readonly("bodies", [](const SceneHandle& s) {
        std::vector<std::string> names;
        for (const BodyDef& b : s.def().bodies) names.push_back(b.name);
        return names;
      }, "A system's body names (body[0] first); [] for none.")
      .def_property_readonly("stations", [](const SceneHandle& s) -> py::object {
        if (!s.is_system()) return py::int_(s.model().stations());
        py::dict d;
        const Model& sys = s.system();
        for (size_t i = 0; i < sys.lines.size(); ++i)
          d[py::str(sys.line_names[i])] = sys.lines[i].stations();
        return d;
      }, "The stations of a line; of a system, a dict {line name: stations}.")
      .def_property_readonly("links", [](const SceneHandle& s) -> py::object {
        if (!s.is_system()) return py::int_(s.model().line.links);
        py::dict d;
        const Model& sys = s.system();
        for (size_t i = 0; i < sys.lines.size(); ++i)
          d[py::str(sys.line_names[i])] = sys.lines[i].line.links;
        return d;
      }, "The links of a line; of a system, a dict {line name: links}.")
      .def("__repr__", [](const SceneHandle& s) {
        const std::string head = "<cablefilm.Scene " + s.path() + ": \"" + s.def().title + "\", ";
        if (!s.is_system()) return head + std::to_string(s.model().line.links) + " links>";
        auto count = [](std::size_t n, const char* one, const char* many) {
          return std::to_string(n) + " " + (n == 1 ? one : many);
        };
        return head + "a system of " + count(s.def().lines.size(), "line", "lines") + ", " +
               count(s.def().points.size(), "point", "points") + ", " +
               count(s.def().bodies.size(), "body", "bodies") + ">";
      });

  m.def("load", &SceneOf, py::arg("source"), py::arg("name") = py::none(),
        "A Scene from a scene file's path or a dict of the same schema (SceneError when the "
        "loader refuses it, with the message `cablefilm check` prints).");

  py::class_<Result>(m, "Result", R"(The rows of a run, as results.nc holds them (the same doubles):
time [n] (s), x, y, z [n, stations] (m; y up, z = 0 for a cable in the x-y plane), the same
as one array position [n, stations, 3], tension
[n, links] (N, 0 when slack), the end motion x_start, y_start, z_start, x_end, y_end, z_end [n]
(m), the end loads load_start, load_end [n, 3] (N: the force the line exerts on what holds
each end, timeseries.csv's fx_start ... fz_end), arc lengths s [stations], s_link [links] (m). The arrays are read-only views of the run.)")
      .def_property_readonly("time", [](const py::object& self) {
        const MemoryRows& r = self.cast<Result&>().run->rows;
        return View(self, r.time.data(), {r.rows}, {1});
      })
      .def_property_readonly("x", [](const py::object& self) { return Positions(self, 0, -1); })
      .def_property_readonly("y", [](const py::object& self) { return Positions(self, 1, -1); })
      .def_property_readonly("z", [](const py::object& self) { return Positions(self, 2, -1); })
      .def_property_readonly("position", [](const py::object& self) { return PositionVectors(self); },
                             "every station's position of every row [n, stations, 3] (m): x, y, z")
      .def_property_readonly("tension", [](const py::object& self) {
        const MemoryRun& r = *self.cast<Result&>().run;
        const int links = r.run.model.line.links;
        return View(self, r.rows.tension.data(), {r.rows.rows, links}, {links, 1});
      })
      .def_property_readonly("x_start", [](const py::object& self) { return Positions(self, 0, 0); })
      .def_property_readonly("y_start", [](const py::object& self) { return Positions(self, 1, 0); })
      .def_property_readonly("z_start", [](const py::object& self) { return Positions(self, 2, 0); })
      .def_property_readonly("x_end", [](const py::object& self) { return Positions(self, 0, 1); })
      .def_property_readonly("y_end", [](const py::object& self) { return Positions(self, 1, 1); })
      .def_property_readonly("z_end", [](const py::object& self) { return Positions(self, 2, 1); })
      .def_property_readonly("load_start", [](const py::object& self) { return EndLoadRows(self, 0); },
                             "the end load at the start [n, 3] (N): the force the line exerts on "
                             "what holds station 0, as timeseries.csv's fx_start, fy_start, fz_start")
      .def_property_readonly("load_end", [](const py::object& self) { return EndLoadRows(self, 1); },
                             "the end load at the end [n, 3] (N), as fx_end, fy_end, fz_end")
      .def_property_readonly("s", [](const Result& r) { return Copy(r.run->run.model.line.arc_length); })
      .def_property_readonly("s_link", [](const Result& r) { return LinkMidpoints(r.run->run.model); })
      .def_property_readonly("minimum_breaking_load",
                             [](const Result& r) { return Copy(r.run->run.model.line.breaking_load); },
                             "Each link's material's minimum_breaking_load [N] (0: not given), as "
                             "results.nc has it: tension / minimum_breaking_load is the utilisation.")
      .def_property_readonly("scene", [](const Result& r) { return r.scene; })
      .def_property_readonly("completed", [](const Result& r) { return r.run->run.summary.completed; })
      .def_property_readonly("failure", [](const Result& r) { return r.run->run.summary.failure; })
      .def_property_readonly("peak_tension", [](const Result& r) { return r.run->run.summary.peak; },
                             "The largest tension of any row [N] (the run's printed peak).")
      .def_property_readonly("peak_time", [](const Result& r) { return r.run->run.summary.peak_t; })
      .def_property_readonly("peak_link", [](const Result& r) { return r.run->run.summary.peak_link; })
      .def_property_readonly("min_tension", [](const Result& r) { return r.run->run.summary.min_tension; })
      .def_property_readonly("min_tension_time", [](const Result& r) { return r.run->run.summary.min_tension_t; })
      .def_property_readonly("min_tension_link", [](const Result& r) { return r.run->run.summary.min_tension_link; })
      .def_property_readonly("stats", [](const Result& r) { return StatsDict(*r.run); })
      .def_property_readonly("warnings", [](const Result& r) {
        return r.run->run.summary.warnings;
      }, "Why the peak cannot be trusted (empty: converged), as run_report.toml says.")
      .def("__repr__", [](const Result& r) {
        const RunSummary& s = r.run->run.summary;
        return "<cablefilm.Result " + std::to_string(r.run->rows.rows) + " rows, " +
               std::to_string(r.run->run.model.stations()) + " stations, peak " +
               FormatNumber(s.peak) + " N" + (s.completed ? "" : ", cut short") + ">";
      });

  m.def("run",
        [](const py::object& source) {
          const SceneHandle scene = SceneOf(source, std::nullopt);
          return scene.is_system() ? RunSystemScene(scene) : RunScene(scene);
        },
        py::arg("scene"),
        "Runs a scene (a Scene, a path or a dict) from its initial state to its end, writing no "
        "file; the GIL is released meanwhile. Returns a Result (a SystemResult for a system of "
        "lines). BlowUpError on a numerical "
        "blow-up (its .result: the rows so far); SceneError when no initial state is found.");

  py::class_<Equilibrium>(m, "Equilibrium",
                          "The static equilibrium: x, y, z [stations] (m), position [stations, 3] "
                          "(m: x, y, z), tension [links] (N), "
                          "s, s_link (m); unpacks as x, y, tension.")
      .def_readonly("x", &Equilibrium::x)
      .def_readonly("y", &Equilibrium::y)
      .def_readonly("z", &Equilibrium::z)
      .def_readonly("position", &Equilibrium::position, "[stations, 3] (m): x, y, z")
      .def_readonly("tension", &Equilibrium::tension)
      .def_readonly("s", &Equilibrium::s)
      .def_readonly("s_link", &Equilibrium::s_link)
      .def_readonly("iterations", &Equilibrium::iterations)
      .def_readonly("residual", &Equilibrium::residual, "largest out-of-balance force [N]")
      .def_readonly("fallback", &Equilibrium::fallback)
      .def("__iter__", [](const Equilibrium& e) {
        return py::iter(py::make_tuple(e.x, e.y, e.tension));
      });
  m.def("equilibrium",
        [](const py::object& source) -> py::object {
          const SceneHandle scene = SceneOf(source, std::nullopt);
          if (scene.is_system()) return SystemSceneEquilibrium(scene);
          return py::cast(SolveSceneEquilibrium(scene));
        },
        py::arg("scene"),
        "The scene's static equilibrium with the ends at their t = 0 positions (the initial "
        "state of a run with [initial] state = \"equilibrium\"), the GIL released. A "
        "SystemEquilibrium for a system of lines (its free bodies at their equilibrium poses).");

#ifdef CABLEFILM_PYTHON_RENDER
  m.def("render_frame", &RenderFrame, py::arg("run"), py::arg("t") = py::none(),
        py::kw_only(), py::arg("row") = py::none(), py::arg("width") = 1280,
        py::arg("height") = 720, py::arg("colormap") = py::none(),
        py::arg("tension_range") = py::none(),
        "The film's frame at the row nearest t [s] (or row; default the last) of a Result or "
        "a SystemResult (a scene is run first): an (height, width, 3) uint8 array, as the film draws it.");
  m.def("render_film", &RenderFilmTo, py::arg("run"), py::arg("path"), py::kw_only(),
        py::arg("width") = py::none(), py::arg("height") = py::none(), py::arg("fps") = py::none(),
        py::arg("speed") = py::none(), py::arg("colormap") = py::none(),
        py::arg("tension_range") = py::none(),
        "The film of a Result or a SystemResult (a scene is run first), as `cablefilm run` "
        "makes it: into PATH "
        "when it ends in .mp4, else PATH/film.mp4. The scene's [film] unless given. Returns "
        "the film's path.");
#endif

  BindSystems(m);
  BindBodyTools(m);

  m.def("sweep", &Sweep, py::arg("scene"), py::arg("values") = py::dict(), py::kw_only(),
        py::arg("cases") = py::none(), py::arg("jobs") = py::none(),
        py::arg("keep_results") = false,
        "Runs the cross product of values ({key: [v1, v2, ...]}, the first key varying slowest) "
        "times the cases (a list of {key: value}) on `jobs` threads (default one per core). "
        "Every case is checked first (SceneError naming the case). Returns one dict a case "
        "with the columns of sweep.csv (numbers as doubles; None for a case that did not "
        "finish), and its Result under \"result\" with keep_results.");
}
