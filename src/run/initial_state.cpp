#include "run/initial_state.h"

#include <algorithm>
#include <cmath>

#include "core/cancel.h"
#include "core/error.h"
#include "scene/key_source.h"
#include "scene/scene_limits.h"
#include "scene/text_escape.h"

namespace cablefilm {
namespace {

// The integrators call a link stretched beyond kMaxStartStretch times its rest length a
// numerical blow-up. A static equilibrium that stretches one that far (the line's own load on
// too soft a material, or too heavy a weight: issue 22 item 5) was found by `check`, which then
// said ok, and `run` stopped at t = 0 with a blow-up that named no key. Refused here, where both
// make the initial state, naming the key at fault: the heaviest weight's mass when the weights
// weigh more than the cable in the fluid and the cable alone would not stretch the link that
// far, else the stretched link's material's youngs_modulus (of a MoorDyn file: the row and
// column it came from, KeyPlace).
// `line` is the line's key ("cable", "line[i]": keys cable.weight[k]), `which` " of line[i]
// (\"its name\")" in a scene of several lines, else "".
void CheckInitialStretch(const SceneDef& scene, const std::string& line, const std::string& which,
                         const std::vector<SectionDef>& sections,
                         const std::vector<WeightDef>& weights, const LineModel& m, const State& s) {
  if (m.line.law != LinkLaw::kElastic) return;
  int worst = -1;
  double stretch = 0;
  for (int j = 0; j < m.line.links; ++j) {
    const double ratio = (s.x.col(j + 1) - s.x.col(j)).norm() / m.line.rest_length[j];
    if (!(ratio <= stretch)) {  // NaN too
      stretch = ratio;
      worst = j;
    }
  }
  if (worst < 0 || stretch <= kMaxStartStretch) return;
  const double g = scene.environment.gravity, rho = scene.environment.fluid_density;
  double weights_net = 0, heaviest_weight = 0;  // [N]
  int heaviest = -1;
  for (std::size_t k = 0; k < weights.size(); ++k) {
    const double w = (weights[k].mass - rho * weights[k].volume) * g;
    weights_net += std::max(0.0, w);
    if (w > heaviest_weight) {
      heaviest_weight = w;
      heaviest = static_cast<int>(k);
    }
  }
  const double cable = std::max(0.0, m.line.link_net_weight.sum());
  const int section = m.line.link_section[static_cast<std::size_t>(worst)];
  const int material_index = sections[static_cast<std::size_t>(section)].material;
  const MaterialDef& material = scene.materials[static_cast<std::size_t>(material_index)];
  const std::string modulus_key = "material[" + std::to_string(material_index) + "].youngs_modulus";
  const double ea = m.line.axial_stiffness[worst];
  // A MoorDyn file names its stiffness by its row's EA, the scene by the modulus.
  const std::string modulus =
      scene.sources.count(modulus_key)
          ? KeyName(scene, modulus_key) + " = " + FormatNumber(ea) + " N of " +
                QuoteText(material.name)
          : modulus_key + " = " + FormatNumber(material.youngs_modulus) + " Pa of " +
                QuoteText(material.name);
  const std::string start = scene.initial == InitialStateKind::kEquilibrium
                                ? "the static equilibrium at t = 0"
                                : "the straight start at t = 0";
  // The weights are at fault when they outweigh the cable and the cable's own net weight, hung
  // from this link, would not stretch it past the limit.
  const bool weights_at_fault =
      heaviest >= 0 && weights_net > cable && 1.0 + cable / ea <= kMaxStartStretch;
  std::string key, cure;
  if (weights_at_fault) {
    key = line + ".weight[" + std::to_string(heaviest) + "].mass";
    cure = "a lighter weight (" + KeyName(scene, key) + " = " +
           FormatNumber(weights[static_cast<std::size_t>(heaviest)].mass) +
           " kg, its net weight " + FormatNumber(heaviest_weight) + " N) or a stiffer material (" +
           modulus + ")";
  } else {
    key = modulus_key;
    cure = "a stiffer material (" + modulus + ") or a lighter load";
  }
  throw Error(KeyPlace(scene, key) + ": " + start + " stretches link " +
              std::to_string(worst) + " (stations " + std::to_string(worst) + "-" +
              std::to_string(worst + 1) + ", section " + std::to_string(section) + ")" + which +
              " to " +
              FormatNumber(stretch) + " times its rest length under its load (tension " +
              FormatNumber(ea * (stretch - 1.0)) + " N, EA = " + FormatNumber(ea) +
              " N); expected at most " + FormatNumber(kMaxStartStretch) +
              " times (beyond it Hooke's law has no meaning and the run stops as a numerical "
              "blow-up): " + cure);
}

}  // namespace

std::vector<State> MakeInitialState(const SceneDef& scene, Model& model, const TimeGrid& grid,
                                    EquilibriumReport* report, const CancelFlag* cancel,
                                    const StaticsCallbacks& progress) {
  std::vector<State> states;
  EquilibriumReport r;
  if (scene.initial == InitialStateKind::kEquilibrium) {
    EquilibriumOptions options;
    options.cancel = cancel;
    options.relaxing = progress.relaxing;
    options.solving = progress.solving;
    options.relaxation = grid.options;
    options.inputs = SceneInputs(model);
    options.inputs.stop = cancel;
    try {
      states = SolveEquilibrium(model, &r, options);
    } catch (const CancelledError&) {
      throw;
    } catch (const Error& e) {
      if (scene.from_moordyn) throw;
      throw Error(std::string(e.what()) +
                  "; [initial] state = \"straight\" starts it from the chord instead");
    }
    // A free body given an initial offset starts there, its lines in equilibrium with it held
    // (a decay test); the others at their equilibrium.
    Model held = model;
    bool offset = false;
    for (int b : model.free_bodies) {
      const Vec6 start = r.body_poses[b] + model.bodies[b].initial_offset;
      PlaceBody(model, b, start);
      if (model.bodies[b].initial_offset == Vec6::Zero()) continue;
      held = HoldBody(held, b, start);
      offset = true;
    }
    if (offset) {
      EquilibriumOptions held_options;
      held_options.cancel = cancel;
      try {
        states = SolveEquilibrium(held, nullptr, held_options);
      } catch (const CancelledError&) {
        throw;
      } catch (const Error& e) {
        throw Error(scene.path + ": with the bodies at their initial offsets: " + e.what());
      }
    }
  } else {
    states = StraightStart(model);
  }
  for (std::size_t i = 0; i < model.lines.size() && i < scene.lines.size(); ++i) {
    const LineDef& line = scene.lines[i];
    // A [[line]] is named (the material's key does not say which line it is), the [cable] not.
    const std::string which = line.key == "cable" ? ""
                              : " of " + KeyName(scene, line.key) + " (" +
                                    QuoteText(line.name) + ")";
    CheckInitialStretch(scene, line.key, which, line.sections, line.weights, model.lines[i], states[i]);
  }
  if (report) *report = r;
  return states;
}

}  // namespace cablefilm
