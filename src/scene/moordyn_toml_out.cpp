#include "scene/moordyn_toml_out.h"

#include <algorithm>

#include "scene/text_escape.h"

namespace cablefilm {

void MoorDynTomlOut::Key(const std::string& key, const std::string& value,
                         const std::string& comment) {
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
