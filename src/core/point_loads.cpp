#include "core/point_loads.h"

#include "core/end_loads.h"
#include "core/forces.h"

namespace cablefilm {

PointLoads::PointLoads(const Model& model) {
  for (const LineModel& m : model.lines) station_forces_.push_back(Points::Zero(kDim, m.stations()));
  const int np = static_cast<int>(model.points.size());
  positions_ = forces_ = Points::Zero(kDim, np);
  for (int p = 0; p < np; ++p) positions_.col(p) = model.points[p].motion.rest();
  body_poses_ = model.body_poses;
  body_loads_.assign(model.bodies.size(), Vec6::Zero());
}

void PointLoads::Compute(const Model& model, const Data& d, const Inputs& in) {
  forces_.setZero();
  for (int i = 0; i < static_cast<int>(d.lines.size()); ++i) {
    const LineModel& m = model.lines[i];
    const LineData& ld = d.lines[i];
    Points& f = station_forces_[i];
    ComputeStationForces(m, ld.water, ld.forces.geometry, ld.forces.tension, ld.state.v, f);
    for (int e = 0; e < 2; ++e) {
      const int p = model.line_points[i][e];
      const int j = e == 0 ? 0 : m.line.links;
      positions_.col(p) = ld.state.x.col(j);
      const PointKind kind = model.points[p].kind;
      if (kind == PointKind::kFree) {
        forces_.col(p) += FreeEndPull(m, ld.forces, e);
        continue;
      }
      Vec a = Vec::Zero();
      // A fixed point's is zero, unless the live view's offset carries it (inputs.h).
      if (kind == PointKind::kMoved || kind == PointKind::kFixed)
        a = EndAcceleration(m, in, j, ld.state.t);
      if (kind == PointKind::kBody) a = ld.a.col(j);
      forces_.col(p) += HeldEndLoad(m, ld.forces.geometry, f, j, a);
    }
  }
  // The bodies: a free one's pose as stepped, a driven one's reference point and angles as
  // they move [m, rad].
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b) {
    const BodySpec& body = model.bodies[b];
    if (body.kind != BodyKind::kDriven) continue;
    body_poses_[b].head<3>() = body.motion.Position(d.t);
    if (body.turn.moves()) body_poses_[b].tail<3>() = body.turn.Position(d.t);
  }
  for (int k = 0; k < static_cast<int>(d.bodies.size()); ++k)
    body_poses_[model.free_bodies[k]] = d.bodies[k].q;
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b) {
    body_loads_[b].setZero();
    for (int p = 0; p < static_cast<int>(model.points.size()); ++p)
      if (model.points[p].on_body == b)
        body_loads_[b] += LoadAbout(body_poses_[b].head<3>(), positions_.col(p), forces_.col(p));
  }
}

}  // namespace cablefilm
