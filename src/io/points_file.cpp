#include "io/points_file.h"

#include "io/csv_line.h"


namespace cablefilm {

PointsWriter::PointsWriter(const std::string& path, const Model& model, const Inputs& in)
    : file_(path), model_(model), in_(in), loads_(model) {
  std::fputs("t,point,x,y,z,fx,fy,fz\n", file_.stream());
}

bool PointsWriter::Row(const Data& d) {
  loads_.Compute(model_, d, in_);
  const Points& x = loads_.positions();
  const Points& f = loads_.forces();
  // "%.10g,%s,%.12g,%.12g,%.12g,%.10g,%.10g,%.10g\n"
  CsvLine line(file_.stream());
  for (int p = 0; p < static_cast<int>(model_.points.size()); ++p) {
    // Point names are plain (letters, digits, _ - .): no CSV quoting needed.
    line.G(d.t, 10).Comma().Text(model_.points[p].name);
    for (int c = 0; c < 3; ++c) line.Comma().G(x(c, p), 12);
    for (int c = 0; c < 3; ++c) line.Comma().G(f(c, p), 10);
    line.Char('\n');
  }
  return true;
}

}  // namespace cablefilm
