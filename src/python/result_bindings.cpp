// The results of the module: cablefilm.run's Result (the rows of every line, point and body,
// as `cablefilm run`'s files hold them: the doubles of results.nc, what timeseries.csv,
// points.csv and body.csv print) with a Line a line, and cablefilm.equilibrium's Equilibrium.
// One type each for every model: a model of one line has its line's arrays on the Result and
// the Equilibrium too, so that a single line reads as r.x, r.tension.
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
#include "run/memory_run.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"

namespace py = pybind11;

namespace cablefilm::python {
namespace {

// ---- what both results read ----

std::vector<std::string> PointNames(const Model& model) {
  std::vector<std::string> names;
  for (const Point& p : model.points) names.push_back(p.name);
  return names;
}

std::vector<std::string> BodyNames(const Model& model) {
  std::vector<std::string> names;
  for (const BodySpec& b : model.bodies) names.push_back(b.name);
  return names;
}

py::array LinkMidpoints(const LineModel& m) {
  py::array_t<double> a(m.line.links);
  double* out = a.mutable_data();
  for (int j = 0; j < m.line.links; ++j)
    out[j] = 0.5 * (m.line.arc_length[j] + m.line.arc_length[j + 1]);
  return std::move(a);
}

// The statics' figures as `cablefilm check` prints them: of a line alone between points that
// hold it, its own solve's (Newton iterations, the residual, the pseudo-transient fallback);
// else the model's (Newton on its shared points and free bodies, the largest residual, and the
// relaxation or a line's fallback). Zero with [initial] state = "straight" (no statics).
struct StaticsFigures {
  int iterations = 0;
  double residual = 0;  // [N]
  bool fallback = false;
};

StaticsFigures ModelStatics(const Model& model, const EquilibriumReport& e) {
  StaticsFigures f;
  if (model.lines.size() == 1 && !model.islands.front().coupled()) {
    if (!e.lines.empty()) {
      f.iterations = e.lines.front().iterations;
      f.residual = e.lines.front().residual;
      f.fallback = e.lines.front().fallback;
    }
    return f;
  }
  f.iterations = e.iterations;
  f.residual = e.residual;
  f.fallback = e.relaxed > 0;
  for (const LineEquilibriumReport& l : e.lines) f.fallback = f.fallback || l.fallback;
  return f;
}

// Line i's own solve (the last, in a coupled island's statics).
StaticsFigures LineStatics(const EquilibriumReport& e, int i) {
  StaticsFigures f;
  if (i < static_cast<int>(e.lines.size())) {
    f.iterations = e.lines[i].iterations;
    f.residual = e.lines[i].residual;
    f.fallback = e.lines[i].fallback;
  }
  return f;
}

// The same keys for a run and for each of its lines.
py::dict StatsDict(const RunSummary& s, const StaticsFigures& statics, double relaxed) {
  py::dict d;
  d["integrator"] = s.scheme;
  d["steps"] = s.stats.steps;
  d["rejected"] = s.stats.rejected;
  d["newton_iterations"] = s.stats.newton_iterations;
  d["snaps"] = s.stats.record.snaps;
  d["unresolved_snaps"] = s.stats.record.unresolved_snaps;
  d["snap_windows"] = s.stats.snap_windows;
  d["explicit_steps"] = s.stats.explicit_steps;
  d["equilibrium_iterations"] = statics.iterations;
  d["equilibrium_residual"] = statics.residual;
  d["equilibrium_relaxed"] = relaxed;
  return d;
}

// An end's tension statistics (run/tension_statistics.h), as run_report.toml names them.
py::dict StatisticsDict(const TensionStatistics& t) {
  py::dict d;
  d["samples"] = t.samples;
  d["mean"] = t.mean;
  d["std"] = t.sigma;
  d["min"] = t.min;
  d["max"] = t.max;
  d["upcrossings"] = t.upcrossings;
  d["mpm"] = t.mpm;
  d["psd_m0"] = t.psd_m0;
  return d;
}

std::string Count(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// ---- a line of a run ----

const Line& LineOf(const py::object& self) { return self.cast<const Line&>(); }
const MemoryRows& RowsOf(const Line& l) { return l.run->lines[l.index]; }
const LineModel& ModelOf(const Line& l) { return l.run->run.model.lines[l.index]; }
const RunSummary& SummaryOf(const Line& l) { return l.run->run.lines[l.index].summary; }

// The positions along `axis` of every row [rows, stations] (station -1), or of the start (0) or
// the end (1) station [rows]. The rows hold x, y, z station by station: an axis is every
// kDim-th double.
py::array Positions(const py::object& self, int axis, int station) {
  const Line& l = LineOf(self);
  const MemoryRows& r = RowsOf(l);
  const int stations = ModelOf(l).stations();
  const double* data = r.x.data() + axis;
  if (station < 0) return View(self, data, {r.rows, stations}, {stations * kDim, kDim});
  return View(self, data + (station == 0 ? 0 : (stations - 1) * kDim), {r.rows},
              {stations * kDim});
}

// Every station's position of every row as one array [rows, stations, 3] (x, y, z).
py::array PositionVectors(const py::object& self) {
  const Line& l = LineOf(self);
  const MemoryRows& r = RowsOf(l);
  const int stations = ModelOf(l).stations();
  return View(self, r.x.data(), {r.rows, stations, kDim}, {stations * kDim, kDim, 1});
}

// The end load of end e (0: start, 1: end) of every row, [rows, 3] (N).
py::array EndLoadRows(const py::object& self, int e) {
  const MemoryRows& r = RowsOf(LineOf(self));
  return View(self, r.end_load.data() + e * kDim, {r.rows, kDim}, {2 * kDim, 1});
}

// ---- a run ----

const MemoryRun& RunOf(const py::object& self) { return *self.cast<Result&>().run; }

// Rows x items x width doubles of `data` as a read-only view [rows, items, width].
py::array Rows3(const py::object& self, const std::vector<double>& data, long rows, size_t items,
                int width) {
  const auto n = static_cast<py::ssize_t>(items);
  return View(self, data.data(), {rows, n, width}, {n * width, width, 1});
}

// A line's attribute on the Result of a model of one line: that line's. A model of several
// has none (AttributeError, so hasattr says False), each line its own.
py::object OnlyLine(const py::object& self, const char* attribute) {
  const Result& r = self.cast<const Result&>();
  if (r.lines.size() == 1) return r.lines.begin()->second.attr(attribute);
  throw py::attribute_error(std::string("a Result of ") + std::to_string(r.lines.size()) +
                            " lines has no ." + attribute + ": each line has its own, r.lines[" +
                            "name]." + attribute + " (the names: r.line_names)");
}

// The line's arrays, on a Line and on the Result of a model of one line.
const char* const kLineArrays[] = {
    "x", "y", "z", "position", "tension", "x_start", "y_start", "z_start", "x_end", "y_end",
    "z_end", "load_start", "load_end", "s", "s_link", "minimum_breaking_load"};

// ---- the equilibrium ----

// The first row's items x width doubles as a new array [items, width].
py::array FirstRow(const std::vector<double>& data, size_t items, int width) {
  py::array_t<double> a({static_cast<py::ssize_t>(items), py::ssize_t{width}});
  if (items > 0) std::memcpy(a.mutable_data(), data.data(), sizeof(double) * items * width);
  return std::move(a);
}

LineEquilibrium MakeLineEquilibrium(const std::string& name, const LineModel& m, const Points& x,
                                    const Eigen::VectorXd& tension) {
  LineEquilibrium e;
  e.name = name;
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

const char* const kLineEquilibriumArrays[] = {"x", "y", "z", "position", "tension", "s",
                                              "s_link"};

py::object OnlyLineEquilibrium(const Equilibrium& e, const char* attribute) {
  if (e.lines.size() == 1) return e.lines.begin()->second.attr(attribute);
  throw py::attribute_error(std::string("an Equilibrium of ") + std::to_string(e.lines.size()) +
                            " lines has no ." + attribute + ": each line has its own, e.lines[" +
                            "name]." + attribute);
}

}  // namespace

py::array Copy(const Eigen::VectorXd& v) {
  py::array_t<double> a(v.size());
  std::memcpy(a.mutable_data(), v.data(), sizeof(double) * static_cast<std::size_t>(v.size()));
  return std::move(a);
}

py::object MakeResult(std::shared_ptr<const MemoryRun> run, const SceneHandle& scene) {
  Result r{run, py::cast(scene), py::dict()};
  for (std::size_t i = 0; i < run->lines.size(); ++i)
    r.lines[py::str(run->run.model.line_names[i])] = py::cast(Line{run, static_cast<int>(i)});
  return py::cast(std::move(r));
}

py::object SceneEquilibrium(const SceneHandle& scene) {
  SceneDef def = scene.def();
  def.initial = InitialStateKind::kEquilibrium;
  CancelFlag cancel{0};
  std::shared_ptr<const MemoryRun> run;
  try {
    run = RunInterruptible(cancel, [&] {
      return std::make_shared<const MemoryRun>(EquilibriumInMemory(def, scene.model(), &cancel));
    });
  } catch (const CancelledError&) {
    throw;
  } catch (const Error& e) {
    throw SceneProblem(SceneErrorMessage(scene.path(), e.what()));
  }
  const Model& model = run->run.model;
  const EquilibriumReport& report = run->run.equilibrium;
  Equilibrium e;
  for (std::size_t i = 0; i < model.lines.size(); ++i) {
    // The tensions as the run's first row has them: its scheme's, at the state.
    const LineData& d = run->run.initial.lines[i];
    LineEquilibrium line =
        MakeLineEquilibrium(model.line_names[i], model.lines[i], d.state.x, d.tension());
    const StaticsFigures own = LineStatics(report, static_cast<int>(i));
    line.iterations = own.iterations;
    line.residual = own.residual;
    line.fallback = own.fallback;
    e.lines[py::str(model.line_names[i])] = py::cast(std::move(line));
  }
  e.point_names = PointNames(model);
  e.body_names = BodyNames(model);
  e.point_position = FirstRow(run->points.point_position, model.points.size(), kDim);
  e.point_force = FirstRow(run->points.point_force, model.points.size(), kDim);
  e.body_pose = FirstRow(run->points.body_pose, model.bodies.size(), 6);
  e.body_load = FirstRow(run->points.body_load, model.bodies.size(), 6);
  const StaticsFigures figures = ModelStatics(model, report);
  e.iterations = figures.iterations;
  e.residual = figures.residual;
  e.fallback = figures.fallback;
  return py::cast(std::move(e));
}

void BindResults(py::module_& m) {
  py::class_<Line> line(m, "Line", R"(A line's rows in a run, as its results.nc holds them (the
same doubles): time [n] (s), x, y, z [n, stations] (m; y up, z = 0 for a line in the x-y
plane), the same as one array position [n, stations, 3], tension [n, links] (N, 0 when slack),
the motion of stations 0 and s x_start ... z_end [n] (m), the end loads load_start, load_end
[n, 3] (N: the force the line exerts on what holds each end), arc lengths s [stations], s_link
[links] (m), minimum_breaking_load [links] (N); its own peak, least tension, stats and
warnings. A part of its run, drawn with it. The arrays are read-only views of the run.)");
  line.def_property_readonly("name", [](const Line& l) {
        return l.run->run.model.line_names[l.index];
      })
      .def_property_readonly("time", [](const py::object& self) {
        const MemoryRows& r = RowsOf(LineOf(self));
        return View(self, r.time.data(), {r.rows}, {1});
      })
      .def_property_readonly("x", [](const py::object& self) { return Positions(self, 0, -1); })
      .def_property_readonly("y", [](const py::object& self) { return Positions(self, 1, -1); })
      .def_property_readonly("z", [](const py::object& self) { return Positions(self, 2, -1); })
      .def_property_readonly("position", &PositionVectors,
                             "every station's position of every row [n, stations, 3] (m): x, y, z")
      .def_property_readonly("tension", [](const py::object& self) {
        const Line& l = LineOf(self);
        const MemoryRows& r = RowsOf(l);
        const int links = ModelOf(l).line.links;
        return View(self, r.tension.data(), {r.rows, links}, {links, 1});
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
      .def_property_readonly("s", [](const Line& l) { return Copy(ModelOf(l).line.arc_length); })
      .def_property_readonly("s_link", [](const Line& l) { return LinkMidpoints(ModelOf(l)); })
      .def_property_readonly("minimum_breaking_load",
                             [](const Line& l) { return Copy(ModelOf(l).line.breaking_load); },
                             "Each link's material's minimum_breaking_load [N] (0: not given), as "
                             "results.nc has it: tension / minimum_breaking_load is the utilisation.")
      .def_property_readonly("peak_tension", [](const Line& l) { return SummaryOf(l).peak; },
                             "The line's largest tension of any row [N].")
      .def_property_readonly("peak_time", [](const Line& l) { return SummaryOf(l).peak_t; })
      .def_property_readonly("peak_link", [](const Line& l) { return SummaryOf(l).peak_link; })
      .def_property_readonly("min_tension", [](const Line& l) { return SummaryOf(l).min_tension; })
      .def_property_readonly("min_tension_time", [](const Line& l) { return SummaryOf(l).min_tension_t; })
      .def_property_readonly("min_tension_link", [](const Line& l) { return SummaryOf(l).min_tension_link; })
      .def_property_readonly("stats", [](const Line& l) {
        return StatsDict(SummaryOf(l), LineStatics(l.run->run.equilibrium, l.index),
                         l.run->run.equilibrium.relaxed);
      }, "The line's steps (its island's), and its own statics' solve.")
      .def_property_readonly("warnings", [](const Line& l) { return SummaryOf(l).warnings; },
                             "Why the line's peak cannot be trusted (empty: converged).")
      .def_property_readonly(
          "tension_statistics",
          [](const Line& l) {
            py::dict d;
            d["start"] = StatisticsDict(SummaryOf(l).ends[0]);
            d["end"] = StatisticsDict(SummaryOf(l).ends[1]);
            return d;
          },
          "The end links' tensions over the rows, {'start': ..., 'end': ...}, each with samples, "
          "mean, std (over n), min, max, upcrossings (of the mean), mpm (the most probable "
          "maximum, mean + std sqrt(2 ln upcrossings)) and psd_m0 (the spectrum's integral) "
          "[N, N^2], as run_report.toml has them.")
      .def_property_readonly(
          "tension_spectrum",
          [](const Line& l) -> py::object {
            const EndTensionSpectrum& s = l.run->run.lines[l.index].spectrum;
            if (s.empty()) return py::none();
            py::dict d;
            auto copy = [](const std::vector<double>& v) {  // py::array_t copies the data
              return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
            };
            d["frequency"] = copy(s.frequency);
            d["start"] = copy(s.density[0]);
            d["end"] = copy(s.density[1]);
            return std::move(d);
          },
          "The end links' tensions' one-sided Welch spectral density, as tension_spectrum.csv "
          "has it: {'frequency' [Hz], 'start', 'end' [N^2/Hz]}; None when the run had too few "
          "rows.")
      .def("__repr__", [](const Line& l) {
        return "<cablefilm.Line \"" + l.run->run.model.line_names[l.index] + "\": " +
               std::to_string(RowsOf(l).rows) + " rows, " +
               std::to_string(ModelOf(l).stations()) + " stations, peak " +
               FormatNumber(SummaryOf(l).peak) + " N>";
      });

  py::class_<Result> result(m, "Result", R"(The rows of a run, as `cablefilm run` writes them
(the doubles of results.nc; points.csv and body.csv print these to 10 to 12 digits): time [n]
(s); lines {name: Line} (each line's rows: x, y, z, position, tension, s, ...); point_names
and point_position, point_force [n, points, 3] (m, N: the force the lines exert on the point);
body_names and body_pose [n, bodies, 6] (x, y, z in m, then the angles about x, y, z in rad),
body_load [n, bodies, 6] (the lines' force in N and moment about the reference point in N m);
the run's peak, least tension, stats and warnings. A model of one line has that line's arrays
here too (r.x is r.lines["cable"].x). The arrays are read-only views of the run.)");
  result.def_property_readonly("time", [](const py::object& self) {
        const MemoryRows& r = RunOf(self).lines.front();  // every line's rows alike
        return View(self, r.time.data(), {r.rows}, {1});
      })
      .def_property_readonly("lines", [](const Result& r) { return r.lines.attr("copy")(); },
                             "{line name: Line}, in the scene's order")
      .def_property_readonly("line_names", [](const Result& r) {
        return r.run->run.model.line_names;
      })
      .def_property_readonly("point_names", [](const Result& r) {
        return PointNames(r.run->run.model);
      })
      .def_property_readonly("body_names", [](const Result& r) {
        return BodyNames(r.run->run.model);
      })
      .def_property_readonly("point_position", [](const py::object& self) {
        const MemoryRun& r = RunOf(self);
        return Rows3(self, r.points.point_position, r.points.rows, r.run.model.points.size(), kDim);
      }, "[n, points, 3] (m)")
      .def_property_readonly("point_force", [](const py::object& self) {
        const MemoryRun& r = RunOf(self);
        return Rows3(self, r.points.point_force, r.points.rows, r.run.model.points.size(), kDim);
      }, "[n, points, 3] (N): the lines' pull on the point (what an anchor or fairlead holds)")
      .def_property_readonly("body_pose", [](const py::object& self) {
        const MemoryRun& r = RunOf(self);
        return Rows3(self, r.points.body_pose, r.points.rows, r.run.model.bodies.size(), 6);
      }, "[n, bodies, 6]: x, y, z (m), angles about x, y, z (rad)")
      .def_property_readonly("body_load", [](const py::object& self) {
        const MemoryRun& r = RunOf(self);
        return Rows3(self, r.points.body_load, r.points.rows, r.run.model.bodies.size(), 6);
      }, "[n, bodies, 6]: force (N), moment about the reference point (N m)")
      .def_property_readonly("scene", [](const Result& r) { return r.scene; })
      .def_property_readonly("completed", [](const Result& r) { return r.run->run.summary.completed; })
      .def_property_readonly("failure", [](const Result& r) { return r.run->run.summary.failure; })
      .def_property_readonly("peak_tension", [](const Result& r) { return r.run->run.summary.peak; },
                             "The largest tension of any line's row [N] (the run's printed peak).")
      .def_property_readonly("peak_time", [](const Result& r) { return r.run->run.summary.peak_t; })
      .def_property_readonly("peak_line", [](const Result& r) -> py::object {
        const Run& run = r.run->run;
        if (run.model.lines.size() == 1 || run.peak_line < 0) return py::none();
        return py::str(run.model.line_names[run.peak_line]);
      }, "The name of the line holding the peak (None for a model of one line, or before any "
         "row).")
      .def_property_readonly("peak_link", [](const Result& r) { return r.run->run.summary.peak_link; },
                             "The peak's link (in peak_line).")
      .def_property_readonly("min_tension", [](const Result& r) { return r.run->run.summary.min_tension; })
      .def_property_readonly("min_tension_time", [](const Result& r) {
        return r.run->run.summary.min_tension_t;
      })
      .def_property_readonly("min_tension_link", [](const Result& r) {
        return r.run->run.summary.min_tension_link;
      }, "The least tension's link (in min_tension_line).")
      .def_property_readonly("min_tension_line", [](const Result& r) -> py::object {
        const RunSummary& s = r.run->run.summary;
        if (s.min_tension_line.empty()) return py::none();
        return py::str(s.min_tension_line);
      }, "The name of the line holding the least tension (None for a model of one line).")
      .def_property_readonly("stats", [](const Result& r) {
        const Run& run = r.run->run;
        return StatsDict(run.summary, ModelStatics(run.model, run.equilibrium),
                         run.equilibrium.relaxed);
      })
      .def_property_readonly("warnings", [](const Result& r) { return r.run->run.summary.warnings; },
                             "Why the peak cannot be trusted (empty: converged), as "
                             "run_report.toml says.")
      .def("__repr__", [](const Result& r) {
        const MemoryRun& run = *r.run;
        const RunSummary& s = run.run.summary;
        const long rows = run.lines.front().rows;
        const std::string what =
            run.lines.size() == 1
                ? std::to_string(run.run.model.lines.front().stations()) + " stations"
                : Count(run.lines.size(), "line", "lines");
        return "<cablefilm.Result " + std::to_string(rows) + " rows, " + what + ", peak " +
               FormatNumber(s.peak) + " N" + (s.completed ? "" : ", cut short") + ">";
      });
  for (const char* name : kLineArrays)
    result.def_property_readonly(name, [name](const py::object& self) {
      return OnlyLine(self, name);
    }, "A model of one line: its line's (AttributeError for several: r.lines[name]).");

  py::class_<LineEquilibrium>(m, "LineEquilibrium",
                              "A line's static equilibrium: x, y, z [stations] (m), position "
                              "[stations, 3] (m: x, y, z), tension [links] (N), s, s_link (m); "
                              "iterations, residual (N) and fallback of its own solve.")
      .def_readonly("name", &LineEquilibrium::name)
      .def_readonly("x", &LineEquilibrium::x)
      .def_readonly("y", &LineEquilibrium::y)
      .def_readonly("z", &LineEquilibrium::z)
      .def_readonly("position", &LineEquilibrium::position, "[stations, 3] (m): x, y, z")
      .def_readonly("tension", &LineEquilibrium::tension)
      .def_readonly("s", &LineEquilibrium::s)
      .def_readonly("s_link", &LineEquilibrium::s_link)
      .def_readonly("iterations", &LineEquilibrium::iterations)
      .def_readonly("residual", &LineEquilibrium::residual, "largest out-of-balance force [N]")
      .def_readonly("fallback", &LineEquilibrium::fallback)
      .def("__iter__", [](const LineEquilibrium& e) {
        return py::iter(py::make_tuple(e.x, e.y, e.tension));
      })
      .def("__repr__", [](const LineEquilibrium& e) {
        return "<cablefilm.LineEquilibrium \"" + e.name + "\": " +
               std::to_string(e.x.shape(0)) + " stations>";
      });

  py::class_<Equilibrium> equilibrium(m, "Equilibrium", R"(The static equilibrium (a run's
first row, its free bodies at their equilibrium poses whatever their initial offsets): lines
{name: LineEquilibrium}; point_names, point_position, point_force [points, 3] (m, N);
body_names, body_pose [bodies, 6] (m, rad), body_load [bodies, 6] (N, N m); iterations,
residual (N) and fallback of the statics. A model of one line has its line's x, y, z,
position, tension, s, s_link here too, and unpacks as x, y, tension.)");
  equilibrium.def_readonly("lines", &Equilibrium::lines)
      .def_readonly("point_names", &Equilibrium::point_names)
      .def_readonly("point_position", &Equilibrium::point_position)
      .def_readonly("point_force", &Equilibrium::point_force)
      .def_readonly("body_names", &Equilibrium::body_names)
      .def_readonly("body_pose", &Equilibrium::body_pose)
      .def_readonly("body_load", &Equilibrium::body_load)
      .def_readonly("iterations", &Equilibrium::iterations)
      .def_readonly("residual", &Equilibrium::residual, "largest out-of-balance force [N]")
      .def_readonly("fallback", &Equilibrium::fallback,
                    "a line alone: its pseudo-transient fallback was needed; several: the "
                    "relaxation or a line's fallback")
      .def("__iter__", [](const Equilibrium& e) {
        if (e.lines.size() != 1)
          throw py::type_error("an Equilibrium of " + std::to_string(e.lines.size()) +
                               " lines does not unpack: each line's is e.lines[name]");
        return py::iter(e.lines.begin()->second);
      })
      .def("__repr__", [](const Equilibrium& e) {
        return "<cablefilm.Equilibrium " + Count(e.lines.size(), "line", "lines") + ", " +
               std::to_string(e.iterations) + " iterations, residual " +
               FormatNumber(e.residual) + " N>";
      });
  for (const char* name : kLineEquilibriumArrays)
    equilibrium.def_property_readonly(name, [name](const Equilibrium& e) {
      return OnlyLineEquilibrium(e, name);
    }, "A model of one line: its line's (AttributeError for several: e.lines[name]).");
}

}  // namespace cablefilm::python
