#include "core/cable_model.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace cablefilm {

CableModel BuildCableModel(const std::vector<SectionSpec>& sections,
                           const std::vector<PrismSpec>& prisms, const EnvironmentSpec& env,
                           EndMotion start, EndMotion end, LinkLaw law) {
  CableModel m;
  int s = 0;
  for (const SectionSpec& sec : sections) s += sec.segments;
  if (s < 1) throw Error("the cable has no links");
  m.links = s;
  m.gravity = env.gravity;
  m.fluid_density = env.fluid_density;
  m.current = env.current;
  m.law = law;
  m.start = std::move(start);
  m.end = std::move(end);

  const double rho = env.fluid_density, g = env.gravity;
  m.rest_length.resize(s);
  m.axial_stiffness.resize(s);
  m.virtual_mass.resize(s);
  m.drag_factor.resize(s);
  m.axial_damping = Eigen::VectorXd::Zero(s);
  m.link_mass.resize(s);
  m.link_net_weight.resize(s);
  m.link_section.resize(s);
  m.arc_length.resize(s + 1);
  m.arc_length[0] = 0;
  int j = 0;
  for (size_t k = 0; k < sections.size(); ++k) {
    const SectionSpec& sec = sections[k];
    const double l = sec.length / sec.segments;
    for (int i = 0; i < sec.segments; ++i, ++j) {
      m.rest_length[j] = l;
      m.axial_stiffness[j] = sec.area * sec.youngs_modulus;
      m.virtual_mass[j] = rho * sec.added_mass_coefficient * l * sec.area;
      m.drag_factor[j] = 0.5 * rho * sec.drag_coefficient * l * sec.diameter;
      m.axial_damping[j] = sec.axial_damping * sec.area / l;
      m.link_mass[j] = sec.mass_per_length * l;
      m.link_net_weight[j] = (sec.mass_per_length - rho * sec.area) * l * g;
      m.link_section[j] = static_cast<int>(k);
      // Accumulate by section so the boundaries fall exactly on the section lengths.
      m.arc_length[j + 1] = m.arc_length[j - i] + (i + 1) * l;
    }
    if (k + 1 < sections.size()) m.section_boundaries.push_back(m.arc_length[j]);
  }

  m.cable_mass = Eigen::VectorXd::Zero(s + 1);
  m.net_weight = Eigen::VectorXd::Zero(s + 1);
  for (int i = 0; i < s; ++i) {
    m.cable_mass[i] += 0.5 * m.link_mass[i];
    m.cable_mass[i + 1] += 0.5 * m.link_mass[i];
    m.net_weight[i] += 0.5 * m.link_net_weight[i];
    m.net_weight[i + 1] += 0.5 * m.link_net_weight[i];
  }
  m.prism_mass = Eigen::Matrix2Xd::Zero(2, s + 1);
  m.prism_drag = Eigen::Matrix2Xd::Zero(2, s + 1);
  for (const PrismSpec& p : prisms) {
    if (p.station < 0 || p.station > s)
      throw Error("weight at station " + std::to_string(p.station) + " is off the cable (0.." +
                  std::to_string(s) + ")");
    m.prism_mass.col(p.station) += Eigen::Vector2d::Constant(p.mass) + rho * p.added_volume;
    m.prism_drag.col(p.station) += 0.5 * rho * p.drag_coefficient.cwiseProduct(p.drag_area);
    m.net_weight[p.station] += (p.mass - rho * p.volume) * g;
    m.weight_stations.push_back(p.station);
  }
  // A damping ratio becomes a coefficient once the stations' masses are known (prisms too; the
  // normal added mass does not act along the link).
  j = 0;
  for (const SectionSpec& sec : sections) {
    for (int i = 0; i < sec.segments; ++i, ++j) {
      if (sec.axial_damping_ratio == 0) continue;
      const double ma = m.cable_mass[j] + m.prism_mass.col(j).minCoeff();
      const double mb = m.cable_mass[j + 1] + m.prism_mass.col(j + 1).minCoeff();
      const double k = m.axial_stiffness[j] / m.rest_length[j];  // [N/m]
      m.axial_damping[j] = 2.0 * sec.axial_damping_ratio * std::sqrt(k * ma * mb / (ma + mb));
    }
  }
  return m;
}

}  // namespace cablefilm
