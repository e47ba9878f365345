#include "interrupt.hpp"

#include <unistd.h>

#include <csignal>
#include <cstring>

#include "pak/io/atomic_file.hpp"

namespace pak::cli {
namespace {

std::atomic<bool> requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the handler may only touch lock-free atomics");

// Only async-signal-safe calls here: write, unlink (removeTemporaries), signal, raise.
extern "C" void onInterrupt(int) {
  if (!requested.exchange(true)) {
    constexpr const char* kMessage =
        "\npak: stopping: the result so far is cleaned up and written (Ctrl-C again to abort)\n";
    [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, kMessage, std::strlen(kMessage));
    return;
  }
  removeTemporaries();
  std::signal(SIGINT, SIG_DFL);
  std::raise(SIGINT);
}

}  // namespace

const std::atomic<bool>& interruptRequest() {
  static const bool installed = [] {
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // reads and writes in progress go on after the first Ctrl-C
    return sigaction(SIGINT, &action, nullptr) == 0;
  }();
  (void)installed;
  return requested;
}

}  // namespace pak::cli
