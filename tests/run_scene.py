#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Runs one expectation file of tests/scenes/ and checks every expectation in it; prints each case's time loop
(the report's wall_seconds) and PASSED/FAILED with the measured number beside its bound, exits non-zero on a failure.

usage: run_scene.py BUILD_DIR SOURCE_DIR NAME        (tests/scenes/NAME.json)
       run_scene.py BUILD_DIR SOURCE_DIR PATH.json   (an expectation file elsewhere: tests/studies/, run by
                                                     make verification, not by make test)

An expectation file is {"doc": "...", "cases": [CASE, ...]}; a CASE is
  {"name": "weak256", "scene": "sod_weak", "args": ["-mpm_cells", "256"], "ranks": 1, "h": 0.078125,
   "expect": {"errors.density.L1": ["<", 0.02], "conservation.mass": ["abs<", 1e-14], "particles": ["==", 1024]},
   "same_as": {"case": "other", "keys": ["errors.density.L1"], "rtol": 1e-9, "fields": true, "steps": true},
   "sweep": {"option": "-mpm_cells", "values": [128, 256, 512], "h": [0.15625, 0.078125, 0.0390625], "per": 1},
   "rate": {"key": "errors.density.L1", "op": [">=", 0.6]}, "expect_last": {...},
   "compare": [{"key": "errors.density.L1", "op": "<", "case": "other", "factor": 0.6}]}
- expect: report keys (dotted paths, scripts/petmpmlib.py get: checks by name, checks.NAME.error_cells with "h")
  against an operator and a bound (<, <=, >, >=, ==, abs<, abs> (|value| > |bound|)), or a list of such pairs;
- same_as: equality with an earlier case of the file, of report keys to rtol and, with "fields", of every final
  point field the two share (bitwise for rtol 0), and of the step count;
- sweep + rate: the case runs once per value of the option ("per": the value is repeated for that many directions,
  "-mpm_cells 16,16" for 2), and the rate fitted to key against h (log-log least squares, scripts/petmpmlib.py
  fit_rate) must satisfy op (rate may be a list); expect then applies to every run of the sweep, expect_last and
  compare to the finest;
- compare: a report key against factor times the same key of an earlier case (op <, <=, >, >=).
A relative "-options_file" in args (a method file, inputs/methods/cpdi1.opts) is taken from the source tree.
"method": NAME at the top of the file (or in a case, where null means none) puts inputs/methods/NAME.opts between
the scene and the case's args: "cth" pins a file's expectations to the CTH study's configuration, where they were
measured, rather than to the program's default method.
"""
import json
import os
import sys
import tempfile

BUILD, SRC, NAME = sys.argv[1], sys.argv[2], sys.argv[3]
sys.path.insert(0, os.path.join(SRC, "scripts"))
import petmpmlib as lib  # noqa: E402

EXE = os.path.join(BUILD, "petmpm")
failures = []
METHOD = None  # the file's "method"


def check(ok, what):
    print(("PASSED " if ok else "FAILED ") + what, flush=True)
    if not ok:
        failures.append(what)


def run_case(case, out, extra=()):
    method = case.get("method", METHOD)  # inputs/methods/NAME.opts after the scene, before the case's args
    extra_args = (["-options_file", f"inputs/methods/{method}.opts"] if method else []) + case.get("args", [])  # a method file (-options_file inputs/methods/X.opts) is relative to the source tree
    extra_args = [os.path.join(SRC, a) if i and extra_args[i - 1] == "-options_file" and not os.path.isabs(a) else a for i, a in enumerate(extra_args)]
    args = ["-options_file", lib.scene_path(case["scene"]), *extra_args, *extra]
    rep, p = lib.run(EXE, args, case.get("ranks", 1), out)
    if rep is None:
        print(p.stdout[-3000:], p.stderr[-3000:])
        raise SystemExit(f"FAILED: case {case['name']}: petmpm {' '.join(args)} exited {p.returncode}")
    print(f"case {case['name']}: {rep.get('wall_seconds', 0.0):.1f} s", flush=True)
    return rep


def expectations(case, rep, label):
    for key, cond in case.get("expect", {}).items():
        v = lib.get(rep, key, case.get("h"))
        for op, bound in cond if isinstance(cond[0], list) else [cond]:
            check(lib.holds(v, op, bound), f"{label}: {key} = {v:.6g} {op} {bound:g}" if isinstance(v, (int, float)) else f"{label}: {key} = {v} {op} {bound}")


def compare(case, rep, label, done):
    for cmp in case.get("compare", []):
        a, b = lib.get(rep, cmp["key"]), lib.get(done[cmp["case"]][0], cmp["key"])
        check(lib.holds(a, cmp["op"], cmp["factor"] * b), f"{label}: {cmp['key']} {a:.4e} {cmp['op']} {cmp['factor']:g} x {cmp['case']}'s {b:.4e}")


def main():
    with open(NAME if NAME.endswith(".json") else os.path.join(SRC, "tests", "scenes", NAME + ".json")) as f:
        spec = json.load(f)
    global METHOD
    METHOD = spec.get("method")
    done = {}
    with tempfile.TemporaryDirectory() as d:
        for case in spec["cases"]:
            name = case["name"]
            out = os.path.join(d, name)
            if "sweep" in case:
                sw, reps = case["sweep"], []
                for v in sw["values"]:
                    rep = run_case(case, os.path.join(out, str(v)), [sw["option"], ",".join([str(v)] * sw.get("per", 1))])
                    expectations(case, rep, f"{name} {sw['option']} {v}")
                    reps.append(rep)
                expectations({"expect": case.get("expect_last", {}), "h": case.get("h")}, reps[-1], f"{name} {sw['option']} {sw['values'][-1]}")
                for rt in case["rate"] if isinstance(case["rate"], list) else [case["rate"]]:
                    errs = [lib.get(r, rt["key"]) for r in reps]
                    op, bound = rt["op"]
                    rate = lib.fit_rate(sw["h"], errs)
                    check(lib.holds(rate, op, bound), f"{name}: {rt['key']} {', '.join(f'{e:.3e}' for e in errs)}: fitted rate {rate:.3f} {op} {bound}")
                done[name] = (reps[-1], os.path.join(out, str(sw["values"][-1])))
                compare(case, reps[-1], f"{name} {sw['option']} {sw['values'][-1]}", done)
                continue
            rep = run_case(case, out)
            done[name] = (rep, out)
            expectations(case, rep, name)
            compare(case, rep, name, done)
            if "same_as" in case:
                sa = case["same_as"]
                ref, refout = done[sa["case"]]
                rtol = sa.get("rtol", 0.0)
                for key in sa.get("keys", []):
                    a, b = lib.get(rep, key), lib.get(ref, key)
                    check(abs(a - b) <= rtol * abs(b), f"{name}: {key} {a:.12e} equals {sa['case']}'s {b:.12e} (rtol {rtol:g})")
                if sa.get("steps", True):
                    check(rep["steps"] == ref["steps"], f"{name}: {rep['steps']} steps == {sa['case']}'s {ref['steps']}")
                if sa.get("fields"):
                    import numpy as np
                    fa, fb = lib.final_fields(os.path.join(out, "petmpm.h5")), lib.final_fields(os.path.join(refout, "petmpm.h5"))
                    common = sorted(set(fa) & set(fb))
                    worst = max(float(np.max(np.abs(fa[k] - fb[k])) / (np.max(np.abs(fb[k])) + 1e-300)) for k in common)
                    check(worst <= rtol, f"{name}: {len(common)} final point fields equal {sa['case']}'s to rtol {rtol:g} (max rel. difference {worst:.1e})")
    print(f"{NAME}: {'FAILED' if failures else 'PASSED'} ({len(failures)} failure(s))")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
