#pragma once
// Ctrl-C: the first asks the run to stop as its time limit would (RunOptions::stopRequest), so
// it still writes a clean result; the second removes any output being written and ends pak.
#include <atomic>

namespace pak::cli {

// Installs the SIGINT handler (once) and returns the flag it sets on the first Ctrl-C.
const std::atomic<bool>& interruptRequest();

}  // namespace pak::cli
