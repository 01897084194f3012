#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_restart: checkpoints and restart: bit for bit the uninterrupted run.

usage: restart.py BUILD_DIR SOURCE_DIR
"""
import json
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SRC, EXE, SCENE, check, run, signal_in_loop, main  # noqa: E402


def test_restart():
    """Checkpoints and restart: the dam break (point splitting, every module of the default method, popping checks) run
    through, and stopped at step 700 with checkpoints every 260 steps (the last two kept) and continued from the one at
    step 520 into the same output folder: on the rank count that wrote it the output file's every dataset and the
    report's checks equal the uninterrupted run's bit for bit (1 and 2 ranks; on 2 the grid balanced by default, its
    ownership ranges set at a rebalance before step 520, which the checkpoint carries); a checkpoint written on 2 ranks
    continued on 1 gives the same checks to 1e-6; a run stopped by SIGTERM writes a checkpoint that continues to the
    uninterrupted answer, bit for bit. Also: two bodies in contact, a load ramp, a rigid body's velocity table, damage
    with pieces that became bodies (1 and 2 ranks), outflow, and a checkpoint of another version refused."""
    import h5py
    import numpy as np
    import signal
    scene = ["-options_file", os.path.join(SRC, "inputs", "dam_break_2d.opts"), "-mpm_cells", "60,25"]

    def report(d):
        with open(os.path.join(d, "report.json")) as f:
            return {c["name"]: c["value"] for c in json.load(f)["checks"]}

    def same_files(a, b):
        with h5py.File(os.path.join(a, "petmpm.h5"), "r") as fa, h5py.File(os.path.join(b, "petmpm.h5"), "r") as fb:
            names = ["time", "particle_count", "grid/nodes"] + ["particle_fields/" + k for k in fa["particle_fields"]]
            return [n for n in names if n not in fb or not np.array_equal(fa[n][:], fb[n][:])]

    def restarted(args, u, w, at, ranks):
        """The run through into u, and stopped at step `at` with a checkpoint and continued into w: both reports and
        the datasets that differ."""
        run([*args, "-mpm_output", u, "-mpm_report", os.path.join(u, "report.json")], ranks)
        run([*args, "-mpm_output", w, "-mpm_checkpoint_interval", at, "-ts_max_steps", at], ranks)
        run([*args, "-mpm_output", w, "-mpm_restart", os.path.join(w, f"checkpoint-{at}.h5"), "-mpm_report", os.path.join(w, "report.json")], ranks)
        with open(os.path.join(u, "report.json")) as f1, open(os.path.join(w, "report.json")) as f2:
            return json.load(f1), json.load(f2), same_files(u, w)

    with tempfile.TemporaryDirectory() as d:
        ref = {}
        for ranks in (1, 2):
            a, b = os.path.join(d, f"a{ranks}"), os.path.join(d, f"b{ranks}")
            run([*scene, "-mpm_output", a, "-mpm_report", os.path.join(a, "report.json")], ranks)
            run([*scene, "-mpm_output", b, "-mpm_checkpoint_interval", "260", "-ts_max_steps", "700"], ranks)
            kept = sorted(f for f in os.listdir(b) if f.startswith("checkpoint-"))
            check(kept == ["checkpoint-260.h5", "checkpoint-520.h5"], f"{ranks} rank(s): the last two checkpoints kept ({kept})")
            run([*scene, "-mpm_output", b, "-mpm_restart", os.path.join(b, "checkpoint-520.h5"), "-mpm_report", os.path.join(b, "report.json")], ranks)
            diff = same_files(a, b)
            check(not diff and report(a) == report(b), f"{ranks} rank(s): restart from step 520 equals the uninterrupted run bit for bit (datasets differing: {diff})")
            if ranks > 1:  # the balanced grid the checkpoint was written on, not a new balance of the points at step 520
                with open(os.path.join(a, "report.json")) as fa, open(os.path.join(b, "report.json")) as fb:
                    ba, bb = ({k: v for k, v in json.load(f)["balance"].items() if not k.startswith("work_")} for f in (fa, fb))  # not the timings
                check(ba == bb and ba["rebalances"] >= 2, f"{ranks} ranks: the restarted run's balance equals the uninterrupted run's ({bb})")
            ref[ranks] = report(a)
        c = os.path.join(d, "c")
        run([*scene, "-mpm_output", c, "-mpm_checkpoint_interval", "500", "-ts_max_steps", "500"], 2)
        run([*scene, "-mpm_output", c, "-mpm_restart", os.path.join(c, "checkpoint-500.h5"), "-mpm_report", os.path.join(c, "report.json")], 1)
        rc = report(c)
        err = max(abs(rc[k] - ref[1][k]) / abs(ref[1][k]) for k in ref[1])
        check(set(rc) == set(ref[1]) and err < 1e-6, f"a 2-rank checkpoint continued on 1 rank: checks within {err:.1e} of the 1-rank run")
        e = os.path.join(d, "e")  # SIGTERM: a checkpoint, continued
        big = ["-options_file", os.path.join(SRC, "inputs", "dam_break_2d.opts"), "-mpm_cells", "120,50"]
        run([*big, "-mpm_output", os.path.join(d, "f"), "-mpm_report", os.path.join(d, "f", "report.json")])
        rc, out = signal_in_loop([EXE, *big, "-mpm_output", e, "-mpm_progress", "0.2"], signal.SIGTERM)
        ck = [f for f in os.listdir(e) if f.startswith("checkpoint-")]
        check(rc != 0 and len(ck) == 1 and ck[0] in out, f"SIGTERM: a checkpoint written and named ({ck})")
        if ck:
            run([*big, "-mpm_output", e, "-mpm_restart", os.path.join(e, ck[0]), "-mpm_report", os.path.join(e, "report.json")])
            diff = same_files(os.path.join(d, "f"), e)
            check(not diff and report(os.path.join(d, "f")) == report(e), f"the interrupted run continued from its checkpoint equals the uninterrupted one bit for bit (differing: {diff})")
        o, p = os.path.join(d, "o"), os.path.join(d, "p")  # outflow: the tallies of points already gone travel in the checkpoint
        flow = ["-options_file", SCENE, "-mpm_bc_hi", "outflow", "-region_right_velocity", "1e5"]
        run([*flow, "-mpm_output", o, "-mpm_report", os.path.join(o, "report.json")])
        run([*flow, "-mpm_output", p, "-mpm_checkpoint_interval", "800", "-ts_max_steps", "800"])
        run([*flow, "-mpm_output", p, "-mpm_restart", os.path.join(p, "checkpoint-800.h5"), "-mpm_report", os.path.join(p, "report.json")])
        with open(os.path.join(o, "report.json")) as f1, open(os.path.join(p, "report.json")) as f2:
            r1, r2 = json.load(f1), json.load(f2)
        check(r2["outflow"] == r1["outflow"] and r2["outflow"]["points"] > 0 and r2["conservation"] == r1["conservation"] and not same_files(o, p),
              f"outflow: a restart after {r2['outflow']['points']} points left gives the uninterrupted tallies and conservation, bit for bit")
        for ranks in (1, 2):  # two bodies in contact (inputs/disks_2d.opts): the body field and the contact module's tallies
            u, w = os.path.join(d, f"u{ranks}"), os.path.join(d, f"w{ranks}")
            disks = ["-options_file", os.path.join(SRC, "inputs", "disks_2d.opts"), "-mpm_cells", "20,20"]
            r1, r2, diff = restarted(disks, u, w, "80", ranks)
            check(r2["contact"] == r1["contact"] and r1["contact"]["corrections"] > 0 and not diff,
                  f"{ranks} rank(s): two bodies in contact restarted at step 80 (after the impact) equal the uninterrupted run bit for bit (contact work {r2['contact']['work']:.4e}; differing: {diff})")
        # a load ramp (the pushed block, inputs/pushed_block_2d.opts) and a rigid body's velocity table (a piston on the
        # bars of inputs/bars_1d.opts), each checkpointed during its ramp: the load's work and the rigid body's travel go on
        pushed = ["-options_file", os.path.join(SRC, "inputs", "pushed_block_2d.opts"), "-ts_max_time", "2e-4"]
        piston = ["-options_file", os.path.join(SRC, "inputs", "bars_1d.opts"), "-region_left_velocity", "0", "-region_right_velocity", "0", "-body_right_rigid_velocity", "0,-1e4",
                  "-body_right_rigid_velocity_times", "0,2e-6", "-ts_max_time", "4e-6"]
        for name, sc, ranks, at in (("pushed", pushed, 2, "300"), ("piston", piston, 1, "100")):
            u, w = os.path.join(d, name + "u"), os.path.join(d, name + "w")
            r1, r2, diff = restarted(sc, u, w, at, ranks)
            check(r2["contact"] == r1["contact"] and r2.get("load") == r1.get("load") and r2["energy_accounted"] == r1["energy_accounted"] and not diff,
                  f"{name} on {ranks} rank(s), restarted at step {at} inside its ramp: equal to the uninterrupted run bit for bit (differing: {diff})")
        # damage and pieces that became bodies (inputs/spall_plate_1d.opts with -mpm_fracture_bodies): the damage fields,
        # the failed-point tallies and the bodies added after the spall travel in the checkpoint
        spall = ["-options_file", os.path.join(SRC, "inputs", "spall_plate_1d.opts"), "-mpm_cells", "1000", "-mpm_fracture_bodies"]
        for ranks in (1, 2):
            u, w = os.path.join(d, f"spu{ranks}"), os.path.join(d, f"spw{ranks}")
            r1, r2, diff = restarted(spall, u, w, "2400", ranks)
            check(r2["damage"] == r1["damage"] and r2["contact"] == r1["contact"] and len(r1["contact"]["bodies"]) == 2 and not diff,
                  f"spall with pieces as bodies on {ranks} rank(s), restarted at step 2400 (after the scab became {r1['contact']['bodies'][-1]['name']}): equal to the uninterrupted run bit for bit (differing: {diff})")
        # a checkpoint of another version (its /state one value short, as before -mpm_dt_min_ratio's entry): refused, said why
        old = os.path.join(d, "old-checkpoint.h5")
        shutil.copy(os.path.join(p, "checkpoint-800.h5"), old)
        with h5py.File(old, "r+") as h:
            st = h["state"][...]
            del h["state"]
            h["state"] = st[:-1]
        q = run([*flow, "-mpm_output", os.path.join(d, "q"), "-mpm_restart", old], expect_ok=False)
        text = q.stdout + q.stderr
        check(q.returncode != 0 and "-mpm_restart" in text and f"holds {st.size - 1} values, not {st.size}" in text and "another version of petmpm" in text
              and not os.path.exists(os.path.join(d, "q", "petmpm.h5")), f"a checkpoint of another version: exit {q.returncode}, the message names -mpm_restart, the sizes and why; no output written")


if __name__ == "__main__":
    main(test_restart)
