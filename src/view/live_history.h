#pragma once
// What the live picture shows besides the cable now, gathered frame by frame in bounded memory:
// the maximum tension in a rolling time window (the scene's duration wide), the markers where
// the sea was changed, the per-link envelope and the peak since the (re)start, the recent path
// of the driven ends, a colour range that grows with the tensions seen (or is locked), and a
// world box that follows the cable (grows at once, shrinks slowly so the picture does not
// jitter).
#include <Eigen/Core>
#include <deque>
#include <string>
#include <vector>

#include "core/waves.h"
#include "view/live_frame.h"

namespace cablefilm {

// The parts of the picture that do not change while the view runs.
struct LiveScenery {
  std::string title;
  std::vector<double> arc_length;          // [m], s+1
  std::vector<double> section_boundaries;  // [m]
  std::vector<std::string> section_names;
  std::vector<int> weight_stations, moving_ends, fixed_ends, free_ends;
  CableSnapshot equilibrium;               // the initial state, t = 0
  std::string reference_label = "equilibrium";  // its name ("initial state (straight)")
  double window = 60;                      // width of the time plot [s]
  bool seabed = false;                     // a flat seabed at seabed_y [m]
  double seabed_y = 0;
  bool waves = false;                      // the water surface of `wave`, drawn as it moves
  Wave wave;
};

class LiveHistory {
 public:
  explicit LiveHistory(LiveScenery scenery);

  void Reset();  // a restart: everything but the locked range and the scenery
  // One frame's state: positions (2 x s+1) [m] and link tensions (s) [N].
  void Add(double t, const Eigen::Matrix2Xd& x, const Eigen::VectorXd& tension);
  void AddMarker(double t, std::string label);

  void LockRange(bool locked);
  void SetRange(double lo, double hi);  // [N]; locks it
  // Unlocks the range and starts it again from the tensions now (it grows from there): a
  // snap's peak no longer squeezes the colours of everything after it.
  void ResetRange();
  bool range_locked() const { return locked_; }
  double range_min() const { return range_lo_; }
  double range_max() const { return range_hi_; }

  double peak() const { return peak_; }
  double peak_t() const { return peak_t_; }
  int peak_link() const { return peak_link_; }

  // The whole picture's input for the frame added last.
  LiveFrameInput MakeInput(const std::string& status) const;
  // The waves as they are now (their height changed live); the surface of the next Add.
  void SetWave(const Wave& wave) { scenery_.wave = wave; }

  static constexpr std::size_t kMaxPathPoints = 4096;  // per moving end
  static constexpr std::size_t kMaxTracePoints = 1 << 16;

 private:
  void GrowRange(double lo, double hi);
  void FollowBox(const Eigen::Matrix2Xd& x);

  LiveScenery scenery_;
  CableSnapshot now_;
  bool has_frame_ = false;
  std::deque<double> times_, max_tension_;
  std::deque<LiveMarker> markers_;
  std::vector<double> link_min_, link_max_;
  std::vector<std::deque<Vec2f>> paths_;
  double peak_ = 0, peak_t_ = 0;
  int peak_link_ = 0;
  bool locked_ = false;
  double range_lo_ = 0, range_hi_ = 1;  // [N]
  double box_[4] = {0, 1, 0, 1};        // x_min, x_max, y_min, y_max [m]
  double union_box_[4] = {0, 1, 0, 1};  // every box since the (re)start: a steady layout
};

}  // namespace cablefilm
