#include "view/system_film.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/cancel.h"
#include "core/step.h"
#include "core/error.h"
#include "scene/film_view.h"
#include "scene/text_escape.h"
#include "view/film_clock.h"
#include "view/film_writer.h"
#include "view/scene_view_builder.h"
#include "view/world_box.h"

namespace cablefilm {

SceneView MakeSystemFilmScene(const SceneDef& scene, const SystemRun& run,
                              const std::string& view) {
  const Model& sys = run.sys;
  std::vector<LineView> lines;
  for (std::size_t i = 0; i < sys.lines.size(); ++i) {
    const LineData& d = run.initial.lines[i];
    lines.push_back(MakeLineView(scene, sys.lines[i], d.state.x, d.tension(), sys.line_names[i]));
    lines.back().section_names.clear();  // the scene's [cable] sections are not a line's
  }
  SceneView v = MakeSceneView(scene, sys.lines.front(), std::move(lines),
                              DrawsInSpace(scene, view));
  v.lines_alike = true;
  v.bodies.resize(sys.bodies.size());
  for (std::size_t b = 0; b < sys.bodies.size(); ++b) {
    BodyView& body = v.bodies[b];
    body.name = sys.bodies[b].name;
    const Vec& a = sys.bodies[b].angles;
    body.rest_angles = {a.x(), a.y(), a.z()};
    if (sys.bodies[b].kind == BodyKind::kDriven && sys.bodies[b].turn.moves())
      body.angles_at = [turn = sys.bodies[b].turn](double t) {
        const Vec now = turn.Position(t);  // [rad]
        return std::array<double, 3>{now.x(), now.y(), now.z()};
      };
    if (b < scene.bodies.size() && scene.bodies[b].has_box) {  // the scene's bodies, in order
      body.has_box = true;
      body.box = scene.bodies[b].box;
      body.box_center = scene.bodies[b].box_center;
    }
  }
  for (const Point& p : sys.points) {
    if (p.ends.empty()) continue;
    if (p.on_body >= 0) {
      v.bodies[p.on_body].points.push_back(static_cast<int>(v.points.size()));
      v.bodies[p.on_body].local.push_back({p.local.x(), p.local.y(), p.local.z()});
    }
    v.points.push_back({p.name, p.ends[0].line, p.ends[0].station});
  }
  return v;
}

FixedPolicy MakeSystemFilmPolicy(const SceneView& view, const SystemRun& run,
                                 const FilmRequest& request, double duration) {
  FixedPolicy policy;
  policy.duration = duration;
  const RunExtent& first = run.extents.front();
  double t_lo = first.tension_min, t_hi = first.tension_max;
  Vec lo = first.box_min, hi = first.box_max;
  for (const RunExtent& e : run.extents) {
    t_lo = std::min(t_lo, e.tension_min);
    t_hi = std::max(t_hi, e.tension_max);
    lo = lo.cwiseMin(e.box_min);
    hi = hi.cwiseMax(e.box_max);
  }
  // As a line's film: from zero (slack) to a little above the largest tension of any line.
  policy.tension_min = request.tension_min >= 0 ? request.tension_min : std::min(0.0, t_lo);
  policy.tension_max =
      request.tension_max >= 0 ? request.tension_max : 1.05 * std::max(t_hi, 1.0);
  policy.box = ShownBox({lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z()}, view.sea,
                        run.sys.lines.front().env.wave);
  return policy;
}

bool RenderSystemFilm(const SceneDef& scene, const SystemRun& run, const FilmRequest& request,
                      const std::atomic<int>& stop, PictureReport* report) {
  const Model& sys = run.sys;
  const std::size_t nl = sys.lines.size();
  const FilmClock clock(request.speed, request.fps, run.grid);
  const TimeGrid grid = clock.Grid(run.grid);
  Inputs inputs = run.inputs;
  inputs.stop = &stop;
  Data sd = run.initial;  // stepped again from t = 0, as the run was
  SystemRowStepper rows(sys, sd, inputs, grid);
  std::vector<MaxTensionLog::Cursor> cursors;  // each line's output rows
  std::vector<std::string> names;
  for (std::size_t i = 0; i < nl; ++i) {
    cursors.emplace_back(run.row_max[i]);
    names.push_back("line \"" + sys.line_names[i] + "\"");
  }
  // On rows: each link's envelope over the rows since the last frame [N] (empty: none yet).
  std::vector<Eigen::VectorXd> row_min(nl), row_max(nl);
  // Steps the system to frame k (k >= 1). Throws BlowUpError, CancelledError.
  auto advance = [&](long k) {
    if (clock.on_rows) {
      const long target = clock.Row(k, grid.outputs);
      while (rows.row() < target) {
        rows.Next();
        for (std::size_t i = 0; i < nl; ++i) {
          const Eigen::VectorXd& T = sd.lines[i].tension();
          if (row_min[i].size() == 0) {
            row_min[i] = row_max[i] = T;
          } else {
            row_min[i] = row_min[i].cwiseMin(T);
            row_max[i] = row_max[i].cwiseMax(T);
          }
        }
      }
      return;
    }
    if (k <= clock.whole) {
      rows.Next();
      return;
    }
    // The shorter last frame, with the step rule of the run's own grid.
    const double span = clock.Time(k) - clock.Time(k - 1);
    const int steps = clock.LastFrameSteps(run.grid);
    for (int i = 0; i < steps; ++i) {
      ThrowIfCancelled(&stop, "the film");
      Step(sys, sd, inputs, span / steps);
    }
    sd.t = clock.Time(k);
    for (LineData& d : sd.lines) d.state.t = sd.t;
  };
  FilmOptions o;
  o.width = request.width;
  o.height = request.height;
  o.fps = request.fps;
  o.crf = request.crf;
  o.colormap = request.colormap;
  o.write_frames = request.frames;
  o.shader_dir = request.shader_dir;
  o.write_max_tension = false;  // max_tension.png comes from the rows
  o.series_label = sys.line_names.front();
  const SceneView view = MakeSystemFilmScene(scene, run, request.view);
  const FixedPolicy policy = MakeSystemFilmPolicy(view, run, request, clock.Time(clock.last));
  FilmWriter writer(o, view, policy, request.out_dir, static_cast<int>(clock.last + 1));
  const LineModel& any = sys.lines.front();  // one environment: any line's is the scene's
  const Vec current = TopCurrent(any, SceneWater(any));
  bool finished = true;
  std::string failure;  // a blow-up in this pass: the film is then partial too
  for (long k = 0; k <= clock.last; ++k) {
    if (stop != 0) {
      finished = false;
      break;
    }
    try {
      if (k > 0) advance(k);
    } catch (const CancelledError&) {
      finished = false;
      break;
    } catch (const BlowUpError& e) {
      failure = e.what();
      break;
    }
    Snapshot snap;  // a line a line of the system, each with its output rows since the last frame
    snap.t = sd.t;
    snap.lines.resize(nl);
    for (std::size_t i = 0; i < nl; ++i)
      SetLineState(sd.lines[i].state.x, sd.lines[i].tension(), &snap.lines[i]);
    if (view.sea.surface) {
      AddWaterSurface(any.env.wave, policy.box, &snap);
      snap.wave = any.env.wave;
    }
    snap.current = current;
    const double until = k == clock.last ? std::numeric_limits<double>::infinity()
                                         : sd.t + 1e-9 * clock.interval;
    TakeRows(cursors, names, until, &snap);
    for (std::size_t i = 0; i < nl; ++i) {  // each link's envelope over those rows
      if (row_min[i].size() != static_cast<Eigen::Index>(snap.lines[i].tension.size())) continue;
      snap.lines[i].row_link_min.assign(row_min[i].data(), row_min[i].data() + row_min[i].size());
      snap.lines[i].row_link_max.assign(row_max[i].data(), row_max[i].data() + row_max[i].size());
      row_min[i].resize(0);
      row_max[i].resize(0);
    }
    writer.Push(std::move(snap));
  }
  const std::string out = EscapeText(request.out_dir);
  if (finished && failure.empty()) {
    writer.Finish();
    if (request.say_written)
      std::printf("wrote %s/film.mp4%s\n", out.c_str(), request.frames ? " and frames/" : "");
  } else {
    writer.FinishPartial();  // plays up to the last frame drawn
    if (request.say_written)
      std::printf("wrote %s/film.partial.mp4 (%s at t = %.4g s)\n", out.c_str(),
                  failure.empty() ? "interrupted" : "the film pass failed", sd.t);
  }
  if (report) {  // over all the lines: the largest of any
    *report = PictureReport{};
    report->frames = writer.frames_done();
    report->last_frame_t = sd.t;
    for (std::size_t i = 0; i < nl; ++i) {
      const double now = sd.lines[i].tension().maxCoeff();
      if (!(now <= report->last_frame_max)) report->last_frame_max = now;
    }
    for (const MaxTensionSeries& s : writer.all_max_tension_series()) {
      for (std::size_t j = 0; j < s.t.size() && j < s.tension.size(); ++j)
        if (std::isfinite(s.tension[j]) && !(s.tension[j] <= report->peak)) {
          report->peak = s.tension[j];
          report->peak_t = s.t[j];
        }
      if (!s.tension.empty() && !(s.tension.back() <= report->last_row_max))
        report->last_row_max = s.tension.back();
    }
  }
  if (!failure.empty())
    throw Error("the film pass failed: " + failure + "; the film up to then is " + out +
                "/film.partial.mp4");
  return finished;
}

}  // namespace cablefilm
