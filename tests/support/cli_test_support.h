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

// Starts `columba render ARGS` in the background and sends `signal` `delay` seconds after it prints
// a line matching `after` (by default "Rendering": its signal handlers are in place by then, and a
// fixed delay from the start raced the scene's loading on a loaded machine). Reports what it
// printed, its exit status ("status=N") and the seconds from the signal to the exit ("answered=S").
inline CommandResult renderAndSignal(const std::string& args, const char* signal, double delay,
                                     const std::string& after = "^Rendering ") {
  return runShell("log=$(mktemp); " + std::string(COLUMBA_BINARY) + " render " + args + " 2>$log & pid=$!; i=0; " +
                  "while ! grep -q '" + after + "' $log && kill -0 $pid 2>/dev/null && [ $i -lt 1200 ]; " +
                  "do sleep 0.05; i=$((i + 1)); done; sleep " + std::to_string(delay) +
                  "; start=$(date +%s.%N); kill -" + signal + " $pid; wait $pid; status=$?; end=$(date +%s.%N); " +
                  "cat $log; rm -f $log; echo status=$status; echo answered=$(echo \"$end - $start\" | bc)");
}

}  // namespace columba::testing
