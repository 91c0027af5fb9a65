// columba: the command-line front end.
#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "app/bsdf_command.h"
#include "app/feather_command.h"
#include "app/montage_command.h"
#include "app/render_command.h"

int main(int argc, char** argv) {
  CLI::App app{"Columba: a spectral renderer for iridescent bird feathers"};
  app.require_subcommand(1);
  columba::addRenderCommand(app);
  columba::addFeatherCommand(app);
  columba::addBSDFCommand(app);
  columba::addMontageCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 1;
  }
  return 0;
}
