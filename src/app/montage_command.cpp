#include "app/montage_command.h"

#include <cctype>
#include <filesystem>

#include "plot/contact_sheet.h"

namespace columba {

namespace {
struct MontageOptions {
  std::vector<std::string> inputs;
  std::string output;
  int columns = 4;
  int tileWidth = 320;
  std::string title;
};

void runMontage(const MontageOptions& options) {
  const ImageFormat format = checkOutputImagePath(options.output);  // before reading the inputs
  std::vector<ContactSheetEntry> entries;
  for (const std::string& path : options.inputs) {
    std::filesystem::path p(path);
    std::string extension = p.extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    Image image = extension == ".exr" ? readEXR(path) : readPNG(path);
    entries.push_back({std::move(image), p.stem().string()});
  }
  Image sheet = makeContactSheet(entries, options.columns, options.tileWidth, options.title);
  std::string inputs;
  for (const std::string& path : options.inputs) inputs += (inputs.empty() ? "" : "\n") + path;
  const ImageMetadata metadata = {{"Images", inputs}};
  if (format == ImageFormat::EXR) writeEXR(options.output, sheet, metadata);
  else writePNG(options.output, sheet, metadata);
}
}  // namespace

void addMontageCommand(CLI::App& app) {
  auto options = std::make_shared<MontageOptions>();
  CLI::App* cmd = app.add_subcommand("montage", "Arrange images (PNG or EXR) into a labelled contact sheet (PNG or EXR)");
  cmd->add_option("images", options->inputs, "Images, in order")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", options->output, "Contact sheet, .png or .exr")->required();
  cmd->add_option("--columns", options->columns, "Tiles per row")->check(CLI::Range(1, 64));
  cmd->add_option("--tile", options->tileWidth, "Tile width in pixels")->check(CLI::Range(16, 4096));
  cmd->add_option("--title", options->title, "Title above the sheet");
  cmd->callback([options] { runMontage(*options); });
}

}  // namespace columba
