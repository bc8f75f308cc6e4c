#include "scene/film_view.h"

#include <cmath>

#include "core/error.h"

namespace cablefilm {
namespace {

// A direction's sideways part: a heading of 180 degrees leaves sin(pi) ~ 1e-16 in z, which
// moves nothing anyone could see.
constexpr double kAcross = 1e-12;

bool EndIsPlanar(const EndDef& end) {
  if (end.position[2] != 0 || end.z_amplitudes[0] != 0 || end.z_amplitudes[1] != 0) return false;
  for (const auto& row : end.table)
    if (row[3] != 0) return false;
  return true;
}

// A driven body turning about x or y takes its points out of the plane z = 0; about z it keeps
// them in it.
bool BodyStaysInPlane(const BodyDef& b) {
  const EndDef& m = b.motion;
  for (const auto* a : {&m.rx_amplitudes, &m.ry_amplitudes})
    if ((*a)[0] != 0 || (*a)[1] != 0) return false;
  for (const auto& row : m.table)
    if (row[4] != 0 || row[5] != 0) return false;
  return true;
}

}  // namespace

const std::vector<std::string>& FilmViewNames() {
  static const std::vector<std::string> names{"auto", "2d", "3d"};
  return names;
}

bool SceneIsPlanar(const SceneDef& scene) {
  for (const PointDef& p : scene.points)  // where its lines' ends are
    if (!EndIsPlanar(p.motion) || p.force[2] != 0) return false;
  for (const BodyDef& b : scene.bodies)
    if (!b.free && !BodyStaysInPlane(b)) return false;
  const EnvironmentDef& env = scene.environment;
  const bool current = env.current != 0 || !env.current_profile.empty();
  if (current && std::fabs(env.current_direction.z()) > kAcross && !env.current_history)
    return false;
  if (current && env.current_history)  // every heading it turns to (linear between rows)
    for (double heading : env.current_history->heading)
      if (std::fabs(std::sin(heading)) > kAcross) return false;
  const WavesDef& w = scene.waves;
  if (w.present && w.height > 0 && std::fabs(std::sin(w.heading * M_PI / 180.0)) > kAcross)
    return false;
  return true;
}

bool DrawsInSpace(const SceneDef& scene, const std::string& view) {
  if (view == "3d") return true;
  if (view == "2d") return false;
  if (view == "auto") return !SceneIsPlanar(scene);
  throw Error("film.view: expected \"auto\", \"2d\" or \"3d\", got \"" + view + "\"");
}

}  // namespace cablefilm
