#include "app/command.h"

namespace cablefilm {

CLI::App* AddSceneCommand(CLI::App& program, const std::string& name, const std::string& help,
                          std::string* scene, const std::string& what) {
  CLI::App* cmd = program.add_subcommand(name, help);
  cmd->add_option("SCENE", *scene, what)->type_name("")->required();
  cmd->allow_extras();  // unknown options and a second scene: reported by main, by name
  return cmd;
}

CLI::Option* Value(CLI::App* app, const std::string& name, const std::string& type,
                   const std::string& help, std::function<void(const std::string&)> apply) {
  return app->add_option_function<std::string>(name, std::move(apply), help)->type_name(type);
}

CLI::Option* Flag(CLI::App* app, const std::string& name, const std::string& help,
                  std::function<void()> apply) {
  return app->add_flag_callback(name, std::move(apply), help)->trigger_on_parse();
}

}  // namespace cablefilm
