#pragma once
// `cablefilm live`'s options, declared beside the live view (the program links them without the
// live view, which it loads as a module when it serves).
#include <CLI/CLI.hpp>

#include <string>

#include "live/live_command.h"

namespace cablefilm {

// The `live` subcommand of `program`: its scene into *scene, its options into *options.
CLI::App* DeclareLiveCommand(CLI::App& program, std::string* scene, LiveCommandOptions* options);

}  // namespace cablefilm
