#include "interrupt.h"

#include <signal.h>
#include <unistd.h>

#include <cstring>

#include "io/file_util.h"

namespace rt {
namespace {

std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};  // The signal that set g_stop.
// Written before the handlers are installed, read only by them.
bool g_quiet = false, g_terminate_finishes = false;
static_assert(std::atomic<bool>::is_always_lock_free, "the flag is set from a signal handler");
static_assert(std::atomic<int>::is_always_lock_free, "the signal is kept from a signal handler");

// Only async-signal-safe calls here: write, unlink (in remove_pending_temporaries), _exit.
void abort_now(int signal_number) {
  remove_pending_temporaries();
  _exit(128 + signal_number);
}

void on_signal(int signal_number) {
  const bool finishes =
      signal_number == SIGINT || (g_terminate_finishes && signal_number == SIGTERM);
  if (finishes && !g_stop.exchange(true)) {
    int none = 0;
    g_signal.compare_exchange_strong(none, signal_number);
    if (g_quiet) return;
    const char msg[] =
        "\nraytracer: interrupt: finishing the current pass, then writing the images "
        "(Ctrl-C again to abort)\n";
    ssize_t ignored = ::write(STDERR_FILENO, msg, sizeof msg - 1);
    (void)ignored;
    return;
  }
  abort_now(signal_number);
}

}  // namespace

void install_interrupt_handlers(bool quiet, bool terminate_finishes) {
  g_quiet = quiet;
  g_terminate_finishes = terminate_finishes;
  struct sigaction sa;
  std::memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;  // Interrupted reads and writes resume; the flag is polled.
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

const std::atomic<bool>& stop_requested() { return g_stop; }

void request_stop(int signal_number) {
  int none = 0;
  g_signal.compare_exchange_strong(none, signal_number);
  g_stop = true;
}

int stop_signal() { return g_signal.load(); }

int interrupt_exit_status() {
  const int s = g_signal.load();
  return 128 + (s > 0 ? s : SIGINT);
}

}  // namespace rt
