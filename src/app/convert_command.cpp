#include "app/commands.h"

#include <cstdio>

#include "io/atomic_file.h"
#include "scene/scene_loader.h"
#include "scene/text_escape.h"

namespace cablefilm {

int ConvertCommand(const std::string& path, const std::string& out_path) {
  std::vector<std::string> warnings;
  const std::string text = MoorDynSceneText(path, &warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  if (out_path.empty() || out_path == "-") {
    std::fputs(text.c_str(), stdout);
    return 0;
  }
  AtomicFile file(out_path);
  std::fputs(text.c_str(), file.stream());
  file.Commit();
  std::fprintf(stderr, "wrote %s\n", EscapeText(out_path).c_str());
  return 0;
}

}  // namespace cablefilm
