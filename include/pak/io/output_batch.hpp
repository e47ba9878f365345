#pragma once
// A run's outputs, replaced together at its end. While a batch is open, every atomic write
// (atomic_file.hpp, which every writer uses) stops short of its rename: the file stays a hidden
// temporary beside its target. commit() renames them all; a batch left without commit (an
// error, an exception) removes them and any folder the run created that is still empty. So a run
// that fails at its third output leaves neither the first two nor half of the third.
#include <string>

namespace pak {

class OutputBatch {
 public:
  OutputBatch();   // one batch at a time (the process's outputs)
  ~OutputBatch();  // without commit(): removes every temporary of the batch
  OutputBatch(const OutputBatch&) = delete;
  OutputBatch& operator=(const OutputBatch&) = delete;

  // Renames every temporary onto its target, in the order written. Throws InputError naming the
  // target when one rename fails (the ones before it stay replaced: rename is atomic per file).
  void commit();
};

// For atomic_file.cpp: if a batch is open, records the finished `temporary` for `path` and
// returns true; else false, and the caller renames at once.
bool deferToOpenBatch(const std::string& temporary, const std::string& path);

}  // namespace pak
