#pragma once
// Runs the real `pak` binary (PAK_BINARY) through the shell and captures what a user sees:
// the exit code, stdout and stderr. Shared by the CLI tests.
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace pak::testing {

struct PakRun {
  int exitCode = -1;
  std::string out;
  std::string err;
  // stderr split into lines (the trailing newline does not make an empty line).
  std::vector<std::string> errLines() const {
    std::vector<std::string> lines;
    std::istringstream in(err);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  }
};

// Single-quotes for /bin/sh, so paths with spaces or quotes pass through unchanged.
inline std::string shellQuoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

inline std::string readWholeFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// Where one run's stdout and stderr go (temporary files, unique per process and run), the
// shell command that sends them there, and collecting them once the run has ended.
class CapturedRun {
 public:
  explicit CapturedRun(const std::string& kind) {
    static std::atomic<int> counter{0};
    const auto stem = std::filesystem::temp_directory_path() /
                      ("pak-" + kind + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    outPath_ = stem.string() + ".out", errPath_ = stem.string() + ".err";
  }
  // Runs from the source tree, so relative paths like examples/scene.svg work as in the
  // README. `arguments` are already quoted where needed (use shellQuoted for paths).
  std::string command(const std::string& arguments) const {
    return "cd " + shellQuoted(PAK_SOURCE_DIR) + " && exec " + shellQuoted(PAK_BINARY) + " " + arguments + " >" +
           shellQuoted(outPath_) + " 2>" + shellQuoted(errPath_) + " </dev/null";
  }
  // `status` as wait() gives it: a signal is reported as 128 + its number, as the shell does.
  void collect(int status, PakRun& run) const {
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    run.out = readWholeFile(outPath_);
    run.err = readWholeFile(errPath_);
    std::filesystem::remove(outPath_);
    std::filesystem::remove(errPath_);
  }

 private:
  std::string outPath_, errPath_;
};

inline PakRun runPak(const std::string& arguments) {
  const CapturedRun captured("cli");
  PakRun run;
  captured.collect(std::system(captured.command(arguments).c_str()), run);
  return run;
}

// A fresh folder for one test's files, removed when the test ends.
class ScratchFolder {
 public:
  explicit ScratchFolder(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("pak-" + name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::string write(const std::string& name, const std::string& contents) const {
    std::ofstream(path_ / name, std::ios::binary) << contents;
    return file(name);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace pak::testing
