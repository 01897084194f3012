#!/usr/bin/python3
# SPDX-License-Identifier: BSD-2-Clause
"""Strong and weak scaling of a 3D impact (issue 18 item 5): the copper bar of inputs/bar_impact_3d.opts (Mie-Gruneisen,
Johnson-Cook, linear shapes, MUSL) on 1, 2 and 4 ranks, with and without -mpm_balance, median of --repeat runs.

  strong: the same bar (--cells, 36 x 36 x 156 cells: 82,944 points) on every rank count;
  weak:   the bar and its box stretched along z with the rank count (24 x 24 x 104 cells and a 2.4 cm bar per rank),
          so that every rank holds about the same number of points when the ranks are balanced.

Efficiency is the point-steps per second per rank against one rank's: rate(P) / (P rate(1)). The imbalance is the
report's max/mean points per rank at the end. The DMDA splits the box into equal slabs; the bar fills the lower
0.4 x 0.4 of a 0.6 x 0.6 cross-section and its length along z, so without balancing the ranks' shares differ.

usage: scripts/scaling.py [--exe build/petmpm] [--ranks 1,2,4] [--repeat 3] [--steps 40] [--markdown docs/scaling.md]
A machine with fewer cores than ranks runs them oversubscribed (the figures then say so): the 2-core machine of this
project gives no speed-up past 2 ranks.

       scripts/scaling.py --from RUNS.jsonl [--markdown FILE]
tabulates the runs of scripts/scaling_runs.sh (1 to 16 ranks on a machine without Python, issue 43 item 4): per case
and method, the median point-steps per second of the runs at each rank count and the efficiency against one rank's
median; the -log_view runs are left out. solo3d's copies (independent one-rank jobs at once) count as one run whose
rate is their sum. A second table sets each rank's seconds in the point phases (the report's
balance.work_seconds_per_rank) against the one-rank runs': what sharing the machine and its slowest core cost.
"""
import argparse
import json
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from petmpmlib import Transcript, get, run, scene_path  # noqa: E402


def case(exe, ranks, balance, weak, steps, cells):
    """One run: (report, point-steps per second, imbalance or None)."""
    args = ["-options_file", scene_path("bar_impact_3d"), "-ts_max_steps", str(steps), "-mpm_progress", "0"]
    if weak:
        k = ranks
        args += ["-mpm_cells", f"24,24,{104 * k}", "-mpm_hi", f"0.6,0.6,{2.6 * k:g}", "-region_bar_hi", f"0.4,0.4,{2.4 * k:g}"]
    else:
        args += ["-mpm_cells", cells]
    args += ["-mpm_balance", "true" if balance else "false"]  # on by default
    with tempfile.TemporaryDirectory() as d:
        rep, p = run(exe, args, ranks, d)
    if rep is None:
        raise SystemExit(f"scaling: the run failed ({' '.join(args)} on {ranks} ranks):\n{(p.stdout + p.stderr)[-2000:]}")
    imb = get(rep, "balance.imbalance") if "balance" in rep else None
    return rep, rep["particle_steps_per_second"], imb


NAMES = {"def": "default", "defw": "default, balance by work", "lin": "linear MUSL"}


def tabulate(path, say, largest=False):
    """The tables of scripts/scaling_runs.sh's JSONL runs (see the module's doc); largest: only each case's largest rank count."""
    rates, machine, pts, copies, work = {}, None, {}, {}, {}
    with open(path) as f:
        for line in f:
            d = json.loads(line)
            if "machine" in d:
                machine = d["machine"]
            elif "copy" in d:  # solo3d: independent one-rank jobs at once; a run's rate is the sum of its copies'
                key = (d["case"], d["method"], d["ranks"])
                c = copies.setdefault((key, d["rep"]), [])
                c.append(float("nan") if d.get("failed") else d["report"]["particle_steps_per_second"])
                if not d.get("failed") and "work_seconds_per_rank" in d["report"].get("balance", {}):
                    work.setdefault((key, d["rep"]), []).extend(d["report"]["balance"]["work_seconds_per_rank"])
                if not d.get("failed"):
                    pts[key] = (d["report"]["particles"] * d["ranks"], 1.0)
            elif not d.get("failed") and not d.get("log_view"):
                key = (d["case"], d["method"], d["ranks"])
                rates.setdefault(key, []).append(d["report"]["particle_steps_per_second"])
                pts[key] = (d["report"]["particles"], get(d["report"], "balance.imbalance"))
                if "work_seconds_per_rank" in d["report"].get("balance", {}):
                    work[(key, d["rep"])] = d["report"]["balance"]["work_seconds_per_rank"]
    for (key, _), c in copies.items():
        rates.setdefault(key, []).append(sum(c))
    if machine:
        say(f"{machine['cores']} cores ({machine['cpu']}), mpiexec {machine['bind']}; medians of the runs at each rank count.")
        say()
    say("| case | method | ranks | points | runs | point-steps/s | per rank | efficiency | imbalance (max/mean points) |")
    say("|---|---|---|---|---|---|---|---|---|")
    for case, method in sorted({k[:2] for k in rates}, key=lambda k: (k[0], list(NAMES).index(k[1]) if k[1] in NAMES else 9)):
        one = statistics.median(rates.get((case, method, 1), [float("nan")]))
        counts = sorted(k[2] for k in rates if k[:2] == (case, method))
        for r in counts[-1:] if largest else counts:
            v = rates[(case, method, r)]
            med = statistics.median(v)
            say(f"| {case} | {NAMES.get(method, method)} | {r} | {pts[(case, method, r)][0]} | {len(v)} | {med:.3g} | {med / r:.3g} | {med / (r * one):.2f} | {pts[(case, method, r)][1]:.2f} |")
    if not work:
        return
    # Each rank's (copy's) seconds in the point phases (the report's balance.work_seconds_per_rank: no communication
    # inside) against the ideal share of the one-rank runs' (their median, times this rank's share of the one-rank
    # points): the mean says what running beside the other cores costs each one, the slowest what a run that waits
    # for it at every step pays; ideal / slowest bounds the efficiency that any exchange could reach on this machine.
    say()
    say("Seconds in the point phases per rank (per copy for solo3d), against the ideal: the one-rank runs' median times the rank's share of their points.")
    say()
    say("| case | method | ranks | run | mean / ideal | slowest / ideal | slowest / mean | ideal / slowest |")
    say("|---|---|---|---|---|---|---|---|")
    for (key, rep) in sorted(work, key=lambda k: (k[0][0], list(NAMES).index(k[0][1]) if k[0][1] in NAMES else 9, k[0][2], k[1])):
        lone = [w[0] for (k, _), w in work.items() if k == (key[0], key[1], 1)]
        if key[2] == 1 or not lone or (largest and key[2] != max(k[2] for (k, _) in work if k[:2] == key[:2])):
            continue
        w = work[(key, rep)]
        ideal = statistics.median(lone) * (pts[key][0] / key[2]) / pts[(key[0], key[1], 1)][0]
        mean = sum(w) / len(w)
        say(f"| {key[0]} | {NAMES.get(key[1], key[1])} | {key[2]} | {rep} | {mean / ideal:.2f} | {max(w) / ideal:.2f} | {max(w) / mean:.2f} | {ideal / max(w):.2f} |")

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("--exe", default=os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "build", "petmpm"))
    ap.add_argument("--ranks", default="1,2,4")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--steps", type=int, default=40)
    ap.add_argument("--cells", default="36,36,156")
    ap.add_argument("--markdown", default="")
    ap.add_argument("--from", dest="runs", default="", help="tabulate scripts/scaling_runs.sh's JSONL instead of running")
    a = ap.parse_args()
    if a.runs:
        say = Transcript()
        tabulate(a.runs, say)
        say.write(a.markdown)
        return 0
    ranks = [int(r) for r in a.ranks.split(",")]
    cores = os.cpu_count()
    say = Transcript()
    say(f"Median of {a.repeat} runs, {a.steps} steps, on a machine with {cores} cores" + (f" (more ranks than {cores} run oversubscribed)" if max(ranks) > cores else "") + ".")
    say()
    say("| scaling | ranks | balance | points | point-steps/s | per rank | efficiency | imbalance (max/mean) | rebalances |")
    say("|---|---|---|---|---|---|---|---|---|")
    for weak in (False, True):
        base = None
        for r in ranks:
            for balance in ((False,) if r == 1 else (False, True)):
                runs = [case(a.exe, r, balance, weak, a.steps, a.cells) for _ in range(a.repeat)]
                rate = statistics.median(x[1] for x in runs)
                rep, imb = runs[0][0], runs[0][2]
                if r == 1:
                    base = rate
                eff = rate / (r * base)
                say(f"| {'weak' if weak else 'strong'} | {r} | {'on' if balance else 'off'} | {rep['particles']} | {rate:.3g} | {rate / r:.3g} | {eff:.2f} | "
                    + (f"{imb:.2f} | {get(rep, 'balance.rebalances')} |" if imb is not None else "- | - |"))
    say.write(a.markdown)
    return 0


if __name__ == "__main__":
    sys.exit(main())
