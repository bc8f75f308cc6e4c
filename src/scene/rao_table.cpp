#include "scene/rao_table.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/error.h"
#include "scene/number_table.h"
#include "scene/scene_limits.h"
#include "scene/text_escape.h"

namespace cablefilm {
namespace {

// a + f (b - a) for amplitudes; for phases [deg] the shorter way from a to b.
double Mix(double a, double b, double f) { return a + f * (b - a); }
double MixPhase(double a, double b, double f) {
  return a + f * std::remainder(b - a, 360.0);
}

std::array<std::array<double, 2>, 6> Mix(const std::array<std::array<double, 2>, 6>& a,
                                         const std::array<std::array<double, 2>, 6>& b,
                                         double f) {
  std::array<std::array<double, 2>, 6> out{};
  for (int j = 0; j < 6; ++j) out[j] = {Mix(a[j][0], b[j][0], f), MixPhase(a[j][1], b[j][1], f)};
  return out;
}

// One heading's RAOs at omega: linear between the rows around it, the end rows held beyond.
std::array<std::array<double, 2>, 6> AtOmega(const std::vector<RaoTable::Row>& rows,
                                             double omega) {
  if (omega <= rows.front().omega) return rows.front().rao;
  if (omega >= rows.back().omega) return rows.back().rao;
  const auto it = std::upper_bound(rows.begin(), rows.end(), omega,
                                   [](double w, const RaoTable::Row& r) { return w < r.omega; });
  const RaoTable::Row& hi = *it;
  const RaoTable::Row& lo = *(it - 1);
  return Mix(lo.rao, hi.rao, (omega - lo.omega) / (hi.omega - lo.omega));
}

}  // namespace

RaoTable ReadRaoTable(const std::string& path, bool body) {
  const std::vector<std::string> point = {"heading", "omega", "x", "x_phase", "y", "y_phase",
                                          "z", "z_phase"};
  std::vector<std::string> turning = point;
  for (const char* c : {"rx", "rx_phase", "ry", "ry_phase", "rz", "rz_phase"})
    turning.push_back(c);
  std::vector<std::vector<double>> rows;
  RaoTable table;
  const std::string units = "(heading in degrees, omega in rad/s, amplitudes in m/m" +
                            std::string(body ? " and deg/m" : "") + ", phases in degrees)";
  rows = ReadNumberTableOfForms(path, {point, turning}, "the RAO table", units, 1);
  table.turns = !rows.empty() && rows.front().size() == turning.size();
  if (table.turns && !body)
    throw Error(EscapeText(path) + ": rx, ry, rz turn a body; a point's RAO table has the "
                "columns " + "heading,omega,x,x_phase,y,y_phase,z,z_phase");
  std::map<double, std::vector<RaoTable::Row>> by_heading;
  long line = 0;
  for (const std::vector<double>& r : rows) {
    ++line;
    const std::string where = EscapeText(path) + ": data row " + std::to_string(line) + ": ";
    if (!(std::abs(r[0]) <= kMaxPhase))
      throw Error(where + "expected a heading from -360 to 360 degrees, got " + FormatNumber(r[0]));
    if (!(r[1] > 0 && r[1] <= 1e3))
      throw Error(where + "expected omega above 0 and at most 1000 rad/s, got " +
                  FormatNumber(r[1]));
    RaoTable::Row row;
    row.omega = r[1];
    for (std::size_t j = 0; 2 + 2 * j + 1 < r.size(); ++j) {
      const double a = r[2 + 2 * j], p = r[3 + 2 * j];
      if (!(a >= 0 && a <= kMaxRao) || !(std::abs(p) <= kMaxPhase))
        throw Error(where + "expected amplitudes from 0 to " + FormatNumber(kMaxRao) +
                    " and phases from -360 to 360 degrees, got " + FormatNumber(a) + " and " +
                    FormatNumber(p));
      row.rao[j] = {a, p};
    }
    double h = std::fmod(r[0], 360.0);
    if (h < 0) h += 360.0;
    std::vector<RaoTable::Row>& list = by_heading[h];
    if (!list.empty() && !(row.omega > list.back().omega))
      throw Error(where + "expected omega to increase within heading " + FormatNumber(r[0]) +
                  " degrees, got " + FormatNumber(row.omega) + " after " +
                  FormatNumber(list.back().omega));
    list.push_back(row);
  }
  for (auto& [h, list] : by_heading) {
    table.headings.push_back(h);
    table.rows.push_back(std::move(list));
  }
  return table;
}

std::array<std::array<double, 2>, 6> RaoAt(const RaoTable& table, double omega,
                                           double heading) {
  const std::size_t n = table.headings.size();
  if (n == 1) return AtOmega(table.rows[0], omega);
  double h = std::fmod(heading, 360.0);
  if (h < 0) h += 360.0;
  // The headings around h, round the circle: hi the first above it (or the first, past 360).
  const std::size_t hi = static_cast<std::size_t>(
      std::upper_bound(table.headings.begin(), table.headings.end(), h) -
      table.headings.begin());
  const std::size_t a = (hi + n - 1) % n, b = hi % n;
  if (a == b) return AtOmega(table.rows[a], omega);
  double span = table.headings[b] - table.headings[a];
  double from = h - table.headings[a];
  if (span <= 0) span += 360.0;
  if (from < 0) from += 360.0;
  return Mix(AtOmega(table.rows[a], omega), AtOmega(table.rows[b], omega), from / span);
}

}  // namespace cablefilm
