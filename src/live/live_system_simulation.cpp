#include "live/live_system_simulation.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/step.h"
#include "live/sea_ramps.h"
#include "scene/build_model.h"
#include "view/scene_view_builder.h"
#include "view/system_film.h"

namespace cablefilm {
namespace {

// A name as a CSV column takes it: no comma, quote or space to split it.
std::string ColumnName(const std::string& name) {
  std::string s = name;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') c = '_';
  return s;
}

// The vessel's points: those with a motion of their own and those of a driven or held body.
std::vector<int> CarriedPoints(const Model& sys) {
  std::vector<int> carried;
  for (int p = 0; p < static_cast<int>(sys.points.size()); ++p) {
    const Point& point = sys.points[p];
    const bool on_vessel = point.on_body >= 0 && sys.bodies[point.on_body].kind != BodyKind::kFree;
    if (point.kind == PointKind::kMoved || on_vessel) carried.push_back(p);
  }
  return carried;
}

}  // namespace

LiveSystemSimulation::LiveSystemSimulation(const SceneDef& scene, const CancelFlag* stop)
    : run_(PrepareSystemRun(scene, BuildSystem(scene), stop)), loads_(run_.sys) {
  Model& sys = run_.sys;
  carried_ = CarriedPoints(sys);
  // The offset moves the carried points' line ends (and the points as the system keeps them);
  // at zero offset they move exactly as before: the initial state stays the run's.
  Vec centre = Vec::Zero();
  for (int p : carried_) {
    Point& point = sys.points[p];
    point.motion = point.motion.Carried();
    for (const LineEnd& e : point.ends) {
      Ends& ends = sys.lines[e.line].ends;
      EndMotion& m = e.station == 0 ? ends.start : ends.end;
      m = m.Carried();
    }
    centre += point.motion.rest();
  }
  for (const BodySpec& b : sys.bodies) scene_forces_.push_back(b.force);
  scene_inputs_ = run_.inputs;
  scene_inputs_.stop = nullptr;
  // A change of the waves keeps their phase at the vessel (its points' middle), else at the
  // first free body, else at the origin.
  if (!carried_.empty())
    scene_inputs_.wave_phase_point = centre / static_cast<double>(carried_.size());
  else if (!sys.free_bodies.empty())
    scene_inputs_.wave_phase_point = sys.body_poses[sys.free_bodies.front()].head<3>();
  const LineModel& m = model();
  scene_sea_.period = 0;
  scene_sea_.current = m.env.current;
  // As a line's (live_simulation.cpp): rounded to 1e-9 of a degree for the state.
  scene_sea_.current_heading = std::round(HeadingOf(m.env.current_direction) / kDegree * 1e9) / 1e9;
  scene_sea_.wave_heading = m.has_waves() ? scene.waves.heading : 0.0;
  scene_sea_.wave_height = m.has_waves() ? m.env.wave.spec.height : 0.0;
  scene_sea_.wave_period = m.has_waves() ? m.env.wave.spec.period : 0.0;
  Restart();
}

void LiveSystemSimulation::Restart() {
  data_ = run_.initial;  // a complete checkpoint, as a run's first row
  inputs_ = scene_inputs_;
  force_x_ = force_z_ = SmoothSchedule(0);
  for (std::size_t b = 0; b < scene_forces_.size(); ++b) run_.sys.bodies[b].force = scene_forces_[b];
}

void LiveSystemSimulation::Advance(double seconds) {
  if (!(seconds > 0)) return;
  const TimeGrid& g = run_.grid;
  const double step = g.automatic ? g.interval : g.dt;
  const int steps = std::max(1, static_cast<int>(std::ceil(seconds / step - 1e-9)));
  // The free bodies' extra force, held over the span at its middle (as the step holds the
  // current); exactly the scene's force while none is asked (adding zero).
  const double mid = t() + 0.5 * seconds;
  const Vec extra(force_x_.ValueAt(mid), 0.0, force_z_.ValueAt(mid));
  for (int b : run_.sys.free_bodies) run_.sys.bodies[b].force = scene_forces_[b] + extra;
  StepSpan(run_.sys, data_, inputs_, seconds, steps);
  RetireRamps(inputs_, t());
  force_x_.Retire(t());
  force_z_.Retire(t());
}

bool LiveSystemSimulation::SetCurrent(double current) {
  return RampCurrent(inputs_, t(), current);
}

bool LiveSystemSimulation::SetCurrentHeading(double degrees) {
  return RampCurrentHeading(inputs_, t(), degrees);
}

bool LiveSystemSimulation::SetWaveHeight(double height) {
  if (!model().has_waves() || !(height >= 0)) return false;
  return RampWaveHeight(inputs_, t(), height, wave().spec.period);
}

bool LiveSystemSimulation::SetWavePeriod(double period) {
  if (!model().has_waves() || !(period > 0)) return false;
  return RampWavePeriod(inputs_, t(), period);
}

bool LiveSystemSimulation::SetWaveHeading(double degrees) {
  if (!model().has_waves()) return false;
  return RampWaveHeading(inputs_, t(), degrees);
}

bool LiveSystemSimulation::ChangeOffset(SmoothSchedule& s, double metres) {
  if (!has_vessel() || !std::isfinite(metres)) return false;
  // The smootherstep's fastest rate is 15/8 of the mean: a long move takes longer.
  const double ramp = std::max(kOffsetRamp, 1.875 * std::abs(metres - s.target()) / kOffsetSpeed);
  return s.Change(t(), metres, ramp);
}

bool LiveSystemSimulation::SetOffsetX(double metres) { return ChangeOffset(inputs_.offset_x, metres); }
bool LiveSystemSimulation::SetOffsetZ(double metres) { return ChangeOffset(inputs_.offset_z, metres); }

SeaTargets LiveSystemSimulation::targets() const {
  SeaTargets s;
  SeaTargetsOf(inputs_, &s);
  s.force_x = force_x_.target();
  s.force_z = force_z_.target();
  return s;
}

Vec LiveSystemSimulation::offset_now() const {
  return Vec(inputs_.offset_x.ValueAt(t()), 0.0, inputs_.offset_z.ValueAt(t()));
}

double LiveSystemSimulation::offset_max() const {
  double shortest = run_.sys.lines.front().line.total_length();
  for (const LineModel& m : run_.sys.lines) shortest = std::min(shortest, m.line.total_length());
  return 0.1 * shortest;
}

bool LiveSystemSimulation::SetForceX(double newtons) {
  if (!has_free_body() || !std::isfinite(newtons)) return false;
  return force_x_.Change(t(), newtons, kForceRamp);
}

bool LiveSystemSimulation::SetForceZ(double newtons) {
  if (!has_free_body() || !std::isfinite(newtons)) return false;
  return force_z_.Change(t(), newtons, kForceRamp);
}

Vec LiveSystemSimulation::force_now() const {
  return Vec(force_x_.ValueAt(t()), 0.0, force_z_.ValueAt(t()));
}

double LiveSystemSimulation::force_max() const {
  double sum = 0;
  for (const LineData& d : run_.initial.lines) sum += d.tension().maxCoeff();
  return sum;
}

SceneView LiveSystemSimulation::MakeView(const SceneDef& scene, const std::string& view) const {
  return MakeSystemFilmScene(scene, run_, view);  // every line, named, its points marked
}

void LiveSystemSimulation::TakeSnapshot(Snapshot* snapshot) const {
  snapshot->t = t();
  snapshot->lines.resize(data_.lines.size());
  for (std::size_t i = 0; i < data_.lines.size(); ++i)
    SetLineState(data_.lines[i].state.x, data_.lines[i].tension(), &snapshot->lines[i]);
  snapshot->current = TopCurrent(model(), data_.lines.front().water);
}

const PointLoads& LiveSystemSimulation::point_loads() {
  loads_.Compute(run_.sys, data_, inputs_);
  return loads_;
}

std::string LiveSystemSimulation::timeseries_header() const {
  std::string h = "t,current,current_heading,offset_x,offset_z,force_x,force_z";
  for (const std::string& n : run_.sys.line_names)
    h += ",tension_max_" + ColumnName(n) + ",link_max_" + ColumnName(n);
  for (const Point& p : run_.sys.points)
    for (const char* c : {"x_", "y_", "z_", "fx_", "fy_", "fz_"}) h += "," + (c + ColumnName(p.name));
  return h + "\n";
}

void LiveSystemSimulation::WriteTimeseriesRow(std::FILE* f) {
  const Vec offset = offset_now();
  const Vec force = force_now();
  std::fprintf(f, "%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g", t(), current_now(),
               current_heading_now(), offset.x(), offset.z(), force.x(), force.z());
  for (const LineData& d : data_.lines) {
    Eigen::Index link = 0;
    const double max = d.tension().maxCoeff(&link);
    std::fprintf(f, ",%.10g,%d", max, static_cast<int>(link));
  }
  const PointLoads& loads = point_loads();
  for (Eigen::Index p = 0; p < loads.positions().cols(); ++p) {
    const auto x = loads.positions().col(p);
    const auto F = loads.forces().col(p);
    std::fprintf(f, ",%.12g,%.12g,%.12g,%.10g,%.10g,%.10g", x[0], x[1], x[2], F[0], F[1], F[2]);
  }
  std::fputc('\n', f);
}

}  // namespace cablefilm
