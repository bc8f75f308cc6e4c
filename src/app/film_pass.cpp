#include "app/film_pass.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

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
  std::vector<MaxTensionSeries> series;
  bool finished = true;
  for (size_t i = 0; i < runs.size(); ++i) {
    const FilmRun& run = runs[i];
    const CableModel& m = *run.model;
    const bool draw = i == 0 && request.film;
    // The film's own grid: one output per frame, the same step rule as the first pass.
    TimeGrid grid = run.grid;
    grid.steps_per_output =
        std::max(1, static_cast<int>(std::ceil(frame_interval / run.grid.dt - 1e-9)));
    grid.interval = frame_interval;
    grid.dt = frame_interval / grid.steps_per_output;
    grid.outputs = static_cast<long>(
        std::floor(run.grid.outputs * run.grid.interval / frame_interval + 1e-9));
    MaxTensionSeries trace;
    trace.label = run.label;
    std::unique_ptr<FilmWriter> writer;
    if (draw) {
      FilmOptions o;
      o.width = request.width;
      o.height = request.height;
      o.fps = request.fps;
      o.crf = request.crf;
      o.colormap = request.colormap;
      o.write_frames = request.frames;
      o.shader_dir = request.shader_dir;
      o.write_max_tension = false;  // written below with every run's series
      o.series_label = run.label;
      writer = std::make_unique<FilmWriter>(
          o, MakeSpec(scene, runs, request, grid.outputs * grid.interval), request.out_dir,
          static_cast<int>(grid.outputs + 1));
    }
    CableState state = run.initial;
    auto integrator = MakeIntegrator(m, grid);
    const bool done =
        Simulate(m, *integrator, state, grid, [&](const CableState& s, const Eigen::VectorXd& T) {
          trace.t.push_back(s.t);
          trace.tension.push_back(T.maxCoeff());
          if (writer) writer->Push(ToSnapshot(s, T));
          return stop == 0;
        });
    if (writer) writer->Finish();
    series.push_back(std::move(trace));
    if (!done) {
      finished = false;
      break;
    }
    if (writer) std::printf("wrote %s/film.mp4%s\n", request.out_dir.c_str(),
                            request.frames ? " and frames/" : "");
  }
  const std::string still = request.out_dir + "/max_tension.png";
  WriteMaxTensionPng(still, series, 1600, 900, "Maximum tension along the cable: " + scene.title,
                     request.shader_dir);
  std::printf("wrote %s\n", still.c_str());
  return finished;
}

}  // namespace cablefilm
