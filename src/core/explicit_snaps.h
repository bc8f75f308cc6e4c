#pragma once
// The implicit scheme's steps through snap loads (issue 21, item 4). A link snapping taut
// within an implicit step longer than kResolvedSnapFraction of its rise time tau
// (snap_monitor.h) jumps over the snap load's rise, and generalized-alpha's numerical damping
// (rho_inf < 1) then takes the axial wave the snap sends along the line: on a soft line under
// a clump weight the default's peak was 18.5 kN against the explicit scheme's 23.9 kN, and no
// shorter implicit step closed the gap (docs/validation.md). So such a step is not taken:
// from its start the line goes on with the explicit scheme's automatic steps (explicit_step.h,
// on the snap's own rise time, refined where links change between slack and taut) over that
// step and a window after it of two axial crossings of the line (the snap's wave down the line
// and back) and two rise times (SnapWindow); then the implicit scheme takes over again from the
// state the explicit steps reached. The explicit steps cost what the explicit scheme would
// cost over the windows alone; a run whose snaps come so often that windows and implicit steps
// together cost more than the explicit scheme would have goes on with explicit steps to its
// end.
//
// Only snaps whose load matters: the snap load of a link closing at speed u between its two
// stations is u sqrt(K m_r) = u K tau / pi (K = EA / l, m_r the stations' reduced mass), and
// a snap whose load is below kSnapLoadFraction of the line's largest tension stays with the
// implicit step (a grounded chain's links snap taut at millimetres per second at every
// touchdown: explicit steps there would cost the explicit scheme's price for nothing).
#include "core/line_data.h"

namespace cablefilm {

// A snap load below this fraction of the line's largest tension stays with the implicit step.
constexpr double kSnapLoadFraction = 0.02;
// The explicit window after a snap: axial crossings of the line (the wave down and back),
// plus rise times of its slowest link (the snap itself: a link between a fixed end and a mass
// stays taut for sqrt(2) tau).
constexpr double kSnapWindowCrossings = 2.0;
constexpr double kSnapWindowRises = 2.0;
// A Newton iteration's cost in explicit steps of the same line (measured: 2.4 on P63 at 60
// links, 2.0 on a 40-link line: `cablefilm run` of each scheme, CPU per iteration and per step).
constexpr double kNewtonIterationCost = 2.4;

// The window after a snap [s]: kSnapWindowCrossings times the time an axial wave takes along
// the line, the sum of its links' l / c (c = sqrt(EA / mu)); with a link's tau
// = pi l / (sqrt(2) c) between equal stations, l / c = sqrt(2) tau / pi (a weight on a
// station makes tau longer, and the window with it); plus kSnapWindowRises of the longest tau.
double SnapWindow(const SnapMonitor& snaps);

// Whether explicit steps through snaps are on (StepOptions::explicit_snaps) and possible (the
// explicit scheme's substep is known).
bool StepsThroughSnaps(const LineData& d);

// After an implicit trial step of h [s] from the state (its end in d.scratch, its link
// lengths and tensions in d.forces): a link that was slack at the state and is taut at the
// step's end, within a step longer than kResolvedSnapFraction of its tau, with a snap load
// above kSnapLoadFraction of the largest tension.
bool SnapsUnresolved(const LineModel& m, const LineData& d, double h);

// When an explicit window opened at t [s] over the step of h [s] left to it ends: SnapWindow
// [s] after that step (the snap fell somewhere within it); or never (infinity) once the windows
// and the implicit steps so far have cost more, in explicit steps (Newton's iterations at
// kNewtonIterationCost each), than the explicit scheme alone would have since start_time with
// steps of max_substep [s]: a run never dearer than the explicit scheme by more than its cost
// up to here. A line's and a coupled island's alike.
double ExplicitWindowEnd(double t, double h, double snap_window, double start_time,
                         double max_substep, long explicit_steps, long newton_iterations);

// The explicit steps of a window from t towards t_end [s]: up to the window's end or t_end,
// whichever is first (a window ending a rounding short of t_end is taken to it, no sliver of
// an implicit step: *explicit_until moved there), in `pieces` equal steps `h` of at most
// max_substep, as the explicit scheme's time grid cuts an interval.
struct ExplicitWindowSpan {
  double stop = 0;  // [s]
  long pieces = 0;  // 0: nothing to step
  double h = 0;     // [s]
};
ExplicitWindowSpan WindowSpan(double t, double t_end, double snap_window, double max_substep,
                              double* explicit_until);

// Leaves the implicit step of h [s] that snapped: the state's forces and (true) accelerations
// computed, the explicit window opened (LineData::explicit_until) over that step and SnapWindow
// after it (the snap fell somewhere within the step).
void EnterExplicitWindow(const LineModel& m, LineData& d, const Inputs& in, double h);

// Explicit steps from the state up to t_end [s] or the window's end, whichever is first; at the
// window's end the implicit scheme's memory is made from the state (accelerations computed:
// the scheme starts afresh, as at t = 0).
void StepExplicitWindow(const LineModel& m, LineData& d, const Inputs& in, double t_end);

}  // namespace cablefilm
