#include "io/output_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/error.h"
#include "io/atomic_file.h"
#include "scene/text_escape.h"

namespace cablefilm {
namespace {

namespace fs = std::filesystem;

// A device or a pipe: opened and written as it is, every failure said.
void WriteInPlace(const std::string& path, const std::string& text) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw Error("cannot open " + EscapeText(path) + ": " + std::strerror(errno));
  errno = 0;
  const bool written =
      std::fwrite(text.data(), 1, text.size(), f) == text.size() && std::fflush(f) == 0;
  const int write_error = errno;
  const bool closed = std::fclose(f) == 0;
  if (!written || !closed)
    throw Error("cannot write " + EscapeText(path) + ": " +
                std::strerror(!written && write_error ? write_error : errno));
}

}  // namespace

void WriteOutputFile(const std::string& path, const std::string& text) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status))
    return WriteInPlace(path, text);
  fs::path target = path;  // a link stays a link: the file it names is replaced
  if (fs::is_symlink(fs::symlink_status(path, ec))) {
    const fs::path resolved = fs::weakly_canonical(path, ec);
    if (!ec) target = resolved;
  }
  AtomicFile file(target.string());
  std::fwrite(text.data(), 1, text.size(), file.stream());
  file.Commit();
}

}  // namespace cablefilm
