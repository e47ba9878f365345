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
#include <iterator>
#include <string>
#include <system_error>

#include "pak/error.hpp"
#include "pak/io/output_batch.hpp"

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
  std::string name = ".";  // appended, not "." + …: g++ 12 warns falsely (-Wrestrict) on that form
  name += target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1));
  return (target.parent_path() / name).string();
}

void removeQuietly(const std::string& path) { ::unlink(path.c_str()); }

// The temporaries being written, in fixed slots that a signal handler can read: a slot is
// free, being filled, or holds a path. A temporary that finds no free slot (more than
// kSlots at once) is not listed.
struct TemporarySlot {
  enum : int { kFree, kFilling, kListed };
  std::atomic<int> state{kFree};
  char path[4096] = {};
};
constexpr int kSlots = 64;
TemporarySlot slots[kSlots];
static_assert(std::atomic<int>::is_always_lock_free);

// The folders the run created, in the same kind of slots (never unlisted).
TemporarySlot folderSlots[8];

void listIn(TemporarySlot* begin, TemporarySlot* end, const std::string& path) {
  if (path.size() >= sizeof(TemporarySlot::path)) return;
  for (TemporarySlot* at = begin; at != end; ++at) {
    TemporarySlot& slot = *at;
    int expected = TemporarySlot::kFree;
    if (!slot.state.compare_exchange_strong(expected, TemporarySlot::kFilling)) continue;
    std::memcpy(slot.path, path.c_str(), path.size() + 1);
    slot.state.store(TemporarySlot::kListed, std::memory_order_release);
    return;
  }
}

void listTemporary(const std::string& path) { listIn(std::begin(slots), std::end(slots), path); }

void unlistTemporary(const std::string& path) {
  for (TemporarySlot& slot : slots)
    if (slot.state.load(std::memory_order_acquire) == TemporarySlot::kListed && path == slot.path) {
      slot.state.store(TemporarySlot::kFree, std::memory_order_release);
      return;
    }
}

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

void checkOutputPath(const std::string& path) { checkWritableTarget(path); }

std::string temporaryPathFor(const std::string& path) {
  checkWritableTarget(path);
  std::string temporary = uniqueTemporaryName(path);
  listTemporary(temporary);
  return temporary;
}

void commitTemporary(const std::string& temporary, const std::string& path) {
  const int renamed = ::rename(temporary.c_str(), path.c_str());
  unlistTemporary(temporary);
  if (renamed != 0) {
    int error = errno;
    removeQuietly(temporary);
    throw InputError(path, "cannot write: " + describeErrno(error));
  }
}

void finishTemporary(const std::string& temporary, const std::string& path) {
  if (!deferToOpenBatch(temporary, path)) commitTemporary(temporary, path);
}

void discardTemporary(const std::string& temporary) {
  removeQuietly(temporary);
  unlistTemporary(temporary);
}

void removeEmptyCreatedFolders() noexcept {
  // Deepest first: a folder the run made inside another it made.
  for (auto at = std::rbegin(folderSlots); at != std::rend(folderSlots); ++at)
    if (at->state.load(std::memory_order_acquire) == TemporarySlot::kListed) ::rmdir(at->path);
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
    unlistTemporary(temporary);
    throw InputError(path, "cannot write: " + describeErrno(error));
  }
  finishTemporary(temporary, path);
}

void listCreatedFolder(const std::string& folder) { listIn(std::begin(folderSlots), std::end(folderSlots), folder); }

void removeTemporaries() noexcept {
  for (TemporarySlot& slot : slots)
    if (slot.state.load(std::memory_order_acquire) == TemporarySlot::kListed) ::unlink(slot.path);
  // rmdir removes only an empty folder: one holding finished outputs stays.
  for (TemporarySlot& slot : folderSlots)
    if (slot.state.load(std::memory_order_acquire) == TemporarySlot::kListed) ::rmdir(slot.path);
}

}  // namespace pak
