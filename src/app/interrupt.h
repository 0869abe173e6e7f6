// Interrupts of a render (Ctrl-C, kill): the first SIGINT asks the scheduler to stop at the
// end of the current pass, so the images are written with the samples taken (every pixel
// with the same count); a second SIGINT, or SIGTERM, aborts at once: any temporary file of
// an unfinished write is removed and the process exits with 128 + the signal's number
// (130, 143), leaving no half-written image (images are only ever renamed into place whole).
#pragma once

#include <atomic>

namespace rt {

// Installs the handlers; call early in main. Unless `quiet`, the first SIGINT says at
// once that the pass is being finished. With `terminate_finishes` the first SIGTERM does
// what the first SIGINT does: mpirun turns a Ctrl-C into SIGTERM to every rank (followed
// by SIGKILL after odls_base_sigkill_timeout), so under it a SIGTERM is the user's stop.
// Calling it again replaces the settings (the distributed driver does, once it knows its
// rank).
void install_interrupt_handlers(bool quiet, bool terminate_finishes = false);

// Set by the first SIGINT (or SIGTERM, as above), or by request_stop; the scheduler's
// cancellation flag.
const std::atomic<bool>& stop_requested();

// Sets the flag as the signal `signal_number` would (another rank of a distributed job
// stopped); the signal is kept for the exit status unless one arrived first.
void request_stop(int signal_number);

// The signal that set the flag; 0 when none did (request_stop(0), or no stop).
int stop_signal();

// 128 + the signal that stopped the run (130 for SIGINT, 143 for SIGTERM); 130 when no
// signal was recorded.
int interrupt_exit_status();

// The exit status of a run that stopped early on SIGINT (130).
constexpr int kInterruptedExitStatus = 130;

}  // namespace rt
