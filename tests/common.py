# SPDX-License-Identifier: BSD-2-Clause
"""What the profile tests (tests/profiles/: physics read from the HDF5 fields) and the tool tests (tests/tools/: the
program's and the scripts' behaviour) share: each runs the executable and asserts physics or behaviour, not just
completion. Tests that only compare report keys, sweeps with fitted rates or runs with each other are expectation
files in tests/scenes/ (run_scene.py).

A test is tests/GROUP/NAME.py BUILD_DIR SOURCE_DIR (ctest scene_NAME): it defines test_NAME() and ends with
main(test_NAME), which prints PASSED/FAILED with the measured numbers and exits non-zero on a failure.
"""
import json
import os
import subprocess
import sys

BUILD, SRC = sys.argv[1], sys.argv[2]
EXE = os.path.join(BUILD, "petmpm")
SCENE = os.path.join(SRC, "inputs", "sod_weak.opts")
CTH = os.path.join(SRC, "inputs", "methods", "cth.opts")
SCENE_CTH = ["-options_file", SCENE, "-options_file", CTH]  # weak Sod in the CTH study's configuration, where these checks were measured
sys.path.insert(0, os.path.join(SRC, "scripts"))
import petmpmlib as lib  # noqa: E402

ENV = lib.ENV
final_fields = lib.final_fields
xdmf_times = lib.xdmf_times
failures = []


def check(ok, what):
    print(("PASSED " if ok else "FAILED ") + what)
    if not ok:
        failures.append(what)


def run(args, ranks=1, expect_ok=True):
    cmd = ([EXE] if ranks == 1 else ["mpiexec", "-n", str(ranks), EXE]) + args
    p = subprocess.run(cmd, capture_output=True, text=True, env=ENV, timeout=300)
    if expect_ok and p.returncode != 0:
        print(p.stdout, p.stderr)
        raise SystemExit("FAILED: " + " ".join(cmd) + f" exited {p.returncode}")
    return p


def sod(out, extra=(), ranks=1):
    rep = os.path.join(out, "report.json")
    p = run([*SCENE_CTH, "-mpm_output", out, "-mpm_report", rep, *extra], ranks)
    with open(rep) as f:
        return json.load(f), p


def scene(name, out, extra=(), ranks=1):
    """Runs inputs/NAME.opts with a report in OUT; returns the report."""
    rep = os.path.join(out, "report.json")
    run(["-options_file", os.path.join(SRC, "inputs", name + ".opts"), "-mpm_output", out, "-mpm_report", rep, *extra], ranks)
    with open(rep) as f:
        return json.load(f)


def study_key(script, cells, extra, args):
    """A digest of everything a study's rows depend on: the executable, the scripts, the scenes and the arguments."""
    import hashlib
    h = hashlib.sha256(json.dumps([script, cells, list(extra), list(args)]).encode())
    files = [EXE] + sorted(os.path.join(r, f) for top in ("scripts", "inputs") for r, _, fs in os.walk(os.path.join(SRC, top)) for f in fs if f.endswith((".py", ".opts")))
    for name in files:
        with open(name, "rb") as f:
            h.update(name.encode() + f.read())
    return h.hexdigest()


def study(script, cells, extra=(), args=()):
    """The rows (--json "runs") of the study scripts/SCRIPT at the given cells ("64,128") with the script's own
    options args and petmpm options extra; a study that fails is a failure of the test (SystemExit), not a row.
    The rows are kept in BUILD/study_cache under a digest of the executable, scripts/, inputs/ and the arguments,
    so that a test that asserts another figure of the same runs (a known failure split off) does not run them again;
    a rebuild or any edit of a script or a scene gives a new digest, and each ctest run empties the cache first (the
    fixture study_cache, tests/CMakeLists.txt); a lock per digest makes a second test wait for the first."""
    import fcntl
    cache = os.path.join(BUILD, "study_cache")
    os.makedirs(cache, exist_ok=True)
    kept = os.path.join(cache, study_key(script, cells, extra, args) + ".json")
    with open(kept + ".lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if os.path.exists(kept):
            print(f"{script} --cells {cells} {' '.join(args)} -- {' '.join(extra)}: the rows of an earlier run of this build ({kept})")
        else:
            p = subprocess.run(["/usr/bin/python3", os.path.join(SRC, "scripts", script), "--cells", cells, "--build", BUILD, "--json", kept + ".part", *args, "--", *extra],
                               capture_output=True, text=True)
            print(p.stdout, p.stderr)
            if p.returncode != 0:
                raise SystemExit(f"FAILED: {script} {' '.join(extra)} exited {p.returncode}")
            os.replace(kept + ".part", kept)
        with open(kept) as f:
            return json.load(f)["runs"]


def signal_in_loop(cmd, sig):
    """Runs cmd (with -mpm_progress set), sends sig once its first progress line says the time loop is running;
    returns the exit code and everything it printed."""
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=ENV)
    lines = []
    for line in p.stdout:
        lines.append(line)
        if " t = " in line and "to go" in line:
            break
    p.send_signal(sig)
    out, _ = p.communicate(timeout=120)
    return p.returncode, "".join(lines) + out


def main(test):
    """Runs test (a function that calls check), prints the verdict with the test's name and exits 1 on a failure."""
    name = os.path.splitext(os.path.basename(sys.argv[0]))[0]
    test()
    print(f"{name}: {'FAILED' if failures else 'PASSED'} ({len(failures)} failure(s))")
    sys.exit(1 if failures else 0)
