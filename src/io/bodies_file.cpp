#include "io/bodies_file.h"

#include <cmath>

#include "io/csv_line.h"

namespace cablefilm {

BodiesWriter::BodiesWriter(const std::string& path, const Model& sys, const Inputs& in)
    : file_(path), sys_(sys), in_(in), loads_(sys) {
  std::fputs("t,body,x,y,z,rx,ry,rz,fx,fy,fz,mx,my,mz\n", file_.stream());
}

bool BodiesWriter::Row(const Data& sd) {
  loads_.Compute(sys_, sd, in_);
  const double deg = 180.0 / M_PI;
  for (int b = 0; b < static_cast<int>(sys_.bodies.size()); ++b) {
    const Vec6& q = loads_.body_poses()[b];
    const Vec6& f = loads_.body_loads()[b];
    // Body names are plain (letters, digits, _ - .): no CSV quoting needed.
    // "%.10g,%s,%.12g,%.12g,%.12g,%.10g x 9\n"
    CsvLine line(file_.stream());
    line.G(sd.t, 10).Comma().Text(sys_.bodies[b].name);
    for (int k = 0; k < 3; ++k) line.Comma().G(q[k], 12);
    for (int k = 3; k < 6; ++k) line.Comma().G(q[k] * deg, 10);
    for (int k = 0; k < 6; ++k) line.Comma().G(f[k], 10);
    line.Char('\n');
  }
  return true;
}

}  // namespace cablefilm
