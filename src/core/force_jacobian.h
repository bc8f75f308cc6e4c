#pragma once
// The analytic derivatives of the right-hand side of eq. (1) that Newton's method needs, laid out
// as the block tridiagonal matrix of the free stations (block i = station first_free() + i).
#include <Eigen/Core>

#include "core/block_tridiagonal.h"
#include "core/line_model.h"
#include "core/forces.h"

namespace cablefilm {

// Adds  -dF/dx - kv dF/dv  to `system`, where F(x, v) is the station force of eq. (1): Hooke
// tension with its slack switch (axial and geometric stiffness) and its axial damping, the
// links' normal and tangential drag through
// both their orientation and the relative velocity, and the prisms' drag. kv = dv/dx of the
// time-stepping scheme (0 for statics). `g` and `tension` must be those of x.
void AddForceJacobian(const LineModel& m, const Water& water, const LinkGeometry& g,
                      const Eigen::VectorXd& tension, const Points& v, double kv,
                      BlockTridiagonal& system);

// Sets the blocks of `system` (not its right-hand side) to  ka M(x) + d(M(x) a)/dx: the inertia
// of eq. (1) with the dependence of the normal and tangential added mass on the links'
// orientation. ka = da/dx of the time-stepping scheme.
void SetInertiaJacobian(const LineModel& m, const LinkGeometry& g, const Points& a,
                        double ka, BlockTridiagonal& system);

}  // namespace cablefilm
