#!/usr/bin/env python3
"""A restart file cut short anywhere, or with a flipped bit in its record, is refused (issue 55,
item 2).

An explicit run writes a results file with the restart fields (tests/scenes/faults/
explicit_contact.yaml). Copies of it cut at a sweep of points (inside the header, inside the
mesh, inside the first record, at a record's boundary, one byte short) are named by
initial_state: `efg check` and `efg run` (1 rank; for some cuts 2 ranks, and 3 with the mesh read in slices) must exit 2 naming the
file, write nothing, and never restart from zeros (before: a file cut at 50 % restarted from rest
at t = 0, exit 0). The intact file restarts (exit 0).

usage: check_restart_damage.py EFG WORKDIR MPIEXEC [MPIEXEC_FLAGS...]
"""
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
FAULTS = os.path.join(HERE, "..", "scenes", "faults")


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout + p.stderr


def main():
    efg, work, mpiexec = sys.argv[1], os.path.abspath(sys.argv[2]), sys.argv[3:]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    code, text = run([efg, "run", os.path.join(FAULTS, "explicit_contact.yaml"), "-o",
                      os.path.join(work, "source")])
    if code != 0:
        sys.exit(f"the source run failed (exit {code}):\n{text[-2000:]}")
    source = os.path.join(work, "source", "explicit_contact.e")
    size = os.path.getsize(source)
    with open(os.path.join(FAULTS, "implicit_restart.yaml")) as f:
        scene_text = f.read()
    failures = []

    # The same restart with the mesh made in slices (each rank its part, mesh.read: distributed).
    sliced_text = scene_text.replace("\nmesh:\n", "\nmesh:\n  read: distributed\n")
    assert sliced_text != scene_text

    def restart_from(data, folder, label, ranks):
        """Writes `data` as the restart file of a copy of the restart scene in `folder`, runs
        check (1 rank) and run (on each of `ranks`); intact data must restart (exit 0), damaged
        data be refused (exit 2 naming initial_state.file and the file, nothing written)."""
        damaged = os.path.join(work, folder, "explicit_contact.e")
        os.makedirs(os.path.dirname(damaged))
        with open(damaged, "wb") as g:
            g.write(data)
        scene = os.path.join(os.path.dirname(damaged), "restart.yaml")
        with open(scene, "w") as f:
            f.write(scene_text)
        sliced = os.path.join(os.path.dirname(damaged), "restart_sliced.yaml")
        with open(sliced, "w") as f:
            f.write(sliced_text)
        intact = data == original
        for command, r in [("check", 1)] + [("run", r) for r in ranks]:
            scene_file = sliced if r == 3 else scene  # 3 ranks: the mesh read in slices
            out = os.path.join(work, folder, f"out_{command}_{r}")
            launch = [efg] if r == 1 else mpiexec + ["-np", str(r), efg]
            code, text = run(launch + [command, scene_file] +
                             (["-o", out] if command == "run" else []))
            expected = 0 if intact else 2
            problems = [f"exit {code}, expected {expected}"] if code != expected else []
            if not intact:
                if "initial_state.file" not in text or damaged not in text:
                    problems.append("the message names neither initial_state.file nor the file")
                if command == "run" and os.path.isdir(out) and os.listdir(out):
                    problems.append(f"wrote {sorted(os.listdir(out))}")
            line = f"{label}, {command} on {r} rank(s)" + (" (sliced)" if r == 3 else "")
            print(f"  {line:50s} exit {code}  " + ("; ".join(problems) if problems else "ok"))
            if problems:
                failures.append(line + ": " + "; ".join(problems) + "\n" + text[-1500:])

    with open(source, "rb") as f:
        original = f.read()
    # The cut points: bytes 3 and 100 (the header), fractions of the file, and one byte short.
    cuts = [3, 100] + [int(size * q) for q in (0.1, 0.25, 0.5, 0.75, 0.9, 0.95, 0.99)] + [size - 1]
    for n, cut in enumerate(cuts + [size]):
        restart_from(original[:cut], f"cut_{n}", f"cut at {cut} of {size} bytes",
                     [1, 2, 3] if n % 3 == 0 or cut == size else [1])
    # A flipped bit in the record the restart reads (the last: the file's last bytes), a value
    # that stays a plausible number: the record's checksum refuses it (io/RecordChecksum).
    flips = [size - 1, size - 9, size - 100, size - 700, size - 2000]
    for n, at in enumerate(flips):
        data = bytearray(original)
        data[at] ^= 0x10
        restart_from(bytes(data), f"flip_{n}", f"bit flipped at byte {at} of {size}", [1])
    if failures:
        sys.exit("\n\n".join(failures))
    print(f"all {len(cuts)} cut files and {len(flips)} flipped bits refused; the intact file restarts")

if __name__ == "__main__":
    main()
