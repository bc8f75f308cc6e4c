#include "scene/input_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "scene/scene_limits.h"
#include "scene/text_escape.h"

namespace cablefilm {

std::string ReadInputFile(const std::string& path, const std::string& what,
                          const std::string& expected) {
  const std::string name = EscapeText(path);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw Error(name + ": is a directory; expected " + expected);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(name + ": cannot open the " + what + ": " + std::strerror(errno));
  // At most kMaxSceneBytes, checked while reading, whatever the file is (/dev/zero).
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxSceneBytes)
      throw Error(name + ": larger than " + std::to_string(kMaxSceneBytes >> 20) +
                  " MiB; expected a " + what + " of at most that size");
  }
  if (in.bad()) throw Error(name + ": cannot read the " + what);
  return text;
}

}  // namespace cablefilm
