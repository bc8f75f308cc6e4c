#pragma once
// A vessel's displacement RAOs (response amplitude operators) by wave heading and frequency,
// from a CSV file, and their value at any heading and frequency. Not in the paper.
//
// Rows "heading,omega,x,x_phase,y,y_phase,z,z_phase" (a point's) or with
// ",rx,rx_phase,ry,ry_phase,rz,rz_phase" too (a body's): the wave's heading [deg] (the direction
// it travels, from +x towards +z), omega [rad/s], and per motion along the scene's axes its
// amplitude per metre of wave amplitude [m/m; deg/m for the angles] and phase [deg] (the
// response is r a cos(theta + p), theta the wave's phase at the rest position, as x_rao's).
// Rows of one heading have omega increasing. Between rows amplitude and phase are joined
// linearly (the phase the shorter way round), in omega within a heading and then in heading
// (round the circle); beyond a heading's first and last omega its end rows hold.
#include <array>
#include <string>
#include <vector>

namespace cablefilm {

struct RaoTable {
  std::vector<double> headings;  // [deg], increasing, in [0, 360)
  // Per heading: rows of omega [rad/s] and the six motions' (amplitude, phase [deg]).
  struct Row {
    double omega = 0;
    std::array<std::array<double, 2>, 6> rao{};
  };
  std::vector<std::vector<Row>> rows;
  bool turns = false;  // the file gives rx, ry, rz
};

// Throws Error naming the file and the line. `body`: the angles' columns are allowed.
RaoTable ReadRaoTable(const std::string& path, bool body);

// The six motions' [amplitude ratio, phase deg] at omega [rad/s] and heading [deg].
std::array<std::array<double, 2>, 6> RaoAt(const RaoTable& table, double omega, double heading);

}  // namespace cablefilm
