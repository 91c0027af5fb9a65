#include "distribute/slurm.h"

#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace columba {

TaskPiece taskPiece(int task, int parts, int passes) {
  return {task / (parts * passes), task / passes % parts + 1, task % passes + 1};
}

int taskIndex(const TaskPiece& piece, int parts, int passes) {
  return (piece.frame * parts + piece.part - 1) * passes + piece.pass - 1;
}

namespace {
bool needsNoQuotes(const std::string& word) {
  return !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::strchr("@%+=:,./-_", c) != nullptr;
  });
}

// `word` quoted as one argument of an #SBATCH line: sbatch reads backslashes as escapes even
// within quotes, so a shell's quoting would lose them.
std::string sbatchQuote(const std::string& word) {
  if (needsNoQuotes(word)) return word;
  std::string quoted = "\"";
  for (char c : word) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}
}  // namespace

std::string shellQuote(const std::string& word) {
  if (needsNoQuotes(word)) return word;
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string shellCommand(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& w : words) line += (line.empty() ? "" : " ") + shellQuote(w);
  return line;
}

std::string arraySpec(std::vector<int> tasks) {
  std::sort(tasks.begin(), tasks.end());
  tasks.erase(std::unique(tasks.begin(), tasks.end()), tasks.end());
  std::string spec;
  for (size_t i = 0; i < tasks.size();) {
    size_t j = i;
    while (j + 1 < tasks.size() && tasks[j + 1] == tasks[j] + 1) ++j;
    spec += (spec.empty() ? "" : ",") +
            (j == i ? std::to_string(tasks[i]) : std::to_string(tasks[i]) + "-" + std::to_string(tasks[j]));
    i = j + 1;
  }
  return spec;
}

namespace {
// `text` with its control characters written as C escapes, for messages.
std::string visible(const std::string& text) {
  std::string shown;
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n')
      shown += "\\n";
    else if (c == '\r')
      shown += "\\r";
    else if (c == '\t')
      shown += "\\t";
    else if (u < 0x20 || u == 0x7f)
      shown += fmt::format("\\x{:02x}", u);
    else
      shown += c;
  }
  return shown;
}

void refuseControlCharacters(const char* what, const std::string& value) {
  for (char c : value) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f)
      throw std::runtime_error(fmt::format(
          "cannot write a Slurm batch script: {} '{}' holds a control character ({}), which a batch script cannot "
          "hold safely",
          what, visible(value), visible(std::string(1, c))));
  }
}

// Every value the scripts hold.
void checkJob(const SlurmJob& job) {
  refuseControlCharacters("the columba binary", job.columba);
  refuseControlCharacters("the working directory", job.workDir);
  for (const std::string& argument : job.renderArguments) refuseControlCharacters("the render argument", argument);
  refuseControlCharacters("the manifest", job.manifestPath);
  refuseControlCharacters("the log directory", job.logDir);
  refuseControlCharacters("the job name (--job-name)", job.jobName);
  refuseControlCharacters("the partition (--partition)", job.partition);
  refuseControlCharacters("the time limit (--time)", job.time);
}

std::string sbatchLine(const std::string& option, const std::string& value) {
  return "#SBATCH " + option + "=" + sbatchQuote(value) + "\n";
}

// `log` names a file in the log directory by Slurm's replacement symbols (%A, %a, %j); a '%' in
// the directory's own name is written %%, which Slurm reads as a '%'.
std::string sbatchHeader(const SlurmJob& job, const std::string& name, const std::string& log, int cpus) {
  std::string logDir;
  for (char c : job.logDir) logDir += c == '%' ? std::string("%%") : std::string(1, c);
  std::string text = sbatchLine("--job-name", name) + sbatchLine("--output", logDir + "/" + log) +
                     "#SBATCH --ntasks=1\n" + fmt::format("#SBATCH --cpus-per-task={}\n", cpus);
  if (!job.partition.empty()) text += sbatchLine("--partition", job.partition);
  if (!job.time.empty()) text += sbatchLine("--time", job.time);
  return text;
}
}  // namespace

std::string renderBatchScript(const SlurmJob& job) {
  checkJob(job);
  const int perFrame = job.parts * job.passes, tasks = job.frames * perFrame;
  std::string text = "#!/bin/bash\n";
  text += fmt::format(
      "# Columba: {} frame(s) x {} part(s) x {} pass(es) = {} array tasks, each rendering one piece.\n"
      "# Task t renders frame t / {}, part (t / {}) % {} + 1, pass t % {} + 1. Written by `columba slurm`,\n"
      "# which prints the sbatch command with the tasks still missing (all: --array=0-{}).\n",
      job.frames, job.parts, job.passes, tasks, perFrame, job.passes, job.parts, job.passes, tasks - 1);
  text += sbatchHeader(job, job.jobName + "-render", "render_%A_%a.log", job.cpusPerTask);
  text += "set -uo pipefail\n";
  text += "task=${SLURM_ARRAY_TASK_ID:?submit this script as a job array: sbatch --array=...}\n";
  text += fmt::format("frame=$(( task / {} ))\npart=$(( task / {} % {} + 1 ))\npass=$(( task % {} + 1 ))\n", perFrame,
                      job.passes, job.parts, job.passes);
  text += fmt::format(
      "echo \"columba task $task: frame $frame, part $part/{}, pass $pass/{}, job ${{SLURM_ARRAY_JOB_ID:-?}}_$task on "
      "$(hostname), started $(date -Is)\"\n",
      job.parts, job.passes);
  // With a trap, bash waits for the render before acting on SIGTERM: the render (which gets the
  // signal too) saves its piece as .partial and exits 143, and the task fails with that status.
  text += "trap 'echo \"task $task: SIGTERM (time limit or scancel): the piece is saved as .partial\"' TERM\n";
  text += "cd " + shellQuote(job.workDir) + " || exit 1\n";
  text += "start=$(date +%s%N)\n";
  std::vector<std::string> command = {job.columba, "render"};
  command.insert(command.end(), job.renderArguments.begin(), job.renderArguments.end());
  text += shellCommand(command) + fmt::format(" --frame \"$frame\" --part \"$part/{}\"", job.parts) +
          (job.passes > 1 ? fmt::format(" --pass \"$pass/{}\"", job.passes) : "") +
          " --threads \"${SLURM_CPUS_PER_TASK:-1}\"\n";
  text += "status=$?\n";
  text += "ms=$(( ($(date +%s%N) - start) / 1000000 ))\n";
  text +=
      "printf 'columba task %s: status %s after %d.%03d s, finished %s\\n' \"$task\" \"$status\" "
      "$((ms / 1000)) $((ms % 1000)) \"$(date -Is)\"\n";
  text += "exit $status\n";
  return text;
}

std::string mergeBatchScript(const SlurmJob& job) {
  checkJob(job);
  std::string text = "#!/bin/bash\n";
  text += fmt::format(
      "# Columba: merges the pieces of {} frame(s) into their images once every render task has succeeded\n"
      "# (submitted with --dependency=afterok:RENDER_JOB); frames already merged are left alone.\n",
      job.frames);
  text += sbatchHeader(job, job.jobName + "-merge", "merge_%j.log", 1);
  text += "set -uo pipefail\n";
  text += "echo \"columba merge: job ${SLURM_JOB_ID:-?} on $(hostname), started $(date -Is)\"\n";
  text += "cd " + shellQuote(job.workDir) + " || exit 1\n";
  text += "exec " + shellCommand({job.columba, "merge", "--manifest", job.manifestPath}) + "\n";
  return text;
}

MissingWork missingWork(const Manifest& manifest, const std::function<bool(const ManifestFrame&)>& frameDone,
                        const std::function<bool(const ManifestPiece&)>& pieceDone) {
  MissingWork work;
  for (const ManifestFrame& frame : manifest.frames) {
    if (frameDone(frame)) continue;
    work.framesToMerge.push_back(frame.frame);
    for (const ManifestPiece& piece : frame.pieces)
      if (!pieceDone(piece))
        work.tasks.push_back(
            taskIndex({frame.frame, piece.part ? piece.part->index : 1, piece.pass ? piece.pass->index : 1},
                      manifest.parts, manifest.passes));
  }
  return work;
}

std::vector<std::string> renderSubmitCommand(const SlurmJob& job, const std::string& renderScript,
                                             const std::string& tasks) {
  return {"sbatch", "--parsable", "--array=" + tasks, renderScript};
}

std::vector<std::string> mergeSubmitCommand(const std::string& mergeScript, const std::string& renderJob) {
  if (renderJob.empty()) return {"sbatch", "--parsable", mergeScript};
  // Without --kill-on-invalid-dep, a failed render task would leave the merge job pending for ever.
  return {"sbatch", "--parsable", "--dependency=afterok:" + renderJob, "--kill-on-invalid-dep=yes", mergeScript};
}

ProgramResult runProgram(const std::vector<std::string>& arguments) {
  ProgramResult result;
  int pipeFds[2];
  if (arguments.empty() || ::pipe(pipeFds) != 0) return result;
  pid_t pid = ::fork();
  if (pid < 0) {
    ::close(pipeFds[0]);
    ::close(pipeFds[1]);
    result.output = std::string("cannot start a process: ") + std::strerror(errno);
    return result;
  }
  if (pid == 0) {
    ::dup2(pipeFds[1], STDOUT_FILENO);
    ::dup2(pipeFds[1], STDERR_FILENO);
    ::close(pipeFds[0]);
    ::close(pipeFds[1]);
    std::vector<char*> argv;
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execvp(argv[0], argv.data());
    std::string message = "cannot run '" + arguments[0] + "': " + std::strerror(errno) + "\n";
    ssize_t ignored = ::write(STDERR_FILENO, message.data(), message.size());
    (void)ignored;
    ::_exit(127);
  }
  ::close(pipeFds[1]);
  char buffer[4096];
  for (;;) {
    ssize_t n = ::read(pipeFds[0], buffer, sizeof buffer);
    if (n > 0)
      result.output.append(buffer, size_t(n));
    else if (n == 0 || errno != EINTR)
      break;
  }
  ::close(pipeFds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string parseJobId(const std::string& output) {
  // The last line that starts with a number: sbatch may print warnings before it.
  std::string id;
  size_t start = 0;
  while (start < output.size()) {
    size_t end = output.find('\n', start);
    std::string line = output.substr(start, end == std::string::npos ? std::string::npos : end - start);
    size_t digits = 0;
    while (digits < line.size() && std::isdigit(static_cast<unsigned char>(line[digits]))) ++digits;
    if (digits > 0 && (digits == line.size() || line[digits] == ';' || line[digits] == '\r'))
      id = line.substr(0, digits);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  if (id.empty()) throw std::runtime_error("sbatch printed no job id: " + output);
  return id;
}

}  // namespace columba
