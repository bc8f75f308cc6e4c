#include "run/initial_state.h"

#include <algorithm>
#include <cmath>

#include "core/cancel.h"
#include "core/error.h"
#include "run/coarse_guess.h"
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
// far, else the stretched link's material's youngs_modulus.
// `line` is "" for the scene's one cable (keys cable.weight[k]), else "line[i]" (a system's),
// `which` then " of line[i] (\"its name\")".
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
  const std::string modulus = modulus_key + " = " + FormatNumber(material.youngs_modulus) +
                              " Pa of " + QuoteText(material.name);
  const double ea = m.line.axial_stiffness[worst];
  const std::string start = scene.initial == InitialStateKind::kEquilibrium
                                ? "the static equilibrium at t = 0"
                                : "the straight start at t = 0";
  // The weights are at fault when they outweigh the cable and the cable's own net weight, hung
  // from this link, would not stretch it past the limit.
  const bool weights_at_fault =
      heaviest >= 0 && weights_net > cable && 1.0 + cable / ea <= kMaxStartStretch;
  std::string key, cure;
  if (weights_at_fault) {
    key = (line.empty() ? "cable" : line) + ".weight[" + std::to_string(heaviest) + "].mass";
    cure = "a lighter weight (" + key + " = " +
           FormatNumber(weights[static_cast<std::size_t>(heaviest)].mass) +
           " kg, its net weight " + FormatNumber(heaviest_weight) + " N) or a stiffer material (" +
           modulus + ")";
  } else {
    key = modulus_key;
    cure = "a stiffer material (" + modulus + ") or a lighter load";
  }
  throw Error(EscapeText(scene.path) + ": " + key + ": " + start + " stretches link " +
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

void CheckSystemInitialStretch(const SceneDef& scene, const Model& sys,
                               const std::vector<State>& states) {
  for (std::size_t i = 0; i < sys.lines.size(); ++i)
    for (std::size_t k = 0; k < scene.lines.size(); ++k)
      if (scene.lines[k].name == sys.line_names[i]) {
        const std::string line = "line[" + std::to_string(k) + "]";
        CheckInitialStretch(scene, line, " of " + line + " (" + QuoteText(scene.lines[k].name) + ")",
                            scene.lines[k].sections, scene.lines[k].weights, sys.lines[i],
                            states[i]);
      }
}

State MakeInitialState(const SceneDef& scene, const LineModel& m, LineEquilibriumReport* report,
                       const CancelFlag* cancel) {
  LineEquilibriumOptions options;
  options.cancel = cancel;
  State s;
  if (scene.initial == InitialStateKind::kEquilibrium) {
    if (m.line.law == LinkLaw::kInextensible) {
      s = SolveInextensibleEquilibrium(m, report, cancel);
    } else {
      try {
        if (const std::optional<Points> guess = CoarseEquilibriumGuess(scene, m, cancel)) {
          // Near the answer, in the full current: Newton from it directly (the continuation
          // from still water only if that fails).
          options.warm_start = true;
          s = SolveLineEquilibrium(m, *guess, report, options);
        } else {
          s = SolveLineEquilibrium(m, report, options);
        }
      } catch (const CancelledError&) {
        throw;
      } catch (const Error& e) {
        // The way out a one-line scene has (a system of lines has none: it starts from its
        // equilibrium, scene_parser.cpp).
        throw Error(std::string(e.what()) +
                    "; [initial] state = \"straight\" starts it from the chord instead");
      }
    }
  } else {
    s.x = StraightChord(m);
    s.v = Points::Zero(kDim, m.stations());
  }
  CheckInitialStretch(scene, "", "", scene.sections, scene.weights, m, s);
  return s;
}

}  // namespace cablefilm
