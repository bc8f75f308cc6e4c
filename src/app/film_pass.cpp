#include "app/film_pass.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/cancel.h"
#include "render/film_writer.h"

namespace cablefilm {
namespace {

CableSnapshot ToSnapshot(const CableState& s, const Eigen::VectorXd& tension) {
  CableSnapshot snap;
  snap.t = s.t;
  snap.x.resize(s.x.cols());
  snap.y.resize(s.x.cols());
  for (Eigen::Index j = 0; j < s.x.cols(); ++j) {
    snap.x[j] = s.x(0, j);
    snap.y[j] = s.x(1, j);
  }
  snap.tension.assign(tension.data(), tension.data() + tension.size());
  return snap;
}

FilmSpec MakeSpec(const SceneDef& scene, const std::vector<FilmRun>& runs,
                  const FilmRequest& request, double duration) {
  const FilmRun& run = runs.front();
  const CableModel& m = *run.model;
  FilmSpec spec;
  spec.title = scene.title;
  spec.arc_length.assign(m.arc_length.data(), m.arc_length.data() + m.arc_length.size());
  spec.section_boundaries = m.section_boundaries;
  // Each section by its material's name, when every section has one (the model keeps one
  // boundary between each two sections, so the counts agree).
  for (const SectionDef& section : scene.sections) {
    const bool named = section.material >= 0 &&
                       static_cast<std::size_t>(section.material) < scene.materials.size() &&
                       !scene.materials[section.material].name.empty();
    if (!named) {
      spec.section_names.clear();
      break;
    }
    spec.section_names.push_back(scene.materials[section.material].name);
  }
  if (spec.section_names.size() != spec.section_boundaries.size() + 1) spec.section_names.clear();
  spec.weight_stations = m.weight_stations;
  for (int j : {0, m.links}) {
    if (m.end_motion(j).moves()) spec.moving_ends.push_back(j);
    if (m.end_motion(j).kind() == EndKind::kFixed) spec.fixed_ends.push_back(j);
  }
  spec.equilibrium = ToSnapshot(run.initial, run.initial_tension);
  spec.duration = duration;
  double t_lo = run.extent.tension_min, t_hi = run.extent.tension_max;
  Eigen::Vector2d lo = run.extent.box_min, hi = run.extent.box_max;
  for (const FilmRun& r : runs) {
    t_lo = std::min(t_lo, r.extent.tension_min);
    t_hi = std::max(t_hi, r.extent.tension_max);
    lo = lo.cwiseMin(r.extent.box_min);
    hi = hi.cwiseMax(r.extent.box_max);
  }
  // Colour range from zero (slack) to a little above the largest tension of every run.
  spec.tension_min = request.tension_min >= 0 ? request.tension_min : std::min(0.0, t_lo);
  spec.tension_max = request.tension_max >= 0 ? request.tension_max : 1.05 * std::max(t_hi, 1.0);
  spec.x_min = lo.x();
  spec.x_max = hi.x();
  spec.y_min = lo.y();
  spec.y_max = hi.y();
  return spec;
}

}  // namespace

bool RenderFilm(const SceneDef& scene, const std::vector<FilmRun>& runs,
                const FilmRequest& request, const std::atomic<int>& stop) {
  const double frame_interval = request.speed / request.fps;  // simulated seconds per frame
  const FilmRun& main = runs.front();
  const long frames = static_cast<long>(
      std::floor(main.grid.outputs * main.grid.interval / frame_interval + 1e-9));
  // Every run steps through the same frame times (in lockstep, so that a second run can be
  // drawn over the first), each with its own scheme's step rule.
  struct Stepper {
    TimeGrid grid;
    CableState state;
    std::unique_ptr<Integrator> integrator;
    MaxTensionSeries trace;
  };
  std::vector<Stepper> steppers;
  for (const FilmRun& run : runs) {
    Stepper st;
    st.grid = run.grid;
    st.grid.steps_per_output =
        std::max(1, static_cast<int>(std::ceil(frame_interval / run.grid.dt - 1e-9)));
    st.grid.interval = frame_interval;
    st.grid.dt = frame_interval / st.grid.steps_per_output;
    st.grid.outputs = frames;
    st.state = run.initial;
    st.integrator = MakeIntegrator(*run.model, st.grid);
    st.integrator->Initialize(*run.model, st.state);
    st.trace.label = run.label;
    steppers.push_back(std::move(st));
  }
  std::unique_ptr<FilmWriter> writer;
  if (request.film) {
    FilmOptions o;
    o.width = request.width;
    o.height = request.height;
    o.fps = request.fps;
    o.crf = request.crf;
    o.colormap = request.colormap;
    o.write_frames = request.frames;
    o.shader_dir = request.shader_dir;
    o.write_max_tension = false;  // written below, with every run's series
    o.series_label = main.label;
    FilmSpec spec = MakeSpec(scene, runs, request, frames * frame_interval);
    spec.label = main.label;
    if (runs.size() > 1) {
      spec.companion_label = runs[1].label;
      spec.companion_equilibrium = ToSnapshot(runs[1].initial, runs[1].initial_tension);
    }
    writer = std::make_unique<FilmWriter>(o, spec, request.out_dir, static_cast<int>(frames + 1));
  }
  bool finished = true;
  std::string failure;  // a blow-up in this pass: the film is then partial too
  for (long k = 0; k <= frames && failure.empty(); ++k) {
    if (stop != 0) {
      finished = false;
      break;
    }
    for (size_t r = 0; r < steppers.size() && failure.empty(); ++r) {
      Stepper& st = steppers[r];
      if (k > 0) {
        try {
          for (int i = 0; i < st.grid.steps_per_output; ++i) {
            ThrowIfCancelled(&stop, "the film");
            st.integrator->Step(*runs[r].model, st.state, st.grid.dt);
          }
        } catch (const CancelledError&) {
          finished = false;
          break;
        } catch (const BlowUpError& e) {
          failure = std::string(e.what()) + " (" + runs[r].label + " run)";
          break;
        }
        st.state.t = k * frame_interval;
      }
      st.trace.t.push_back(st.state.t);
      st.trace.tension.push_back(st.integrator->tensions().maxCoeff());
    }
    if (!finished || !failure.empty()) break;
    if (!writer) continue;
    CableSnapshot snap = ToSnapshot(steppers[0].state, steppers[0].integrator->tensions());
    if (steppers.size() > 1) {
      const CableSnapshot other =
          ToSnapshot(steppers[1].state, steppers[1].integrator->tensions());
      snap.cx = other.x;
      snap.cy = other.y;
      snap.ctension = other.tension;
    }
    writer->Push(std::move(snap));
  }
  const bool complete = finished && failure.empty();
  if (writer) {
    if (complete) {
      writer->Finish();
      std::printf("wrote %s/film.mp4%s\n", request.out_dir.c_str(),
                  request.frames ? " and frames/" : "");
    } else {
      writer->FinishPartial();  // plays up to the last frame drawn
      std::printf("wrote %s/film.partial.mp4 (%s at t = %.4g s)\n", request.out_dir.c_str(),
                  failure.empty() ? "interrupted" : "the film pass failed",
                  steppers[0].state.t);
    }
  }
  std::vector<MaxTensionSeries> series;
  for (Stepper& st : steppers) series.push_back(std::move(st.trace));
  const std::string still =
      request.out_dir + (complete ? "/max_tension.png" : "/max_tension.partial.png");
  WriteMaxTensionPng(still, series, 1600, 900, "Maximum tension along the cable: " + scene.title,
                     request.shader_dir);
  std::printf("wrote %s\n", still.c_str());
  if (!failure.empty())
    throw Error("the film pass failed: " + failure + "; the film up to then is " +
                request.out_dir + "/film.partial.mp4");
  return finished;
}

}  // namespace cablefilm
