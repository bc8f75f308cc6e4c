#include "view/snapshot.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace cablefilm {
namespace {

std::string At(std::size_t line, double t) {
  return "line " + std::to_string(line + 1) + " at t = " + std::to_string(t) + " s";
}

// stations_of(i): the stations of line i (a function, so that no list is made per frame).
template <class StationsOf>
void CheckSizes(const Snapshot& s, std::size_t lines, StationsOf stations_of) {
  if (s.lines.size() != lines)
    throw Error("frame: the snapshot at t = " + std::to_string(s.t) + " s has " +
                std::to_string(s.lines.size()) + (s.lines.size() == 1 ? " line" : " lines") +
                "; the scene has " + std::to_string(lines));
  for (std::size_t i = 0; i < lines; ++i) {
    const LineSnapshot& l = s.lines[i];
    const std::size_t n = stations_of(i);
    if (l.x.size() != n || l.y.size() != n || (!l.z.empty() && l.z.size() != n) ||
        l.tension.size() + 1 != n)
      throw Error("frame: " + At(i, s.t) + " has " + std::to_string(l.x.size()) + " x, " +
                  std::to_string(l.y.size()) + " y and " + std::to_string(l.tension.size()) +
                  " tensions; it has " + std::to_string(n) + " stations and " +
                  std::to_string(n - 1) + " links");
    if (l.row_max.size() != s.row_t.size())
      throw Error("frame: " + At(i, s.t) + " carries " + std::to_string(l.row_max.size()) +
                  " row maxima for " + std::to_string(s.row_t.size()) + " row times");
    const bool envelope = !l.row_link_min.empty() || !l.row_link_max.empty();
    if (envelope && (l.row_link_min.size() + 1 != n || l.row_link_max.size() + 1 != n))
      throw Error("frame: " + At(i, s.t) + " carries a row envelope of " +
                  std::to_string(l.row_link_min.size()) + " and " +
                  std::to_string(l.row_link_max.size()) + " links; it has " +
                  std::to_string(n - 1) + " links");
  }
}

}  // namespace

void SetLineState(const Points& x, const Eigen::Ref<const Eigen::VectorXd>& tension,
                  LineState* line) {
  std::vector<double>* axes[] = {&line->x, &line->y, &line->z};
  for (Eigen::Index d = 0; d < 3; ++d) {
    std::vector<double>& v = *axes[d];
    if (d >= x.rows()) {  // an axis the core does not have (z in the plane)
      v.clear();
      continue;
    }
    v.resize(static_cast<std::size_t>(x.cols()));
    for (Eigen::Index j = 0; j < x.cols(); ++j) v[j] = x(d, j);
  }
  line->tension.assign(tension.data(), tension.data() + tension.size());
}

void CheckSnapshotSizes(const Snapshot& s, const std::vector<std::size_t>& stations) {
  CheckSizes(s, stations.size(), [&](std::size_t i) { return stations[i]; });
}

void CheckSnapshot(const SceneView& scene, const Snapshot& s) {
  CheckSizes(s, scene.lines.size(),
             [&](std::size_t i) { return scene.lines[i].arc_length.size(); });
  if (!std::isfinite(s.t)) throw Error("frame: the snapshot's time is not finite");
  for (std::size_t i = 0; i < s.lines.size(); ++i) {
    const LineSnapshot& l = s.lines[i];
    for (std::size_t j = 0; j < l.x.size(); ++j)
      if (!std::isfinite(l.x[j]) || !std::isfinite(l.y[j]) ||
          (!l.z.empty() && !std::isfinite(l.z[j])))
        throw Error("frame: station " + std::to_string(j) + " of " + At(i, s.t) +
                    " is not finite (" + std::to_string(l.x[j]) + ", " + std::to_string(l.y[j]) +
                    ")");
    for (std::size_t j = 0; j < l.tension.size(); ++j)
      if (!std::isfinite(l.tension[j]))
        throw Error("frame: tension of link " + std::to_string(j) + " of " + At(i, s.t) +
                    " is not finite");
  }
}

}  // namespace cablefilm
