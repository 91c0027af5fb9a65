#pragma once
// Running a sweep or a split render on a Slurm cluster: one job array whose tasks each render one
// piece (frame x part x pass), and a merge job that runs after all of them succeeded (afterok).
// Task t renders frame t / (parts * passes), part (t / passes) % parts + 1 and pass
// t % passes + 1; the task numbers stay the same when only missing pieces are resubmitted.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>
#include "distribute/manifest.h"

namespace columba {

// The most array tasks of one job: Slurm's MaxArraySize allows 1,000 by default and at most
// 4,000,000, and the manifest holds every task's piece.
constexpr int64_t kMostArrayTasks = 1000000;

struct SlurmJob {
  std::string columba;                       // the binary the tasks run (absolute)
  std::string workDir;                       // the directory the tasks run in (absolute)
  std::vector<std::string> renderArguments;  // after `columba render`: scene, options, sweeps, pieces' names
  std::string manifestPath;                  // absolute
  std::string logDir;                        // absolute; one log per task
  std::string jobName = "columba";
  std::string partition, time;  // "" leaves them to the cluster's defaults
  int cpusPerTask = 1;
  int frames = 1, parts = 1, passes = 1;
};

struct TaskPiece {
  int frame = 0, part = 1, pass = 1;  // frame 0-based, part and pass 1-based
};
TaskPiece taskPiece(int task, int parts, int passes);
int taskIndex(const TaskPiece& piece, int parts, int passes);

// The job array's batch script and the merge job's. Every value is quoted, for bash in the
// commands and for sbatch in the #SBATCH lines (which bash reads as comments, so that a line
// break in a value would start a command of its own): a value holding a control character is
// refused with a std::runtime_error naming it.
std::string renderBatchScript(const SlurmJob& job);
std::string mergeBatchScript(const SlurmJob& job);

// `word` quoted for a POSIX shell (as is when it needs no quoting).
std::string shellQuote(const std::string& word);
std::string shellCommand(const std::vector<std::string>& words);
// Array indices as Slurm's --array takes them: "0-3,7,9-11" (sorted, runs joined).
std::string arraySpec(std::vector<int> tasks);

struct MissingWork {
  std::vector<int> tasks;          // array tasks to (re)submit
  std::vector<int> framesToMerge;  // frames whose merged image is not done
};
// What is still to do: every frame whose output `frameDone` rejects needs merging, and each of its
// pieces that `pieceDone` rejects needs rendering.
MissingWork missingWork(const Manifest& manifest, const std::function<bool(const ManifestFrame&)>& frameDone,
                        const std::function<bool(const ManifestPiece&)>& pieceDone);

// The submission commands: the render array (for `tasks`) and the merge job after it
// (`renderJob` is the render array's id, or "" for a merge on its own).
std::vector<std::string> renderSubmitCommand(const SlurmJob& job, const std::string& renderScript,
                                             const std::string& tasks);
std::vector<std::string> mergeSubmitCommand(const std::string& mergeScript, const std::string& renderJob);

// Runs a program (found on PATH) with `arguments`, collecting stdout and stderr together.
struct ProgramResult {
  int status = -1;  // exit status; -1 if it could not be run or died of a signal
  std::string output;
};
ProgramResult runProgram(const std::vector<std::string>& arguments);
// The job id that `sbatch --parsable` printed ("1234" or "1234;cluster"); throws with the output
// when there is none.
std::string parseJobId(const std::string& sbatchOutput);

}  // namespace columba
