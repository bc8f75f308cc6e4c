#pragma once
// points.csv of a system of lines: t,point,x,y,z,fx,fy,fz, one row per point per output time,
// the point's position [m] and the force its lines exert on it [N] (core/point_loads.h,
// PointLoads); written whole or not at all.
#include <string>

#include "core/point_loads.h"
#include "io/atomic_file.h"
#include "run/driver.h"

namespace cablefilm {

class PointsWriter : public RowSink {
 public:
  PointsWriter(const std::string& path, const Model& model, const Inputs& in);
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
