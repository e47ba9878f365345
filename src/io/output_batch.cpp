#include "pak/io/output_batch.hpp"

#include <unistd.h>

#include <cassert>
#include <mutex>
#include <utility>
#include <vector>

#include "pak/io/atomic_file.hpp"

namespace pak {
namespace {

// The open batch's finished temporaries and their targets; writers may run on several threads.
struct Pending {
  std::mutex mutex;
  bool open = false;
  std::vector<std::pair<std::string, std::string>> files;  // temporary, target
};

Pending& pending() {
  static Pending instance;
  return instance;
}

}  // namespace

OutputBatch::OutputBatch() {
  std::lock_guard lock(pending().mutex);
  assert(!pending().open);
  pending().open = true;
  pending().files.clear();
}

OutputBatch::~OutputBatch() {
  std::vector<std::pair<std::string, std::string>> files;
  {
    std::lock_guard lock(pending().mutex);
    files.swap(pending().files);
    pending().open = false;
  }
  for (const auto& [temporary, path] : files) discardTemporary(temporary);
  if (!files.empty()) removeEmptyCreatedFolders();
}

void OutputBatch::commit() {
  std::vector<std::pair<std::string, std::string>> files;
  {
    std::lock_guard lock(pending().mutex);
    files.swap(pending().files);
    pending().open = false;
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    try {
      commitTemporary(files[i].first, files[i].second);
    } catch (...) {
      for (std::size_t j = i + 1; j < files.size(); ++j) discardTemporary(files[j].first);
      throw;
    }
  }
}

bool deferToOpenBatch(const std::string& temporary, const std::string& path) {
  std::lock_guard lock(pending().mutex);
  if (!pending().open) return false;
  pending().files.emplace_back(temporary, path);
  return true;
}

}  // namespace pak
