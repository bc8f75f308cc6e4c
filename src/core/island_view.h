#pragma once
// Island k of a model and its Data as the coupled steps take them (coupled_step.h,
// coupled_explicit_step.h): line i of the island (0..n-1) is model line isl.lines[i], free body
// k of the island (0..) is model body isl.free_bodies[k], its motion Data::bodies[id.bodies[k]].
#include "core/data.h"

namespace cablefilm {

struct IslandView {
  const Model& model;
  const Island& isl;
  IslandData& id;
  Data& d;
  IslandView(const Model& m, int k, Data& data)
      : model(m), isl(m.islands[k]), id(data.islands[k]), d(data) {}
  int lines() const { return static_cast<int>(isl.lines.size()); }
  const LineModel& M(int i) const { return model.lines[isl.lines[i]]; }
  LineData& L(int i) const { return d.lines[isl.lines[i]]; }
  int shared() const { return static_cast<int>(isl.shared_points.size()); }
  int body0() const { return kDim * shared(); }  // the first body unknown of the dense system
  int bodies() const { return static_cast<int>(isl.free_bodies.size()); }
  BodyMotion& body(int k) const { return d.bodies[id.bodies[k]]; }
  const BodySpec& body_spec(int k) const { return model.bodies[isl.free_bodies[k]]; }
  // The station of line i's end e (0: station 0, 1: station s).
  int end_station(int i, int e) const { return e == 0 ? 0 : M(i).line.links; }
};

}  // namespace cablefilm
