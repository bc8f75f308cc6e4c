#pragma once
// A procedural, P63-like cable for benchmarks, tests and demos (NOT physics): 61 stations over
// two 45.72 m sections, anchored at the origin, a 453.6 kg weight at 27.43 m, the end driven on
// a circle of 1.83 m around (80, 30.48) m with a 10 s period; the shape is a sagging curve
// between the ends and the tensions a static part growing with height plus a travelling wave.
#include "view/history.h"
#include "view/scene_view.h"
#include "view/snapshot.h"

namespace cablefilm {

SceneView MakeDemoScene(int segments = 60);  // one line, its reference the state at t = 0
// The film's range (0 to 30 kN) and a box holding the cable, over `duration` [s].
FixedPolicy MakeDemoPolicy(double duration);
Snapshot MakeDemoSnapshot(const SceneView& scene, double t);  // t [s]

}  // namespace cablefilm
