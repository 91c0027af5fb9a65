#include "app/feather_command.h"

#include <fmt/format.h>

#include <chrono>
#include <memory>
#include "app/interruption.h"
#include "feather/feather_generator.h"

namespace columba {

void addFeatherCommand(CLI::App& app) {
  struct Settings {
    bool single = false, neck = false;
    std::string output;
    FeatherGenerationOptions options;
  };
  auto settings = std::make_shared<Settings>();
  CLI::App* cmd = app.add_subcommand("feather", "Write procedural feather geometry as a feather PLY");
  auto* single = cmd->add_flag("--single", settings->single, "One feather, 1.2 long, centred on the origin, facing +z");
  auto* neck = cmd->add_flag("--neck", settings->neck,
                             "A neck of overlapping feathers (x in [-2.4, 3.4], y in [-1.6, 3], facing +z)");
  single->excludes(neck);
  cmd->add_option("-o,--output", settings->output, "Output PLY file")->required();
  cmd->add_option("--seed", settings->options.seed, "Random seed")->capture_default_str();
  cmd->add_option("--feathers", settings->options.feathers, "Feathers on the neck")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->needs(neck);
  cmd->add_option("--barbs", settings->options.barbsPerSide,
                  "Barbs per side of each feather (default: as many as lie edge to edge at the default barbwidth)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--binary", settings->options.binary, "Write binary_little_endian instead of ASCII");
  // The colour: the barbules' keratin cortex thickness (docs/feather-ply.md).
  FeatherGenerationOptions& o = settings->options;
  cmd->add_option("--height", o.greenHeight, "Cortex thickness of the green barbules (a single feather's), um")
      ->capture_default_str();
  cmd->add_option("--purple-height", o.purpleHeight, "Cortex thickness of the purple barbules, um")
      ->capture_default_str()
      ->needs(neck);
  cmd->add_option("--height-spread", o.heightSpread, "Each feather's thickness varies by up to this much, um")
      ->capture_default_str();
  cmd->add_option("--purple-below", o.purpleBelow,
                  "Height on the neck (y, -1.6 at the top to 3 at the bottom) around which green turns purple")
      ->capture_default_str()
      ->needs(neck);
  cmd->add_option("--colour-blend", o.colourBlend,
                  "Width of the change from green to purple on either side of the boundary (0: sharp)")
      ->capture_default_str()
      ->needs(neck);
  cmd->callback([settings] {
    if (settings->single == settings->neck) throw CLI::ValidationError("feather", "choose one of --single or --neck");
    settings->options.neck = settings->neck;
    auto start = std::chrono::steady_clock::now();
    // Ctrl-C stops at the next barb and removes the unfinished file.
    InterruptionGuard interruption("\nStopping: removing the unfinished file (interrupt again to quit at once)\n");
    interruption.deferStops();
    settings->options.cancel = &interruption.requested();
    FeatherGenerationSummary s = generateFeatherPly(settings->options, settings->output);
    if (!s.written) throw CLI::RuntimeError(128 + interruption.signalNumber());
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    fmt::print(
        "wrote {}: {} feather{}, {} barbs, {} faces, {} vertices in {:.2f} s; barbs lie edge to edge at "
        "barbwidth {:.4g}\n",
        settings->output, s.feathers, s.feathers == 1 ? "" : "s", s.barbs, s.faces, s.vertices, seconds,
        s.tilingBarbWidth);
  });
}

}  // namespace columba
