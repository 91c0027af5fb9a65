#include "app/feather_command.h"

#include <fmt/format.h>

#include <chrono>
#include <memory>
#include "app/interruption.h"
#include "barbule/parameter_reader.h"
#include "feather/feather_generator.h"
#include "feather/rock_dove.h"

namespace columba {

namespace {

// --barbule's NAME=VALUE pairs, read as a scene's <bsdf type="barbulebsdf"> is, so that a mistake
// is refused (naming the option) before anything is written. Numbered layer stacks are taken
// where the purple feathers choose one (`purpleStack` > 0), and must then reach it.
std::vector<std::pair<std::string, std::string>> checkedBarbuleParameters(const std::vector<std::string>& given,
                                                                          int purpleStack) {
  std::vector<std::pair<std::string, std::string>> pairs;
  Properties props;
  props.tag = "bsdf";
  props.type = "barbulebsdf";
  props.nameParameter = [](const std::string& name) { return "--barbule " + name; };
  for (const std::string& item : given) {
    const size_t equals = item.find('=');
    if (equals == std::string::npos || equals == 0)
      throw CLI::ValidationError("--barbule", "give NAME=VALUE, not '" + item + "'");
    const std::string name = item.substr(0, equals), value = item.substr(equals + 1);
    // The generated feathers carry H, mu and height at every vertex, which win over the BSDF's.
    if (name == "height")
      throw CLI::ValidationError("--barbule",
                                 "each neck feather's cortex thickness comes from --height and "
                                 "--purple-height (and --height-spread), not from the BSDF");
    if (name == "H" || name == "mu" || name == "preset")
      throw CLI::ValidationError("--barbule", "'" + name +
                                                  "' would have no effect: the feathers give every vertex its own "
                                                  "spacing H and tilt mu (a preset sets those; give b, phi_0 and "
                                                  "phi_1 instead)");
    if (props.has(name)) throw CLI::ValidationError("--barbule", "'" + name + "' is given twice");
    props.setFromText(name, value);
    pairs.emplace_back(name, value);
  }
  std::optional<BarbuleParameterProblem> odd;
  readBarbuleParameters(props, odd);
  readBarbuleQuadrature(props);  // trt_offsets, trt_angles
  const size_t stacks = readNumberedLayerStacks(props).size();
  if (stacks != size_t(purpleStack))
    throw CLI::ValidationError(
        "--purple-stack",
        purpleStack == 0
            ? fmt::format("--barbule {} would have no effect: no feather chooses a numbered layer stack (give "
                          "--purple-stack N for the purple feathers to choose layers_N)",
                          layerStackParameter(1))
            : fmt::format("the purple feathers choose layer stack {}: give --barbule layers_1=... to {}=... "
                          "(numbered without gaps), and none beyond it ({} given)",
                          purpleStack, layerStackParameter(purpleStack), stacks));
  try {
    props.checkAllUsed();
  } catch (const std::exception& e) {
    throw CLI::ValidationError("--barbule", e.what());  // an unknown name
  }
  if (odd) fmt::print(stderr, "warning: --barbule {}: {}\n", odd->parameter, odd->message);
  return pairs;
}

}  // namespace

void addFeatherCommand(CLI::App& app) {
  struct Settings {
    bool single = false, neck = false, bird = false;
    std::string output;
    FeatherGenerationOptions options;
    float featherScale = 1.0f;
    std::vector<std::string> barbule;
  };
  auto settings = std::make_shared<Settings>();
  CLI::App* cmd = app.add_subcommand("feather", "Write procedural feather geometry as a feather PLY");
  auto* single = cmd->add_flag("--single", settings->single, "One feather, 1.2 long, centred on the origin, facing +z");
  auto* neck = cmd->add_flag("--neck", settings->neck,
                             "A neck of overlapping feathers (x in [-2.4, 3.4], y in [-1.6, 3], facing +z)");
  auto* bird =
      cmd->add_flag("--bird", settings->bird,
                    "A rock dove (cm, x toward the beak, y up): -o names a directory for rock_dove.xml, a scene "
                    "to <include>, and its feather templates");
  single->excludes(neck, bird);
  neck->excludes(bird);
  cmd->add_option("-o,--output", settings->output, "Output PLY file (a directory with --bird)")->required();
  cmd->add_option("--seed", settings->options.seed, "Random seed")->capture_default_str();
  cmd->add_option("--feathers", settings->options.feathers, "Feathers on the neck")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->needs(neck);
  cmd->add_option("--barbs", settings->options.barbsPerSide,
                  "Barbs per side of each feather (default: as many as lie edge to edge at the default barbwidth)")
      ->check(CLI::PositiveNumber)
      ->excludes(bird);
  cmd->add_flag("--binary", settings->options.binary,
                "Write binary_little_endian instead of ASCII (the bird's templates are always binary)")
      ->excludes(bird);
  // The colour: the barbules' keratin cortex thickness (docs/feather-ply.md).
  FeatherGenerationOptions& o = settings->options;
  cmd->add_option("--height", o.greenHeight, "Cortex thickness of the green barbules (a single feather's), um")
      ->capture_default_str();
  cmd->add_option("--purple-height", o.purpleHeight, "Cortex thickness of the purple barbules, um")
      ->capture_default_str()
      ->excludes(single);
  cmd->add_option("--feather-scale", settings->featherScale,
                  "With --bird: every feather this much larger (fewer feathers) or smaller (more), 0.2 to 5")
      ->capture_default_str()
      ->needs(bird);
  cmd->add_option("--barbule", settings->barbule,
                  "With --bird: a further parameter of the neck's barbule BSDF, NAME=VALUE as in a scene (e.g. "
                  "profile_exponent=4, layers=parotia-occipital); repeatable")
      ->needs(bird);
  cmd->add_option("--height-spread", o.heightSpread, "Each feather's thickness varies by up to this much, um")
      ->capture_default_str();
  cmd->add_option("--purple-below", o.purpleBelow,
                  "Height on the neck (y, -1.6 at the top to 3 at the bottom) around which green turns purple")
      ->capture_default_str()
      ->needs(neck);
  auto* purpleStack =
      cmd->add_option("--purple-stack", o.purpleStack,
                      "The layer stack (1 to 15) the purple barbules choose, written per vertex as 'stack': their "
                      "barbulebsdf's layers_N (docs/feather-ply.md); with --bird, give it as --barbule layers_N=...")
          ->check(CLI::Range(1, kMaxLayerStacks - 1));
  purpleStack->excludes(single);
  cmd->add_option("--colour-blend", o.colourBlend,
                  "Width of the change from green to purple on either side of the boundary (0: sharp)")
      ->capture_default_str()
      ->needs(neck);
  cmd->callback([settings, cmd] {
    if (int(settings->single) + int(settings->neck) + int(settings->bird) != 1)
      throw CLI::ValidationError("feather", "choose one of --single, --neck or --bird");
    settings->options.neck = settings->neck;
    auto start = std::chrono::steady_clock::now();
    // Ctrl-C stops at the next barb and removes the unfinished file.
    InterruptionGuard interruption("\nStopping: removing the unfinished file (interrupt again to quit at once)\n");
    interruption.deferStops();
    settings->options.cancel = &interruption.requested();
    if (settings->bird) {
      RockDoveOptions dove;
      dove.seed = settings->options.seed;
      dove.featherScale = settings->featherScale;
      dove.greenHeight = settings->options.greenHeight;
      dove.purpleHeight = settings->options.purpleHeight;
      if (cmd->count("--height-spread") > 0) dove.heightSpread = settings->options.heightSpread;
      dove.purpleStack = settings->options.purpleStack;
      dove.barbule = checkedBarbuleParameters(settings->barbule, dove.purpleStack);
      dove.cancel = settings->options.cancel;
      RockDoveSummary s = writeRockDove(dove, settings->output);
      if (!s.written) throw CLI::RuntimeError(128 + interruption.signalNumber());
      double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      fmt::print(
          "wrote {}/rock_dove.xml: {} feathers ({} iridescent), copies of {} templates of {} barbs in all, in {:.2f} "
          "s\n",
          settings->output, s.feathers, s.iridescent, dove.templates, s.templateBarbs, seconds);
      return;
    }
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
