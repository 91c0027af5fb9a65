// Splitting work into pieces without a renderer: row bands, sample ranges, sweeps, frame names,
// manifests and Slurm batch scripts (src/distribute/).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

#include "distribute/manifest.h"
#include "distribute/pieces.h"
#include "distribute/slurm.h"
#include "distribute/sweep.h"
#include "support/cli_test_support.h"
#include "support/temp_dir_test.h"

using namespace columba;

namespace {
// Every row of `rows` in exactly one band, bands in order and none empty.
void expectBandsCoverOnce(const std::vector<int>& bounds, int rows, int parts) {
  ASSERT_EQ(bounds.size(), size_t(parts) + 1);
  EXPECT_EQ(bounds.front(), 0);
  EXPECT_EQ(bounds.back(), rows);
  std::vector<int> covered(size_t(rows), 0);
  for (int k = 1; k <= parts; ++k) {
    PixelRect w = partWindow(bounds, k, 7);
    EXPECT_FALSE(w.empty()) << "part " << k;
    EXPECT_EQ(w.x0, 0);
    EXPECT_EQ(w.x1, 7);
    for (int y = w.y0; y < w.y1; ++y) ++covered[size_t(y)];
  }
  for (int y = 0; y < rows; ++y) EXPECT_EQ(covered[size_t(y)], 1) << "row " << y;
}
}  // namespace

TEST(PartWindows, BandsCoverTheImageExactlyOnce) {
  const std::vector<std::vector<uint64_t>> profiles = {
      std::vector<uint64_t>(37, 5),  // uniform
      std::vector<uint64_t>(37, 0),  // free
      [] {
        std::vector<uint64_t> c(37, 1);
        c[20] = 100000;
        return c;
      }(),  // one row holds nearly all
      [] {
        std::vector<uint64_t> c(37);
        for (size_t i = 0; i < c.size(); ++i) c[i] = i * i;
        return c;
      }(),
  };
  for (const auto& costs : profiles)
    for (int parts = 1; parts <= 37; ++parts) {
      SCOPED_TRACE(parts);
      expectBandsCoverOnce(balancedRowBands(costs, parts), 37, parts);
    }
}

TEST(PartWindows, BandsCostAboutTheSame) {
  // A scene whose lower half costs ten times the upper: equal bands would give 1 : 10.
  std::vector<uint64_t> costs(400, 10);
  for (size_t y = 200; y < 400; ++y) costs[y] = 100;
  const double total = std::accumulate(costs.begin(), costs.end(), 0.0) + 400;  // +1 a row, as the split counts
  for (int parts : {2, 3, 4, 7}) {
    std::vector<int> b = balancedRowBands(costs, parts);
    for (int k = 0; k < parts; ++k) {
      double share = 0;
      for (int y = b[size_t(k)]; y < b[size_t(k) + 1]; ++y) share += double(costs[size_t(y)]) + 1;
      // Whole rows: each band is within one row's cost of its share.
      EXPECT_NEAR(share, total / parts, 101.0) << parts << " parts, band " << k;
    }
  }
}

TEST(PartWindows, MorePartsThanRowsIsAnError) {
  try {
    balancedRowBands(std::vector<uint64_t>(3, 1), 4);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("3 rows into 4 parts"), std::string::npos) << e.what();
  }
}

TEST(Passes, SampleRangesAreDisjointAndCoverEverySample) {
  for (int spp : {1, 2, 7, 64, 1000})
    for (int n = 1; n <= std::min(spp, 9); ++n) {
      int next = 0;
      for (int k = 1; k <= n; ++k) {
        auto [b, e] = passSamples({k, n}, spp);
        EXPECT_EQ(b, next) << spp << " spp, pass " << k << "/" << n;
        EXPECT_GT(e, b);
        EXPECT_LE(e - b, spp / n + 1);
        next = e;
      }
      EXPECT_EQ(next, spp);
    }
  EXPECT_THROW(passSamples({1, 5}, 4), std::runtime_error);
}

TEST(Pieces, IndexAndFileNames) {
  EXPECT_EQ(parsePieceIndex("--part", "2/4", 100), (PieceIndex{2, 4}));
  for (const char* bad : {"0/4", "5/4", "2/0", "2", "a/b", "2/4x", "-1/4"})
    EXPECT_THROW(parsePieceIndex("--part", bad, 100), std::runtime_error) << bad;
  EXPECT_EQ(pieceFileName("out/la.exr", PieceIndex{2, 4}, std::nullopt), "out/la.part2of4.exr");
  EXPECT_EQ(pieceFileName("out/la.png", std::nullopt, PieceIndex{1, 3}), "out/la.pass1of3.exr");
  EXPECT_EQ(pieceFileName("la.exr", PieceIndex{1, 2}, PieceIndex{3, 3}), "la.part1of2.pass3of3.exr");
  EXPECT_EQ(partialFileName("out/la.part2of4.exr"), "out/la.part2of4.partial.exr");
  EXPECT_EQ(textHash(""), "cbf29ce484222325");  // FNV-1a 64's offset basis
  EXPECT_NE(textHash("<scene/>"), textHash("<scene />"));
}

TEST(Pieces, MetadataRoundTrips) {
  PieceInfo info;
  info.scene = "scenes/a.xml";
  info.sceneHash = textHash("x");
  info.defines = "angle=10\nres=64";
  info.seed = 7;
  info.spp = 64;
  info.frameWidth = 40;
  info.frameHeight = 30;
  info.complete = false;
  info.seconds = 1.5;
  info.part = PieceIndex{2, 3};
  info.partBounds = {0, 10, 20, 30};
  info.pass = PieceIndex{1, 2};
  info.sampleBegin = 0;
  info.sampleEnd = 32;
  EXRImageFile file;
  file.metadata = pieceMetadata(info);
  file.frameWidth = 40;
  file.frameHeight = 30;
  file.dataWindow = {0, 10, 40, 20};
  PieceInfo back = pieceInfoFromFile("p.exr", file);
  EXPECT_EQ(back.scene, info.scene);
  EXPECT_EQ(back.sceneHash, info.sceneHash);
  EXPECT_EQ(back.defines, info.defines);
  EXPECT_EQ(back.seed, 7u);
  EXPECT_EQ(back.spp, 64);
  EXPECT_FALSE(back.complete);
  EXPECT_DOUBLE_EQ(back.seconds, 1.5);
  EXPECT_EQ(back.part, info.part);
  EXPECT_EQ(back.partBounds, info.partBounds);
  EXPECT_EQ(back.pass, info.pass);
  EXPECT_EQ(back.sampleEnd, 32);
  EXPECT_EQ(back.window, (PixelRect{0, 10, 40, 20}));
  // An image that is not a piece is named with what it lacks.
  file.metadata = {{"Software", "x"}};
  try {
    pieceInfoFromFile("other.exr", file);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("'other.exr'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'Scene'"), std::string::npos) << e.what();
  }
}

TEST(Sweep, RangesWithDecimalStepsReachTheirEnd) {
  SweepAxis a = parseSweep("height=0:1:0.1");
  EXPECT_EQ(a.name, "height");
  EXPECT_EQ(a.values,
            (std::vector<std::string>{"0", "0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7", "0.8", "0.9", "1"}));
  EXPECT_EQ(parseSweep("angle=-10:60:10").values,
            (std::vector<std::string>{"-10", "0", "10", "20", "30", "40", "50", "60"}));
  EXPECT_EQ(parseSweep("h=0.5:0.62:0.05").values,
            (std::vector<std::string>{"0.5", "0.55", "0.6"}));  // 0.62 not reached
  EXPECT_EQ(parseSweep("x=1:0:-0.25").values, (std::vector<std::string>{"1", "0.75", "0.5", "0.25", "0"}));
  EXPECT_EQ(parseSweep("x=3:3:1").values, (std::vector<std::string>{"3"}));
  EXPECT_EQ(parseSweep("s=1e-3:3e-3:1e-3").values, (std::vector<std::string>{"0.001", "0.002", "0.003"}));
}

TEST(Sweep, ListsKeepTheirText) {
  EXPECT_EQ(parseSweep("feather=a.ply,dir/b.ply").values, (std::vector<std::string>{"a.ply", "dir/b.ply"}));
  EXPECT_EQ(parseSweep("angle=5").values, (std::vector<std::string>{"5"}));
}

TEST(Sweep, MistakesAreNamed) {
  for (const char* bad : {"angle", "=1,2", "angle=", "angle=0:10:0", "angle=0:10:-1", "angle=0:x:1", "angle=1:2",
                          "angle=1,,2", "angle=1,1"})
    EXPECT_THROW(parseSweep(bad), std::runtime_error) << bad;
  EXPECT_THROW(expandSweeps({parseSweep("a=1,2"), parseSweep("a=3")}), std::runtime_error);
}

TEST(Sweep, SeveralSweepsFormAGridWithTheFirstSlowest) {
  std::vector<SweepFrame> frames = expandSweeps({parseSweep("a=1,2"), parseSweep("b=x,y,z")});
  ASSERT_EQ(frames.size(), 6u);
  const char* expected[6][2] = {{"1", "x"}, {"1", "y"}, {"1", "z"}, {"2", "x"}, {"2", "y"}, {"2", "z"}};
  for (int f = 0; f < 6; ++f) {
    EXPECT_EQ(frames[size_t(f)].index, f);
    EXPECT_EQ(frames[size_t(f)].values[0], std::make_pair(std::string("a"), std::string(expected[f][0])));
    EXPECT_EQ(frames[size_t(f)].values[1], std::make_pair(std::string("b"), std::string(expected[f][1])));
  }
  std::vector<SweepFrame> none = expandSweeps({});
  ASSERT_EQ(none.size(), 1u);
  EXPECT_TRUE(none[0].values.empty());
}

TEST(Sweep, FrameFileNames) {
  std::vector<SweepFrame> frames = expandSweeps({parseSweep("angle=-10:10:10"), parseSweep("feather=a/b.ply,c.ply")});
  EXPECT_EQ(frameFileFromOutput("out/la.exr", frames[0]), "out/la_angle=-10_feather=a_b.ply.exr");
  EXPECT_EQ(frameFileFromPattern("la_%03d.exr", frames[4]), "la_004.exr");
  EXPECT_EQ(frameFileFromPattern("la{angle:03}_{feather}.png", frames[0]), "la-10_a_b.ply.png");
  EXPECT_EQ(frameFileFromPattern("la{angle:03}_%d%%{{x}}.exr", frames[2]), "la000_2%{x}.exr");
  EXPECT_EQ(frameFileFromPattern("{angle:+.1f}.exr", frames[5]), "+10.0.exr");
  EXPECT_THROW(frameFileFromPattern("la{height}.exr", frames[0]), std::runtime_error);
  EXPECT_THROW(frameFileFromPattern("la%s.exr", frames[0]), std::runtime_error);
  EXPECT_THROW(frameFileFromPattern("{feather:03}.exr", frames[0]), std::runtime_error);
  // Two frames may not share a file.
  EXPECT_THROW(frameFiles("", "la{angle}.exr", frames), std::runtime_error);
  EXPECT_EQ(frameFiles("", "la_%d.exr", frames).size(), 6u);
  EXPECT_EQ(frameFiles("x.exr", "", expandSweeps({})), std::vector<std::string>{"x.exr"});
}

TEST(Sweep, FrameFilesNoLongerThanAFileSystemTakes) {
  std::vector<SweepFrame> frames = expandSweeps({parseSweep("v=1,2")});
  // A width or precision beyond the longest file name is refused before it is formatted.
  for (const char* pattern : {"x{v:>10000000}.exr", "x{v:.10000000f}.exr", "x{v:0300}.exr", "x{v:>256}.exr"}) {
    try {
      frameFileFromPattern(pattern, frames[0]);
      ADD_FAILURE() << pattern;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("more than 255 (the longest file name)"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(frameFileFromPattern("x{v:>200}.exr", frames[0]).size(), 205u);
  EXPECT_EQ(frameFileFromPattern("{v:0>5}_{v:.3f}_{v:07.2f}.exr", frames[1]), "00002_2.000_0002.00.exr");
  // Names and paths that no file can have.
  try {
    frameFiles("", "x{v:>200}{v:>60}_%d.exr", frames);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("a name in its path is 267 bytes long, more than 255"), std::string::npos)
        << e.what();
  }
  std::string deep;
  for (int i = 0; i < 17; ++i) deep += "{v:>240}/";
  try {
    frameFiles("", deep + "%d.exr", frames);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("its path is 4102 bytes long, more than 4095"), std::string::npos) << e.what();
  }
  EXPECT_THROW(frameFiles(std::string(300, 'o') + ".exr", "", frames), std::runtime_error);
}

namespace {
Manifest sampleManifest(int frames, int parts, int passes) {
  Manifest m;
  m.columbaVersion = "test";
  m.scene = "/s/scene.xml";
  m.sceneHash = textHash("scene");
  m.defines = {{"res", "64"}};
  m.sweeps = {parseSweep("angle=0:" + std::to_string(10 * (frames - 1)) + ":10")};
  m.spp = 16;
  m.seed = 3;
  m.parts = parts;
  m.passes = passes;
  for (int f = 0; f < frames; ++f) {
    ManifestFrame frame;
    frame.frame = f;
    frame.defines = {{"res", "64"}, {"angle", std::to_string(10 * f)}};
    frame.seed = 3;
    frame.output = "/o/la" + std::to_string(f) + ".exr";
    for (int k = 1; k <= parts; ++k)
      for (int p = 1; p <= passes; ++p) {
        ManifestPiece piece;
        piece.part = PieceIndex{k, parts};
        if (passes > 1) piece.pass = PieceIndex{p, passes};
        piece.file = pieceFileName("/o/parts/la" + std::to_string(f) + ".exr", piece.part, piece.pass);
        frame.pieces.push_back(piece);
      }
    m.frames.push_back(frame);
  }
  return m;
}
}  // namespace

TEST(Manifest, RoundTripsThroughJSON) {
  Manifest m = sampleManifest(3, 2, 2);
  m.frames[1].status = "done";
  m.frames[1].spp = 16;
  m.frames[1].seconds = 2.25;
  m.frames[1].pieces[3].status = "interrupted";
  m.renderScript = "/o/render.sbatch";
  m.submissions.push_back({"12", "13", "0-11", "2024-01-01T00:00:00+0000"});
  Manifest back = manifestFromJSON(manifestToJSON(m), "test");
  EXPECT_EQ(manifestToJSON(back), manifestToJSON(m));
  EXPECT_EQ(back.frames[1].pieces[3].pass, (PieceIndex{2, 2}));
  EXPECT_EQ(back.submissions.at(0).renderJob, "12");
  const nlohmann::json j = manifestToJSON(m);
  // What a reader of the file looks for: frame -> defines, seed, spp, time, output.
  EXPECT_EQ(j["frames"][1]["defines"]["angle"], "10");
  EXPECT_EQ(j["frames"][1]["seed"], 3);
  EXPECT_EQ(j["frames"][1]["spp"], 16);
  EXPECT_EQ(j["frames"][1]["time"], 2.25);
  EXPECT_EQ(j["frames"][1]["output"], "/o/la1.exr");
  EXPECT_THROW(manifestFromJSON(nlohmann::json{{"format", "other"}}, "x"), std::runtime_error);
}

TEST(Slurm, TaskNumbersMapToPiecesAndBack) {
  std::set<std::tuple<int, int, int>> seen;
  for (int t = 0; t < 5 * 3 * 2; ++t) {
    TaskPiece p = taskPiece(t, 3, 2);
    EXPECT_EQ(taskIndex(p, 3, 2), t);
    EXPECT_TRUE(seen.insert({p.frame, p.part, p.pass}).second);
    EXPECT_LT(p.frame, 5);
    EXPECT_GE(p.part, 1);
    EXPECT_LE(p.part, 3);
  }
  EXPECT_EQ(arraySpec({7, 0, 1, 2, 3, 9, 10, 11, 5}), "0-3,5,7,9-11");
  EXPECT_EQ(arraySpec({4}), "4");
}

TEST(Slurm, BatchScriptsRunOnePiecePerTaskAndMergeAfterwards) {
  SlurmJob job;
  job.columba = "/opt/columba/bin/columba";
  job.workDir = "/home/me/project dir";
  job.renderArguments = {"/s/scene.xml",    "-D",       "feather=feather.ply",      "--sweep",
                         "angle=-10:60:10", "--frames", "/o/parts/la{angle:03}.exr"};
  job.manifestPath = "/o/manifest.json";
  job.logDir = "/o/logs";
  job.jobName = "columba-la";
  job.partition = "gpu";
  job.time = "30:00";
  job.cpusPerTask = 8;
  job.frames = 8;
  job.parts = 4;
  job.passes = 1;
  const std::string render = renderBatchScript(job);
  for (const char* line :
       {"#!/bin/bash\n", "#SBATCH --job-name=columba-la-render\n", "#SBATCH --output=/o/logs/render_%A_%a.log\n",
        "#SBATCH --cpus-per-task=8\n", "#SBATCH --partition=gpu\n", "#SBATCH --time=30:00\n", "frame=$(( task / 4 ))\n",
        "part=$(( task / 1 % 4 + 1 ))\n", "cd '/home/me/project dir' || exit 1\n",
        "/opt/columba/bin/columba render /s/scene.xml -D feather=feather.ply --sweep angle=-10:60:10 "
        "--frames '/o/parts/la{angle:03}.exr' --frame \"$frame\" --part \"$part/4\" --threads "
        "\"${SLURM_CPUS_PER_TASK:-1}\"\n",
        "trap '", "exit $status\n", "= 32 array tasks"})
    EXPECT_NE(render.find(line), std::string::npos) << line << "\n---\n" << render;
  EXPECT_EQ(render.find("--pass"), std::string::npos);
  job.passes = 2;
  EXPECT_NE(renderBatchScript(job).find("--pass \"$pass/2\""), std::string::npos);
  const std::string merge = mergeBatchScript(job);
  for (const char* line : {"#SBATCH --output=/o/logs/merge_%j.log\n", "#SBATCH --cpus-per-task=1\n",
                           "exec /opt/columba/bin/columba merge --manifest /o/manifest.json\n"})
    EXPECT_NE(merge.find(line), std::string::npos) << line << "\n---\n" << merge;
  EXPECT_EQ(shellCommand(mergeSubmitCommand("/o/merge.sbatch", "41")),
            "sbatch --parsable --dependency=afterok:41 --kill-on-invalid-dep=yes /o/merge.sbatch");
  EXPECT_EQ(shellCommand(renderSubmitCommand(job, "/o/render.sbatch", "0-3,7")),
            "sbatch --parsable --array=0-3,7 /o/render.sbatch");
  EXPECT_EQ(shellQuote("it's"), "'it'\\''s'");
}

TEST(Slurm, ResubmissionTakesOnlyTheMissingPieces) {
  Manifest m = sampleManifest(3, 4, 1);
  std::set<std::string> onDisk;
  for (const ManifestFrame& f : m.frames)
    for (const ManifestPiece& p : f.pieces) onDisk.insert(p.file);
  onDisk.erase(m.frames[1].pieces[2].file);  // frame 1, part 3/4: task 6
  onDisk.erase(m.frames[2].pieces[0].file);  // frame 2, part 1/4: task 8
  std::set<int> merged = {0};                // frame 0 is merged
  MissingWork work = missingWork(
      m, [&](const ManifestFrame& f) { return merged.count(f.frame) > 0; },
      [&](const ManifestPiece& p) { return onDisk.count(p.file) > 0; });
  EXPECT_EQ(work.tasks, (std::vector<int>{6, 8}));
  EXPECT_EQ(work.framesToMerge, (std::vector<int>{1, 2}));
  // A merged frame needs nothing, even when its pieces are gone.
  onDisk.clear();
  merged = {0, 1, 2};
  work = missingWork(
      m, [&](const ManifestFrame& f) { return merged.count(f.frame) > 0; },
      [&](const ManifestPiece& p) { return onDisk.count(p.file) > 0; });
  EXPECT_TRUE(work.tasks.empty());
  EXPECT_TRUE(work.framesToMerge.empty());
  // With passes, task numbers count parts x passes per frame.
  Manifest p = sampleManifest(2, 2, 3);
  work = missingWork(
      p, [](const ManifestFrame&) { return false; },
      [&](const ManifestPiece& piece) { return !(piece.part->index == 2 && piece.pass->index == 3); });
  EXPECT_EQ(work.tasks, (std::vector<int>{5, 11}));
}

TEST(Slurm, JobIdsAndPrograms) {
  EXPECT_EQ(parseJobId("1234\n"), "1234");
  EXPECT_EQ(parseJobId("sbatch: warning: something\n5678;cluster\n"), "5678");
  EXPECT_THROW(parseJobId("sbatch: error: Batch job submission failed\n"), std::runtime_error);
  ProgramResult r = runProgram({"sh", "-c", "echo out; echo err >&2; exit 3"});
  EXPECT_EQ(r.status, 3);
  EXPECT_EQ(r.output, "out\nerr\n");
  EXPECT_EQ(runProgram({"/nonexistent/sbatch"}).status, 127);
}

namespace {
// A job whose every value is ordinary.
SlurmJob plainJob() {
  SlurmJob job;
  job.columba = "/opt/columba/bin/columba";
  job.workDir = "/home/me/project";
  job.renderArguments = {"/s/scene.xml", "-D", "res=64", "--frames", "/o/parts/la%d.exr"};
  job.manifestPath = "/o/manifest.json";
  job.logDir = "/o/logs";
  job.jobName = "columba-la";
  job.partition = "short";
  job.time = "30:00";
  job.frames = 2;
  job.parts = 3;
  return job;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> all;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) all.push_back(line);
  return all;
}

// The arguments sbatch takes from the text after "#SBATCH", read as its batch-script parser
// reads them: words split at blanks, quotes grouping, a backslash escaping the next character
// (within quotes too) and an unquoted '#' ending the line.
std::vector<std::string> sbatchArguments(const std::string& text) {
  std::vector<std::string> words;
  std::string word;
  bool inWord = false, escaped = false;
  char quote = 0;
  for (char c : text) {
    if (escaped) {
      word += c;
      escaped = false;
    } else if (c == '\\') {
      escaped = inWord = true;
    } else if (quote) {
      if (c == quote)
        quote = 0;
      else
        word += c;
    } else if (c == '"' || c == '\'') {
      quote = c;
      inWord = true;
    } else if (c == '#') {
      break;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      if (inWord) words.push_back(word);
      word.clear();
      inWord = false;
    } else {
      word += c;
      inWord = true;
    }
  }
  if (inWord) words.push_back(word);
  return words;
}
}  // namespace

TEST(Slurm, ControlCharactersInAnyValueOfTheScriptsAreRefused) {
  const std::pair<const char*, std::string SlurmJob::*> fields[] = {
      {"the job name (--job-name)", &SlurmJob::jobName}, {"the partition (--partition)", &SlurmJob::partition},
      {"the time limit (--time)", &SlurmJob::time},      {"the log directory", &SlurmJob::logDir},
      {"the working directory", &SlurmJob::workDir},     {"the manifest", &SlurmJob::manifestPath},
      {"the columba binary", &SlurmJob::columba}};
  const std::pair<const char*, const char*> controls[] = {{"\n", "\\n"},     {"\r", "\\r"},     {"\t", "\\t"},
                                                          {"\x01", "\\x01"}, {"\x1b", "\\x1b"}, {"\x7f", "\\x7f"}};
  for (const auto& [control, shown] : controls) {
    std::vector<SlurmJob> jobs;
    std::vector<std::string> names;
    for (const auto& [name, field] : fields) {
      SlurmJob job = plainJob();
      job.*field = std::string("x") + control + "touch FILE";
      jobs.push_back(job);
      names.push_back(name);
    }
    // A scene file whose name holds the character, and a -D value.
    SlurmJob scene = plainJob();
    scene.renderArguments[0] = std::string("/s/x") + control + "touch FILE.xml";
    jobs.push_back(scene);
    names.push_back("the render argument");
    SlurmJob define = plainJob();
    define.renderArguments[2] = std::string("res=6") + control + "4";
    jobs.push_back(define);
    names.push_back("the render argument");
    for (size_t j = 0; j < jobs.size(); ++j)
      for (auto script : {renderBatchScript, mergeBatchScript}) {
        try {
          script(jobs[j]);
          ADD_FAILURE() << names[j] << " with " << shown << " was written into a script";
        } catch (const std::runtime_error& e) {
          const std::string message = e.what();
          EXPECT_NE(message.find(names[j]), std::string::npos) << message;
          EXPECT_NE(message.find(std::string("holds a control character (") + shown + ")"), std::string::npos)
              << message;
          EXPECT_EQ(message.find(control), std::string::npos) << "the message shows the character itself";
        }
      }
  }
}

TEST(Slurm, AwkwardValuesStayWithinTheirLines) {
  // Blanks, both quotes, $(...), backticks, ';', '#', '%' and backslashes: in the commands, bash
  // must read them back as given; in the #SBATCH lines (comments to bash), sbatch must.
  const std::string awkward = "a b 'c' \"d\" $(touch CANARY) `touch CANARY`; #e % \\f";
  SlurmJob job = plainJob();
  job.columba = "/opt/" + awkward + "/columba";
  job.workDir = "/home/" + awkward;
  job.renderArguments = {"/s/" + awkward + ".xml", "-D", "text=" + awkward, "--frames", "/o/" + awkward + "%d.exr"};
  job.manifestPath = "/o/" + awkward + "/manifest.json";
  job.logDir = "/o/" + awkward;
  job.jobName = awkward;
  job.partition = awkward;
  job.time = awkward;
  const std::string logDir = "/o/a b 'c' \"d\" $(touch CANARY) `touch CANARY`; #e %% \\f";  // % written %%
  const std::map<std::string, std::string> sbatchValues = {{"--job-name", awkward + "-render"},
                                                           {"--output", logDir + "/render_%A_%a.log"},
                                                           {"--partition", awkward},
                                                           {"--time", awkward}};
  const std::string script = renderBatchScript(job), plain = renderBatchScript(plainJob());
  const std::vector<std::string> got = lines(script), expected = lines(plain);
  // Line for line the script of ordinary values, but for the lines that hold the values.
  ASSERT_EQ(got.size(), expected.size()) << script;
  std::set<std::string> changed;
  for (size_t i = 0; i < got.size(); ++i) {
    if (got[i] == expected[i]) continue;
    const std::string kind = expected[i].substr(0, expected[i].find_first_of("= "));
    changed.insert(kind == "#SBATCH" ? expected[i].substr(0, expected[i].find('=')) : kind);
    if (kind == "#SBATCH") {
      const std::string option = expected[i].substr(8, expected[i].find('=') - 8);
      ASSERT_TRUE(sbatchValues.count(option)) << expected[i];
      EXPECT_EQ(sbatchArguments(got[i].substr(8)), std::vector<std::string>{option + "=" + sbatchValues.at(option)})
          << got[i];
    }
  }
  EXPECT_EQ(changed, (std::set<std::string>{"#SBATCH --job-name", "#SBATCH --output", "#SBATCH --partition",
                                            "#SBATCH --time", "cd", "/opt/columba/bin/columba"}))
      << script;
  const std::string merge = mergeBatchScript(job);
  EXPECT_EQ(lines(merge).size(), lines(mergeBatchScript(plainJob())).size()) << merge;
  EXPECT_NE(merge.find("#SBATCH --job-name=\"a b 'c' \\\"d\\\" $(touch CANARY) `touch CANARY`; #e % \\\\f-merge\"\n"),
            std::string::npos)
      << merge;
}

namespace {
class SlurmScripts : public columba::testing::TempDirTest {};
}  // namespace

TEST_F(SlurmScripts, BashRunsTheCommandsWithAwkwardValuesAsGiven) {
  const std::string awkward = "a b 'c' \"d\" $(touch CANARY) `touch CANARY`; #e % \\f";
  const std::filesystem::path bin = dir_ / awkward, work = dir_ / ("work " + awkward);
  std::filesystem::create_directories(bin);
  std::filesystem::create_directories(work);
  // A stand-in for columba that prints where it runs and its arguments, one a line.
  std::ofstream(bin / "columba") << "#!/bin/sh\npwd\nfor a in \"$@\"; do printf '[%s]\\n' \"$a\"; done\n";
  std::filesystem::permissions(bin / "columba", std::filesystem::perms::owner_all);
  SlurmJob job = plainJob();
  job.columba = (bin / "columba").string();
  job.workDir = work.string();
  job.renderArguments = {"/s/" + awkward + ".xml", "-D", "text=" + awkward};
  job.manifestPath = (dir_ / awkward / "manifest.json").string();
  job.jobName = job.partition = job.time = awkward;
  const std::string render = write("render.sbatch", renderBatchScript(job));
  const std::string merge = write("merge.sbatch", mergeBatchScript(job));
  for (const std::string& script : {render, merge}) {
    columba::testing::CommandResult r = columba::testing::runShell("bash -n " + shellQuote(script));
    EXPECT_EQ(r.status, 0) << r.output;
  }
  // Task 4 of 2 frames x 3 parts: frame 1, part 2/3.
  columba::testing::CommandResult r = columba::testing::runShell("cd " + shellQuote(dir_.string()) +
                                                                 " && SLURM_ARRAY_TASK_ID=4 SLURM_CPUS_PER_TASK=2 "
                                                                 "bash render.sbatch");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find(work.string() + "\n[render]\n[/s/" + awkward + ".xml]\n[-D]\n[text=" + awkward +
                          "]\n[--frame]\n[1]\n[--part]\n[2/3]\n[--threads]\n[2]\n"),
            std::string::npos)
      << r.output;
  r = columba::testing::runShell("cd " + shellQuote(dir_.string()) + " && bash merge.sbatch");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find(work.string() + "\n[merge]\n[--manifest]\n[" + job.manifestPath + "]\n"), std::string::npos)
      << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "CANARY"));
  EXPECT_FALSE(std::filesystem::exists(work / "CANARY"));
}
