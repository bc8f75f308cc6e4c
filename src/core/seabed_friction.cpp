#include "core/seabed_friction.h"

#include <cmath>

namespace cablefilm {

StickSlipForce StickSlipFriction(double mu, double N, double K, double C, const Vec& s,
                                 const Vec& v) {
  StickSlipForce f;
  f.across = Mat::Identity();
  f.across(kVertical, kVertical) = 0;  // I_h: the bed's plane
  const double limit = mu * N;         // mu N_j [N]
  const Vec trial = -(K * s + C * v);  // what sticking takes [N]
  const double size = trial.norm();
  if (size <= limit) {
    f.force = trial;
    return f;
  }
  const Vec u = trial / size;
  f.sliding = true;
  f.force = limit * u;
  f.scale = limit / size;
  f.across -= u * u.transpose();
  return f;
}

void ResetFrictionAnchors(const LineModel& m, const Points& x, LinkGeometry& g) {
  if (!HasStickSlip(m)) {
    g.friction_anchor.resize(kDim, 0);
    g.stick.resize(kDim, 0);
    return;
  }
  g.friction_anchor = x;
  g.friction_anchor.row(kVertical).setZero();
  g.stick = Points::Zero(kDim, x.cols());
}

void ComputeStick(const Points& x, LinkGeometry& g) {
  if (g.friction_anchor.cols() == 0) return;
  g.stick = x - g.friction_anchor;
  g.stick.row(kVertical).setZero();
}

void UpdateFrictionAnchors(const LineModel& m, const Points& x, const Points& v, LinkGeometry& g) {
  if (g.friction_anchor.cols() == 0) return;
  const SeabedSpec& bed = m.env.seabed;
  for (int j = 0; j <= m.line.links; ++j) {
    const Vec xh = HorizontalPart(x.col(j));
    const double p = bed.y - x(kVertical, j);  // penetration [m]
    const double N = p > 0 ? SeabedNormal(m, j, p, v(kVertical, j)).N : 0.0;  // [N]
    const Vec s = xh - g.friction_anchor.col(j);
    const double K = m.line.friction_stiffness[j], held = K * s.norm();  // [N/m], [N]
    const double limit = bed.friction * N;
    // Slid: the spring keeps its direction and holds mu N (0 off the bed: the anchor is the
    // station).
    if (held > limit) g.friction_anchor.col(j) = xh - (limit / held) * s;
  }
  ComputeStick(x, g);
}

}  // namespace cablefilm
