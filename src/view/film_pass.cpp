#include "view/film_pass.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/cancel.h"
#include "core/step.h"
#include "core/error.h"
#include "view/film_clock.h"
#include "view/film_writer.h"
#include "view/max_tension_figure.h"
#include "view/scene_view_builder.h"
#include "view/time_trace.h"
#include "view/world_box.h"
#include "scene/film_view.h"
#include "scene/text_escape.h"

namespace cablefilm {

SceneView MakeFilmScene(const SceneDef& scene, const std::vector<const Run*>& runs,
                        const std::string& view) {
  std::vector<LineView> lines;
  for (const Run* run : runs)
    lines.push_back(MakeLineView(scene, run->model, run->initial.state.x, run->initial.tension(),
                                 run->label));
  return MakeSceneView(scene, runs.front()->model, std::move(lines), DrawsInSpace(scene, view));
}

FixedPolicy MakeFilmPolicy(const SceneView& view, const std::vector<const Run*>& runs,
                           const FilmRequest& request, double duration) {
  const Run& run = *runs.front();
  FixedPolicy policy;
  policy.duration = duration;
  double t_lo = run.extent.tension_min, t_hi = run.extent.tension_max;
  Vec lo = run.extent.box_min, hi = run.extent.box_max;
  for (const Run* r : runs) {
    t_lo = std::min(t_lo, r->extent.tension_min);
    t_hi = std::max(t_hi, r->extent.tension_max);
    lo = lo.cwiseMin(r->extent.box_min);
    hi = hi.cwiseMax(r->extent.box_max);
  }
  // Colour range from zero (slack) to a little above the largest tension of every run.
  policy.tension_min = request.tension_min >= 0 ? request.tension_min : std::min(0.0, t_lo);
  policy.tension_max =
      request.tension_max >= 0 ? request.tension_max : 1.05 * std::max(t_hi, 1.0);
  policy.box =
      ShownBox({lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z()}, view.sea, run.model.env.wave);
  return policy;
}

bool RenderFilm(const SceneDef& scene, const std::vector<const Run*>& runs,
                const FilmRequest& request, const std::atomic<int>& stop, PictureReport* report) {
  const Run& main = *runs.front();
  // Every run steps again from its initial LineData to the frames (film_clock.h), in lockstep so
  // that a run can be drawn over another.
  const FilmClock clock(request.speed, request.fps, main.grid);
  const double frame_interval = clock.interval;
  const long last = clock.last;
  auto frame_time = [&](long k) { return clock.Time(k); };
  struct Stepper {
    TimeGrid grid;
    Inputs inputs;
    LineData data;
    Eigen::VectorXd row_min, row_max;  // on_rows: each link's envelope over the rows since the
                                       // last frame [N] (empty: none yet)
  };
  std::vector<Stepper> steppers;
  steppers.reserve(runs.size());
  std::vector<MaxTensionLog::Cursor> cursors;  // each run's output rows
  std::vector<std::string> names;
  for (const Run* run : runs) {
    Stepper st{clock.Grid(run->grid), run->inputs, run->initial, {}, {}};
    st.inputs.stop = &stop;
    steppers.push_back(std::move(st));
    cursors.emplace_back(run->row_max);
    names.push_back("the " + run->label + " run");
  }
  std::vector<RowStepper> row_steppers;
  for (std::size_t r = 0; r < runs.size(); ++r)
    row_steppers.emplace_back(runs[r]->model, steppers[r].data, steppers[r].inputs,
                              steppers[r].grid);
  // Steps run r to frame k (k >= 1). Throws BlowUpError, CancelledError.
  auto advance = [&](std::size_t r, long k) {
    Stepper& st = steppers[r];
    RowStepper& rows = row_steppers[r];
    if (clock.on_rows) {
      const long target = clock.Row(k, st.grid.outputs);
      while (rows.row() < target) {
        rows.Next();
        const Eigen::VectorXd& T = st.data.tension();
        if (st.row_min.size() == 0) {
          st.row_min = st.row_max = T;
        } else {
          st.row_min = st.row_min.cwiseMin(T);
          st.row_max = st.row_max.cwiseMax(T);
        }
      }
      return;
    }
    if (k <= clock.whole) {
      rows.Next();
      return;
    }
    // The shorter last frame, with the step rule of the run's own grid.
    const double span = frame_time(k) - frame_time(k - 1);
    const int steps = clock.LastFrameSteps(runs[r]->grid);
    for (int i = 0; i < steps; ++i) {
      ThrowIfCancelled(&stop, "the film");
      StepLine(runs[r]->model, st.data, st.inputs, span / steps);
    }
    st.data.state.t = frame_time(k);
  };
  FilmOptions o;
  o.width = request.width;
  o.height = request.height;
  o.fps = request.fps;
  o.crf = request.crf;
  o.colormap = request.colormap;
  o.write_frames = request.frames;
  o.shader_dir = request.shader_dir;
  o.write_max_tension = false;  // max_tension.png comes from the rows (WriteMaxTensionFigure)
  o.series_label = main.label;
  const SceneView view = MakeFilmScene(scene, runs, request.view);
  const FixedPolicy policy = MakeFilmPolicy(view, runs, request, frame_time(last));
  FilmWriter writer(o, view, policy, request.out_dir, static_cast<int>(last + 1));
  const Vec current = TopCurrent(main.model, SceneWater(main.model));  // a run's is the scene's
  bool finished = true;
  std::string failure;  // a blow-up in this pass: the film is then partial too
  for (long k = 0; k <= last && failure.empty(); ++k) {
    if (stop != 0) {
      finished = false;
      break;
    }
    for (size_t r = 0; k > 0 && r < steppers.size() && failure.empty(); ++r) {
      try {
        advance(r, k);
      } catch (const CancelledError&) {
        finished = false;
        break;
      } catch (const BlowUpError& e) {
        failure = std::string(e.what()) + " (" + runs[r]->label + " run)";
        break;
      }
    }
    if (!finished || !failure.empty()) break;
    Snapshot snap;  // a line a run, each with its output rows since the last frame
    snap.t = steppers[0].data.state.t;
    snap.lines.resize(steppers.size());
    for (std::size_t r = 0; r < steppers.size(); ++r)
      SetLineState(steppers[r].data.state.x, steppers[r].data.tension(), &snap.lines[r]);
    if (view.sea.surface) {
      AddWaterSurface(main.model.env.wave, policy.box, &snap);
      snap.wave = main.model.env.wave;
    }
    snap.current = current;
    // The output rows up to this frame (all that are left at the last frame): the first run's
    // times, every run's largest tension at each.
    const double until = k == last ? std::numeric_limits<double>::infinity()
                                   : steppers[0].data.state.t + 1e-9 * frame_interval;
    TakeRows(cursors, names, until, &snap);
    for (std::size_t r = 0; r < steppers.size(); ++r) {  // each link's envelope over those rows
      Stepper& st = steppers[r];
      if (st.row_min.size() != static_cast<Eigen::Index>(snap.lines[r].tension.size())) continue;
      snap.lines[r].row_link_min.assign(st.row_min.data(), st.row_min.data() + st.row_min.size());
      snap.lines[r].row_link_max.assign(st.row_max.data(), st.row_max.data() + st.row_max.size());
      st.row_min.resize(0);
      st.row_max.resize(0);
    }
    writer.Push(std::move(snap));
  }
  const bool complete = finished && failure.empty();
  if (complete) {
    writer.Finish();
    if (request.say_written)
      std::printf("wrote %s/film.mp4%s\n", request.out_dir.c_str(),
                  request.frames ? " and frames/" : "");
  } else {
    writer.FinishPartial();  // plays up to the last frame drawn
    if (request.say_written)
      std::printf("wrote %s/film.partial.mp4 (%s at t = %.4g s)\n", request.out_dir.c_str(),
                  failure.empty() ? "interrupted" : "the film pass failed",
                  steppers[0].data.state.t);
  }
  if (report) {
    *report = PictureReport{};
    const std::vector<MaxTensionSeries> shown = writer.all_max_tension_series();
    FindPeak(shown[0].t, shown[0].tension, report);
    report->frames = writer.frames_done();
    report->last_frame_max = steppers[0].data.tension().maxCoeff();
    report->last_frame_t = steppers[0].data.state.t;
    if (!shown[0].tension.empty()) report->last_row_max = shown[0].tension.back();
  }
  if (!failure.empty())
    throw Error("the film pass failed: " + failure + "; the film up to then is " +
                request.out_dir + "/film.partial.mp4");
  return finished;
}

}  // namespace cablefilm
