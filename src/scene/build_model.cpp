#include "scene/build_model.h"

#include <cmath>

#include "core/error.h"

namespace cablefilm {
namespace {

EndMotion MakeEndMotion(const EndDef& e) {
  const Vec rest(e.position[0], e.position[1], e.position[2]);
  switch (e.motion) {
    case EndMotionKind::kFixed:
      return EndMotion::Fixed(rest);
    case EndMotionKind::kFree:
      return EndMotion::Free(rest);
    case EndMotionKind::kTrochoid:
      return EndMotion::Trochoid(
          rest, Vec(e.x_amplitudes[0], e.y_amplitudes[0], e.z_amplitudes[0]),
          Vec(e.x_amplitudes[1], e.y_amplitudes[1], e.z_amplitudes[1]), 2.0 * M_PI / e.period,
          e.ramp_rate);
    case EndMotionKind::kTable: {
      std::vector<double> times;
      std::vector<Vec> offsets;
      for (const auto& r : e.table) {
        times.push_back(r[0]);
        offsets.emplace_back(r[1], r[2], r[3]);
      }
      return EndMotion::Table(rest, times, offsets);
    }
  }
  throw Error("unknown end motion");
}

}  // namespace

WaveSpec MakeWaveSpec(const SceneDef& scene) {
  WaveSpec w;
  const WavesDef& d = scene.waves;
  if (!d.present) return w;
  w.present = true;
  w.height = d.height;
  w.period = d.period;
  w.depth = d.depth;
  w.surface_y = d.surface_y;
  w.phase = d.phase * M_PI / 180.0;
  w.heading = d.heading * M_PI / 180.0;
  w.ramp_rate = d.ramp_rate;
  return w;
}

int StationAt(const SceneDef& scene, double arc_length) {
  int station = 0;
  double start = 0;
  for (const SectionDef& sec : scene.sections) {
    const double l = sec.length / sec.segments;
    const double k = std::round((arc_length - start) / l);
    if (k >= 0 && k <= sec.segments && std::abs(arc_length - start - k * l) <= 1e-6 * l)
      return station + static_cast<int>(k);
    station += sec.segments;
    start += sec.length;
  }
  throw Error(scene.path + ": a weight at " + std::to_string(arc_length) +
              " m is not on a station");
}

Model BuildModel(const SceneDef& scene) {
  std::vector<SectionSpec> sections;
  for (const SectionDef& def : scene.sections) {
    const MaterialDef& mat = scene.materials.at(def.material);
    SectionSpec s;
    s.length = def.length;
    s.segments = def.segments;
    s.diameter = mat.diameter;
    s.area = mat.area;
    s.mass_per_length = mat.mass_per_length;
    s.youngs_modulus = mat.youngs_modulus;
    s.drag_coefficient = mat.drag_coefficient;
    s.added_mass_coefficient = mat.added_mass_coefficient;
    s.axial_damping = mat.axial_damping;
    s.axial_damping_ratio = mat.axial_damping_ratio;
    sections.push_back(s);
  }
  std::vector<PrismSpec> prisms;
  for (const WeightDef& w : scene.weights) {
    PrismSpec p;
    p.station = StationAt(scene, w.at);
    p.mass = w.mass;
    p.volume = w.volume;
    p.added_volume = Vec(w.added_volume[0], w.added_volume[1], w.added_volume[2]);
    p.drag_coefficient = Vec(w.drag_coefficient[0], w.drag_coefficient[1], w.drag_coefficient[2]);
    p.drag_area = Vec(w.drag_area[0], w.drag_area[1], w.drag_area[2]);
    prisms.push_back(p);
  }
  EnvironmentSpec env;
  env.gravity = scene.environment.gravity;
  env.fluid_density = scene.environment.fluid_density;
  env.current = scene.environment.current;
  env.current_profile = scene.environment.current_profile;
  env.current_direction = scene.environment.current_direction;
  env.seabed = scene.seabed;
  env.waves = MakeWaveSpec(scene);
  const LinkLaw law =
      scene.model == CableModelKind::kElastic ? LinkLaw::kElastic : LinkLaw::kInextensible;
  return MakeModel(sections, prisms, env, MakeEndMotion(scene.start), MakeEndMotion(scene.end),
                   law);
}

}  // namespace cablefilm
