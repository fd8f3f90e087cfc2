#!/usr/bin/env python3
"""Fault injection (issue 55): an error raised on ONE rank at each phase of a run stops every rank
with the same exit code, the failure's message, within seconds, on 2 and 3 ranks.

The hook is src/parallel/FaultInjection.hpp (EFG_FAULT=PHASE:RANK[:EXIT]). Each phase is reached
by one of two scenes: tests/scenes/faults/explicit_contact.yaml (mesh to report, explicit with a
rigid disc and a load of t) and implicit_restart.yaml (a restart from the former's results, then
Newton). For every phase the test asserts: exit code 3 (or 2 where injected as bad input); the
message naming the phase and rank; no MPI error (mismatched collectives); the run
ended within LIMIT seconds (a fault-free run takes about 1 s; a rank stopped by the watchdog
waits 5 s, src/parallel/FailureWatchdog.hpp); and where the failure is bad input (exit 2) the
output folder is left empty. Fails if a phase's fault point never fires (exit 0).

usage: check_fault_injection.py EFG WORKDIR RANKS MPIEXEC [MPIEXEC_FLAGS...]
"""
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "..", "scenes", "faults")
LIMIT = 30.0  # seconds: 5 s of the watchdog's wait, the rest for a busy 2-core machine
HANG = 120.0  # a run past this is a hang (killed)

# phase -> scene that reaches it. 'mesh' is read on rank 0 only (the others receive it).
PHASES = {
    "mesh": "explicit", "discretization": "explicit", "operators": "explicit",
    "stable_step": "explicit", "loads": "explicit", "contact": "explicit",
    "internal_force": "explicit", "output": "explicit", "report": "explicit",
    "initial_state": "implicit", "newton": "implicit",
}


def run(cmd, out_dir, env_fault):
    env = dict(os.environ)
    env.pop("EFG_FAULT", None)
    if env_fault:
        env["EFG_FAULT"] = env_fault
    shutil.rmtree(out_dir, ignore_errors=True)
    started = time.monotonic()
    try:
        p = subprocess.run(cmd + ["-o", out_dir], env=env, capture_output=True, text=True,
                           timeout=HANG)
        code, text = p.returncode, p.stdout + p.stderr
    except subprocess.TimeoutExpired as e:
        code = "hang"
        text = (e.stdout or b"").decode(errors="replace") + (e.stderr or b"").decode(errors="replace")
    return code, text, time.monotonic() - started


def main():
    efg, work, ranks, mpiexec = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4:]
    os.makedirs(work, exist_ok=True)
    launch = mpiexec + ["-np", str(ranks), efg, "run"]
    # The restart scene reads the explicit run's results beside it.
    restart_dir = os.path.join(work, "restart")
    os.makedirs(restart_dir, exist_ok=True)
    implicit_scene = os.path.join(restart_dir, "implicit_restart.yaml")
    shutil.copy(os.path.join(SCENES, "implicit_restart.yaml"), implicit_scene)
    explicit_scene = os.path.join(SCENES, "explicit_contact.yaml")
    code, text, seconds = run(launch + [explicit_scene], os.path.join(work, "clean"), None)
    if code != 0:
        sys.exit(f"the fault-free explicit run failed (exit {code}):\n{text[-3000:]}")
    shutil.copy(os.path.join(work, "clean", "explicit_contact.e"), restart_dir)
    code, text, seconds_implicit = run(launch + [implicit_scene], os.path.join(work, "clean2"), None)
    if code != 0:
        sys.exit(f"the fault-free implicit run failed (exit {code}):\n{text[-3000:]}")
    print(f"{ranks} ranks, fault-free: explicit {seconds:.1f} s, implicit {seconds_implicit:.1f} s")

    cases = [(phase, 3) for phase in PHASES] + [("loads", 2), ("output", 2), ("mesh", 2)]
    failures = []
    for phase, exit_code in cases:
        rank = 0 if phase == "mesh" else ranks - 1
        scene = explicit_scene if PHASES[phase] == "explicit" else implicit_scene
        out_dir = os.path.join(work, f"{phase}_{exit_code}")
        fault = f"{phase}:{rank}" + (":2" if exit_code == 2 else "")
        code, text, seconds = run(launch + [scene], out_dir, fault)
        message = f"fault injected by EFG_FAULT in phase '{phase}' on rank {rank}"
        problems = []
        if code != exit_code:
            problems.append(f"exit {code}, expected {exit_code}")
        if message not in text:  # (a Newton cutback's warnings quote it too)
            problems.append(f"the message '{message}' is missing")
        if "MPI_ERR" in text:
            problems.append("an MPI error (mismatched collective calls)")
        if seconds > LIMIT:
            problems.append(f"took {seconds:.1f} s (limit {LIMIT} s)")
        if exit_code == 2 and os.path.isdir(out_dir) and os.listdir(out_dir):
            problems.append(f"bad input wrote {sorted(os.listdir(out_dir))}")
        way = "watchdog" if "did not learn of this failure" in text else "agreed"
        print(f"  {fault:22s} exit {code}  {seconds:5.1f} s  {way:8s} "
              + ("; ".join(problems) if problems else "ok"))
        if problems:
            failures.append(f"{fault}: " + "; ".join(problems) + "\n--- output ---\n" + text[-2500:])
    if failures:
        sys.exit("\n\n".join(failures))
    print(f"all {len(cases)} injected faults stopped every rank with their code")


if __name__ == "__main__":
    main()
