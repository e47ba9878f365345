// Atomic file output: write everything to a temporary file in the target's folder, then
// rename it over the target. rename() within one folder is atomic on POSIX, so readers see
// either the old file or the complete new one, never a half-written file.
#include "pak/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>

#include "pak/error.hpp"

namespace pak {
namespace {

namespace fs = std::filesystem;

std::string describeErrno(int error) { return std::generic_category().message(error); }

// The folder a path lives in ("." for a bare file name).
fs::path folderOf(const std::string& path) {
  fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

// Catch the usual mistakes before creating anything, so the message names the real cause
// ("folder … does not exist") rather than an errno from deep inside a writer.
void checkWritableTarget(const std::string& path) {
  if (path.empty()) throw InputError("", "output file name is empty");
  fs::path target(path);
  if (!target.has_filename()) throw InputError(path, "output path names a folder, not a file");
  std::error_code error;
  if (fs::is_directory(target, error)) throw InputError(path, "output path is a folder, not a file");
  fs::path folder = folderOf(path);
  if (!fs::exists(folder, error))
    throw InputError(path, "cannot write: folder '" + folder.string() + "' does not exist");
  if (!fs::is_directory(folder, error))
    throw InputError(path, "cannot write: '" + folder.string() + "' is not a folder");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw InputError(path, "cannot write into folder '" + folder.string() + "': " + describeErrno(errno));
}

// Unique among threads (counter) and processes (pid); hidden so a crash leaves no clutter
// that looks like a real output.
std::string uniqueTemporaryName(const std::string& path) {
  static std::atomic<unsigned long> counter{0};
  fs::path target(path);
  std::string name = "." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                     std::to_string(counter.fetch_add(1));
  return (target.parent_path() / name).string();
}

void removeQuietly(const std::string& path) { ::unlink(path.c_str()); }

// write() until everything is out, retrying on EINTR and short writes.
bool writeAll(int descriptor, const std::string& contents) {
  const char* data = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    ssize_t written = ::write(descriptor, data, left);
    if (written < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
  return true;
}

}  // namespace

std::string temporaryPathFor(const std::string& path) {
  checkWritableTarget(path);
  return uniqueTemporaryName(path);
}

void commitTemporary(const std::string& temporary, const std::string& path) {
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    int error = errno;
    removeQuietly(temporary);
    throw InputError(path, "cannot write: " + describeErrno(error));
  }
}

void writeFileAtomically(const std::string& path, const std::string& contents) {
  std::string temporary = temporaryPathFor(path);
  // O_EXCL: never write through a file (or link) someone else put there.
  int descriptor = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (descriptor < 0) throw InputError(path, "cannot write: " + describeErrno(errno));
  bool ok = writeAll(descriptor, contents);
  int error = ok ? 0 : errno;
  // close() can report a delayed write error (NFS, full disk), so it counts as a write.
  if (::close(descriptor) != 0 && ok) {
    ok = false;
    error = errno;
  }
  if (!ok) {
    removeQuietly(temporary);
    throw InputError(path, "cannot write: " + describeErrno(error));
  }
  commitTemporary(temporary, path);
}

}  // namespace pak
