#include "scene/moordyn_toml_out.h"

#include <algorithm>

#include "scene/text_escape.h"

namespace cablefilm {

void MoorDynTomlOut::Table(const std::string& key, int line, const std::string& place) {
  table = key;
  row = {line, place};
  if (line > 0) sources[key] = row;
}

void MoorDynTomlOut::Source(const std::string& key, int line, const std::string& place) {
  if (line > 0) sources[table.empty() ? key : table + "." + key] = {line, place};
}

void MoorDynTomlOut::Key(const std::string& key, const std::string& value,
                         const std::string& comment, const std::string& columns) {
  if (!columns.empty())
    Source(key, row.line,
           row.place + (columns.find(',') == std::string::npos ? ", column " : ", columns ") +
               columns);
  std::string line = key + " = " + value;
  if (!comment.empty()) {
    constexpr std::size_t kCommentColumn = 34;  // lines up most comments
    line.resize(std::max(line.size() + 1, kCommentColumn), ' ');
    line += "# " + EscapeText(comment);
  }
  text << line << "\n";
}

void MoorDynTomlOut::Comment(const std::string& comment) {
  text << "# " << EscapeText(comment) << "\n";
}

void MoorDynTomlOut::Warn(int line, const std::string& message) {
  warnings.push_back(file + (line > 0 ? ":" + std::to_string(line) : "") + ": " +
                     EscapeText(message));
}

}  // namespace cablefilm
