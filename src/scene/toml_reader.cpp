#include "scene/toml_reader.h"

namespace cablefilm {

toml::table ParseToml(const std::string& text, const std::string& file) {
  try {
    return toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << EscapeText(file) << ":" << e.source().begin.line
       << ": not valid TOML: " << EscapeText(e.description());
    throw Error(os.str());
  }
}

}  // namespace cablefilm
