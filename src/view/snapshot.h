#pragma once
// One output time of the simulation as the pictures take it: each line's positions and link
// tensions, the output rows since the previous snapshot (so that a plot shows every row, not one
// sample a frame), and the water surface. Made from the core's state by SetLineState, for the
// film pass, the Python module's frames and the live session alike.
#include <Eigen/Core>
#include <vector>

#include "core/vec.h"
#include "core/waves.h"
#include "view/scene_view.h"

namespace cablefilm {

struct LineSnapshot : LineState {
  // This line's largest link tension at each of Snapshot::row_t [N] (same size).
  std::vector<double> row_max;
  // Optional, size s: each link's smallest and largest tension over those rows [N], so that the
  // min-max envelope covers every row too, not only the snapshots.
  std::vector<double> row_link_min, row_link_max;
};

struct Snapshot {
  double t = 0;                     // simulated time [s]
  std::vector<LineSnapshot> lines;  // the scene view's lines, in its order
  // The output rows (timeseries.csv) since the previous snapshot, up to this one's time [s].
  // Empty: each line's largest tension now is the time plot's sample.
  std::vector<double> row_t;
  // Optional: the water surface at this time, a polyline (x increasing, y) [m] reaching beyond
  // the world box on both sides (the plot shows what falls in its x range); empty: none.
  std::vector<double> surface_x, surface_y;
  // The waves now (wave.spec.present false: none), for the 3D view's surface at t; and the
  // current at the top of the water [m/s] (SeaView::current).
  Wave wave;
  Vec current = Vec::Zero();
};

// `line`'s positions and tensions from the core's: a column per station of `x` [m] (an axis a
// row: z too in space) and `tension` [N]. Its storage is reused (no allocation once sized).
void SetLineState(const Points& x, const Eigen::Ref<const Eigen::VectorXd>& tension,
                  LineState* line);

// Throws Error (naming the line, the time and the sizes) unless the snapshot has one line per
// entry of `stations` with that many stations (z empty or as many), one tension fewer, rows
// paired with row_t and a row envelope of a value per link or none.
void CheckSnapshotSizes(const Snapshot& snapshot, const std::vector<std::size_t>& stations);
// CheckSnapshotSizes for the scene's lines, and a finite time, positions and tensions.
void CheckSnapshot(const SceneView& scene, const Snapshot& snapshot);

}  // namespace cablefilm
