#pragma once
// MoorDyn's frame and cablefilm's. MoorDyn: x and y horizontal, z up. cablefilm: x and z
// horizontal, y up. A MoorDyn point (x, y, z) is cablefilm's (x, z, -y): a rotation by -90
// degrees about x, right-handed on both sides (a heading measured from +x towards +y in
// MoorDyn is measured from +x towards -z in cablefilm).
#include <array>

#include "scene/moordyn_file.h"

namespace cablefilm {

using MoorDynVec = std::array<double, 3>;

// (x, y, z) in MoorDyn's axes -> (x, z, -y) in cablefilm's.
MoorDynVec MoorDynToCablefilm(const MoorDynVec& p);

// A point fixed to a body, from the body's frame to MoorDyn's global frame:
// X0 + R p, R = Rx(r0) Ry(p0) Rz(y0), the angles in degrees, each a right-handed rotation
// about MoorDyn's global axis (MoorDyn-C, Misc.hpp, Euler2Quat: AngleAxis(x) * AngleAxis(y) *
// AngleAxis(z); positive roll lowers the starboard side -y, positive pitch the bow +x,
// positive yaw turns the bow to port +y).
MoorDynVec MoorDynBodyPoint(const MoorDynBody& body, const MoorDynVec& p);

// A body's angles (r0, p0, y0 [deg], R = Rx(r0) Ry(p0) Rz(y0) in MoorDyn's axes) as
// cablefilm's [about x, about y, about z] [deg] (R = Rz Ry Rx in its axes, the same turn): a
// yaw alone is a turn about cablefilm's y by the same angle.
MoorDynVec MoorDynAnglesToCablefilm(const MoorDynVec& rpy);

// A point's position in MoorDyn's global frame: as given, or through its body's pose for a
// Body#N point (whose body must be defined).
MoorDynVec MoorDynPointPosition(const MoorDynSystem& system, const MoorDynPoint& point);

}  // namespace cablefilm
