#include "io/bodies_file.h"

#include <cmath>

namespace cablefilm {

BodiesWriter::BodiesWriter(const std::string& path, const SystemModel& sys, const Inputs& in)
    : file_(path), sys_(sys), in_(in), loads_(sys) {
  std::fputs("t,body,x,y,z,rx,ry,rz,fx,fy,fz,mx,my,mz\n", file_.stream());
}

bool BodiesWriter::Row(const SystemData& sd) {
  loads_.Compute(sys_, sd, in_);
  const double deg = 180.0 / M_PI;
  for (int b = 0; b < static_cast<int>(sys_.bodies.size()); ++b) {
    const Vec6& q = loads_.body_poses()[b];
    const Vec6& f = loads_.body_loads()[b];
    // Body names are plain (letters, digits, _ - .): no CSV quoting needed.
    std::fprintf(file_.stream(),
                 "%.10g,%s,%.12g,%.12g,%.12g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,"
                 "%.10g\n",
                 sd.t, sys_.bodies[b].name.c_str(), q[0], q[1], q[2], q[3] * deg, q[4] * deg,
                 q[5] * deg, f[0], f[1], f[2], f[3], f[4], f[5]);
  }
  return true;
}

}  // namespace cablefilm
