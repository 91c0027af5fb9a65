#pragma once
// The manifest of a sweep or a split render: a JSON file saying, for every frame, its defines,
// seed, samples per pixel, output file, state and render time, and (for renders split into
// pieces) every piece's file. Local sweeps write it as frames finish; `columba slurm` writes it
// when it plans the job and the merge job updates it; a rerun of `columba slurm` reads it to find
// what is still missing.
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>
#include "distribute/pieces.h"
#include "distribute/sweep.h"

namespace columba {

struct ManifestPiece {
  std::optional<PieceIndex> part, pass;
  std::string file;
  std::string status = "pending";  // pending, done, interrupted
  double seconds = 0.0;            // render time, once done
};

struct ManifestFrame {
  int frame = 0;
  std::map<std::string, std::string> defines;  // every -D of the frame, the swept ones included
  uint64_t seed = 0;
  int spp = 0;  // 0: not known yet (the scene's sampler decides)
  std::string output;
  std::string status = "pending";  // pending, done, interrupted, failed
  double seconds = 0.0;            // render time (summed over the pieces)
  std::vector<ManifestPiece> pieces;
};

struct SlurmSubmission {
  std::string renderJob, mergeJob;  // job ids ("" when not submitted)
  std::string tasks;                // the array indices submitted, "0-11" or "3,7"
  std::string submitted;            // when (ISO 8601)
};

struct Manifest {
  std::string columbaVersion;
  std::string scene, sceneHash;
  std::map<std::string, std::string> defines;  // the -D given besides the sweeps
  std::vector<SweepAxis> sweeps;
  int spp = 0;  // --spp, 0: the scene's own
  uint64_t seed = 0;
  int parts = 1, passes = 1;  // pieces of every frame (1, 1: whole frames)
  std::vector<ManifestFrame> frames;
  // For Slurm: the batch scripts and what was submitted.
  std::string renderScript, mergeScript, logDir;
  std::vector<SlurmSubmission> submissions;
};

nlohmann::json manifestToJSON(const Manifest& manifest);
// Throws std::runtime_error naming `source` for a manifest it cannot read.
Manifest manifestFromJSON(const nlohmann::json& json, const std::string& source);
Manifest readManifest(const std::string& path);
void writeManifest(const std::string& path, const Manifest& manifest);  // through a temporary file

}  // namespace columba
