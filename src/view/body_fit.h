#pragma once
// Where a body is, from where its points are: the frames carry the lines, not the bodies'
// poses, and a body's points (its fairleads) are its lines' ends, fixed in its axes. Three or
// more points not on one line give its turn and place (the least-squares rigid fit, Kabsch's);
// fewer give its place alone, at its rest angles.
#include <array>
#include <vector>

#include "core/vec.h"
#include "view/body_box.h"
#include "view/scene_view.h"
#include "view/snapshot.h"

namespace cablefilm {

struct BodyPlacement {
  Vec r = Vec::Zero();       // its reference point [m]
  Mat R = Mat::Identity();   // its turn: a local point p is at r + R p
};

// The placement that takes each `local` point nearest its `world` place (same sizes, at least
// one); `rest` (R(theta) at the rest angles) when the points lie on one line or fewer than 3.
BodyPlacement FitBodyPlacement(const std::vector<Vec>& local, const std::vector<Vec>& world,
                               const Mat& rest);

// Each body's box edges where its points are in `lines` (a line's z empty: 0), as the scene's
// bodies; empty for a body without a box, without local positions or without its points. `t`
// [s]: the snapshot's time, for a driven body's angles (BodyView::angles_at).
std::vector<std::vector<std::array<Vec, 2>>> BodyBoxesNow(
    const SceneView& scene, const std::vector<LineSnapshot>& lines, double t = 0);

}  // namespace cablefilm
