#pragma once
// What a picture shows besides the lines now, gathered snapshot by snapshot: each line's
// maximum tension against time, its per-link min-max envelope and its peak, the paths of the
// moving ends, markers at control changes, and the colour range and world box the frames are
// drawn on. Two policies:
// - fixed (the film): the duration, the colour range and the box are known before the first
//   frame (a first pass found them) and hold for every frame; the time trace takes every output
//   row the snapshots carry (Snapshot::row_t), else the snapshot's own largest tension, thinned
//   to the extremes of each 1/kTimeTraceSpans of the duration (ThinnedTrace: its largest value
//   is the largest row's, whatever the frame rate); the envelope since t = 0; each end's path
//   as segments between cells of a 1000 x 1000 grid over the box, each cell pair stored once,
//   so a periodic path stops growing.
// - following (the live view): the time plot a rolling window (the scene's duration wide), a
//   colour range that grows with the tensions seen (or is locked, set, or reset), a box that
//   follows the lines (grows at once, shrinks slowly so the picture does not jitter), each
//   end's recent path, and memory bounded however long it runs.
// Plain C++; a copy is a consistent picture (the live view draws one while the run goes on).
#include <cstdint>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "core/waves.h"
#include "view/end_path.h"
#include "view/scene_view.h"
#include "view/snapshot.h"
#include "view/time_panel.h"
#include "view/time_trace.h"
#include "view/world_box.h"

namespace cablefilm {

struct FixedPolicy {                        // the film's
  double start = 0;                         // the film's first time (a window's) [s]
  double duration = 0;                      // simulated seconds the film covers [s]
  double tension_min = 0, tension_max = 1;  // colour and plot range [N], finite, increasing
  WorldBox box;                             // what the cable panel shows [m] (ShownBox)
};

struct FollowingPolicy {  // the live view's
  double window = 60;     // width of the time plot [s], > 0
  Wave wave;              // the waves now (drawn when the scene's sea has a surface)
};

class History {
 public:
  static constexpr int kTimeTraceSpans = 8192;       // fixed: finer than any plot's columns
  static constexpr std::size_t kMaxPathPoints = 1024;      // following: per moving end
  static constexpr std::size_t kMaxTracePoints = 1 << 16;  // following: in the window
  static constexpr std::size_t kMaxMarkers = 256;

  // Check the scene (CheckSceneView) and the policy; throw Error naming the offending value.
  History(const SceneView& scene, const FixedPolicy& policy);
  History(const SceneView& scene, const FollowingPolicy& policy);

  // Checks the snapshot's sizes against the scene (CheckSnapshotSizes) before changing anything.
  void Add(const Snapshot& snapshot);
  void AddMarker(double t, std::string label);  // a control change at t [s]
  void Reset();  // a restart: everything but a locked range
  void SetWave(const Wave& wave);  // following: the waves now; the surface of the next Add

  // The following policy's colour range (a fixed one stays as its policy set it).
  void LockRange(bool locked);
  void SetRange(double lo, double hi);  // [N]; locks it
  // Unlocks the range and starts it again from the tensions now (it grows from there): a
  // snap's peak no longer squeezes the colours of everything after it.
  void ResetRange();

  bool following() const { return following_; }
  long count() const { return count_; }  // snapshots added since the start or restart
  // The snapshot added last (with the water surface, following); before any, the scene's
  // reference states at t = 0.
  const Snapshot& now() const { return count_ > 0 ? now_ : initial_; }

  double range_min() const { return range_lo_; }  // colour and plot range [N]
  double range_max() const { return range_hi_; }
  bool range_locked() const { return locked_; }
  WorldBox box() const;  // what the cable panel shows [m]
  // What a 3D view shows [m]: fixed, the box; following, every box since the (re)start (a
  // camera that fits it does not pump as the lines swing).
  WorldBox view_box() const;
  // Width / height the cable panel's width is fitted to (0: the box's own): following, the box
  // over the whole run so far, so that the panels do not move as the lines swing.
  double layout_aspect() const;
  double time_min() const;  // the time plot's axis [s]
  double time_max() const;
  double duration() const { return following_ ? 0 : fixed_.duration; }  // fixed [s]
  double start() const { return following_ ? 0 : fixed_.start; }        // fixed [s]

  // The time trace: its times [s] and, per line, the largest tension [N] at each.
  const std::vector<double>& times() const;
  const std::vector<std::vector<double>>& max_tension() const;
  // Each link's smallest and largest tension since the (re)start [N], size s (0 before any).
  const std::vector<double>& link_min(std::size_t line = 0) const { return link_min_[line]; }
  const std::vector<double>& link_max(std::size_t line = 0) const { return link_max_[line]; }
  // A line's largest tension so far [N] (of its rows when the snapshots carry them), its time
  // [s] and its link (-1: not known, a row's); all 0 until has_peak.
  bool has_peak(std::size_t line = 0) const { return peaks_[line].seen; }
  double peak(std::size_t line = 0) const { return peaks_[line].value; }
  double peak_t(std::size_t line = 0) const { return peaks_[line].t; }
  int peak_link(std::size_t line = 0) const { return peaks_[line].link; }
  // A path per moving end of every line, in the lines' order; fixed, in pieces (the stored
  // segments joined where one starts at the end of the one before), following, one polyline of
  // the newest kMaxPathPoints positions.
  const std::vector<EndPath>& end_paths() const { return end_paths_; }
  // Following: those inside the window; fixed: all (the newest kMaxMarkers).
  const std::vector<TimeMarker>& markers() const { return markers_; }

 private:
  struct Peak {
    bool seen = false;
    double value = 0, t = 0;  // [N], [s]
    int link = 0;
  };
  History(const SceneView& scene, bool following);
  void AddSample(double t, const double* values, const int* links);
  void GrowRange(double lo, double hi);
  void FollowBox(const Snapshot& s);
  void AddToPath(std::size_t e, Vec3f p);

  bool following_;
  FixedPolicy fixed_;
  FollowingPolicy follow_;
  SeaView sea_;
  std::vector<std::size_t> stations_;  // of each line
  Snapshot initial_, now_;
  long count_ = 0;

  ThinnedTrace trace_;  // fixed: a channel a line
  std::vector<double> window_times_;                 // following [s]
  std::vector<std::vector<double>> window_max_;      // following: per line [N]
  std::vector<double> sample_;                       // per line, reused [N]
  std::vector<int> sample_link_;                     // per line, reused
  std::vector<std::vector<double>> link_min_, link_max_;
  std::vector<Peak> peaks_;
  std::vector<TimeMarker> markers_;

  std::vector<EndPath> end_paths_;
  struct PairHash {
    std::size_t operator()(const std::pair<std::uint64_t, std::uint64_t>& p) const {
      return std::hash<std::uint64_t>()(p.first * 0x9e3779b97f4a7c15ull ^ p.second);
    }
  };
  using CellPairs = std::unordered_set<std::pair<std::uint64_t, std::uint64_t>, PairHash>;
  double x0_ = 0, y0_ = 0, z0_ = 0, cell_ = 1;  // fixed: the path grid's origin, cell size [m]
  std::vector<Vec3f> path_last_;       // fixed: last stored point of each end
  std::vector<CellPairs> path_seen_;   // fixed: cell pairs stored

  bool locked_ = false;
  double range_lo_ = 0, range_hi_ = 1;  // [N]
  WorldBox box_;        // following: the lines' box now [m]
  WorldBox union_box_;  // following: every box since the (re)start (a steady layout)
};

}  // namespace cablefilm
