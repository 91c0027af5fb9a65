// columba: the command-line front end.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>

#include "app/bsdf_command.h"
#include "app/cli_checks.h"
#include "app/compare_command.h"
#include "app/feather_command.h"
#include "app/fit_command.h"
#include "app/merge_command.h"
#include "app/montage_command.h"
#include "app/render_command.h"
#include "app/slurm_command.h"
#include "core/version.h"

namespace {

// "unknown command 'rendr' — did you mean 'render'?", or "" when the first argument is a
// command or an option.
std::string unknownCommandMessage(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return "";
  std::vector<std::string> commands;
  for (const CLI::App* command : app.get_subcommands({})) commands.push_back(command->get_name());
  if (std::find(commands.begin(), commands.end(), argv[1]) != commands.end()) return "";
  std::string message = fmt::format("unknown command '{}'", argv[1]);
  std::string suggestion = columba::closestName(argv[1], commands);
  if (!suggestion.empty()) return message + " \u2014 did you mean '" + suggestion + "'?";
  std::string list;
  for (const std::string& c : commands) list += (list.empty() ? "" : ", ") + c;
  return message + " (commands: " + list + ")";
}

// Arguments the parser did not expect, named with the option they were probably meant to be.
std::string unexpectedArgumentsMessage(const CLI::App& app) {
  const std::vector<CLI::App*> used = app.get_subcommands();
  const CLI::App& command = used.empty() ? app : *used.front();
  std::string message;
  for (const std::string& argument : command.remaining()) {
    if (!message.empty()) message += "\n";
    if (argument.size() < 2 || argument[0] != '-') {
      message += fmt::format("unexpected argument '{}'", argument);
      continue;
    }
    const std::string name = argument.substr(0, argument.find('='));
    message += fmt::format("unknown option '{}' for '{}'", name, command.get_name());
    std::string suggestion = columba::closestName(name, columba::optionNames(command));
    if (!suggestion.empty()) message += " \u2014 did you mean '" + suggestion + "'?";
  }
  return message;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Columba: a spectral renderer for iridescent bird feathers", "columba"};
  app.set_version_flag("--version", std::string("columba ") + columba::kColumbaVersion);
  app.require_subcommand(1);
  columba::addRenderCommand(app);
  columba::addFeatherCommand(app);
  columba::addBSDFCommand(app);
  columba::addMontageCommand(app);
  columba::addFitCommand(app);
  columba::addMergeCommand(app);
  columba::addCompareCommand(app);
  columba::addSlurmCommand(app);
  columba::requireFiniteNumbers(app);
  if (std::string message = unknownCommandMessage(app, argc, argv); !message.empty()) {
    fmt::print(stderr, "error: {}\nRun with --help for more information.\n", message);
    return 1;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // Unexpected arguments are named even when another error (such as a missing command) was
    // found first: they are usually its cause.
    std::string unexpected = e.get_exit_code() == 0 ? "" : unexpectedArgumentsMessage(app);
    if (unexpected.empty()) return app.exit(e);
    fmt::print(stderr, "error: {}\nRun with --help for more information.\n", unexpected);
    return e.get_exit_code();
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  }
  return 0;
}
