// The Python module `cablefilm`: scenes loaded from a file or a dict and changed key by key,
// runs as numpy arrays with no file written, the static equilibrium, the film and its frames,
// sweeps over scene keys. Bindings only: the work is that of the program's libraries
// (scene_loader, run/memory_run, view/film_pass, run/sweep), called as the command line
// calls them, so a run gives the very doubles of `cablefilm run`'s results.nc. One path for
// every scene, one line or several: result_bindings.cpp binds what a run and the statics
// return, body_tools.cpp a body's stiffness and offset curve.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "core/error.h"
#include "core/version.h"
#include "python/bindings.h"
#include "python/interruptible.h"
#include "python/scene_handle.h"
#include "python/toml_values.h"
#include "run/memory_run.h"
#include "run/run_summary.h"
#include "run/sweep.h"
#include "run/sweep_plan.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"
#ifdef CABLEFILM_PYTHON_RENDER
#include "scene/film_settings.h"
#include "view/film_pass.h"
#include "view/memory_film.h"
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

#ifdef CABLEFILM_PYTHON_RENDER
namespace {

// The run of a Result, or of a scene (run here; `holder` keeps it). A Line is drawn with the
// others of its run: its ends move with them.
const MemoryRun& RunOf(const py::object& obj, py::object* holder) {
  if (py::isinstance<Line>(obj))
    throw py::type_error("expected a Result or a scene, got a Line: a line is drawn with its "
                         "run (the Result its line came from)");
  *holder = py::isinstance<Result>(obj) ? obj : RunScene(SceneOf(obj, std::nullopt));
  return *holder->cast<Result&>().run;
}

// The film's options: the scene's [film], with those given (each checked as the loader and the
// command line check theirs); a whole film's frame count too.
FilmRequest FilmOptions(const SceneDef& scene, std::optional<int> width, std::optional<int> height,
                        std::optional<double> fps, std::optional<double> speed,
                        std::optional<std::string> colormap,
                        std::optional<std::pair<double, double>> tension_range, bool whole_film,
                        std::optional<std::string> window = std::nullopt) {
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
  if (window) {
    check("window", FilmWindowProblem(*window, &o.window));
    o.window_given = true;
  }
  o.frames = 0;
  try {
    return MakeFilmRequest(ResolveFilm(scene, o, kPythonNames, whole_film), "", "");
  } catch (const Error& e) {
    throw py::value_error(e.what());
  }
}

py::array RenderFrame(const py::object& obj, std::optional<double> t, std::optional<long> row,
                      int width, int height, std::optional<std::string> colormap,
                      std::optional<std::pair<double, double>> tension_range) {
  py::object holder;
  const MemoryRun& run = RunOf(obj, &holder);
  const FilmRequest request = FilmOptions(run.scene, width, height, std::nullopt, std::nullopt,
                                          colormap, tension_range, false);
  const MemoryRows& rows = run.lines.front();  // every line's rows alike
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
  const Image image =
      RunInterruptible(cancel, [&] { return DrawMemoryRunFrame(run, chosen, request); });
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
                         std::optional<std::pair<double, double>> tension_range,
                         std::optional<std::string> window) {
  namespace fs = std::filesystem;
  py::object holder;
  const MemoryRun& run = RunOf(obj, &holder);
  const RunSummary& summary = run.run.summary;
  // Before any folder is made: the film pass steps the run again to its end.
  if (!summary.completed)
    throw py::value_error("the run did not reach its end" +
                          (summary.failure.empty() ? std::string() : ": " + summary.failure) +
                          "; a film is made of a whole run");
  FilmRequest request =
      FilmOptions(run.scene, width, height, fps, speed, colormap, tension_range, true, window);
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
    finished = RunInterruptible(cancel, [&] { return RenderMemoryRunFilm(run, request, cancel); });
  } catch (...) {
    if (file) fs::remove_all(dir);
    throw;
  }
  if (!file) return (dir / (finished ? "film.mp4" : "film.partial.mp4")).string();
  fs::rename(dir / "film.mp4", target);
  fs::remove_all(dir);
  return target.string();
}

}  // namespace
#endif

namespace {
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
  std::vector<CaseOutcome> outcomes(n);
  CancelFlag cancel{0};
  RunInterruptible(cancel, [&] {
    ThreadExecutor executor(threads, [&](std::size_t i, const CancelFlag* stop) {
      CaseOutcome o;
      try {
        auto run = std::make_shared<const MemoryRun>(
            RunInMemory(scenes[i].def(), scenes[i].model(), stop));
        o = OutcomeOf(run->run.summary, *stop != 0);
        if (keep_results) kept[i] = std::move(run);
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
    if (keep_results) d["result"] = kept[i] ? MakeResult(kept[i], scenes[i]) : py::none();
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
      .def_property_readonly("lines", [](const SceneHandle& s) { return s.model().line_names; },
                             "The line names in the scene's order (line[0] first; a [cable]: "
                             "[\"cable\"]).")
      .def_property_readonly("points", [](const SceneHandle& s) {
        std::vector<std::string> names;
        for (const PointDef& p : s.def().points) names.push_back(p.name);
        return names;
      }, "The point names (point[0] first; a [cable]'s ends: [\"start\", \"end\"]).")
      .def_property_readonly("bodies", [](const SceneHandle& s) {
        std::vector<std::string> names;
        for (const BodyDef& b : s.def().bodies) names.push_back(b.name);
        return names;
      }, "The body names (body[0] first); [] for none.")
      .def_property_readonly("stations", [](const SceneHandle& s) -> py::object {
        const Model& model = s.model();
        if (model.lines.size() == 1) return py::int_(model.lines.front().stations());
        py::dict d;
        for (size_t i = 0; i < model.lines.size(); ++i)
          d[py::str(model.line_names[i])] = model.lines[i].stations();
        return d;
      }, "The stations of a scene of one line; of several, a dict {line name: stations}.")
      .def_property_readonly("links", [](const SceneHandle& s) -> py::object {
        const Model& model = s.model();
        if (model.lines.size() == 1) return py::int_(model.lines.front().line.links);
        py::dict d;
        for (size_t i = 0; i < model.lines.size(); ++i)
          d[py::str(model.line_names[i])] = model.lines[i].line.links;
        return d;
      }, "The links of a scene of one line; of several, a dict {line name: links}.")
      .def("__repr__", [](const SceneHandle& s) {
        const std::string head = "<cablefilm.Scene " + s.path() + ": \"" + s.def().title + "\", ";
        const Model& model = s.model();
        if (model.lines.size() == 1)
          return head + std::to_string(model.lines.front().line.links) + " links>";
        auto count = [](std::size_t n, const char* one, const char* many) {
          return std::to_string(n) + " " + (n == 1 ? one : many);
        };
        return head + count(model.lines.size(), "line", "lines") + ", " +
               count(model.points.size(), "point", "points") + ", " +
               count(model.bodies.size(), "body", "bodies") + ">";
      });

  m.def("load", &SceneOf, py::arg("source"), py::arg("name") = py::none(),
        "A Scene from a scene file's path or a dict of the same schema (SceneError when the "
        "loader refuses it, with the message `cablefilm check` prints).");

  BindResults(m);

  m.def("run", [](const py::object& source) { return RunScene(SceneOf(source, std::nullopt)); },
        py::arg("scene"),
        "Runs a scene (a Scene, a path or a dict) from its initial state to its end, writing no "
        "file; the GIL is released meanwhile. Returns a Result. BlowUpError on a numerical "
        "blow-up (its .result: the rows so far); SceneError when no initial state is found.");
  m.def("equilibrium",
        [](const py::object& source) { return SceneEquilibrium(SceneOf(source, std::nullopt)); },
        py::arg("scene"),
        "The scene's static equilibrium with the ends at their t = 0 positions and the free "
        "bodies at their equilibrium poses (the initial state of a run with [initial] state = "
        "\"equilibrium\" and no initial offsets), the GIL released: an Equilibrium.");

#ifdef CABLEFILM_PYTHON_RENDER
  m.def("render_frame", &RenderFrame, py::arg("run"), py::arg("t") = py::none(),
        py::kw_only(), py::arg("row") = py::none(), py::arg("width") = 1280,
        py::arg("height") = 720, py::arg("colormap") = py::none(),
        py::arg("tension_range") = py::none(),
        "The film's frame at the row nearest t [s] (or row; default the last) of a Result (a "
        "scene is run first): an (height, width, 3) uint8 array, as the film draws it.");
  m.def("render_film", &RenderFilmTo, py::arg("run"), py::arg("path"), py::kw_only(),
        py::arg("width") = py::none(), py::arg("height") = py::none(), py::arg("fps") = py::none(),
        py::arg("speed") = py::none(), py::arg("colormap") = py::none(),
        py::arg("tension_range") = py::none(), py::arg("window") = py::none(),
        "The film of a Result (a scene is run first), as `cablefilm run` makes it: into PATH "
        "when it ends in .mp4, else PATH/film.mp4. The scene's [film] unless given; window: "
        "'peak:SECONDS', 'T0,T1' or 'whole'. Returns the film's path.");
#endif

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
