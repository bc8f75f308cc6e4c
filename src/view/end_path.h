#pragma once
// Where a moving end of a line has been, as the history keeps it and the cable panel draws it.
#include <vector>

#include "view/frame.h"

namespace cablefilm {

struct EndPath {
  int line = 0;     // index into the scene view's lines
  int station = 0;  // the moving end (one of its marks.moving_ends)
  std::vector<std::vector<Vec3f>> pieces;  // polylines [m] (z = 0 in the plane)
};

}  // namespace cablefilm
