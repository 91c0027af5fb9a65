// The command line of sweeps, split renders and Slurm jobs: `columba render --sweep/--part/--pass`,
// `columba merge`, `columba compare` and `columba slurm` (with stand-ins for sbatch and squeue; the
// real cluster is tested by scripts/slurm-render-test.sh).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "distribute/manifest.h"
#include "distribute/slurm.h"
#include "io/image.h"
#include "support/cli_test_support.h"
#include "support/render_test_support.h"
#include "support/temp_dir_test.h"

namespace fs = std::filesystem;
using columba::testing::CommandResult;
using columba::testing::renderAndSignal;
using columba::testing::run;
using columba::testing::runShell;
using columba::testing::samePixels;
using namespace columba;

namespace {

// A sphere lit from a direction that `angle` turns, on a 16 x 12 film.
const char* kScene = R"(<scene version="3.0.0">
  <default name="angle" value="0"/>
  <default name="spp" value="3"/>
  <integrator type="direct"/>
  <sensor type="perspective"><float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0, -4, 0" target="0, 0, 0" up="0, 0, 1"/></transform>
    <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="12"/></film>
    <sampler type="independent"><integer name="sample_count" value="$spp"/></sampler></sensor>
  <shape type="sphere"><bsdf type="diffuse"/></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="0.5"/><rotate x="1" angle="180"/><translate z="3"/>
    <rotate y="1" angle="$angle"/></transform>
    <emitter type="area"><spectrum name="radiance" value="20"/></emitter></shape>
  <emitter type="constant"><spectrum name="radiance" value="0.1"/></emitter>
</scene>
)";

bool sameFilePixels(const std::string& a, const std::string& b) { return samePixels(readEXR(a), readEXR(b)); }

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

class SweepCli : public columba::testing::TempDirTest {
 protected:
  std::string scene() { return write("sphere.xml", kScene); }
  std::string at(const std::string& name) { return (dir_ / name).string(); }
};

}  // namespace

TEST_F(SweepCli, ASweepRendersOneFramePerValueAndWritesAManifest) {
  std::string s = scene();
  CommandResult r = run("render " + s + " --sweep angle=0:20:10 -o " + at("s.exr"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("Frame 1 (2 of 3): angle=10"), std::string::npos) << r.output;
  // Progress and the line after the frame name it alike: by its index, then its count from 1.
  EXPECT_NE(r.output.find("frame 1 (2 of 3): 100%"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Frame 1 (2 of 3) done in"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("frame 2/3"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Rendered 3 frames"), std::string::npos) << r.output;
  Manifest m = readManifest(at("s.manifest.json"));
  ASSERT_EQ(m.frames.size(), 3u);
  for (int f = 0; f < 3; ++f) {
    const std::string angle = std::to_string(10 * f);
    const ManifestFrame& frame = m.frames[size_t(f)];
    EXPECT_EQ(frame.output, at("s_angle=" + angle + ".exr"));
    EXPECT_EQ(frame.defines.at("angle"), angle);
    EXPECT_EQ(frame.status, "done");
    EXPECT_EQ(frame.spp, 3);
    EXPECT_GT(frame.seconds, 0.0);
    EXPECT_TRUE(fs::exists(at("s_angle=" + angle + ".png")));
    // Each frame is the render of that value on its own.
    ASSERT_EQ(run("render " + s + " -D angle=" + angle + " -o " + at("one.exr")).status, 0);
    EXPECT_TRUE(sameFilePixels(frame.output, at("one.exr"))) << angle;
  }
  EXPECT_FALSE(sameFilePixels(m.frames[0].output, m.frames[2].output));
}

TEST_F(SweepCli, GridsAndFramePatterns) {
  fs::create_directories(dir_ / "frames");
  CommandResult r = run("render " + scene() + " --sweep angle=0,30 --sweep spp=1:2:1 --frames '" +
                        at("frames/f_%02d_{angle:03}.exr") + "'");
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* name : {"f_00_000.exr", "f_01_000.exr", "f_02_030.exr", "f_03_030.exr"})
    EXPECT_TRUE(fs::exists(dir_ / "frames" / name)) << name << "\n" << r.output;
  Manifest m = readManifest(at("frames/manifest.json"));
  ASSERT_EQ(m.frames.size(), 4u);
  EXPECT_EQ(m.frames[3].defines.at("spp"), "2");
  EXPECT_EQ(m.frames[3].spp, 2);
  // One frame of the sweep on its own (as a Slurm task renders it); no manifest is touched.
  fs::remove(at("frames/manifest.json"));
  r = run("render " + scene() + " --sweep angle=0,30 --sweep spp=1:2:1 --frames '" + at("frames/g_%02d.exr") +
          "' --frame 2");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(sameFilePixels(at("frames/g_02.exr"), at("frames/f_02_030.exr")));
  EXPECT_FALSE(fs::exists(at("frames/g_00.exr")));
  EXPECT_FALSE(fs::exists(at("frames/manifest.json")));
  // Mistakes are named before any work.
  r = run("render " + scene() + " --sweep angle=0,30 --frames '" + at("frames/same.exr") + "'");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("would both be written"), std::string::npos) << r.output;
  r = run("render " + scene() + " --sweep angle=0,30 --frame 2");
  EXPECT_NE(r.output.find("--frame 2: the sweep has 2 frames"), std::string::npos) << r.output;
  r = run("render " + scene() + " -D angle=3 --sweep angle=0,30");
  EXPECT_NE(r.output.find("both set $angle"), std::string::npos) << r.output;
}

TEST_F(SweepCli, PartsOfACroppedFilmMergeIntoTheCroppedRender) {
  // The parts split the crop window, not the film, and hold its pixels where a render in one piece
  // puts them.
  std::string text = kScene;
  const std::string height = R"(<integer name="height" value="12"/>)";
  text.replace(text.find(height), height.size(),
               height + R"(<integer name="crop_offset_x" value="3"/><integer name="crop_offset_y" value="2"/>
      <integer name="crop_width" value="9"/><integer name="crop_height" value="7"/>)");
  const std::string s = write("cropped.xml", text);
  ASSERT_EQ(run("render " + s + " -o " + at("whole.exr")).status, 0);
  for (int k = 1; k <= 2; ++k) {
    CommandResult r = run("render " + s + " -o " + at("img.exr") + " --part " + std::to_string(k) + "/2");
    ASSERT_EQ(r.status, 0) << r.output;
  }
  EXPECT_EQ(readEXRFile(at("img.part2of2.exr")).frameWidth, 9);
  EXPECT_EQ(readEXRFile(at("img.part2of2.exr")).frameHeight, 7);
  ASSERT_EQ(run("merge " + at("img.part1of2.exr") + " " + at("img.part2of2.exr") + " -o " + at("merged.exr")).status,
            0);
  EXPECT_EQ(readEXR(at("whole.exr")).width, 9);
  EXPECT_TRUE(sameFilePixels(at("merged.exr"), at("whole.exr")));
}

TEST_F(SweepCli, PartsAndPassesMergeIntoTheWholeRender) {
  std::string s = scene();
  ASSERT_EQ(run("render " + s + " --spp 8 -o " + at("whole.exr")).status, 0);
  for (int k = 1; k <= 3; ++k) {
    CommandResult r = run("render " + s + " --spp 8 -o " + at("img.exr") + " --part " + std::to_string(k) + "/3");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("img.part" + std::to_string(k) + "of3.exr"), std::string::npos) << r.output;
  }
  EXPECT_FALSE(fs::exists(at("img.exr")));
  CommandResult r = run("merge " + at("img.part1of3.exr") + " " + at("img.part3of3.exr") + " -o " + at("merged.exr"));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("part 2/3"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("is missing"), std::string::npos) << r.output;
  r = run("merge " + at("img.part1of3.exr") + " " + at("img.part2of3.exr") + " " + at("img.part3of3.exr") + " -o " +
          at("merged.exr"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(at("merged.png")));
  EXPECT_TRUE(sameFilePixels(at("merged.exr"), at("whole.exr")));
  r = run("compare " + at("merged.exr") + " " + at("whole.exr"));
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("identical"), std::string::npos) << r.output;

  for (int k = 1; k <= 2; ++k)
    ASSERT_EQ(run("render " + s + " --spp 8 -o " + at("img.exr") + " --pass " + std::to_string(k) + "/2").status, 0);
  ASSERT_EQ(run("merge " + at("img.pass1of2.exr") + " " + at("img.pass2of2.exr") + " -o " + at("passes.exr")).status,
            0);
  r = run("compare " + at("passes.exr") + " " + at("whole.exr") + " --tolerance 1e-6");
  EXPECT_EQ(r.status, 0) << r.output;
  r = run("compare " + at("whole.exr") + " " + at("img.pass1of2.exr"));  // half the samples: not the same
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("values differ"), std::string::npos) << r.output;
}

TEST_F(SweepCli, AnInterruptedPartIsLeftPartialNeverDone) {
  std::string s = scene();
  CommandResult r = renderAndSignal(s + " --spp 16000000 -o " + at("img.exr") + " --part 1/2", "TERM", 0.5);
  EXPECT_NE(r.output.find("status=143"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(at("img.part1of2.exr")));
  ASSERT_TRUE(fs::exists(at("img.part1of2.partial.exr"))) << r.output;
  EXRImageFile partial = readEXRFile(at("img.part1of2.partial.exr"), false);
  EXPECT_EQ(metadataValue(partial.metadata, "Status"), "interrupted");
  EXPECT_EQ(metadataValue(partial.metadata, "Part"), "1/2");
  r = run("merge " + at("img.part1of2.partial.exr") + " -o " + at("m.exr"));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("interrupted"), std::string::npos) << r.output;
}

namespace {
// Stand-ins for sbatch and squeue: sbatch logs its arguments and prints job ids 101, 102, ...
void installFakeSlurm(const fs::path& bin) {
  fs::create_directories(bin);
  std::ofstream(bin / "sbatch") << "#!/bin/sh\n"
                                   "n=$(($(cat \"$0.count\" 2>/dev/null || echo 100) + 1)); echo $n > \"$0.count\"\n"
                                   "echo \"$*\" >> \"$0.log\"\necho $n\n";
  std::ofstream(bin / "squeue") << "#!/bin/sh\nexit 0\n";
  fs::permissions(bin / "sbatch", fs::perms::owner_all);
  fs::permissions(bin / "squeue", fs::perms::owner_all);
}
}  // namespace

TEST_F(SweepCli, SlurmJobsRunTheirPiecesAndRerunsSubmitOnlyWhatIsMissing) {
  const std::string s = scene();
  const fs::path bin = dir_ / "bin";
  installFakeSlurm(bin);
  const std::string env = "cd " + dir_.string() + " && PATH=" + bin.string() + ":$PATH ";
  const std::string slurm = env + COLUMBA_BINARY + " slurm " + s +
                            " --spp 4 --sweep angle=0,20 --frames 'la{angle:03}.exr' --parts 3 --out-dir out "
                            "--partition short --time 5:00 --cpus-per-task 2";
  // Without --submit: the scripts, the manifest and the commands.
  CommandResult r = runShell(slurm);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("2 frames x 3 parts x 1 pass = 6 array tasks; 6 to render, 2 frames to merge"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("render=$(sbatch --parsable --array=0-5 " + (dir_ / "out/render.sbatch").string() + ")"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("--dependency=afterok:${render%;*} --kill-on-invalid-dep=yes"), std::string::npos)
      << r.output;
  const std::string script = readText(dir_ / "out/render.sbatch");
  EXPECT_NE(script.find("#SBATCH --partition=short"), std::string::npos) << script;
  EXPECT_NE(script.find("#SBATCH --time=5:00"), std::string::npos) << script;
  EXPECT_NE(script.find("#SBATCH --cpus-per-task=2"), std::string::npos) << script;
  EXPECT_FALSE(fs::exists(bin / "sbatch.log"));

  // Submitted: the array and the merge job after it.
  r = runShell(slurm + " --submit");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("render job: 101"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("merge job: 102"), std::string::npos) << r.output;
  std::string log = readText(bin / "sbatch.log");
  EXPECT_NE(log.find("--parsable --array=0-5 " + (dir_ / "out/render.sbatch").string()), std::string::npos) << log;
  EXPECT_NE(log.find("--dependency=afterok:101 --kill-on-invalid-dep=yes"), std::string::npos) << log;

  // The cluster runs the tasks (here, the script itself); task 4 (frame 1, part 2/3) fails to.
  for (int task : {0, 1, 2, 3, 5}) {
    r = runShell("SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " SLURM_CPUS_PER_TASK=2 bash " +
                 (dir_ / "out/render.sbatch").string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("columba task " + std::to_string(task) + ": status 0 after"), std::string::npos)
        << r.output;
  }
  r = runShell("bash " + (dir_ / "out/merge.sbatch").string());
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("part 2/3 is missing: '" + (dir_ / "out/parts/la020.part2of3.exr").string()),
            std::string::npos)
      << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "out/la000.exr")) << r.output;  // the complete frame is merged all the same
  EXPECT_FALSE(fs::exists(dir_ / "out/la020.exr"));

  // A rerun submits the missing piece only, and its merge.
  r = runShell(slurm + " --submit");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("1 to render, 1 frame to merge"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("render job: 103"), std::string::npos) << r.output;
  log = readText(bin / "sbatch.log");
  EXPECT_NE(log.find("--array=4 "), std::string::npos) << log;
  EXPECT_NE(log.find("--dependency=afterok:103"), std::string::npos) << log;
  Manifest m = readManifest((dir_ / "out/manifest.json").string());
  ASSERT_EQ(m.submissions.size(), 2u);
  EXPECT_EQ(m.submissions[1].tasks, "4");
  EXPECT_EQ(m.frames[1].pieces[1].status, "pending");

  r = runShell("SLURM_ARRAY_TASK_ID=4 bash " + (dir_ / "out/render.sbatch").string() + " && bash " +
               (dir_ / "out/merge.sbatch").string());
  ASSERT_EQ(r.status, 0) << r.output;
  m = readManifest((dir_ / "out/manifest.json").string());
  for (const ManifestFrame& frame : m.frames) {
    EXPECT_EQ(frame.status, "done");
    EXPECT_EQ(frame.spp, 4);
    ASSERT_EQ(run("render " + s + " --spp 4 -D angle=" + frame.defines.at("angle") + " -o " + at("local.exr")).status,
              0);
    EXPECT_TRUE(sameFilePixels(frame.output, at("local.exr"))) << frame.output;
  }
  r = runShell(slurm + " --submit");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("Nothing to do"), std::string::npos) << r.output;

  // Another render in the same directory is refused.
  r = runShell(env + COLUMBA_BINARY + " slurm " + s +
               " --spp 4 --seed 9 --sweep angle=0,20 --frames 'la{angle:03}.exr' "
               "--parts 3 --out-dir out");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("is of another render: its seed is 0, now 9"), std::string::npos) << r.output;
}

TEST_F(SweepCli, FrameNamesLongerThanAFileNameAreRefusedAtOnce) {
  for (const char* pattern : {"x{v:>1000000000}.exr", "x{v:.1000000000f}.exr"}) {
    CommandResult r = run("render " + scene() + " --sweep v=1,2 --frames '" + at(pattern) + "'");
    EXPECT_NE(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("more than 255 (the longest file name)"), std::string::npos) << r.output;
  }
}

TEST_F(SweepCli, MergeNeverWritesOverAPiece) {
  const std::string s = scene();
  for (int k = 1; k <= 2; ++k)
    ASSERT_EQ(run("render " + s + " --spp 2 -o " + at("A.exr") + " --part " + std::to_string(k) + "/2").status, 0);
  const std::string pieces = at("A.part1of2.exr") + " " + at("A.part2of2.exr");
  const std::string first = readText(at("A.part1of2.exr")), second = readText(at("A.part2of2.exr"));
  fs::create_directories(dir_ / "sub");
  fs::create_symlink(at("A.part1of2.exr"), at("link.exr"));
  // The merged EXR beside a PNG named like a piece, a piece itself, by `..`, and through a link.
  for (const std::string& output :
       {at("A.part1of2.png"), at("A.part2of2.exr"), at("sub/../A.part2of2.exr"), at("link.png")}) {
    CommandResult r = run("merge " + pieces + " -o " + output);
    EXPECT_NE(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("which the merge reads"), std::string::npos) << r.output;
  }
  EXPECT_EQ(readText(at("A.part1of2.exr")), first);
  EXPECT_EQ(readText(at("A.part2of2.exr")), second);
  // A manifest whose frame is one of its own pieces.
  const std::string env = "cd " + dir_.string() + " && ";
  ASSERT_EQ(runShell(env + COLUMBA_BINARY + " slurm " + s + " --spp 2 --parts 2 --out-dir out").status, 0);
  ASSERT_EQ(runShell(env + "for t in 0 1; do SLURM_ARRAY_TASK_ID=$t bash out/render.sbatch || exit 1; done").status, 0);
  nlohmann::json j = nlohmann::json::parse(readText(dir_ / "out/manifest.json"));
  j["frames"][0]["output"] = j["frames"][0]["pieces"][1]["file"];
  std::ofstream(dir_ / "out/manifest.json") << j.dump();
  const std::string piece = readText(dir_ / "out/parts/sphere.part2of2.exr");
  CommandResult r = run("merge --manifest " + at("out/manifest.json"));
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("it is the piece '" + at("out/parts/sphere.part2of2.exr") + "', which the merge reads"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(readText(dir_ / "out/parts/sphere.part2of2.exr"), piece);
}

TEST_F(SweepCli, ASweepReplacesOnlyALocalSweepsManifest) {
  const std::string s = scene();
  const std::string env = "cd " + dir_.string() + " && ";
  const std::string sweep =
      std::string(COLUMBA_BINARY) + " render " + s + " --spp 1 --sweep angle=0,10 --frames 'f%d.exr'";
  // A Slurm job's manifest in the directory the frames go to.
  ASSERT_EQ(runShell(env + COLUMBA_BINARY + " slurm " + s + " --spp 1 --out-dir .").status, 0);
  const std::string slurmManifest = readText(dir_ / "manifest.json");
  CommandResult r = runShell(env + sweep);
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("the manifest of a Slurm job"), std::string::npos) << r.output;
  EXPECT_EQ(readText(dir_ / "manifest.json"), slurmManifest);
  EXPECT_FALSE(fs::exists(dir_ / "f0.exr"));
  // A file that is no manifest.
  write("manifest.json", "{\"name\": \"an application's manifest\"}\n");
  r = runShell(env + sweep);
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("which is no Columba manifest"), std::string::npos) << r.output;
  EXPECT_EQ(readText(dir_ / "manifest.json"), "{\"name\": \"an application's manifest\"}\n");
  // An earlier local sweep's: replaced, as a rerun does.
  fs::remove(dir_ / "manifest.json");
  ASSERT_EQ(runShell(env + sweep).status, 0);
  r = runShell(env + sweep);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(readManifest(at("manifest.json")).frames.size(), 2u);
}

TEST_F(SweepCli, SlurmRefusesControlCharactersBeforeWritingAnything) {
  const std::string s = scene();
  const struct {
    std::vector<std::string> option;
    std::string named;
  } cases[] = {
      {{"--job-name", "x\ntouch FILE"}, "the job name (--job-name) 'x\\ntouch FILE' holds a control character (\\n)"},
      {{"--partition", "p\rq"}, "the partition (--partition) 'p\\rq' holds a control character (\\r)"},
      {{"--time", "1:00\x01"}, "the time limit (--time) '1:00\\x01' holds a control character (\\x01)"},
      {{"--out-dir", at("o\tq")}, "the render argument '" + at("o\\tq") + "/parts/sphere.exr'"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> command = {COLUMBA_BINARY, "slurm", s, "--spp", "2"};
    if (c.option[0] != "--out-dir") command.insert(command.end(), {"--out-dir", at("out")});
    command.insert(command.end(), c.option.begin(), c.option.end());
    ProgramResult r = runProgram(command);
    EXPECT_NE(r.status, 0) << r.output;
    EXPECT_NE(r.output.find(c.named), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(at("out"))) << c.option[0];
    EXPECT_FALSE(fs::exists(at("o\tq")));
  }
  // A scene file whose name holds a line break: its default job name and output directory would too.
  write("x\ntouch FILE.xml", kScene);
  CommandResult r = runShell("cd " + shellQuote(dir_.string()) + " && " + COLUMBA_BINARY +
                             " slurm \"$(printf 'x\\ntouch FILE.xml')\"");
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("the render argument '" + at("x\\ntouch FILE.xml") + "' holds a control character (\\n)"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 2) << "only the scenes";
}

TEST_F(SweepCli, SlurmScriptsOfAwkwardValuesRunAsGiven) {
  // Run from a directory, and named, with blanks, quotes, $(...), ';' and '#': the tasks and the
  // merge find their files, and nothing else runs.
  const fs::path work = dir_ / "work 'q' \"d\" $(touch CANARY); #x";
  fs::create_directories(work);
  std::ofstream(work / "sphere.xml") << kScene;
  const std::string jobName = "a b'c\"$(touch CANARY);d #e \\f";
  CommandResult r =
      runShell("cd " + shellQuote(work.string()) + " && " + COLUMBA_BINARY +
               " slurm sphere.xml --spp 2 --parts 2 --partition 'p q' --time 1:00 --job-name " + shellQuote(jobName));
  ASSERT_EQ(r.status, 0) << r.output;
  const fs::path out = work / "slurm-sphere";
  for (const char* script : {"render.sbatch", "merge.sbatch"}) {
    r = runShell("bash -n " + shellQuote((out / script).string()));
    EXPECT_EQ(r.status, 0) << script << ": " << r.output;
  }
  const std::string render = readText(out / "render.sbatch");
  EXPECT_NE(render.find("\n#SBATCH --job-name=\"a b'c\\\"$(touch CANARY);d #e \\\\f-render\"\n"), std::string::npos)
      << render;
  EXPECT_NE(render.find("\n#SBATCH --partition=\"p q\"\n"), std::string::npos) << render;
  r = runShell("cd " + shellQuote(dir_.string()) + " && for t in 0 1; do SLURM_ARRAY_TASK_ID=$t bash " +
               shellQuote((out / "render.sbatch").string()) + " || exit 1; done && bash " +
               shellQuote((out / "merge.sbatch").string()));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(out / "sphere.exr")) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "CANARY"));
  EXPECT_FALSE(fs::exists(work / "CANARY"));
}

TEST_F(SweepCli, SlurmRendersAgainAPieceCutShort) {
  const std::string slurm =
      "cd " + dir_.string() + " && " + COLUMBA_BINARY + " slurm " + scene() + " --spp 2 --parts 2 --out-dir out";
  ASSERT_EQ(runShell(slurm).status, 0);
  CommandResult r = runShell("cd " + dir_.string() +
                             " && for t in 0 1; do SLURM_ARRAY_TASK_ID=$t bash out/render.sbatch" + " || exit 1; done");
  ASSERT_EQ(r.status, 0) << r.output;
  // Its header whole, its pixels not.
  fs::resize_file(dir_ / "out/parts/sphere.part1of2.exr", 1200);
  r = runShell(slurm);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("1 to render, 1 frame to merge"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--array=0 "), std::string::npos) << r.output;
  Manifest m = readManifest((dir_ / "out/manifest.json").string());
  EXPECT_EQ(m.frames[0].pieces[0].status, "pending");
  EXPECT_EQ(m.frames[0].pieces[1].status, "done");
}

TEST_F(SweepCli, SlurmRefusesSplitsEveryTaskWouldFail) {
  const std::string s = scene();
  std::string tracer = kScene;
  tracer.replace(tracer.find("<integrator type=\"direct\"/>"), 27, "<integrator type=\"ptracer\"/>");
  const std::string ptracer = write("ptracer.xml", tracer);
  const std::pair<std::string, std::string> cases[] = {
      {s + " --spp 2 --parts 13", "--parts 13: the image of " + s + " has 12 rows, and a part is at least one row"},
      {s + " --spp 2 --passes 3", "--passes 3: " + s + " renders 2 samples per pixel (--spp)"},
      {s + " --passes 4", "--passes 4: " + s + " renders 3 samples per pixel (its sampler's sample_count)"},
      {s + " --sweep spp=4,2 --passes 3", "--passes 3: " + s + " (frame 1, spp=2) renders 2 samples per pixel"},
      {ptracer + " --spp 2", ptracer + ": its integrator is ptracer, which renders whole images"},
      {s + " --spp 2 --parts 1000 --passes 100000",
       "1 frame x --parts 1000 x --passes 100000 make 100000000 array tasks, more than 1000000"},
  };
  for (const auto& [arguments, message] : cases) {
    CommandResult r = run("slurm " + arguments + " --out-dir " + at("out"));
    EXPECT_NE(r.status, 0) << arguments << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(at("out"))) << arguments;
  }
}

TEST_F(SweepCli, SlurmFramesStayInTheOutputDirectory) {
  const std::string s = scene();
  for (const char* frames : {"../../x%d.exr", "/tmp/x%d.exr", "{d}/x.exr", "a/../../x%d.exr"}) {
    CommandResult r = run("slurm " + s + " --spp 1 --sweep d=..,y --frames '" + frames + "' --out-dir " + at("out"));
    EXPECT_NE(r.status, 0) << frames << "\n" << r.output;
    EXPECT_NE(r.output.find("is not in --out-dir '" + at("out") + "'"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(at("out"))) << frames;
  }
  CommandResult r = run("slurm " + s + " --spp 1 --sweep d=..,y --frames 'a/../f{d}.exr' --out-dir " + at("out"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(fs::path(readManifest(at("out/manifest.json")).frames[0].output).lexically_normal(), at("out/f...exr"));
}
