// cablefilm: the command line. Each command declares its own options beside its code
// (app/command.h, live/live_options.h); here they are gathered, the arguments parsed, and the
// chosen command run. Every bad option is answered on stderr with a message that names it
// (input text escaped) and exit status 2, before anything is read or simulated; --help and
// --version exit 0. Whatever the command, standard output that could not be written is an
// error, status 1.
#include <CLI/CLI.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <regex>
#include <string>
#include <vector>

#include "app/command.h"
#include "app/run_support.h"
#include "core/cancel.h"
#include "core/error.h"
#include "core/version.h"
#ifdef CABLEFILM_LIVE
#include "live/live_options.h"
#endif
#include "scene/option_values.h"
#include "scene/scene_loader.h"
#include "scene/text_escape.h"

namespace {

using cablefilm::Shown;

std::string VersionText() {
  std::string text = std::string("cablefilm ") + cablefilm::kVersion;
  if (*cablefilm::kGitDescribe) text += std::string(" (git ") + cablefilm::kGitDescribe + ")";
  return text;
}

// An error of a command: a scene's file named first (the loader's already start with it).
int ReportError(const std::string& scene, const cablefilm::Error& e) {
  std::fflush(stdout);
  const std::string message = cablefilm::SceneErrorMessage(scene, e.what());
  std::fprintf(stderr, "cablefilm: error: %s\n", message.c_str());
  return 1;
}

// A usage error: the message, then where to read the options; status 2.
int UsageFailure(const std::string& message, const std::string& command) {
  std::fflush(stdout);
  std::fprintf(stderr, "cablefilm: %s\nrun 'cablefilm%s --help' for the options\n",
               message.c_str(), command.empty() ? "" : (" " + command).c_str());
  return 2;
}

// CLI11's own message, escaped (it may quote what was typed); a missing value said plainly.
std::string ParserMessage(const CLI::ParseError& e) {
  std::string message = e.what();
  static const std::regex missing("^(-[^:]*): 1 required (.*) missing$");
  std::smatch m;
  if (std::regex_match(message, m, missing))
    message = m[1].str() + ": missing value (expected " + m[2].str() + ")";
  return cablefilm::EscapeText(message);
}

// What stood before the command other than --help and --version, said; "" when nothing did.
std::string BeforeTheCommand(const CLI::App& app) {
  const std::vector<std::string> extras = app.remaining();
  if (extras.empty()) return "";
  const std::string& what = extras.front();
  if (!what.empty() && what[0] == '-')
    return "unknown option " + Shown(what) + " (options go after the command)";
  return "unknown command " + Shown(what);
}

// The subcommand parsed (the last given).
CLI::App* ChosenCommand(CLI::App& app) {
  CLI::App* command = nullptr;
  for (CLI::App* c : app.get_subcommands()) command = c;
  return command;
}

// What the program printed must have reached standard output (a full disk, /dev/full, a closed
// descriptor lose it silently otherwise): an error naming it, status 1 unless already failing.
int CheckedStdout(int status) {
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  if (flushed && !std::ferror(stdout)) return status;
  std::fprintf(stderr, "cablefilm: error: cannot write standard output: %s\n",
               !flushed && error ? std::strerror(error)
                                     : "a write to it failed, the output is incomplete");
  return status == 0 ? 1 : status;
}

// The program: parses the command line and runs the command; its exit status.
int Main(int argc, char** argv) {
  CLI::App app("cablefilm " + std::string(cablefilm::kVersion) +
                   ": a lumped-mass cable in a fluid (Polachek et al. 1963), simulated and "
                   "filmed with its tension",
               "cablefilm");
  app.set_version_flag("--version", VersionText(), "print the version and exit");
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.allow_extras();
  app.get_formatter()->column_width(27);

  std::string scene;
  std::vector<cablefilm::Command> commands = {
      cablefilm::DeclareRunCommand(app, &scene),       cablefilm::DeclareCompareCommand(app, &scene),
      cablefilm::DeclareCheckCommand(app, &scene),     cablefilm::DeclareConvertCommand(app, &scene),
      cablefilm::DeclareStiffnessCommand(app, &scene), cablefilm::DeclareOffsetCommand(app, &scene),
      cablefilm::DeclareSweepCommand(app, &scene)};
#ifdef CABLEFILM_LIVE
  cablefilm::LiveCommandOptions live_options;
  commands.push_back({cablefilm::DeclareLiveCommand(app, &scene, &live_options),
                      [&] { return cablefilm::LiveCommand(scene, live_options); }});
#endif
  app.footer("'cablefilm COMMAND --help' shows the options of a command; 'cablefilm --version'\n"
             "the version.");

  if (argc < 2) return UsageFailure("missing command", "");
  const std::string first = argv[1];
  if (first == "help") {  // `cablefilm help [COMMAND]`
    const CLI::App* about = &app;
    if (argc > 2) {
      try {
        about = app.get_subcommand(argv[2]);
      } catch (const CLI::OptionNotFound&) {
        return UsageFailure("unknown command " + Shown(argv[2]), "");
      }
    }
    std::printf("%s", about == &app ? app.help().c_str() : about->help("cablefilm").c_str());
    return 0;
  }
#ifndef CABLEFILM_LIVE
  if (first == "live") {
    std::fprintf(stderr,
                 "cablefilm: this build has no live view (configured with CABLEFILM_RENDER=OFF)\n");
    return 2;
  }
#endif

  CLI::App* command = nullptr;
  try {
    app.parse(argc, argv);
    if (const std::string bad = BeforeTheCommand(app); !bad.empty()) return UsageFailure(bad, "");
    command = ChosenCommand(app);
    if (!command) return UsageFailure("missing command", "");
    for (const std::string& extra : command->remaining())
      cablefilm::Bad(!extra.empty() && extra[0] == '-'
                         ? "unknown option " + Shown(extra) + " for " + command->get_name()
                         : "more than one scene given");
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    if (const std::string bad = BeforeTheCommand(app); !bad.empty()) return UsageFailure(bad, "");
    command = ChosenCommand(app);
    return UsageFailure(ParserMessage(e), command ? command->get_name() : "");
  } catch (const cablefilm::UsageError& e) {
    if (!command) command = ChosenCommand(app);
    return UsageFailure(e.what(), command ? command->get_name() : "");
  }

  try {
    for (const cablefilm::Command& c : commands)
      if (c.cli == command) return c.run();
    return UsageFailure("unknown command " + Shown(command->get_name()), "");
  } catch (const cablefilm::UsageError& e) {  // an option's check that needs the others
    return UsageFailure(e.what(), command->get_name());
  } catch (const cablefilm::CancelledError& e) {  // a signal seen inside the work
    std::fflush(stdout);
    std::fprintf(stderr, "cablefilm: %s\n", e.what());
    return cablefilm::InterruptedExitStatus();
  } catch (const cablefilm::Error& e) {
    return ReportError(scene, e);
  }
}

}  // namespace

int main(int argc, char** argv) { return CheckedStdout(Main(argc, argv)); }
