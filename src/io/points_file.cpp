#include "io/points_file.h"


namespace cablefilm {

PointsWriter::PointsWriter(const std::string& path, const SystemModel& sys, const Inputs& in)
    : file_(path), sys_(sys), in_(in), loads_(sys) {
  std::fputs("t,point,x,y,z,fx,fy,fz\n", file_.stream());
}

bool PointsWriter::Row(const SystemData& sd) {
  loads_.Compute(sys_, sd, in_);
  const Points& x = loads_.positions();
  const Points& f = loads_.forces();
  for (int p = 0; p < static_cast<int>(sys_.points.size()); ++p)
    // Point names are plain (letters, digits, _ - .): no CSV quoting needed.
    std::fprintf(file_.stream(), "%.10g,%s,%.12g,%.12g,%.12g,%.10g,%.10g,%.10g\n", sd.t,
                 sys_.points[p].name.c_str(), x(0, p), x(1, p), x(2, p), f(0, p), f(1, p),
                 f(2, p));
  return true;
}

}  // namespace cablefilm
