#include "io/bodies_file.h"

#include <cmath>

#include "io/csv_line.h"

namespace cablefilm {

BodiesWriter::BodiesWriter(const std::string& path, const Model& model, const Inputs& in)
    : file_(path), model_(model), in_(in), loads_(model) {
  std::fputs("t,body,x,y,z,rx,ry,rz,fx,fy,fz,mx,my,mz\n", file_.stream());
}

bool BodiesWriter::Row(const Data& d) {
  loads_.Compute(model_, d, in_);
  const double deg = 180.0 / M_PI;
  for (int b = 0; b < static_cast<int>(model_.bodies.size()); ++b) {
    const Vec6& q = loads_.body_poses()[b];
    const Vec6& f = loads_.body_loads()[b];
    // Body names are plain (letters, digits, _ - .): no CSV quoting needed.
    // "%.10g,%s,%.12g,%.12g,%.12g,%.10g x 9\n"
    CsvLine line(file_.stream());
    line.G(d.t, 10).Comma().Text(model_.bodies[b].name);
    for (int k = 0; k < 3; ++k) line.Comma().G(q[k], 12);
    for (int k = 3; k < 6; ++k) line.Comma().G(q[k] * deg, 10);
    for (int k = 0; k < 6; ++k) line.Comma().G(f[k], 10);
    line.Char('\n');
  }
  return true;
}

}  // namespace cablefilm
