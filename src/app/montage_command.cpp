#include "app/montage_command.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "io/output_directory.h"
#include "plot/canvas.h"
#include "plot/contact_sheet.h"

namespace columba {

namespace {
struct MontageOptions {
  std::vector<std::string> inputs;
  std::string output;
  int columns = 4;
  int tileWidth = 320;
  std::string title;
  std::vector<std::string> labels;  // one per image, in order; the file name's stem when none
  std::string labelsFile;           // one label per line
};

// The labels given with --label or in --labels FILE, one per image.
std::vector<std::string> readLabels(const MontageOptions& options) {
  std::vector<std::string> labels = options.labels;
  if (!options.labelsFile.empty()) {
    if (!labels.empty()) throw std::runtime_error("give the labels either with --label or with --labels, not both");
    std::ifstream in(options.labelsFile);
    if (!in) throw std::runtime_error("cannot read the labels file '" + options.labelsFile + "'");
    for (std::string line; std::getline(in, line);) labels.push_back(line);
  }
  if (!labels.empty() && labels.size() != options.inputs.size())
    throw std::runtime_error(std::to_string(labels.size()) + " labels for " + std::to_string(options.inputs.size()) +
                             " images: give one label per image");
  return labels;
}

void runMontage(const MontageOptions& options) {
  // Before reading the inputs; a missing directory is made once the sheet is.
  const bool vector = isVectorFigurePath(options.output);
  if (vector) checkOutputDirectory(options.output, directoryOf(options.output));
  const ImageFormat format = vector ? ImageFormat::PNG : checkOutputImagePath(options.output, true);
  const std::vector<std::string> labels = readLabels(options);
  std::vector<ContactSheetEntry> entries;
  for (const std::string& path : options.inputs) {
    std::filesystem::path p(path);
    std::string extension = p.extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    Image image = extension == ".exr" ? readEXR(path) : readPNG(path);
    entries.push_back({std::move(image), labels.empty() ? p.stem().string() : labels[entries.size()]});
  }
  std::string inputs;
  for (const std::string& path : options.inputs) inputs += (inputs.empty() ? "" : "\n") + path;
  const ImageMetadata metadata = {{"Images", inputs}};
  makeOutputDirectory(options.output, directoryOf(options.output));
  if (vector) {
    writeContactSheet(options.output, entries, options.columns, options.tileWidth, options.title);
    return;
  }
  Image sheet = makeContactSheet(entries, options.columns, options.tileWidth, options.title);
  if (format == ImageFormat::EXR)
    writeEXR(options.output, sheet, metadata);
  else
    writePNG(options.output, sheet, metadata);
}
}  // namespace

void addMontageCommand(CLI::App& app) {
  auto options = std::make_shared<MontageOptions>();
  CLI::App* cmd =
      app.add_subcommand("montage", "Arrange images (PNG or EXR) into a labelled contact sheet (PNG, EXR, SVG or PDF)");
  cmd->add_option("images", options->inputs, "Images, in order")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", options->output,
                  "Contact sheet, .png, .exr, .svg or .pdf (its directory made if missing)")
      ->required();
  cmd->add_option("--columns", options->columns, "Tiles per row")->check(CLI::Range(1, 64));
  cmd->add_option("--tile", options->tileWidth, "Tile width in pixels")->check(CLI::Range(16, 4096));
  cmd->add_option("--title", options->title, "Title above the sheet (wrapped to its width)");
  cmd->add_option("--label", options->labels, "Label of the next image, in order (repeat once per image)")
      ->allow_extra_args(false);
  cmd->add_option("--labels", options->labelsFile, "File with one label per line, one per image")
      ->check(CLI::ExistingFile);
  cmd->callback([options] { runMontage(*options); });
}

}  // namespace columba
