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
namespace {

// The name of a run's line among the film's lines.
std::string FilmLineName(const Run& run, std::size_t i, bool several_runs) {
  if (run.model.lines.size() == 1) return run.label;
  return several_runs ? run.model.line_names[i] + " (" + run.label + ")" : run.model.line_names[i];
}

// How a time plot's rows name a run's line in messages.
std::string RowsName(const Run& run, std::size_t i) {
  if (run.model.lines.size() == 1) return "the " + run.label + " run";
  return "line \"" + run.model.line_names[i] + "\" of the " + run.label + " run";
}

}  // namespace

SceneView MakeFilmScene(const SceneDef& scene, const std::vector<const Run*>& runs,
                        const std::string& view) {
  const Run& first = *runs.front();
  const Model& model = first.model;
  const bool alike = model.lines.size() > 1;
  std::vector<LineView> lines;
  for (const Run* run : runs)
    for (std::size_t i = 0; i < run->model.lines.size(); ++i) {
      const LineData& d = run->initial.lines[i];
      const std::vector<SectionDef> none;
      const std::vector<SectionDef>& sections =
          !alike && i < scene.lines.size() ? scene.lines[i].sections : none;
      lines.push_back(MakeLineView(scene, sections, run->model.lines[i], d.state.x, d.tension(),
                                   FilmLineName(*run, i, runs.size() > 1)));
    }
  SceneView v = MakeSceneView(scene, model.lines.front(), std::move(lines), DrawsInSpace(scene, view));
  if (!alike) return v;
  v.lines_alike = true;
  v.bodies.resize(model.bodies.size());
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    BodyView& body = v.bodies[b];
    body.name = model.bodies[b].name;
    const Vec& a = model.bodies[b].angles;
    body.rest_angles = {a.x(), a.y(), a.z()};
    if (model.bodies[b].kind == BodyKind::kDriven && model.bodies[b].turn.moves())
      body.angles_at = [turn = model.bodies[b].turn](double t) {
        const Vec now = turn.Position(t);  // [rad]
        return std::array<double, 3>{now.x(), now.y(), now.z()};
      };
    if (b < scene.bodies.size() && scene.bodies[b].has_box) {  // the scene's bodies, in order
      body.has_box = true;
      body.box = scene.bodies[b].box;
      body.box_center = scene.bodies[b].box_center;
    }
  }
  for (const Point& p : model.points) {
    if (p.ends.empty()) continue;
    if (p.on_body >= 0) {
      v.bodies[p.on_body].points.push_back(static_cast<int>(v.points.size()));
      v.bodies[p.on_body].local.push_back({p.local.x(), p.local.y(), p.local.z()});
    }
    v.points.push_back({p.name, p.ends[0].line, p.ends[0].station});
  }
  return v;
}

FixedPolicy MakeFilmPolicy(const SceneView& view, const std::vector<const Run*>& runs,
                           const FilmRequest& request, double start, double end) {
  FixedPolicy policy;
  policy.start = start;
  policy.duration = end - start;
  const RunExtent& first = runs.front()->lines.front().extent;
  double t_lo = first.tension_min, t_hi = first.tension_max;
  Vec lo = first.box_min, hi = first.box_max;
  for (const Run* r : runs)
    for (const LineRecord& line : r->lines) {
      t_lo = std::min(t_lo, line.extent.tension_min);
      t_hi = std::max(t_hi, line.extent.tension_max);
      lo = lo.cwiseMin(line.extent.box_min);
      hi = hi.cwiseMax(line.extent.box_max);
    }
  // Colour range from zero (slack) to a little above the largest tension of every line.
  policy.tension_min = request.tension_min >= 0 ? request.tension_min : std::min(0.0, t_lo);
  policy.tension_max =
      request.tension_max >= 0 ? request.tension_max : 1.05 * std::max(t_hi, 1.0);
  policy.box = ShownBox({lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z()}, view.sea,
                        runs.front()->model.lines.front().env.wave);
  return policy;
}

bool RenderFilm(const SceneDef& scene, const std::vector<const Run*>& runs,
                const FilmRequest& request, const std::atomic<int>& stop, PictureReport* report) {
  const Run& main = *runs.front();
  // Every run steps again from its initial Data (or a checkpoint before its window) to the
  // frames (film_clock.h), in lockstep so that a run can be drawn over another.
  const RowSpan window = WindowRows(request.window, main.grid, main.summary.peak_t);
  const FilmClock clock(request.speed, request.fps, main.grid, window.first, window.last);
  const long last = clock.last;
  struct Stepper {
    TimeGrid grid;  // the run's, from the row its Data is at
    Inputs inputs;
    Data data;
    // on_rows: each line's links' envelope over the rows since the last frame [N] (empty: none
    // yet).
    std::vector<Eigen::VectorXd> row_min, row_max;
  };
  std::vector<Stepper> steppers;
  steppers.reserve(runs.size());
  std::vector<MaxTensionLog::Cursor> cursors;  // each line's output rows, run by run
  std::vector<std::string> names;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const Run* run = runs[r];
    long from = 0;  // the row of the Data it steps from
    const Data* start = r < request.starts.size() && request.starts[r]
                            ? request.starts[r]->StartFor(window.first, &from)
                            : nullptr;
    Stepper st{run->grid, run->inputs, start ? *start : run->initial, {}, {}};
    st.grid.first_output = start ? from : 0;
    st.inputs.stop = &stop;
    st.row_min.resize(run->lines.size());
    st.row_max.resize(run->lines.size());
    steppers.push_back(std::move(st));
    for (std::size_t i = 0; i < run->lines.size(); ++i) {
      cursors.emplace_back(run->lines[i].row_max);
      names.push_back(RowsName(*run, i));
    }
  }
  std::vector<RowStepper> row_steppers;
  for (std::size_t r = 0; r < runs.size(); ++r)
    row_steppers.emplace_back(runs[r]->model, steppers[r].data, steppers[r].inputs,
                              steppers[r].grid);
  // Steps run r to the window's first row, undrawn. Throws BlowUpError, CancelledError.
  auto lead_in = [&](std::size_t r) {
    while (row_steppers[r].row() < window.first) row_steppers[r].Next();
  };
  // Steps run r to frame k (k >= 1). Throws BlowUpError, CancelledError.
  auto advance = [&](std::size_t r, long k) {
    Stepper& st = steppers[r];
    RowStepper& rows = row_steppers[r];
    if (clock.on_rows) {
      const long target = clock.Row(k);
      while (rows.row() < target) {
        rows.Next();
        for (std::size_t i = 0; i < st.data.lines.size(); ++i) {
          const Eigen::VectorXd& T = st.data.lines[i].tension();
          if (st.row_min[i].size() == 0) {
            st.row_min[i] = st.row_max[i] = T;
          } else {
            st.row_min[i] = st.row_min[i].cwiseMin(T);
            st.row_max[i] = st.row_max[i].cwiseMax(T);
          }
        }
      }
      return;
    }
    // Off the rows: the frame's steps with the step rule of the run's own grid.
    const int steps = clock.FrameSteps(k, runs[r]->grid);
    const double h = k <= clock.whole ? clock.interval / steps
                                      : (clock.Time(k) - clock.Time(k - 1)) / steps;
    for (int i = 0; i < steps; ++i) {
      ThrowIfCancelled(&stop, "the film");
      Step(runs[r]->model, st.data, st.inputs, h);
    }
    st.data.t = clock.Time(k);
    for (LineData& line : st.data.lines) line.state.t = st.data.t;
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
  o.series_label = main.model.lines.size() == 1 ? main.label : main.model.line_names.front();
  const SceneView view = MakeFilmScene(scene, runs, request.view);
  const FixedPolicy policy = MakeFilmPolicy(view, runs, request, clock.start, clock.Time(last));
  FilmWriter writer(o, view, policy, request.out_dir, static_cast<int>(last + 1));
  const LineModel& any = main.model.lines.front();  // one environment: any line's is the scene's
  const Vec current = TopCurrent(any, SceneWater(any));  // a run's is the scene's
  bool finished = true;
  std::string failure;  // a blow-up in this pass: the film is then partial too
  // The rows before the window are not the film's.
  if (window.first > 0) {
    Snapshot before;
    before.lines.resize(cursors.size());
    TakeRows(cursors, names, clock.start - 1e-9 * main.grid.interval, &before);
  }
  for (long k = 0; k <= last && failure.empty(); ++k) {
    if (stop != 0) {
      finished = false;
      break;
    }
    for (std::size_t r = 0; r < steppers.size() && failure.empty(); ++r) {
      try {
        if (k == 0)
          lead_in(r);
        else
          advance(r, k);
      } catch (const CancelledError&) {
        finished = false;
        break;
      } catch (const BlowUpError& e) {
        failure = std::string(e.what()) + (runs.size() > 1 ? " (" + runs[r]->label + " run)" : "");
        break;
      }
    }
    if (!finished || !failure.empty()) break;
    Snapshot snap;  // every line of every run, each with its output rows since the last frame
    snap.t = steppers[0].data.t;
    for (const Stepper& st : steppers)
      for (const LineData& line : st.data.lines) {
        snap.lines.emplace_back();
        SetLineState(line.state.x, line.tension(), &snap.lines.back());
      }
    if (view.sea.surface) {
      AddWaterSurface(any.env.wave, policy.box, &snap);
      snap.wave = any.env.wave;
    }
    snap.current = current;
    // The output rows up to this frame (all that are left at the run's end): the first line's
    // times, every line's largest tension at each.
    const double until = k == last && window.last == main.grid.outputs
                             ? std::numeric_limits<double>::infinity()
                             : steppers[0].data.t + 1e-9 * clock.interval;
    TakeRows(cursors, names, until, &snap);
    std::size_t at = 0;  // each link's envelope over those rows
    for (Stepper& st : steppers)
      for (std::size_t i = 0; i < st.data.lines.size(); ++i, ++at) {
        LineSnapshot& line = snap.lines[at];
        if (st.row_min[i].size() != static_cast<Eigen::Index>(line.tension.size())) continue;
        line.row_link_min.assign(st.row_min[i].data(), st.row_min[i].data() + st.row_min[i].size());
        line.row_link_max.assign(st.row_max[i].data(), st.row_max[i].data() + st.row_max[i].size());
        st.row_min[i].resize(0);
        st.row_max[i].resize(0);
      }
    writer.Push(std::move(snap));
  }
  const std::string out = EscapeText(request.out_dir);
  const bool complete = finished && failure.empty();
  if (complete) {
    writer.Finish();
    if (request.say_written)
      std::printf("wrote %s/film.mp4%s\n", out.c_str(), request.frames ? " and frames/" : "");
  } else {
    writer.FinishPartial();  // plays up to the last frame drawn
    if (request.say_written)
      std::printf("wrote %s/film.partial.mp4 (%s at t = %.4g s)\n", out.c_str(),
                  failure.empty() ? "interrupted" : "the film pass failed", steppers[0].data.t);
  }
  if (report) {  // over the first run's lines: the largest of any
    *report = PictureReport{};
    report->frames = writer.frames_done();
    const Data& d = steppers[0].data;
    report->last_frame_t = d.t;
    for (const LineData& line : d.lines) {
      const double now = line.tension().maxCoeff();
      if (!(now <= report->last_frame_max)) report->last_frame_max = now;
    }
    const std::vector<MaxTensionSeries> shown = writer.all_max_tension_series();
    for (std::size_t i = 0; i < d.lines.size() && i < shown.size(); ++i) {
      const MaxTensionSeries& s = shown[i];
      FindPeak(s.t, s.tension, report);
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
