#pragma once
// Runs `pak` as runPak does, under a watchdog: a run still going after `seconds` is killed
// (its whole process group) and reported as timed out, so a hang fails the test at once
// instead of stalling the suite.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

#include "cli/run_pak.hpp"

namespace pak::testing {

struct WatchedRun : PakRun {
  bool timedOut = false;
  double seconds = 0.0;
};

inline WatchedRun runPakWithin(const std::string& arguments, double seconds) {
  const CapturedRun captured("watched");
  const std::string command = captured.command(arguments);
  WatchedRun run;
  const auto start = std::chrono::steady_clock::now();
  const pid_t child = ::fork();
  if (child == 0) {
    ::setpgid(0, 0);  // its own group: the watchdog kills pak and anything it started
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::setpgid(child, child);
  int status = 0;
  for (;;) {
    const pid_t done = ::waitpid(child, &status, WNOHANG);
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (done == child) break;
    if (run.seconds > seconds) {
      ::kill(-child, SIGKILL);
      ::waitpid(child, &status, 0);
      run.timedOut = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  captured.collect(status, run);
  return run;
}

}  // namespace pak::testing
