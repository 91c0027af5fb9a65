#pragma once
// Runs the `columba` binary (or any shell command line) from a test and collects what it prints.
#include <sys/wait.h>

#include <cstdio>
#include <string>

namespace columba::testing {

struct CommandResult {
  int status = -1;
  std::string output;  // stdout and stderr
};

// Runs a shell command line, collecting stdout and stderr.
inline CommandResult runShell(const std::string& commandLine) {
  CommandResult r;
  FILE* pipe = popen(("(" + commandLine + ") 2>&1").c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) r.output.append(buffer, n);
  int status = pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// Runs `columba ARGS`.
inline CommandResult run(const std::string& args) { return runShell(std::string(COLUMBA_BINARY) + " " + args); }

}  // namespace columba::testing
