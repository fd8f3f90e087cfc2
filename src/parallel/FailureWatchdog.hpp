// The last line of defence against a run that hangs after an error on some of its ranks.
//
// An error raised on a subset of ranks must reach all ranks (parallel/Collective.hpp does it where
// the code knows a phase may fail on one rank). Where it does not, the failing rank unwinds to
// main while the others wait in a collective operation it will never join: a deadlock, the worst
// outcome of a batch run (no message, the allocation burnt). The watchdog turns every such case
// into a clean stop by construction, whatever throw site a review missed: a rank that leaves its
// work with an error raises the alarm; if the ranks have not settled the exit together within
// kPeerWaitSeconds, the alarmed rank prints its message and exits with its code, and the MPI
// launcher then stops the job with that code (mpirun: "exited with non-zero status").
#pragma once

#include <string>

namespace efg {

/// Seconds an alarmed rank waits for the others to settle the exit with it.
constexpr double kPeerWaitSeconds = 5.0;

/// Starts the watchdog's thread and makes the failure handlers' communicator (once, from main,
/// on every rank, after MPI is initialized: collective).
void start_failure_watchdog();

/// This rank leaves its work with `message` and exit `code`; the other ranks may not know. The
/// first alarm is kept (its message is the cause); later ones do not restart the wait.
void raise_failure_alarm(int code, const std::string& message);

/// Every rank has settled the exit (or learned of the failure): the alarm is off.
void settle_failure_alarm();

/// Called by a handler of a failure before its collective clean-up (writing the last good state,
/// keeping the partial files), on every rank that handles one there. It returns once every rank
/// has come: the failure is known to all (every rank raised it, or parallel/Collective agreed on
/// it), and the clean-up's collective calls meet each other. A failure of this rank alone never
/// gets past it (the other ranks are in another collective): the alarm raised with `message`
/// ends the run after kPeerWaitSeconds, before any mismatched collective call could corrupt
/// messages (MPI_ERR_TRUNCATE) or hang. The meeting uses a communicator of its own, so it never
/// matches the run's collective calls. Past the meeting the alarm is off (a stage may go on).
/// Without start_failure_watchdog (unit tests): returns.
void meet_in_failure(int code, const std::string& message);

}  // namespace efg
