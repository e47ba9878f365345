#pragma once
// Writes files atomically: a temporary file beside the target, then a rename, so a
// crash or an error never leaves a half-written output.
#include <string>

namespace pak {

// Throws InputError if the file cannot be written.
void writeFileAtomically(const std::string& path, const std::string& contents);
// Throws InputError if `path` cannot be written (a missing or read-only folder): for writers
// to fail before their work.
void checkOutputPath(const std::string& path);
// A temporary path beside `path` for writers that need a file name (cairo), and the commit.
std::string temporaryPathFor(const std::string& path);
void commitTemporary(const std::string& temporary, const std::string& path);
// A finished temporary: renamed now, or, while an OutputBatch is open, when it commits.
void finishTemporary(const std::string& temporary, const std::string& path);
// Removes a temporary that will not be committed.
void discardTemporary(const std::string& temporary);
// Removes each folder this run created (listCreatedFolder) that is still empty.
void removeEmptyCreatedFolders() noexcept;
// A folder this run created for its outputs (an animation's, the snapshots').
void listCreatedFolder(const std::string& folder);
// Removes every temporary still being written, then each listed folder left empty.
// Async-signal-safe: for a handler that ends the process (a second Ctrl-C), so that no
// half-written file, and no empty folder of the run's, is left.
void removeTemporaries() noexcept;

}  // namespace pak
