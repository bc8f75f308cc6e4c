#include "core/line_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"

namespace cablefilm {

LineModel MakeLineModel(const std::vector<SectionSpec>& sections, const std::vector<PrismSpec>& prisms,
                const EnvironmentSpec& env, EndMotion start, EndMotion end, LinkLaw law) {
  LineModel model;
  Line& m = model.line;
  Environment& e = model.env;
  int s = 0;
  for (const SectionSpec& sec : sections) s += sec.segments;
  if (s < 1) throw Error("the cable has no links");
  m.links = s;
  e.gravity = env.gravity;
  e.fluid_density = env.fluid_density;
  e.current = env.current;
  e.current_profile = env.current_profile;
  e.current_direction = env.current_direction;
  e.current_history = env.current_history;
  if (e.current_profile.y.size() != e.current_profile.speed.size())
    throw Error("the current profile has " + std::to_string(e.current_profile.y.size()) +
                " elevations but " + std::to_string(e.current_profile.speed.size()) + " speeds");
  for (size_t i = 1; i < e.current_profile.y.size(); ++i)
    if (!(e.current_profile.y[i] > e.current_profile.y[i - 1]))
      throw Error("the current profile's elevations must increase strictly");
  e.seabed = env.seabed;
  m.law = law;
  model.ends.start = std::move(start);
  model.ends.end = std::move(end);

  const double rho = env.fluid_density, g = env.gravity;
  m.rest_length.resize(s);
  m.axial_stiffness.resize(s);
  m.virtual_mass.resize(s);
  m.drag_factor.resize(s);
  m.tangential_virtual_mass.resize(s);
  m.tangential_drag_factor.resize(s);
  m.axial_damping = Eigen::VectorXd::Zero(s);
  m.link_mass.resize(s);
  m.link_net_weight.resize(s);
  m.link_section.resize(s);
  m.breaking_load.resize(s);
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
      // Along the link: the drag on its wetted surface pi d l, the added mass on its volume.
      m.tangential_virtual_mass[j] = rho * sec.tangential_added_mass_coefficient * l * sec.area;
      m.tangential_drag_factor[j] =
          0.5 * rho * sec.tangential_drag_coefficient * M_PI * sec.diameter * l;
      m.axial_damping[j] = sec.axial_damping * sec.area / l;
      m.link_mass[j] = sec.mass_per_length * l;
      m.link_net_weight[j] = (sec.mass_per_length - rho * sec.area) * l * g;
      m.link_section[j] = static_cast<int>(k);
      m.breaking_load[j] = sec.minimum_breaking_load;
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
  m.prism_mass = Points::Zero(kDim, s + 1);
  m.prism_drag = Points::Zero(kDim, s + 1);
  m.prism_force = Points::Zero(kDim, s + 1);
  for (const PrismSpec& p : prisms) {
    if (p.station < 0 || p.station > s)
      throw Error("weight at station " + std::to_string(p.station) + " is off the cable (0.." +
                  std::to_string(s) + ")");
    m.prism_mass.col(p.station) += Vec::Constant(p.mass) + rho * p.added_volume;
    m.prism_drag.col(p.station) += 0.5 * rho * p.drag_coefficient.cwiseProduct(p.drag_area);
    m.prism_force.col(p.station) += p.force;
    m.net_weight[p.station] += (p.mass - rho * p.volume) * g;
    m.weight_stations.push_back(p.station);
  }
  // Each station once: several weights on one station add up in the sums above, and the force
  // loops over weight_stations must count them once.
  std::sort(m.weight_stations.begin(), m.weight_stations.end());
  m.weight_stations.erase(std::unique(m.weight_stations.begin(), m.weight_stations.end()),
                          m.weight_stations.end());
  // A damping ratio becomes a coefficient once the stations' masses are known (prisms too; the
  // normal added mass does not act along the link, and the tangential one is left out as
  // MoorDyn's negative BA leaves it out: its c uses the line's own mass).
  j = 0;
  for (const SectionSpec& sec : sections) {
    for (int i = 0; i < sec.segments; ++i, ++j) {
      if (sec.moordyn_axial_damping_ratio > 0) {
        // MoorDyn's BA = zeta l sqrt(EA mu) [N s], whose tension BA (dL/dt) / l is c dL/dt.
        m.axial_damping[j] =
            sec.moordyn_axial_damping_ratio * std::sqrt(m.axial_stiffness[j] * sec.mass_per_length);
        continue;
      }
      if (sec.axial_damping_ratio == 0) continue;
      const double ma = m.cable_mass[j] + m.prism_mass.col(j).minCoeff();
      const double mb = m.cable_mass[j + 1] + m.prism_mass.col(j + 1).minCoeff();
      const double k = m.axial_stiffness[j] / m.rest_length[j];  // [N/m]
      m.axial_damping[j] = 2.0 * sec.axial_damping_ratio * std::sqrt(k * ma * mb / (ma + mb));
    }
  }
  if (e.seabed.present) {
    // Each station's share of the line, half of each adjoining link, carries the bed's
    // stiffness and damping per unit length. The default damping is critical for the station
    // on its spring with its inertia across a line lying flat (its mass, the prism's m^y and
    // half the normal added mass of each link).
    m.seabed_stiffness = Eigen::VectorXd::Zero(s + 1);
    m.seabed_damping = Eigen::VectorXd::Zero(s + 1);
    m.friction_stiffness = Eigen::VectorXd::Zero(s + 1);
    m.friction_damping = Eigen::VectorXd::Zero(s + 1);
    // The shear spring is the normal one unless the scene gives its own; its dashpot keeps the
    // normal dashpot's ratio to critical (sqrt(K / k) times c_j).
    const double shear = e.seabed.shear_stiffness();  // K [N/m^2]
    m.seabed_rest_depth = Eigen::VectorXd::Zero(s + 1);
    m.seabed_landing_time = Eigen::VectorXd::Zero(s + 1);
    for (int i = 0; i <= s; ++i) {
      double share = 0, added = 0;
      for (int k = i - 1; k <= i; ++k) {
        if (k < 0 || k >= s) continue;
        share += 0.5 * m.rest_length[k];
        added += 0.5 * m.virtual_mass[k];
      }
      m.seabed_stiffness[i] = e.seabed.stiffness * share;
      const double mass = m.cable_mass[i] + m.prism_mass(1, i) + added;
      m.seabed_damping[i] = e.seabed.damping >= 0
                                ? e.seabed.damping * share
                                : 2.0 * std::sqrt(m.seabed_stiffness[i] * mass);
      m.friction_stiffness[i] = shear * share;
      m.friction_damping[i] = m.seabed_damping[i] * std::sqrt(shear / e.seabed.stiffness);
      m.seabed_rest_depth[i] = std::max(std::abs(m.net_weight[i]) / m.seabed_stiffness[i], 1e-9);
      const bool critical = m.seabed_damping[i] >= 2.0 * std::sqrt(m.seabed_stiffness[i] * mass);
      m.seabed_landing_time[i] = critical ? std::sqrt(mass / m.seabed_stiffness[i])
                                          : std::numeric_limits<double>::infinity();
    }
  }
  if (env.waves.present) {
    e.wave = MakeWave(env.waves, g);
    m.station_buoyancy = Eigen::VectorXd::Zero(s + 1);
    m.wet_band = Eigen::VectorXd::Zero(s + 1);
    m.link_fluid_mass.resize(s);
    m.link_axial_fluid_mass.resize(s);
    j = 0;
    for (const SectionSpec& sec : sections) {
      for (int i = 0; i < sec.segments; ++i, ++j) {
        const double l = m.rest_length[j], displaced = rho * sec.area * l;  // [kg]
        m.link_fluid_mass[j] = displaced + m.virtual_mass[j];
        m.link_axial_fluid_mass[j] = sec.axial_froude_krylov
                                         ? displaced + m.tangential_virtual_mass[j]
                                         : m.tangential_virtual_mass[j];
        for (int st : {j, j + 1}) {
          m.station_buoyancy[st] += 0.5 * displaced * g;
          m.wet_band[st] += 0.5 * l;
        }
      }
    }
    m.prism_added_mass = Points::Zero(kDim, s + 1);
    m.prism_fluid_mass = Points::Zero(kDim, s + 1);
    for (const PrismSpec& p : prisms) {
      m.prism_added_mass.col(p.station) += rho * p.added_volume;
      m.prism_fluid_mass.col(p.station) +=
          rho * (p.added_volume + Vec::Constant(p.volume));
      m.station_buoyancy[p.station] += rho * p.volume * g;
    }
  }
  return model;
}

}  // namespace cablefilm
