#include "app/merge_command.h"

#include <fmt/format.h>

#include <filesystem>

#include "distribute/manifest.h"
#include "distribute/merge.h"
#include "io/output_directory.h"

namespace columba {

namespace {

struct MergeOptions {
  std::vector<std::string> pieces;
  std::string output;
  std::string manifest;
  int frame = -1;
};

// OUT.exr and OUT.png from -o naming either, neither of them one of the pieces.
std::pair<std::string, std::string> outputPair(const std::string& output, const std::vector<std::string>& pieces) {
  std::filesystem::path exr = output, png = output;
  if (checkOutputImagePath(output, true) == ImageFormat::EXR)
    png.replace_extension(".png");
  else
    exr.replace_extension(".exr");
  checkOutputImagePath(exr.string(), true);
  checkOutputImagePath(png.string(), true);
  for (const std::filesystem::path& out : {exr, png})
    refuseWritingOverAnInput(out.string(), pieces, "the merged image", "the piece", "the merge");
  return {exr.string(), png.string()};
}

std::string mergedFrom(const MergedImage& merged) {
  return merged.passes > 1 ? fmt::format(
                                 "{} parts x {} passes (pass means weighted by their sample counts, summed "
                                 "in double: equal to a one-piece render to float32 round-off)",
                                 merged.parts, merged.passes)
                           : fmt::format("{} parts (bit-identical to a one-piece render)", merged.parts);
}

void writeMerged(const MergedImage& merged, const std::pair<std::string, std::string>& output) {
  const auto& [exr, png] = output;
  makeOutputDirectory(exr, directoryOf(exr));
  ImageMetadata metadata = pieceMetadata(merged.info);
  metadata.emplace_back("Merged from", mergedFrom(merged));
  writeEXRAndPNG(exr, png, merged.image, metadata);
}

int mergeFiles(const MergeOptions& options) {
  if (options.output.empty()) throw std::runtime_error("merge needs -o OUT.exr (or --manifest FILE)");
  const auto output = outputPair(options.output, options.pieces);  // checked before reading the pieces
  MergedImage merged = mergePieceFiles(options.pieces);
  writeMerged(merged, output);
  fmt::print("Merged {} pieces into {}: {}\n", options.pieces.size(), options.output, mergedFrom(merged));
  return 0;
}

// Merges the frames of a manifest whose images are not done; returns the exit status.
int mergeManifest(const MergeOptions& options) {
  Manifest manifest = readManifest(options.manifest);
  int merged = 0, skipped = 0;
  std::vector<std::string> failures;
  for (ManifestFrame& frame : manifest.frames) {
    if (options.frame >= 0 && frame.frame != options.frame) continue;
    if (frame.pieces.empty()) continue;  // rendered whole
    if (frame.status == "done" && std::filesystem::exists(frame.output)) {
      ++skipped;
      continue;
    }
    std::vector<std::string> problems, files;
    for (const ManifestPiece& p : frame.pieces) files.push_back(p.file);
    std::pair<std::string, std::string> output;
    try {
      output = outputPair(frame.output, files);
    } catch (const std::exception& e) {
      problems.push_back(e.what());
    }
    std::vector<Piece> pieces;
    for (ManifestPiece& p : frame.pieces) {
      std::string what = p.part ? "part " + p.part->str() : "";
      if (p.pass) what += (what.empty() ? "pass " : ", pass ") + p.pass->str();
      if (!std::filesystem::exists(p.file)) {
        const std::string partial = partialFileName(p.file);
        p.status = std::filesystem::exists(partial) ? "interrupted" : "pending";
        problems.push_back(p.status == "interrupted"
                               ? fmt::format("{} was interrupted: there is only '{}'", what, partial)
                               : fmt::format("{} is missing: '{}' does not exist", what, p.file));
        continue;
      }
      try {
        pieces.push_back(loadPiece(p.file));
        p.status = pieces.back().info.complete ? "done" : "interrupted";
        p.seconds = pieces.back().info.seconds;
      } catch (const std::exception& e) {
        problems.push_back(fmt::format("{}: {}", what, e.what()));
      }
    }
    if (problems.empty()) {
      try {
        MergedImage image = mergePieces(pieces);
        writeMerged(image, output);
        frame.status = "done";
        frame.spp = image.info.spp;
        frame.seconds = image.info.seconds;
        ++merged;
        fmt::print("Frame {}: merged {} pieces ({:.2f} s of rendering) into {}\n", frame.frame, pieces.size(),
                   image.info.seconds, frame.output);
      } catch (const std::exception& e) {
        problems.push_back(e.what());
      }
    }
    if (!problems.empty()) {
      frame.status = "failed";
      std::string text = fmt::format("frame {} ({}):", frame.frame, frame.output);
      for (const std::string& p : problems) text += "\n    " + p;
      failures.push_back(text);
    }
    writeManifest(options.manifest, manifest);
  }
  fmt::print("Merged {} frame{}{}{}\n", merged, merged == 1 ? "" : "s",
             skipped ? fmt::format(", {} already merged", skipped) : "",
             failures.empty() ? "" : fmt::format(", {} failed", failures.size()));
  if (failures.empty()) return 0;
  std::string message = "cannot merge every frame:";
  for (const std::string& f : failures) message += "\n  " + f;
  throw std::runtime_error(message);
}

}  // namespace

void addMergeCommand(CLI::App& app) {
  auto options = std::make_shared<MergeOptions>();
  CLI::App* cmd = app.add_subcommand("merge", "Put the pieces of a split render (--part, --pass) back together");
  cmd->add_option("pieces", options->pieces, "The pieces' EXR files (OUT.part1of4.exr ...)");
  cmd->add_option("-o,--output", options->output,
                  "The merged image, .exr or .png (the other is written beside it; its directory made if missing)");
  cmd->add_option("--manifest", options->manifest,
                  "Merge every frame of this manifest (of `columba slurm`) whose image is not done");
  cmd->add_option("--frame", options->frame, "With --manifest: only this frame")->check(CLI::NonNegativeNumber);
  cmd->callback([options] {
    if (!options->manifest.empty() && !options->pieces.empty())
      throw std::runtime_error("give either pieces and -o, or --manifest, not both");
    if (options->manifest.empty() && options->pieces.empty())
      throw std::runtime_error("merge needs the pieces' files and -o OUT.exr, or --manifest FILE");
    int code = options->manifest.empty() ? mergeFiles(*options) : mergeManifest(*options);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace columba
