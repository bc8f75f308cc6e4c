// The quasi-static tools of a moored body (core/body_statics.h), as `cablefilm stiffness` and
// `cablefilm offset` compute them: the body's equilibrium pose, the moorings' 6x6 stiffness
// there (central differences of 1e-4 of the shortest line on the body), and the
// offset-restoring curve along a heading.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "core/body_statics.h"
#include "core/error.h"
#include "python/bindings.h"
#include "python/interruptible.h"
#include "run/initial_state.h"
#include "run/time_grid.h"
#include "scene/scene_loader.h"

namespace py = pybind11;

namespace cablefilm::python {
namespace {

// The index of the body named `name` (None: the only one); ValueError naming the choices.
int FindBody(const SceneHandle& scene, const std::optional<std::string>& name) {
  const Model& model = scene.model();
  if (model.bodies.empty())
    throw py::value_error(scene.path() + ": the scene has no [[body]]: the quasi-static tools "
                          "move a body its lines end on");
  if (!name) {
    if (model.bodies.size() == 1) return 0;
    throw py::value_error(scene.path() + ": the scene has " + std::to_string(model.bodies.size()) +
                          " bodies: name one with body=");
  }
  std::string names;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    if (model.bodies[b].name == *name) return static_cast<int>(b);
    names += (b ? ", \"" : "\"") + model.bodies[b].name + "\"";
  }
  throw py::value_error(scene.path() + ": body: no body is named \"" + *name +
                        "\" (the bodies: " + names + ")");
}

py::array Vector6(const Vec6& v) {
  py::array_t<double> a(6);
  for (int k = 0; k < 6; ++k) a.mutable_at(k) = v[k];
  return std::move(a);
}

// Core work with the GIL released and Ctrl-C polled; an Error is a SceneError of the scene.
// `work` is given body b's pose at the model's equilibrium as `run` finds it (MakeInitialState,
// the bodies without their initial offsets: `cablefilm stiffness` and `cablefilm offset`'s)
// and options that start each held pose's statics from that equilibrium.
template <class Work>
auto Statics(const SceneHandle& scene, int b, Work&& work) {
  CancelFlag cancel{0};
  try {
    return RunInterruptible(cancel, [&] {
      SceneDef at_rest = scene.def();
      at_rest.initial = InitialStateKind::kEquilibrium;
      Model model = scene.model();
      for (BodySpec& body : model.bodies) body.initial_offset = Vec6::Zero();
      const TimeGrid grid = ChooseTimeGrid(model, at_rest.simulation, at_rest.output.interval);
      EquilibriumReport report;
      const std::vector<State> states = MakeInitialState(at_rest, model, grid, &report, &cancel);
      EquilibriumOptions options;
      options.cancel = &cancel;
      options.guess = &states;
      options.guess_poses = report.body_poses.data();
      return work(report.body_poses[b], options);
    });
  } catch (const CancelledError&) {
    throw;
  } catch (const Error& e) {
    throw SceneProblem(SceneErrorMessage(scene.path(), e.what()));
  }
}

py::tuple Stiffness(const py::object& source, const std::optional<std::string>& body) {
  const SceneHandle scene = SceneOf(source, std::nullopt);
  const int b = FindBody(scene, body);
  const Model& model = scene.model();
  struct Out {
    Vec6 pose;
    Mat6 K;
  };
  const Out out = Statics(scene, b, [&](const Vec6& pose, const EquilibriumOptions& options) {
    Out o;
    o.pose = pose;
    o.K = MooringStiffness(model, b, o.pose, 1e-4 * ShortestLineOn(model, b), options);
    return o;
  });
  py::array_t<double> K({6, 6});
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) K.mutable_at(i, j) = out.K(i, j);
  return py::make_tuple(Vector6(out.pose), K);
}

py::dict Offset(const py::object& source, const std::optional<std::string>& body, double heading,
                const std::optional<std::vector<double>>& given) {
  const SceneHandle scene = SceneOf(source, std::nullopt);
  const int b = FindBody(scene, body);
  const Model& model = scene.model();
  if (given) {
    if (given->empty()) throw py::value_error("offsets: expected at least one offset [m]");
    for (double o : *given)
      if (!std::isfinite(o)) throw py::value_error("offsets: expected finite offsets [m]");
  }
  struct Out {
    Vec6 pose;
    std::vector<OffsetPoint> curve;
  };
  const Out out = Statics(scene, b, [&](const Vec6& pose, const EquilibriumOptions& options) {
    Out o;
    o.pose = pose;
    std::vector<double> offsets;
    if (given) {
      offsets = *given;
    } else {  // `cablefilm offset`'s: 11 from 0 to a twentieth of the shortest line on the body
      const double most = 0.05 * ShortestLineOn(model, b);
      const int points = 11;
      for (int k = 0; k < points; ++k) offsets.push_back(most * k / (points - 1));
    }
    o.curve = OffsetCurve(model, b, o.pose, heading, offsets, options);  // checks the heading
    return o;
  });
  const auto k = static_cast<py::ssize_t>(out.curve.size());
  py::array_t<double> offset(k), restoring(k), load({k, py::ssize_t{6}});
  py::dict tension;
  for (size_t i = 0; i < model.lines.size(); ++i) {
    if (std::isnan(out.curve.front().load.end_tension[i])) continue;  // not on the body
    py::array_t<double> t(k);
    for (py::ssize_t p = 0; p < k; ++p) t.mutable_at(p) = out.curve[p].load.end_tension[i];
    tension[py::str(model.line_names[i])] = t;
  }
  for (py::ssize_t p = 0; p < k; ++p) {
    offset.mutable_at(p) = out.curve[p].offset;
    restoring.mutable_at(p) = out.curve[p].restoring;
    for (int c = 0; c < 6; ++c) load.mutable_at(p, c) = out.curve[p].load.load[c];
  }
  py::dict d;
  d["body"] = model.bodies[b].name;
  d["pose"] = Vector6(out.pose);
  d["heading"] = heading;
  d["offset"] = offset;
  d["restoring"] = restoring;
  d["load"] = load;
  d["tension"] = tension;
  return d;
}

}  // namespace

void BindBodyTools(py::module_& m) {
  m.def("stiffness", &Stiffness, py::arg("scene"), py::arg("body") = py::none(),
        "The moorings' stiffness on a body, as `cablefilm stiffness` computes it: "
        "(pose, K). pose [6]: the body's equilibrium pose (x, y, z in m, angles about x, y, z "
        "in rad); K [6, 6] = -dF/dq there by central differences of 1e-4 of the shortest line "
        "on the body (rows Fx, Fy, Fz [N], Mx, My, Mz [N m] about the reference point; columns "
        "x, y, z [m], angles [rad]). The moorings only: not the body's hydrostatics. `body`: "
        "its name (None: the scene's only body). The GIL is released.");
  m.def("offset_curve", &Offset, py::arg("scene"), py::arg("body") = py::none(),
        py::arg("heading") = 0.0, py::arg("offsets") = py::none(),
        "The offset-restoring curve of a body, as `cablefilm offset` computes it: the body moved "
        "from its equilibrium by each of `offsets` [m] (default 11 from 0 to a twentieth of the "
        "shortest line on it) along `heading` [deg, from +x towards +z], its other degrees of "
        "freedom held. Returns a dict: body, pose [6] (the equilibrium: m, rad), heading, "
        "offset [k] (m), restoring [k] (N, the horizontal force against the heading), load "
        "[k, 6] (N, N m about the reference point), tension {line name: [k]} (N, at the end on "
        "the body) for the lines on the body. The GIL is released.");
}

}  // namespace cablefilm::python
