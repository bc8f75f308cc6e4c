#pragma once
// body.csv of a system with bodies: t,body,x,y,z,rx,ry,rz,fx,fy,fz,mx,my,mz, one row per body
// per output time: its pose (its reference point [m], its angles about x, then y, then z
// [deg]) and the load its lines exert on it (force [N], moment about the reference point
// [N m]; core/point_loads.h, PointLoads); written whole or not at all.
#include <string>

#include "core/point_loads.h"
#include "io/atomic_file.h"
#include "run/driver.h"

namespace cablefilm {

class BodiesWriter : public RowSink {
 public:
  BodiesWriter(const std::string& path, const Model& model, const Inputs& in);
  bool Row(const Data& d) override;
  void Commit() { file_.Commit(); }
  void CommitPartial(const std::string& path) { file_.CommitAs(path); }

 private:
  AtomicFile file_;
  const Model& model_;
  const Inputs& in_;
  PointLoads loads_;
};

}  // namespace cablefilm
