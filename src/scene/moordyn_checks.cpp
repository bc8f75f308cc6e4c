#include "scene/moordyn_checks.h"

#include <unordered_map>
#include <vector>

#include "core/error.h"
#include "scene/text_escape.h"

namespace cablefilm {
namespace {

std::string Where(const std::string& file, int line, const char* section, int row,
                  const char* column) {
  return file + ":" + std::to_string(line) + ": " + section + " row " + std::to_string(row) +
         ", column " + column + ": ";
}

std::string TypeNames(const MoorDynSystem& system) {
  std::string names;
  for (const auto& t : system.line_types) names += (names.empty() ? "" : ", ") + QuoteText(t.name);
  return names.empty() ? "none: the file has no LINE TYPES" : names;
}

void CheckType(const std::string& file, const MoorDynSystem& system,
               const std::unordered_map<std::string, std::size_t>& types,
               const MoorDynLine& line) {
  if (types.count(line.type)) return;
  throw Error(Where(file, line.line, "LINES", line.id, "LineType") +
              "expected the name of a line type of LINE TYPES (" + TypeNames(system) +
              "), got " + QuoteText(line.type));
}

void CheckPoint(const std::string& file, const MoorDynSystem& system, const MoorDynLine& line,
                int point, const char* column) {
  if (point <= static_cast<int>(system.points.size())) return;
  throw Error(Where(file, line.line, "LINES", line.id, column) + "point " +
              std::to_string(point) + " is not defined; expected " +
              (system.points.empty() ? std::string("a point of POINTS (the file has none)")
                                     : "a point's ID from 1 to " +
                                           std::to_string(system.points.size()) + " (POINTS)"));
}

void CheckBody(const std::string& file, const MoorDynSystem& system, const MoorDynPoint& p) {
  if (p.attachment != MoorDynAttachment::kBody ||
      p.body <= static_cast<int>(system.bodies.size()))
    return;
  throw Error(Where(file, p.line, "POINTS", p.id, "Attachment") + "body " +
              std::to_string(p.body) + " is not defined; expected " +
              (system.bodies.empty() ? std::string("a body of BODIES (the file has none)")
                                     : "Body1 to Body" + std::to_string(system.bodies.size()) +
                                           " (BODIES)"));
}

}  // namespace

void CheckMoorDynReferences(const std::string& file, MoorDynSystem* system) {
  std::vector<bool> used(system->points.size() + 1, false);
  const auto types = MoorDynLineTypeIndex(*system);
  for (const MoorDynLine& line : system->lines) {
    CheckType(file, *system, types, line);
    CheckPoint(file, *system, line, line.point_a, "AttachA");
    CheckPoint(file, *system, line, line.point_b, "AttachB");
    used[line.point_a] = used[line.point_b] = true;
  }
  for (const MoorDynPoint& p : system->points) {
    CheckBody(file, *system, p);
    if (!used[p.id])
      system->warnings.push_back(file + ":" + std::to_string(p.line) + ": POINTS row " +
                                 std::to_string(p.id) + ": point " + std::to_string(p.id) +
                                 " is attached to no line");
  }
}

}  // namespace cablefilm
