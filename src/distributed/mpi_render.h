// The distributed driver: under mpirun, the raytracer spreads the tasks of a JobPlan over
// the ranks. Rank 0 lists the images, hands out tasks one at a time to whichever rank asks
// (dynamic scheduling: a rank that finishes early takes more), gathers the bands, writes each
// image atomically once it is whole, and prints the job's one progress line; it renders tasks
// too, on a thread of its own. Every rank renders on its own device: the node's GPU its local
// rank picks, or the CPU reference with the node's cores shared among the node's ranks.
//
// Faults: a rank whose device fails or whose task throws reports the reason to rank 0, which
// stops handing out work, prints one line naming the rank and the reason, and exits 1; the
// images finished before it stay written and no partial image is. A rank killed outright ends
// the job through mpirun (which names the rank and the signal). --skip-existing resumes.
//
// Interrupts: the job's stop is any rank's (a signal there; under mpirun SIGTERM is the
// user's stop too, app/interrupt.h) or rank 0's kTagStop; every rank ends its task at a pass
// and sends its band, and rank 0 writes the images in progress partial (with checkpoints
// when kept) and returns 128 + its signal, once every rank has stopped.
// This code is compiled only when CMake finds MPI.
#pragma once

#include "app/cli.h"

namespace rt {

// True when the process was started by mpirun/srun (the launcher's environment is set).
bool launched_by_mpi();

// Runs the job on every rank; returns the exit status (0; 1 with the line printed by rank
// 0; on rank 0 after an interrupt 130 or 143, the other ranks 0).
int render_distributed(const CliOptions& opt);

}  // namespace rt
