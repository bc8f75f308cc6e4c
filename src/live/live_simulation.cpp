#include "live/live_simulation.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "core/step.h"
#include "io/result_files.h"
#include "scene/build_model.h"
#include "view/film_pass.h"
#include "view/scene_view_builder.h"

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
std::vector<int> CarriedPoints(const Model& model) {
  std::vector<int> carried;
  for (int p = 0; p < static_cast<int>(model.points.size()); ++p) {
    const Point& point = model.points[p];
    const bool on_vessel =
        point.on_body >= 0 && model.bodies[point.on_body].kind != BodyKind::kFree;
    if (point.kind == PointKind::kMoved || on_vessel) carried.push_back(p);
  }
  return carried;
}

// The driven end whose period the controls show (a moving line end with a period: each line's
// far end before its start), and its point; null when none.
const EndMotion* DrivenEnd(const Model& model, int* point) {
  for (std::size_t i = 0; i < model.lines.size(); ++i)
    for (int e : {1, 0}) {
      const EndMotion& m = e == 1 ? model.lines[i].ends.end : model.lines[i].ends.start;
      if (!m.moves() || !(m.period() > 0)) continue;
      *point = model.line_points[i][e];
      return &m;
    }
  return nullptr;
}

}  // namespace

LiveSimulation::LiveSimulation(const SceneDef& scene, const CancelFlag* stop)
    : run_(PrepareRun(scene, BuildModel(scene), "live", stop)), loads_(run_.model),
      row_ends_(run_.model.lines.front()) {
  Model& model = run_.model;
  int driven_point = -1;
  if (const EndMotion* e = DrivenEnd(model, &driven_point)) {
    base_period_ = e->period();
    end_follows_wave_ = driven_point < static_cast<int>(scene.points.size()) &&
                        scene.points[driven_point].motion.follows_wave;
  }
  carried_ = CarriedPoints(model);
  // The offset moves the carried points' line ends (and the points as the model keeps them);
  // at zero offset they move exactly as before: the initial state stays the run's.
  Vec centre = Vec::Zero();
  for (int p : carried_) {
    Point& point = model.points[p];
    point.motion = point.motion.Carried();
    for (const LineEnd& e : point.ends) {
      Ends& ends = model.lines[e.line].ends;
      EndMotion& m = e.station == 0 ? ends.start : ends.end;
      m = m.Carried();
    }
    centre += point.motion.rest();
  }
  for (const BodySpec& b : model.bodies) scene_forces_.push_back(b.force);
  scene_inputs_ = run_.inputs;
  scene_inputs_.stop = nullptr;
  // A change of the waves keeps their phase at the vessel (its points' middle), else at the
  // first free body, else mid-way between the first line's ends.
  const State& first = run_.initial.lines.front().state;
  if (!carried_.empty())
    scene_inputs_.wave_phase_point = centre / static_cast<double>(carried_.size());
  else if (!model.free_bodies.empty())
    scene_inputs_.wave_phase_point = model.body_poses[model.free_bodies.front()].head<3>();
  else
    scene_inputs_.wave_phase_point = 0.5 * (first.x.col(0) + first.x.col(first.x.cols() - 1));
  const LineModel& m = model.lines.front();
  scene_sea_.period = base_period_;
  scene_sea_.current = m.env.current;
  // The scene's headings: waves.heading as it gives it; the current's from its direction
  // (current_heading, or that of [u, w]), in (-180, 180] degrees and rounded to 1e-9 of a
  // degree for the state (the round trip through a sine and a cosine leaves 120 as
  // 120.00000000000001; the current itself turns from the direction's own angle).
  scene_sea_.current_heading =
      std::round(HeadingOf(m.env.current_direction) / kDegree * 1e9) / 1e9;
  scene_sea_.wave_heading = m.has_waves() ? scene.waves.heading : 0.0;
  scene_sea_.wave_height = m.has_waves() ? m.env.wave.spec.height : 0.0;
  scene_sea_.wave_period = m.has_waves() ? m.env.wave.spec.period : 0.0;
  Restart();
}

void LiveSimulation::Restart() {
  data_ = run_.initial;  // a complete checkpoint, as a run's first row
  inputs_ = scene_inputs_;
  force_x_ = force_z_ = SmoothSchedule(0);
  for (std::size_t b = 0; b < scene_forces_.size(); ++b) run_.model.bodies[b].force = scene_forces_[b];
}

void LiveSimulation::Advance(double seconds) {
  if (!(seconds > 0)) return;
  const TimeGrid& g = run_.grid;
  const double step = g.automatic ? g.interval : g.dt;
  const int steps = std::max(1, static_cast<int>(std::ceil(seconds / step - 1e-9)));
  // The free bodies' extra force, held over the span at its middle (as the step holds the
  // current); exactly the scene's force while none is asked (adding zero).
  const double mid = t() + 0.5 * seconds;
  const Vec extra(force_x_.ValueAt(mid), 0.0, force_z_.ValueAt(mid));
  for (int b : run_.model.free_bodies) run_.model.bodies[b].force = scene_forces_[b] + extra;
  StepSpan(run_.model, data_, inputs_, seconds, steps);
  RetireRamps(inputs_, t());
  force_x_.Retire(t());
  force_z_.Retire(t());
}

double LiveSimulation::MotionRamp() const {
  // One period of the motion as it is now: the change takes a cycle, as a ship's would.
  const double period = base_period_ / inputs_.end_clock.ValueAt(t());
  return std::clamp(period, kMotionRamp, 30.0);
}

bool LiveSimulation::SetAmplitudeScale(double scale) {
  if (!has_driven_end()) return false;
  return inputs_.end_scale.Change(t(), scale, MotionRamp());
}

bool LiveSimulation::SetPeriod(double period) {
  if (!has_driven_end() || !(period > 0)) return false;
  return inputs_.end_clock.Change(t(), base_period_ / period, MotionRamp());
}

bool LiveSimulation::SetCurrent(double current) { return RampCurrent(inputs_, t(), current); }

bool LiveSimulation::SetCurrentHeading(double degrees) {
  return RampCurrentHeading(inputs_, t(), degrees);
}

bool LiveSimulation::SetWaveHeight(double height) {
  if (!has_waves() || !(height >= 0)) return false;
  return RampWaveHeight(inputs_, t(), height, wave().spec.period);
}

bool LiveSimulation::SetWavePeriod(double period) {
  if (!has_waves() || !(period > 0)) return false;
  double ramp = 0;
  if (!RampWavePeriod(inputs_, t(), period, &ramp)) return false;
  // The end that follows the wave: the same ramp of its clock (its rate is base / period).
  if (end_follows_wave_ && has_driven_end())
    inputs_.end_clock.Change(t(), base_period_ / period, ramp);
  return true;
}

bool LiveSimulation::SetWaveHeading(double degrees) {
  if (!has_waves()) return false;
  return RampWaveHeading(inputs_, t(), degrees);
}

bool LiveSimulation::ChangeOffset(SmoothSchedule& s, double metres) {
  if (!has_vessel() || !std::isfinite(metres)) return false;
  // The smootherstep's fastest rate is 15/8 of the mean: a long move takes longer.
  const double ramp = std::max(kOffsetRamp, 1.875 * std::abs(metres - s.target()) / kOffsetSpeed);
  return s.Change(t(), metres, ramp);
}

bool LiveSimulation::SetOffsetX(double metres) { return ChangeOffset(inputs_.offset_x, metres); }
bool LiveSimulation::SetOffsetZ(double metres) { return ChangeOffset(inputs_.offset_z, metres); }

bool LiveSimulation::SetForceX(double newtons) {
  if (!has_free_body() || !std::isfinite(newtons)) return false;
  return force_x_.Change(t(), newtons, kForceRamp);
}

bool LiveSimulation::SetForceZ(double newtons) {
  if (!has_free_body() || !std::isfinite(newtons)) return false;
  return force_z_.Change(t(), newtons, kForceRamp);
}

SeaTargets LiveSimulation::targets() const {
  SeaTargets s;
  SeaTargetsOf(inputs_, &s);
  s.amplitude_scale = inputs_.end_scale.target();
  s.period = has_driven_end() ? base_period_ / inputs_.end_clock.target() : 0;
  s.force_x = force_x_.target();
  s.force_z = force_z_.target();
  return s;
}

double LiveSimulation::current_now() const {
  const CurrentHistory* h = model().lines.front().env.current_history.get();
  return inputs_.current.ValueAt(t()) * (h ? h->FactorAt(t()) : 1.0);
}
double LiveSimulation::current_heading_now() const {
  if (const CurrentHistory* h = model().lines.front().env.current_history.get())
    return h->HeadingAt(t()) / kDegree;
  return inputs_.current_heading.ValueAt(t()) / kDegree;
}
double LiveSimulation::wave_heading_now() const {
  return inputs_.wave_heading.ValueAt(t()) / kDegree;
}
double LiveSimulation::wave_height_now() const { return inputs_.wave_height.ValueAt(t()); }
double LiveSimulation::wave_period_now() const { return inputs_.wave_period.ValueAt(t()); }

Vec LiveSimulation::offset_now() const {
  return Vec(inputs_.offset_x.ValueAt(t()), 0.0, inputs_.offset_z.ValueAt(t()));
}

Vec LiveSimulation::force_now() const {
  return Vec(force_x_.ValueAt(t()), 0.0, force_z_.ValueAt(t()));
}

double LiveSimulation::offset_max() const {
  double shortest = model().lines.front().line.total_length();
  for (const LineModel& m : model().lines) shortest = std::min(shortest, m.line.total_length());
  return 0.1 * shortest;
}

double LiveSimulation::force_max() const {
  double sum = 0;
  for (const LineData& d : run_.initial.lines) sum += d.tension().maxCoeff();
  return sum;
}

const PointLoads& LiveSimulation::point_loads() {
  loads_.Compute(run_.model, data_, inputs_);
  return loads_;
}

SceneView LiveSimulation::MakeView(const SceneDef& scene, const std::string& view) const {
  SceneView v = MakeFilmScene(scene, {&run_}, view);  // a line alone unnamed: it needs no name
  if (v.lines.size() == 1) v.lines.front().label.clear();
  return v;
}

void LiveSimulation::TakeSnapshot(Snapshot* snapshot) const {
  snapshot->t = t();
  snapshot->lines.resize(data_.lines.size());
  for (std::size_t i = 0; i < data_.lines.size(); ++i)
    SetLineState(data_.lines[i].state.x, data_.lines[i].tension(), &snapshot->lines[i]);
  snapshot->current = TopCurrent(model().lines.front(), data_.lines.front().water);
}

std::string LiveSimulation::timeseries_header() const {
  if (line_count() == 1) return kTimeseriesHeader;
  std::string h = "t,current,current_heading,offset_x,offset_z,force_x,force_z";
  for (const std::string& n : model().line_names)
    h += ",tension_max_" + ColumnName(n) + ",link_max_" + ColumnName(n);
  for (const Point& p : model().points)
    for (const char* c : {"x_", "y_", "z_", "fx_", "fy_", "fz_"}) h += "," + (c + ColumnName(p.name));
  return h + "\n";
}

void LiveSimulation::WriteTimeseriesRow(std::FILE* f) {
  if (line_count() == 1) {
    cablefilm::WriteTimeseriesRow(f, model().lines.front(), data_.lines.front(), inputs_,
                                  row_ends_);
    return;
  }
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
