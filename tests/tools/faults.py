#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_faults: no signal, kill or second run loses a result; a restart cannot be silently wrong.

usage: faults.py BUILD_DIR SOURCE_DIR
"""
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import BUILD, SRC, EXE, ENV, SCENE, SCENE_CTH, check, run, sod, lib, main  # noqa: E402

TAYLOR3D = ["-options_file", os.path.join(SRC, "inputs", "taylor_anvil_3d.opts"), "-mpm_cells", "64,64,168", "-ts_max_steps", "40"]
DAM = ["-options_file", os.path.join(SRC, "inputs", "dam_break_2d.opts"), "-mpm_cells", "240,100", "-mpm_progress", "0.2"]


def test_faults():
    import h5py
    with tempfile.TemporaryDirectory() as top:
        # 1. One run per folder: a second run is refused naming the holder; a killed run's lock is stale.
        d = os.path.join(top, "lock")
        p = subprocess.Popen([EXE, *DAM, "-mpm_output", d], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=ENV)
        for line in p.stdout:
            if "to go" in line:
                break
        q = run([*SCENE_CTH, "-mpm_output", d], expect_ok=False)
        text = q.stdout + q.stderr
        check(q.returncode != 0 and f"Output folder {d} (-mpm_output) is in use by another petmpm run (process {p.pid} on" in text,
              f"a second run into a folder in use: exit {q.returncode}, names the folder and the process {p.pid}: {text.strip()[:160]}")
        p.send_signal(signal.SIGKILL)
        p.wait()
        q = run([*SCENE_CTH, "-mpm_output", d], expect_ok=False)
        ok, t = lib.complete_outputs(d)
        check(q.returncode == 0 and ok, f"after the holder's SIGKILL its lock is stale: the next run goes on (exit {q.returncode}) and leaves a complete file ({t})")

        # 2. SIGTERM at moments across set-up, the first output, the loop and the end: the folder holds the earlier
        #    result as it was, or this run's complete outputs; never an unreadable file.
        d = os.path.join(top, "sig")
        sod(d, ["-mpm_cells", "64"])
        before = open(os.path.join(d, "petmpm.h5"), "rb").read()
        phases = set()
        for delay, ranks in ((0.1, 1), (0.3, 1), (0.8, 1), (4.0, 1), (0.3, 2), (1.0, 2)):
            if os.path.exists(os.path.join(d, "report.json")):
                os.remove(os.path.join(d, "report.json"))
            sod(d, ["-mpm_cells", "64"])
            before = open(os.path.join(d, "petmpm.h5"), "rb").read()
            launcher = [] if ranks == 1 else ["mpiexec", "-n", "2"]
            p = subprocess.Popen([*launcher, EXE, *TAYLOR3D, "-mpm_output", d, "-mpm_report", os.path.join(d, "report.json")], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=ENV)
            time.sleep(delay)
            p.send_signal(signal.SIGTERM)
            out, _ = p.communicate(timeout=300)
            m = re.search(r"Interrupted by SIGTERM (during the set-up|after step|during the final output)", out)
            phase = m.group(1) if m else ("finished" if p.returncode == 0 else "killed")
            phases.add(phase)
            same = open(os.path.join(d, "petmpm.h5"), "rb").read() == before
            ok, t = lib.complete_outputs(d)
            left = os.path.exists(os.path.join(d, ".petmpm-new.h5"))
            if phase == "during the set-up":
                good = p.returncode != 0 and same and os.path.exists(os.path.join(d, "report.json")) and not left
                what = "the earlier result and its report as they were, no temporary file"
            elif phase in ("after step", "during the final output", "finished"):
                good = ok and not same and len(t) >= 1 and (phase != "after step" or any(f.startswith("checkpoint-") for f in os.listdir(d)))
                good = good and (phase == "after step" or os.path.exists(os.path.join(d, "report.json")))
                what = "this run's complete outputs (and a checkpoint / its report)"
            elif same:  # no message, the earlier result untouched: the signal came before the handler was in place (a loaded machine)
                good = p.returncode != 0 and os.path.exists(os.path.join(d, "report.json")) and not left
                what = "killed before its signal handler was in place: the earlier result and its report as they were, no temporary file"
            else:  # no message: only a signal that reaches mpiexec while the ranks finalise MPI, after the report, may end a run silently (docs/robustness.md)
                good = ok and len(t) >= 1 and os.path.exists(os.path.join(d, "report.json")) and not left
                what = "ended silently: only after its result was complete (outputs and report), in MPI's finalisation"
            check(good, f"SIGTERM at {delay} s on {ranks} rank(s) ({phase}, exit {p.returncode}): {what}; file complete {ok}, times {t}")
        check("during the set-up" in phases and len(phases) >= 2, f"the signals landed in {len(phases)} phases: {sorted(phases)}")
        for delay in (0.3, 0.8):  # SIGKILL: no chance to react; still the earlier result or complete outputs
            sod(d, ["-mpm_cells", "64"])
            before = open(os.path.join(d, "petmpm.h5"), "rb").read()
            p = subprocess.Popen([EXE, *TAYLOR3D, "-mpm_output", d], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=ENV)
            time.sleep(delay)
            p.send_signal(signal.SIGKILL)
            p.wait()
            same = open(os.path.join(d, "petmpm.h5"), "rb").read() == before
            ok, t = lib.complete_outputs(d)
            if not ok and not os.path.exists(os.path.join(d, "petmpm.xmf")):  # killed between a first output's renames: no XDMF, never a stale one
                with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
                    t = [float(x) for x in f["time"][:]]
                    ok = len(t) >= 1 and {f["particle_fields/" + k].shape[0] for k in f["particle_fields"]} == {len(t)} and f["particle_count"].shape[0] == len(t)
            check(same or ok, f"SIGKILL at {delay} s: the earlier result intact ({same}) or this run's outputs complete and readable ({ok}, {t}; "
                              f"the XDMF {'present' if os.path.exists(os.path.join(d, 'petmpm.xmf')) else 'absent'})")

        # 2b. kill -9 of mpiexec: the ranks stop (the one whose launcher is gone at its next step, the other in MPI);
        #     the folder holds complete outputs.
        d = os.path.join(top, "launcher")
        p = subprocess.Popen(["mpiexec", "-n", "2", EXE, *DAM, "-mpm_output", d], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=ENV, start_new_session=True)
        for line in p.stdout:
            if "to go" in line:
                break
        p.send_signal(signal.SIGKILL)
        p.wait()
        t0 = time.time()
        while time.time() - t0 < 20 and subprocess.run(["pgrep", "-f", f"petmpm.*{d}"], capture_output=True).returncode == 0:
            time.sleep(0.05)
        gone = time.time() - t0
        ok, t = lib.complete_outputs(d)
        check(gone < 20 and ok, f"kill -9 of mpiexec: the ranks stopped within {gone:.2f} s; the file opens with {len(t or [])} complete outputs")

        # 2c. A file that cannot grow (the file size limit; a full disk takes the same path): the message names the
        #     file and why; the earlier result stays when the first output cannot be written, the outputs before the
        #     failure stay readable when a later one cannot.
        import resource

        def limited():
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (8_000_000, 8_000_000))
        d = os.path.join(top, "full")
        sod(d, ["-mpm_cells", "64"])
        before = open(os.path.join(d, "petmpm.h5"), "rb").read()
        q = subprocess.run([EXE, *TAYLOR3D, "-mpm_output", d], capture_output=True, text=True, env=ENV, preexec_fn=limited, timeout=300)
        check(q.returncode != 0 and f"in {d}/" in q.stderr and "file size limit" in q.stderr and open(os.path.join(d, "petmpm.h5"), "rb").read() == before,
              f"a first output that cannot be written: exit {q.returncode}, the message names the file and the limit, the earlier result intact: {q.stderr.strip()[:160]}")
        q = subprocess.run([EXE, "-options_file", SCENE, "-mpm_cells", "40000", "-ts_max_time", "1e-6", "-mpm_output_interval", "500", "-mpm_output", d], capture_output=True, text=True, env=ENV, preexec_fn=limited, timeout=300)
        ok, t = lib.complete_outputs(d)
        check(q.returncode != 0 and f"{d}/petmpm.h5" in q.stderr and "file size limit" in q.stderr and t and len(t) >= 1 and open(os.path.join(d, "petmpm.h5"), "rb").read() != before,
              f"a later output that cannot be written: exit {q.returncode}, named; the file opens with {len(t or [])} complete output(s) by /time: {q.stderr.strip()[:160]}")

        # 3. Restarts that cannot be silently wrong.
        d = os.path.join(top, "ck")
        sod(d, ["-mpm_checkpoint_interval", "200"])
        ck = sorted((f for f in os.listdir(d) if f.startswith("checkpoint-")), key=lambda f: int(f[11:-3]))[0]
        ck = os.path.join(d, ck)
        with h5py.File(ck, "r") as f:
            tck, cells = float(f["state"][0]), int(f["state"][21])
        strong = ["-options_file", os.path.join(SRC, "inputs", "sod_strong.opts"), "-options_file", os.path.join(SRC, "inputs", "methods", "cth.opts")]
        q = run([*strong, "-mpm_cells", str(cells), "-mpm_output", os.path.join(top, "strong"), "-mpm_restart", ck], expect_ok=False)
        text = q.stdout + q.stderr
        check(q.returncode != 0 and "checkpoint is of another scene or method" in text and "-region_left_density" in text and not os.path.exists(os.path.join(top, "strong")),
              f"strong Sod from a weak-Sod checkpoint: refused (exit {q.returncode}) naming the option that differs, nothing written: {text.strip()[:200]}")
        q = run([*SCENE_CTH, "-mpm_cfl", "0.3", "-mpm_output", os.path.join(top, "force"), "-mpm_restart", ck, "-mpm_restart_force"], expect_ok=False)
        check(q.returncode == 0 and "-mpm_restart_force: continuing" in q.stdout and "-mpm_cfl" in q.stdout, f"-mpm_restart_force continues with a method change and names it (exit {q.returncode})")
        q = run([*SCENE_CTH, "-mpm_stop_at_rest", "0.5", "-mpm_output", os.path.join(top, "steer"), "-mpm_restart", ck], expect_ok=False)
        check(q.returncode == 0, f"a restart that changes only how the run is steered (-mpm_stop_at_rest): accepted (exit {q.returncode})")
        q = run([*SCENE_CTH, "-ts_max_time", str(tck / 2), "-mpm_output", os.path.join(top, "early"), "-mpm_restart", ck], expect_ok=False)
        check(q.returncode != 0 and "-ts_max_time" in q.stdout + q.stderr and "nothing to do" in q.stdout + q.stderr, f"a restart whose -ts_max_time is before the checkpoint: refused (exit {q.returncode})")
        new = os.path.join(top, "new")
        run([*SCENE_CTH, "-mpm_output", new, "-mpm_restart", ck])
        ok, t = lib.complete_outputs(new)
        with h5py.File(os.path.join(new, "petmpm.h5"), "r") as f:
            rho0 = f["particle_fields/density"][0][: int(f["particle_count"][0])]
        check(ok and abs(t[0] - tck) <= 1e-12 * tck and rho0.min() > 0, f"a restart into a new folder: its first output is the checkpoint's state (t {t[0]:.6g} = {tck:.6g} s, min density {rho0.min():.4g} > 0)")
        q = run([*SCENE_CTH, "-ts_init_time", "1e-6", "-mpm_output", os.path.join(top, "init")], expect_ok=False)
        check(q.returncode != 0 and "-ts_init_time" in q.stdout + q.stderr and not os.path.exists(os.path.join(top, "init")), f"-ts_init_time 1e-6: refused (exit {q.returncode})")

        # 3b. The soak test of scripts/soak.py, a small count (the script runs 40 by default).
        import soak
        n, lost, kept = soak.soak(2, seed=7, build=BUILD, log=lambda line: print("  " + line))
        check(lost == 0, f"scripts/soak.py: {n} random kills, {lost} lost a result ({kept} left the earlier result)")

        # 4. Messages a user can act on.
        selfref = os.path.join(top, "self.opts")
        with open(selfref, "w") as f:
            f.write("# a scene that includes itself\n-mpm_cells 10 -options_file " + selfref + "\n")
        q = subprocess.run([EXE, "-options_file", selfref], capture_output=True, text=True, env=ENV, timeout=60)
        check(q.returncode == 1 and f"-options_file {os.path.realpath(selfref)} includes itself" in q.stderr, f"an options file that includes itself: exit {q.returncode} (not a crash), named")
        q = run([*SCENE_CTH, "\u2013mpm_cells", "50", "-mpm_output", os.path.join(top, "dash")], expect_ok=False)
        check(q.returncode != 0 and "en dash" in q.stderr and "-mpm_cells" in q.stderr, f"an en dash before an option: refused (exit {q.returncode}): {q.stderr.strip()[:120]}")
        q = run(["-options_file", SCENE, "-mpm_cells", "2", "-mpm_output", os.path.join(top, "two")], expect_ok=False)
        check(q.returncode != 0 and "-mpm_cells 2: too few cells" in q.stderr and "valid is >= 3" in q.stderr, f"-mpm_cells 2 in 1D: names the option and the minimum (exit {q.returncode})")
        nocells = os.path.join(top, "nocells.opts")
        with open(os.path.join(SRC, "inputs", "lax_liu3_2d.opts")) as f, open(nocells, "w") as g:
            g.write("".join(line for line in f if not line.startswith("-mpm_cells")))
        q = run(["-options_file", nocells, "-mpm_output", os.path.join(top, "nocells")], expect_ok=False)
        check(q.returncode != 0 and "-mpm_cells: the scene gives no cell count" in q.stderr and not os.path.exists(os.path.join(top, "nocells")), f"a 2D scene without -mpm_cells: refused, naming the option (exit {q.returncode}; it ran on one cell before)")
        q = run([*SCENE_CTH, "-mpm_cells", "200000000", "-mpm_output", os.path.join(top, "huge")], expect_ok=False)
        check(q.returncode != 0 and "-mpm_cells 200000000" in q.stderr and "index range" in q.stderr, f"-mpm_cells 200000000: names the index limit (exit {q.returncode})")
        avail = 0.0
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemAvailable:"):
                    avail = float(line.split()[1]) * 1024
        need = 3 * 570 ** 3 * 11 * 8  # the grid's three copies of 11 reals per node
        if avail and need > avail:
            q = run([*TAYLOR3D[:2], "-mpm_cells", "570,570,570", "-mpm_output", os.path.join(top, "mem")], expect_ok=False)
            check(q.returncode != 0 and "GiB, more than the" in q.stderr and "-mpm_memory_check" in q.stderr and not os.path.exists(os.path.join(top, "mem")),
                  f"a grid larger than the memory: refused before allocating, with the need, the memory and the override (exit {q.returncode})")


if __name__ == "__main__":
    main(test_faults)
