#include "app/body_commands.h"

#include <cmath>
#include <memory>
#include <cstdio>
#include <sstream>

#include "app/command.h"
#include "app/output_over_input.h"
#include "app/progress.h"
#include "app/run_support.h"
#include "core/body_statics.h"
#include "core/error.h"
#include "io/output_file.h"
#include "run/initial_state.h"
#include "scene/build_model.h"
#include "scene/option_values.h"
#include "scene/scene_limits.h"
#include "scene/scene_loader.h"
#include "scene/text_escape.h"

namespace cablefilm {
namespace {

// The index of the body named `name` (empty: the only one); throws Error naming the choices.
int FindBody(const SceneDef& scene, const Model& sys, const std::string& name) {
  if (sys.bodies.empty())
    throw Error(scene.path + ": the scene has no [[body]]: the quasi-static tools move a body");
  if (name.empty()) {
    if (sys.bodies.size() == 1) return 0;
    throw Error(scene.path + ": the scene has " + std::to_string(sys.bodies.size()) +
                " bodies: name one with --body");
  }
  std::string names;
  for (size_t b = 0; b < sys.bodies.size(); ++b) {
    if (sys.bodies[b].name == name) return static_cast<int>(b);
    names += (b ? ", " : "") + QuoteText(sys.bodies[b].name);
  }
  throw Error(scene.path + ": --body: no body is named " + QuoteText(name) + " (the bodies: " +
              names + ")");
}

Model LoadWithBodies(const std::string& scene_path, SceneDef* scene) {
  *scene = LoadScene(scene_path);
  Model model = BuildModel(*scene);
  if (model.bodies.empty())
    throw Error(scene_path + ": the scene has no body: the quasi-static tools take a scene with "
                             "a [[body]] its lines end on");
  return model;
}

// The model's equilibrium as `run` finds it (run/initial_state.h, without the bodies' initial
// offsets); `options` then start each held pose's statics from it.
struct Equilibrium {
  EquilibriumReport report;
  std::vector<State> states;
  EquilibriumOptions options;
};

void FindEquilibrium(const SceneDef& scene, const Model& sys, Equilibrium& e) {
  InstallSignalHandlers();
  StaticsProgress progress;
  SceneDef at_rest = scene;
  at_rest.initial = InitialStateKind::kEquilibrium;
  Model model = sys;
  for (BodySpec& b : model.bodies) b.initial_offset = Vec6::Zero();
  const TimeGrid grid = ChooseTimeGrid(model, scene.simulation, scene.output.interval);
  e.states = MakeInitialState(at_rest, model, grid, &e.report, &g_signal,
                              {progress.relaxing(), progress.solving()});
  e.options.cancel = &g_signal;
  e.options.guess = &e.states;
  e.options.guess_poses = e.report.body_poses.data();
}

void PrintPose(const char* what, const Vec6& pose) {
  std::printf("%s: x %.6g m, y %.6g m, z %.6g m, about x %.6g deg, about y %.6g deg, about z "
              "%.6g deg\n",
              what, pose[0], pose[1], pose[2], pose[3] * 180 / M_PI, pose[4] * 180 / M_PI,
              pose[5] * 180 / M_PI);
}

}  // namespace

int StiffnessCommand(const std::string& scene_path, const std::string& body) {
  SceneDef scene;
  const Model sys = LoadWithBodies(scene_path, &scene);
  const int b = FindBody(scene, sys, body);
  Equilibrium e;
  FindEquilibrium(scene, sys, e);
  const Vec6 pose = e.report.body_poses[b];
  const double step = 1e-4 * ShortestLineOn(sys, b);
  const Mat6 K = MooringStiffness(sys, b, pose, step, e.options);
  std::printf("body %s\n", QuoteText(sys.bodies[b].name).c_str());
  PrintPose("pose at equilibrium", pose);
  std::printf("mooring stiffness K = -dF/dq at that pose (central differences of %.3g m):\n"
              "rows: Fx, Fy, Fz [N], Mx, My, Mz [N m] about the reference point; columns: x, "
              "y, z [m], about x, y, z [rad]\n",
              step);
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) std::printf("%s%14.6e", j ? " " : "", K(i, j));
    std::printf("\n");
  }
  return 0;
}

int OffsetCommand(const std::string& scene_path, const OffsetOptions& o) {
  SceneDef scene;
  const Model sys = LoadWithBodies(scene_path, &scene);
  std::vector<std::string> inputs{scene_path};  // the scene and the motion tables it reads
  for (const PointDef& p : scene.points)
    if (!p.motion.table_file.empty()) inputs.push_back(p.motion.table_file);
  for (const BodyDef& b : scene.bodies)
    if (!b.motion.table_file.empty()) inputs.push_back(b.motion.table_file);
  RefuseOutputOverInput(o.out, inputs);
  const int b = FindBody(scene, sys, o.body);
  Equilibrium e;
  FindEquilibrium(scene, sys, e);
  const Vec6 pose = e.report.body_poses[b];
  const double most = o.max_offset >= 0 ? o.max_offset : 0.05 * ShortestLineOn(sys, b);
  std::vector<double> offsets;
  for (int k = 0; k < o.points; ++k)
    offsets.push_back(o.points > 1 ? most * k / (o.points - 1) : most);
  const std::vector<OffsetPoint> curve =
      OffsetCurve(sys, b, pose, o.heading, offsets, e.options);
  std::ostringstream csv;
  csv.precision(10);
  csv << "offset,restoring,fx,fy,fz,mx,my,mz";
  std::vector<int> on_body;
  for (size_t i = 0; i < sys.lines.size(); ++i)
    if (!std::isnan(curve.front().load.end_tension[i])) {
      on_body.push_back(static_cast<int>(i));
      csv << ",tension_" << sys.line_names[i];
    }
  csv << "\n";
  for (const OffsetPoint& p : curve) {
    csv << p.offset << "," << p.restoring;
    for (int k = 0; k < 6; ++k) csv << "," << p.load.load[k];
    for (int i : on_body) csv << "," << p.load.end_tension[i];
    csv << "\n";
  }
  std::fprintf(stderr, "body %s from its equilibrium along %.6g deg, offsets 0 to %.6g m\n",
               QuoteText(sys.bodies[b].name).c_str(), o.heading, most);
  if (o.out.empty() || o.out == "-") {
    std::fputs(csv.str().c_str(), stdout);  // main checks that standard output took it
    return 0;
  }
  WriteOutputFile(o.out, csv.str());
  std::fprintf(stderr, "wrote %s\n", EscapeText(o.out).c_str());
  return 0;
}

Command DeclareStiffnessCommand(CLI::App& program, std::string* scene) {
  auto body = std::make_shared<std::string>();
  CLI::App* cmd = AddSceneCommand(
      program, "stiffness", "print the moorings' 6x6 stiffness matrix of a body at equilibrium",
      scene);
  cmd->add_option("--body", *body, "the body (default: the scene's only one)")->type_name("NAME");
  return {cmd, [scene, body] { return StiffnessCommand(*scene, *body); }};
}

Command DeclareOffsetCommand(CLI::App& program, std::string* scene) {
  auto o = std::make_shared<OffsetOptions>();
  CLI::App* cmd = AddSceneCommand(
      program, "offset", "the offset-restoring curve of a body along a heading (CSV)", scene);
  cmd->add_option("--body", o->body, "the body (default: the scene's only one)")->type_name("NAME");
  Value(cmd, "--heading", "DEG", "direction of the offset from +x towards +z (default 0)",
        [o](const std::string& v) {
          // The offset curve's own range, refused here before anything is read.
          o->heading = ParseNumber("--heading", v, -kMaxHeading, kMaxHeading, false, " degrees");
        });
  Value(cmd, "--max", "M", "largest offset in m (default: a twentieth of the shortest line on the body)",
        [o](const std::string& v) { o->max_offset = ParseNumber("--max", v, 0, kMaxLength, false, " m"); });
  Value(cmd, "--points", "N", "offsets from 0 to --max, 1 to 10000 (default 11)",
        [o](const std::string& v) {
          o->points = static_cast<int>(ParseNumber("--points", v, 1, 10000, false, " points"));
          if (o->points != std::stod(v)) Bad("--points: expected a whole number");
        });
  cmd->add_option("-o,--out", o->out, "the CSV file (default: standard output)")->type_name("FILE");
  cmd->footer(
      "Columns: offset [m], restoring (the moorings' horizontal force against the heading)\n"
      "[N], fx, fy, fz [N], mx, my, mz [N m] (the moorings' load on the body), then the load\n"
      "at each line's end on the body, tension_<line> [N]. The body moves from its\n"
      "equilibrium; its other degrees of freedom are held. See docs/cli.md.");
  return {cmd, [scene, o] { return OffsetCommand(*scene, *o); }};
}

}  // namespace cablefilm
