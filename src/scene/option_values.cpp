#include "scene/option_values.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "scene/film_settings.h"
#include "scene/scene_limits.h"
#include "scene/text_escape.h"

namespace cablefilm {

void Bad(const std::string& message) { throw UsageError(message); }

std::string Shown(const std::string& text) { return QuoteText(text); }

bool ParseDouble(const std::string& text, double* v) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
  char* end = nullptr;
  errno = 0;
  *v = std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0' && errno != ERANGE && std::isfinite(*v);
}

double ParseNumber(const std::string& option, const std::string& text, double lo, double hi,
                   bool lo_open, const std::string& unit) {
  double v = 0;
  const bool ok = ParseDouble(text, &v) && (lo_open ? v > lo : v >= lo) && v <= hi;
  if (!ok)
    Bad(option + ": expected a number " + (lo_open ? "above " : "from ") + FormatNumber(lo) +
        " to " + FormatNumber(hi) + unit + ", got " + Shown(text));
  return v;
}

void ParseSize(const std::string& option, const std::string& s, int* width, int* height) {
  const std::size_t x = s.find('x');
  auto whole = [](const std::string& part, long max, int* out) {
    if (part.empty() || part.size() > 6 ||
        part.find_first_not_of("0123456789") != std::string::npos)
      return false;
    const long v = std::stol(part);
    if (v < kMinFilmSize || v > max || v % 2) return false;
    *out = static_cast<int>(v);
    return true;
  };
  if (x == std::string::npos || !whole(s.substr(0, x), kMaxFilmWidth, width) ||
      !whole(s.substr(x + 1), kMaxFilmHeight, height))
    Bad(option + ": expected WxH with even numbers of pixels, " + std::to_string(kMinFilmSize) +
        "x" + std::to_string(kMinFilmSize) + " to " + std::to_string(kMaxFilmWidth) + "x" +
        std::to_string(kMaxFilmHeight) + ", got " + Shown(s));
}

std::string ParseColormap(const std::string& option, const std::string& text) {
  std::string list;
  for (const std::string& name : ColormapNames()) {
    if (name == text) return name;
    list += (list.empty() ? "" : ", ") + name;
  }
  Bad(option + ": expected one of " + list + ", got " + Shown(text));
}

std::string ParseView(const std::string& option, const std::string& text) {
  if (ViewProblem(text).empty()) return text;
  Bad(option + ": " + ViewProblem(text));
}

std::string ParseShaderDir(const std::string& option, const std::string& text) {
  std::error_code ec;
  if (!std::filesystem::is_directory(text, ec))
    Bad(option + ": expected a folder of GLSL shaders, got " + Shown(text));
  return text;
}

void ParseTensionRange(const std::string& option, const std::string& v, double* lo, double* hi) {
  const std::size_t comma = v.find(',');
  if (comma == std::string::npos || !ParseDouble(v.substr(0, comma), lo) ||
      !ParseDouble(v.substr(comma + 1), hi) || !(*lo >= 0) || !(*hi > *lo) ||
      !(*hi <= kMaxTension))
    Bad(option + ": expected MIN,MAX in N with " + FormatNumber(kMaxTension) +
        " >= MAX > MIN >= 0, got " + Shown(v));
}

}  // namespace cablefilm
