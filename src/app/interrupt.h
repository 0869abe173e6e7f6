// Interrupts of a render (Ctrl-C, kill): the first SIGINT asks the scheduler to stop at the
// end of the current pass, so the images are written with the samples taken (every pixel
// with the same count); a second SIGINT, or SIGTERM, aborts at once: any temporary file of
// an unfinished write is removed and the process exits with 128 + the signal's number
// (130, 143), leaving no half-written image (images are only ever renamed into place whole).
#pragma once

#include <atomic>

namespace rt {

// Installs the handlers; call once, early in main. Unless `quiet`, the first SIGINT says at
// once that the pass is being finished.
void install_interrupt_handlers(bool quiet);

// Set by the first SIGINT; the scheduler's cancellation flag.
const std::atomic<bool>& stop_requested();

// The exit status of a run that stopped early on SIGINT (130).
constexpr int kInterruptedExitStatus = 130;

}  // namespace rt
