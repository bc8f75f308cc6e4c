#include "view/scene_view_builder.h"

#include <utility>

#include "view/snapshot.h"

namespace cablefilm {

LineView MakeLineView(const SceneDef& scene, const std::vector<SectionDef>& sections,
                      const LineModel& model, const Points& initial_x,
                      const Eigen::VectorXd& initial_tension, std::string label) {
  const Line& line = model.line;
  LineView view;
  view.label = std::move(label);
  view.arc_length.assign(line.arc_length.data(), line.arc_length.data() + line.arc_length.size());
  view.section_boundaries = line.section_boundaries;
  // Each section by its material's name, when every section has one (the model keeps one
  // boundary between each two sections, so the counts agree).
  for (const SectionDef& section : sections) {
    const bool named = section.material >= 0 &&
                       static_cast<std::size_t>(section.material) < scene.materials.size() &&
                       !scene.materials[section.material].name.empty();
    if (!named) {
      view.section_names.clear();
      break;
    }
    view.section_names.push_back(scene.materials[section.material].name);
  }
  if (view.section_names.size() != view.section_boundaries.size() + 1) view.section_names.clear();
  view.marks.weights = line.weight_stations;
  for (int j : {0, line.links}) {  // each end by its role in the scene
    if (model.end_motion(j).moves()) view.marks.moving_ends.push_back(j);
    if (model.end_motion(j).kind() == EndKind::kFixed) view.marks.fixed_ends.push_back(j);
    if (model.end_motion(j).kind() == EndKind::kFree) view.marks.free_ends.push_back(j);
  }
  SetLineState(initial_x, initial_tension, &view.reference);
  view.breaking_load = SingleBreakingLoad(line.breaking_load);
  return view;
}

Vec TopCurrent(const LineModel& model, const Water& water) {
  const CurrentProfile& profile = model.env.current_profile;
  const double top = model.has_waves()  ? model.env.wave.spec.surface_y
                     : profile.empty() ? 0.0
                                       : profile.y.back();
  return CurrentAt(model, water, top);
}

SceneView MakeSceneView(const SceneDef& scene, const LineModel& model, std::vector<LineView> lines,
                        bool space) {
  SceneView view;
  view.title = scene.title;
  view.lines = std::move(lines);
  if (scene.initial == InitialStateKind::kStraight) view.reference_label = kStraightStateLabel;
  if (model.env.seabed.present) {
    view.sea.seabed = true;
    view.sea.seabed_y = model.env.seabed.y;
  }
  view.sea.surface = model.has_waves();
  const Vec current = TopCurrent(model, SceneWater(model));
  view.sea.current = {current.x(), current.y(), current.z()};
  view.sea.current_profile = !model.env.current_profile.empty();
  view.space = space;
  return view;
}

}  // namespace cablefilm
