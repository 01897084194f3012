#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""Soak test: kill runs at random moments, many times, and check that no result is lost (docs/robustness.md).

usage: scripts/soak.py [--trials N] [--seed S] [--build build] [--keep DIR]

Each trial writes a complete earlier result (weak Sod) into a folder, then starts the 3D Taylor rod into the same
folder (1 or 2 ranks, checkpoints every 10 steps) and sends it SIGTERM, SIGINT or SIGKILL after a random delay
(0 to 4 s: set-up, first output, loop, final output). After each it checks that
  - the folder holds the earlier result byte for byte, or this run's outputs all complete (every dataset as long as
    /time, the XDMF naming exactly those times) and readable;
  - no checkpoint under its final name is incomplete, and the newest restarts: a run from it to 3 steps further
    exits 0;
  - a SIGTERM or SIGINT ended with a message naming it (unless the run had finished and printed its summary: a
    signal during MPI's finalisation ends the process without a word, its result complete).
Prints one line per trial and the counts; exits 1 if any trial lost a result.
"""
import argparse
import os
import random
import re
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import petmpmlib as lib  # noqa: E402


def trial(exe, d, rng, env, log):
    """One kill; returns (ok, line)."""
    sod = ["-options_file", os.path.join(SRC, "inputs", "sod_weak.opts"), "-mpm_cells", "64", "-mpm_output", d]
    subprocess.run([exe, *sod], capture_output=True, env=env, check=True)
    before = open(os.path.join(d, "petmpm.h5"), "rb").read()
    for f in os.listdir(d):
        if f.startswith("checkpoint-"):
            os.remove(os.path.join(d, f))
    ranks = rng.choice((1, 2))
    sig = rng.choice((signal.SIGTERM, signal.SIGINT, signal.SIGKILL))
    delay = rng.uniform(0.0, 4.0)
    scene = ["-options_file", os.path.join(SRC, "inputs", "taylor_anvil_3d.opts"), "-mpm_cells", "64,64,168", "-ts_max_steps", "40", "-mpm_checkpoint_interval", "10"]
    cmd = ([exe] if ranks == 1 else ["mpiexec", "-n", "2", exe]) + scene + ["-mpm_output", d]
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env, start_new_session=True)
    time.sleep(delay)
    p.send_signal(sig)
    out, _ = p.communicate(timeout=300)
    t0 = time.time()
    while time.time() - t0 < 20 and subprocess.run(["pgrep", "-f", f"petmpm.*{d}"], capture_output=True).returncode == 0:
        time.sleep(0.05)  # a rank whose launcher was killed
    same = open(os.path.join(d, "petmpm.h5"), "rb").read() == before
    ok, t = lib.complete_outputs(d)
    finished = re.search(r"steps to t = .* point-steps/s", out) is not None  # the summary: the signal came at the exit
    named = sig == signal.SIGKILL or p.returncode == 0 or finished or re.search(r"Interrupted by SIG(TERM|INT)", out) is not None
    cks = sorted((f for f in os.listdir(d) if re.fullmatch(r"checkpoint-\d+\.h5", f)), key=lambda f: int(f[11:-3]))
    restart = "none"
    if cks:
        step = int(cks[-1][11:-3])
        r = subprocess.run([exe, *scene, "-ts_max_steps", str(step + 3), "-mpm_checkpoint_interval", "10", "-mpm_output", d, "-mpm_restart", os.path.join(d, cks[-1])], capture_output=True, text=True, env=env)
        restart = "ok" if r.returncode == 0 else f"exit {r.returncode}: {r.stderr.strip()[:120]}"
    good = (same or ok) and named and restart in ("none", "ok")
    line = f"{'ok  ' if good else 'LOST'} {signal.Signals(sig).name} at {delay:.2f} s on {ranks} rank(s): exit {p.returncode}, " \
           f"{'earlier result intact' if same else f'{len(t or [])} complete outputs' if ok else 'UNREADABLE or incomplete'}, newest checkpoint restart: {restart}"
    log(line)
    return good, same


def soak(trials, seed=1, build=None, log=print):
    """Runs the trials; returns (trials, lost, kept earlier results)."""
    exe = os.path.join(build or os.path.join(SRC, "build"), "petmpm")
    rng = random.Random(seed)
    lost = kept = 0
    with tempfile.TemporaryDirectory() as top:
        d = os.path.join(top, "out")
        for _ in range(trials):
            good, same = trial(exe, d, rng, lib.ENV, log)
            lost += not good
            kept += same
    return trials, lost, kept


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--trials", type=int, default=40)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--build", default=os.path.join(SRC, "build"))
    args = ap.parse_args()
    n, lost, kept = soak(args.trials, args.seed, args.build)
    print(f"soak: {n} kills, {lost} lost a result, {kept} left the earlier result, {n - lost - kept} left this run's complete outputs")
    sys.exit(1 if lost else 0)


if __name__ == "__main__":
    main()
