#include "app/material_summary.h"

#include <cstdio>

#include "scene/text_escape.h"

namespace cablefilm {

void PrintTangentialMaterials(const SceneDef& scene) {
  for (const MaterialDef& m : scene.materials) {
    if (m.tangential_drag_coefficient == 0 && m.tangential_added_mass_coefficient == 0) continue;
    std::printf("  material %s: along the line tangential_drag_coefficient %.4g (on pi d l), "
                "tangential_added_mass_coefficient %.4g\n",
                QuoteText(m.name).c_str(), m.tangential_drag_coefficient,
                m.tangential_added_mass_coefficient);
  }
}

}  // namespace cablefilm
