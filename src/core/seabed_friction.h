#pragma once
// The stick-slip seabed friction (FrictionModel::kStickSlip, line_model.h): an elastic-plastic
// spring on the bed. A grounded station j is held to its anchor a_j, the point on the bed
// where it last slid, by a shear spring K l_j [N/m] and a dashpot C_j [N s/m]:
//   F_h = -K l_j s - C_j v_h,   s = x_h - a_j [m], v_h its velocity along the bed [m/s],
// as long as |F_h| <= mu N_j (it sticks); beyond, it slides: F_h = mu N_j u, u = F_h / |F_h|
// of the expression above, and when the step is accepted the anchor follows the station so
// that the spring holds no more than mu N_j (|K l_j s| = mu N_j). Static friction without
// creep, Coulomb's force while sliding, and every force a piecewise smooth function of the
// state (an implicit step's Newton sees the tangent of each branch). OrcaFlex's seabed
// friction is of this kind; MoorDyn's is a velocity law (see docs/model.md).
//
// The anchors are state: they live in the geometry of a LineData (LinkGeometry::friction_anchor),
// set when the LineData is made (ResetFrictionAnchors) and moved once per accepted step
// (UpdateFrictionAnchors); every force evaluation between sees them fixed.
#include "core/forces.h"

namespace cablefilm {

// Whether the model's seabed friction is stick-slip (a bed, mu > 0, the model asks for it).
inline bool HasStickSlip(const LineModel& m) {
  const SeabedSpec& bed = m.env.seabed;
  return bed.present && bed.friction > 0 && bed.friction_model == FrictionModel::kStickSlip;
}
// K l_j [N/m] and C_j [N s/m] of station j; 0 without stick-slip friction.
inline double ShearStiffness(const LineModel& m, int j) {
  return HasStickSlip(m) ? m.line.friction_stiffness[j] : 0.0;
}
inline double ShearDamping(const LineModel& m, int j) {
  return HasStickSlip(m) ? m.line.friction_damping[j] : 0.0;
}

struct StickSlipForce {
  Vec force = Vec::Zero();  // F_h [N]
  bool sliding = false;
  // dF_h = -scale (K l_j ds + C_j dv_h) projected by `across` (I_h sticking, I_h - u u^T
  // sliding) + mu u dN (sliding only): the Jacobian's pieces.
  double scale = 1;          // 1 sticking, mu N / |trial| sliding
  Mat across = Mat::Zero();
};

// The friction on a station with normal reaction N [N], shear spring K [N/m] and dashpot
// C [N s/m], displaced s [m] from its anchor and moving at v [m/s] (both horizontal).
StickSlipForce StickSlipFriction(double mu, double N, double K, double C, const Vec& s,
                                 const Vec& v);

// A state at rest on the bed: every anchor where its station is (no friction force yet).
// Sizes the anchors (allocates); clears them when the model has no stick-slip friction.
void ResetFrictionAnchors(const LineModel& m, const Points& x, LinkGeometry& g);
// g.stick = x_h - a_j for every station (no-op without anchors); ComputeGeometry calls it.
void ComputeStick(const Points& x, LinkGeometry& g);
// After a step is accepted at x, v: an anchor whose spring would hold more than mu N_j moves
// along it until it holds mu N_j; a station off the bed takes its anchor with it. g.stick is
// then that of the new anchors. Allocates nothing.
void UpdateFrictionAnchors(const LineModel& m, const Points& x, const Points& v, LinkGeometry& g);

}  // namespace cablefilm
