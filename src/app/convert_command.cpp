#include "app/commands.h"

#include <cstdio>
#include <memory>

#include "app/output_over_input.h"
#include "io/output_file.h"
#include "scene/scene_loader.h"
#include "scene/text_escape.h"

namespace cablefilm {

int ConvertCommand(const std::string& path, const std::string& out_path) {
  RefuseOutputOverInput(out_path, {path});
  std::vector<std::string> warnings;
  const std::string text = MoorDynSceneText(path, &warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  if (out_path.empty() || out_path == "-") {
    std::fputs(text.c_str(), stdout);  // main checks that standard output took it
    return 0;
  }
  WriteOutputFile(out_path, text);
  std::fprintf(stderr, "wrote %s\n", EscapeText(out_path).c_str());
  return 0;
}

Command DeclareConvertCommand(CLI::App& program, std::string* scene) {
  auto out = std::make_shared<std::string>();
  CLI::App* cmd =
      AddSceneCommand(program, "convert",
                      "write a MoorDyn v2 input file as the equivalent scene (TOML)", scene,
                      "the MoorDyn v2 input file");
  cmd->add_option("-o,--out", *out, "the scene file to write (default: standard output)")
      ->type_name("FILE");
  cmd->footer(
      "'run', 'check' and 'sweep' read a MoorDyn file as it is, through this scene (a sweep\n"
      "sets its keys); MoorDyn's z-up axes become cablefilm's y-up ones: (x, y, z) ->\n"
      "(x, z, -y). See docs/moordyn.md.");
  return {cmd, [scene, out] { return ConvertCommand(*scene, *out); }};
}

}  // namespace cablefilm
