#pragma once
// A command of the program as the command line offers it: its subcommand (CLI11), with the
// options it declares beside its own code, and what runs it. main.cpp only dispatches.
#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace cablefilm {

struct Command {
  CLI::App* cli = nullptr;   // its subcommand
  std::function<int()> run;  // the process's exit status; errors thrown as Error
};

// A subcommand taking a scene file (`what` says which kind) into *scene.
CLI::App* AddSceneCommand(CLI::App& program, const std::string& name, const std::string& help,
                          std::string* scene,
                          const std::string& what = "the scene file (TOML, or a MoorDyn v2 "
                                                    "input file)");

// An option taking one value, checked and converted by `apply` (which throws UsageError).
CLI::Option* Value(CLI::App* app, const std::string& name, const std::string& type,
                   const std::string& help, std::function<void(const std::string&)> apply);
// A flag whose effect depends on its place among the others (the last one given wins).
CLI::Option* Flag(CLI::App* app, const std::string& name, const std::string& help,
                  std::function<void()> apply);

// The batch commands, each declared beside its code.
Command DeclareRunCommand(CLI::App& program, std::string* scene);      // commands.cpp
Command DeclareCompareCommand(CLI::App& program, std::string* scene);  // commands.cpp
Command DeclareCheckCommand(CLI::App& program, std::string* scene);    // commands.cpp
Command DeclareConvertCommand(CLI::App& program, std::string* scene);  // convert_command.cpp
Command DeclareStiffnessCommand(CLI::App& program, std::string* scene);  // body_commands.cpp
Command DeclareOffsetCommand(CLI::App& program, std::string* scene);     // body_commands.cpp
Command DeclareSweepCommand(CLI::App& program, std::string* scene);      // sweep_command.cpp

}  // namespace cablefilm
