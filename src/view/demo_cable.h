#pragma once
// A procedural, P63-like cable for benchmarks, tests and demos (NOT physics): 61 stations over
// two 45.72 m sections, anchored at the origin, a 453.6 kg weight at 27.43 m, the end driven on
// a circle of 1.83 m around (80, 30.48) m with a 10 s period; the shape is a sagging curve
// between the ends and the tensions a static part growing with height plus a travelling wave.
#include "view/frame.h"

namespace cablefilm {

FilmSpec MakeDemoSpec(double duration, int segments = 60);
CableSnapshot MakeDemoSnapshot(const FilmSpec& spec, double t);

}  // namespace cablefilm
