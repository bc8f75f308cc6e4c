#include "scene/scene_loader.h"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <vector>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "scene/input_file.h"
#include "scene/key_source.h"
#include "scene/moordyn_convert.h"
#include "scene/moordyn_file.h"
#include "scene/scene_limits.h"
#include "scene/scene_parser.h"
#include "scene/text_escape.h"

namespace cablefilm {

std::string ReadSceneFile(const std::string& path) {
  return ReadInputFile(path, "scene file", "a scene file (TOML)");
}

bool IsMoorDynText(const std::string& text) {
  // A MoorDyn file's section headers: a line of dashes around a key phrase, "---- LINES ----".
  // Never valid TOML, so a scene is never taken for one.
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    const std::size_t first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line.compare(first, 3, "---") == 0) {
      std::string upper;
      for (char c : line) upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      if (upper.find("LINE") != std::string::npos || upper.find("POINT") != std::string::npos ||
          upper.find("OPTIONS") != std::string::npos)
        return true;
    }
    start = end + 1;
  }
  return false;
}

namespace {

// The scene a MoorDyn file's `text` converts into, refused when larger than a scene file may be:
// the file is then refused alike as it is and converted. The reader's warnings first, then the
// conversion's (as the scene's header lists them); `sources` (optional): where in the file each
// key of the scene came from.
std::string ConvertMoorDyn(const std::string& text, const std::string& path,
                           std::vector<std::string>* warnings, KeySources* sources = nullptr) {
  const MoorDynSystem system = ReadMoorDynText(text, path);
  std::vector<std::string> all = system.warnings;
  std::string scene = MoorDynToToml(system, &all, sources);
  if (scene.size() > kMaxSceneBytes) {
    char mib[32];
    std::snprintf(mib, sizeof mib, "%.1f", static_cast<double>(scene.size()) / (1 << 20));
    throw Error(EscapeText(path) + ": the scene it converts into (cablefilm convert) is " + mib +
                " MiB, from " + std::to_string(system.points.size()) + " rows of POINTS, " +
                std::to_string(system.lines.size()) + " of LINES and " +
                std::to_string(system.line_types.size()) + " of LINE TYPES; expected at most " +
                std::to_string(kMaxSceneBytes >> 20) +
                " MiB, the size limit of a scene file (fewer points or lines)");
  }
  if (warnings) warnings->insert(warnings->end(), all.begin(), all.end());
  return scene;
}

}  // namespace

std::string MoorDynSceneText(const std::string& path, std::vector<std::string>* warnings) {
  return ConvertMoorDyn(ReadSceneFile(path), path, warnings);
}

std::string EditableSceneText(const std::string& path, std::vector<std::string>* warnings) {
  const std::string text = ReadSceneFile(path);
  return IsMoorDynText(text) ? ConvertMoorDyn(text, path, warnings) : text;
}

SceneDef LoadScene(const std::string& path) {
  std::string text = ReadSceneFile(path);
  if (!IsMoorDynText(text)) {
    try {
      return ParseScene(text, path);
    } catch (const Error&) {
      // A MoorDyn file's name (.txt, .dat) that is neither: what the MoorDyn reader finds wrong
      // with it, as `cablefilm convert` says, rather than a TOML syntax error at its line 1.
      const std::string ext = std::filesystem::path(path).extension().string();
      if (ext == ".txt" || ext == ".dat") ReadMoorDynText(text, path);
      throw;
    }
  }
  SceneDef scene;
  std::vector<std::string> warnings;
  KeySources sources;
  text = ConvertMoorDyn(text, path, &warnings, &sources);
  try {
    scene = ParseScene(text, path);
  } catch (const Error& e) {
    // The message's line is the converted scene's: told at the file's row and column instead,
    // else pointed to `cablefilm convert`, which shows that scene.
    const std::string told = MoorDynKeyMessage(e.what(), path, sources);
    if (!told.empty()) throw Error(told);
    throw Error(std::string(e.what()) + " (in the scene converted from this MoorDyn file: "
                "'cablefilm convert " + EscapeText(path) + "' shows it)");
  }
  scene.from_moordyn = true;
  scene.sources = std::move(sources);
  scene.warnings = std::move(warnings);
  return scene;
}

std::string SceneErrorMessage(const std::string& scene_path, const std::string& what) {
  const std::string prefix = EscapeText(scene_path) + ":";
  return what.compare(0, prefix.size(), prefix) == 0 ? what : prefix + " " + what;
}

}  // namespace cablefilm
