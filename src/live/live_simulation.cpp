#include "live/live_simulation.h"

#include <algorithm>
#include <cmath>

#include "core/step.h"
#include "io/result_files.h"
#include "run/initial_state.h"
#include "scene/build_model.h"
#include "scene/film_view.h"
#include "view/scene_view_builder.h"

namespace cablefilm {
namespace {

// The end whose period the controls show: the far end if it moves, else the start.
const EndMotion* DrivenEnd(const LineModel& m) {
  if (m.ends.end.moves()) return &m.ends.end;
  if (m.ends.start.moves()) return &m.ends.start;
  return nullptr;
}

}  // namespace

LiveSimulation::LiveSimulation(const SceneDef& scene, const CancelFlag* stop)
    : model_(BuildModel(scene)) {
  // The scene's own scheme and step rule; the output interval only bounds the implicit step.
  grid_ = ChooseTimeGrid(model_, scene.simulation, 1.0 / 30);
  if (!grid_.automatic) fixed_step_ = scene.simulation.time_step;
  scene_inputs_ = SceneInputs(model_);
  LineEquilibriumReport report;
  const State initial = MakeInitialState(scene, model_, &report, stop);
  if (const EndMotion* e = DrivenEnd(model_)) base_period_ = e->period();
  // The wave's phase is kept where the driven end is (else mid-way between the ends).
  const int last = model_.line.links;
  scene_inputs_.wave_phase_point = model_.ends.end.moves()     ? Vec(initial.x.col(last))
                                   : model_.ends.start.moves() ? Vec(initial.x.col(0))
                                                               : Vec(0.5 * (initial.x.col(0) +
                                                                            initial.x.col(last)));
  initial_ = MakeLineData(model_, scene_inputs_, grid_.options, initial);
  scene_sea_.period = base_period_;
  scene_sea_.current = model_.env.current;
  // The scene's headings: waves.heading as it gives it; the current's from its direction
  // (current_heading, or that of [u, w]), in (-180, 180] degrees and rounded to 1e-9 of a
  // degree for the state (the round trip through a sine and a cosine leaves 120 as
  // 120.00000000000001; the current itself turns from the direction's own angle).
  scene_sea_.current_heading =
      std::round(HeadingOf(model_.env.current_direction) / kDegree * 1e9) / 1e9;
  scene_sea_.wave_heading = model_.has_waves() ? scene.waves.heading : 0.0;
  scene_sea_.wave_height = model_.has_waves() ? model_.env.wave.spec.height : 0.0;
  scene_sea_.wave_period = model_.has_waves() ? model_.env.wave.spec.period : 0.0;
  end_follows_wave_ = (model_.ends.end.moves() && scene.end.follows_wave) ||
                      (!model_.ends.end.moves() && model_.ends.start.moves() &&
                       scene.start.follows_wave);
  Restart();
}

void LiveSimulation::Restart() {
  data_ = initial_;  // a complete checkpoint: the scheme's memory starts afresh with it
  inputs_ = scene_inputs_;
}

SeaTargets LiveSimulation::targets() const {
  SeaTargets s;
  SeaTargetsOf(inputs_, &s);
  s.amplitude_scale = inputs_.end_scale.target();
  s.period = has_driven_end() ? base_period_ / inputs_.end_clock.target() : 0;
  return s;
}

double LiveSimulation::wave_height_now() const { return inputs_.wave_height.ValueAt(t()); }
double LiveSimulation::wave_period_now() const { return inputs_.wave_period.ValueAt(t()); }

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
  if (!model_.has_waves() || !(height >= 0)) return false;
  return RampWaveHeight(inputs_, t(), height, data_.water.wave.spec.period);
}

bool LiveSimulation::SetWavePeriod(double period) {
  if (!model_.has_waves() || !(period > 0)) return false;
  double ramp = 0;
  if (!RampWavePeriod(inputs_, t(), period, &ramp)) return false;
  // The end that follows the wave: the same ramp of its clock (its rate is base / period).
  if (end_follows_wave_ && has_driven_end())
    inputs_.end_clock.Change(t(), base_period_ / period, ramp);
  return true;
}

bool LiveSimulation::SetWaveHeading(double degrees) {
  if (!model_.has_waves()) return false;
  return RampWaveHeading(inputs_, t(), degrees);
}

void LiveSimulation::Advance(double seconds) {
  if (!(seconds > 0)) return;
  const int steps =
      fixed_step_ > 0 ? std::max(1, static_cast<int>(std::ceil(seconds / fixed_step_ - 1e-9))) : 1;
  const double dt = seconds / steps;
  const double t0 = t();
  for (int i = 0; i < steps; ++i) {
    StepLine(model_, data_, inputs_, dt);
    data_.state.t = t0 + (i + 1) * dt;  // no round-off drift
  }
  RetireRamps(inputs_, t());
}

SceneView LiveSimulation::MakeView(const SceneDef& scene, const std::string& view) const {
  return MakeSceneView(scene, model_,
                       {MakeLineView(scene, model_, initial_state().x, initial_tensions(), "")},
                       DrawsInSpace(scene, view));
}

void LiveSimulation::TakeSnapshot(Snapshot* snapshot) const {
  snapshot->t = t();
  snapshot->lines.resize(1);
  SetLineState(state().x, tensions(), &snapshot->lines[0]);
  snapshot->current = TopCurrent(model_, water());
}

std::string LiveSimulation::timeseries_header() const { return kTimeseriesHeader; }

void LiveSimulation::WriteTimeseriesRow(std::FILE* file) {
  cablefilm::WriteTimeseriesRow(file, model_, data_, inputs_, row_ends_);
}

}  // namespace cablefilm
