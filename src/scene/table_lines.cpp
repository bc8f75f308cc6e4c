#include "scene/table_lines.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "core/error.h"
#include "scene/scene_limits.h"
#include "scene/text_escape.h"

namespace cablefilm {
namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

}  // namespace

std::string ShownLine(const std::string& line) {
  constexpr std::size_t kShown = 60;
  return line.size() <= kShown ? QuoteText(line) : QuoteText(line.substr(0, kShown)) + "...";
}

void ReadTableLines(const std::string& path, const std::string& what, const std::string& expected,
                    const std::function<void(std::string&& line, long number)>& take) {
  const std::string name = EscapeText(path);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw Error(name + ": is a directory; expected " + what + ", a CSV file of " + expected);
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) throw Error(name + ": cannot open " + what + ": " + std::strerror(errno));
  long number = 0;
  std::uintmax_t bytes = 0;
  std::string line;
  const auto pass = [&] {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    take(std::move(line), number);
    line.clear();
  };
  char buffer[1 << 16];
  for (;;) {
    const std::size_t n = std::fread(buffer, 1, sizeof buffer, file.get());
    if (n == 0) {
      if (std::ferror(file.get()))
        throw Error(name + ": cannot read " + what + ": " + std::strerror(errno));
      break;
    }
    bytes += n;
    if (bytes > kMaxTableBytes)
      throw Error(name + ": larger than " + std::to_string(kMaxTableBytes >> 20) +
                  " MiB; expected " + what + " of at most that size (" +
                  std::to_string(kMaxTableRows) + " rows)");
    for (std::size_t i = 0; i < n; ++i) {
      if (buffer[i] == '\n') {
        ++number;
        pass();
        continue;
      }
      if (line.size() >= kMaxTableLineLength)
        throw Error(name + ":" + std::to_string(number + 1) + ": longer than " +
                    std::to_string(kMaxTableLineLength) + " characters; expected " + expected +
                    ", got " + ShownLine(line));
      line += buffer[i];
    }
  }
  if (!line.empty()) {
    ++number;
    pass();
  }
}

}  // namespace cablefilm
