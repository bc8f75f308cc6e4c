#pragma once
// Builds the abstract frame of the film (no GL) from the panels (header_panel, cable_panel,
// colorbar_panel, tension_panel, time_panel): the cable to scale coloured by link tension with
// a colour bar, the tension along the cable (now, equilibrium, min-max envelope so far, the
// sections named), the maximum tension against time, the title and the simulated time. Also
// the still of the maximum tension against time (the paper's Figure 1). Pure functions of
// their inputs; the live view (live_frame.h) composes the same panels.
#include <cstdint>
#include <string>
#include <unordered_set>
#include <vector>

#include "view/colormap.h"
#include "view/frame.h"
#include "view/frame_layout.h"
#include "view/plot_layout.h"
#include "view/theme.h"
#include "view/time_trace.h"

namespace cablefilm {

// What the film has shown so far, accumulated snapshot by snapshot: the O(s) envelope (of the
// snapshots' tensions and of the rows' envelopes they carry), the
// maximum tension against time (and the companion cable's, when there is one), and the end's
// path as segments between cells of a 1000 x 1000 grid over the world box, each cell pair
// stored once, so a periodic path stops growing. The time trace takes every output row a
// snapshot carries (CableSnapshot::row_t), else the snapshot's own largest tension, thinned to
// the extremes of each 1/kTimeTraceSpans of the film's duration (ThinnedTrace): its largest
// value is the largest row's, whatever the frame rate.
class FilmHistory {
 public:
  static constexpr int kTimeTraceSpans = 8192;  // finer than any time plot's pixel columns
  explicit FilmHistory(const FilmSpec& spec);
  // Checks the snapshot against the spec (sizes, finite values; throws Error with the values).
  void Add(const CableSnapshot& snapshot);

  long count() const { return count_; }
  const std::vector<double>& link_min() const { return link_min_; }  // [N], size s
  const std::vector<double>& link_max() const { return link_max_; }  // [N], size s
  const std::vector<double>& times() const { return trace_.times(); }  // [s], the trace's samples
  const std::vector<double>& max_tension() const { return trace_.values(0); }  // [N], per sample
  // The companion cable's maximum tension [N], one per sample of times() (NaN where a snapshot
  // has no companion): empty while no snapshot had one.
  const std::vector<double>& companion_max_tension() const {
    return companion_seen_ ? trace_.values(1) : no_companion_;
  }
  // The largest of max_tension() so far [N] and its time [s] (NaN before any snapshot).
  double peak() const { return peak_; }
  double peak_t() const { return peak_t_; }
  struct PathSegment {
    Vec2f a, b;  // [m]
  };
  // Path of each of spec.moving_ends (same order), as segments in no particular order.
  const std::vector<std::vector<PathSegment>>& end_paths() const { return end_paths_; }

 private:
  void AddSample(double t, double max, double companion_max);
  std::vector<int> moving_ends_;
  std::size_t stations_;
  bool companion_required_;
  double x0_, y0_, cell_;  // path grid: origin and cell size [m]
  long count_ = 0;
  std::vector<double> link_min_, link_max_;
  ThinnedTrace trace_;     // channel 0: the cable's maximum tension, 1: the companion's
  bool companion_seen_ = false;
  std::vector<double> no_companion_;
  double peak_, peak_t_;
  std::vector<std::vector<PathSegment>> end_paths_;
  std::vector<Vec2f> path_last_;                            // last stored point of each end
  std::vector<std::unordered_set<std::uint64_t>> path_seen_;  // cell pairs already stored
};

// Where everything goes (FrameLayout, frame_layout.h) for the film: the spec's box, cable,
// duration, range and legends. Throws Error on an invalid spec or a frame under 16x16.
FrameLayout MakeFrameLayout(const FilmSpec& spec, int width, int height);

// Throws Error (with the sizes or the offending value) unless the snapshot fits the spec: its
// stations, links, finite values, and the companion's when it has one (or the spec names one).
void CheckSnapshot(const FilmSpec& spec, const CableSnapshot& snapshot);

// When the snapshot has a companion cable it is overlaid (same colour map and range) with its
// tension and maximum-tension curves; legends name spec.label and spec.companion_label.
Frame MakeFrame(const FilmSpec& spec, const FilmHistory& history, const CableSnapshot& snapshot,
                const FrameLayout& layout, const Colormap& colormap,
                const Theme& theme = Theme::Dark());

// One labelled curve of maximum tension along the cable against time.
struct MaxTensionSeries {
  std::string label;            // e.g. "elastic", "inextensible"
  std::vector<double> t;        // [s]
  std::vector<double> tension;  // [N], same size as t
};
// The still: every series on one pair of axes with a legend. Throws Error on mismatched sizes.
Frame MakeMaxTensionFigure(const std::string& title, const std::vector<MaxTensionSeries>& series,
                           int width, int height, const Theme& theme = Theme::Light());

}  // namespace cablefilm
