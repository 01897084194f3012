#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""Print the headline numbers of a petmpm JSON report: usage: summary.py report.json"""
import json
import sys

r = json.load(open(sys.argv[1]))
print(f"scene {r['scene']}: {r['dim']}D, cells {r['cells']}, {r['particles']} points, {r['ranks']} rank(s), "
      f"{r['shape']}/{r['update']}/{r['viscosity']}")
print(f"  {r['steps']} steps to t = {r['time']:.6g} s in {r['wall_seconds']:.3f} s: "
      f"{r['particle_steps_per_second']:.3g} point-steps/s")
if "errors" in r:
    for k, v in r["errors"].items():
        print(f"  {k:12s} relative error  L1 {v['L1']:.3e}  L2 {v['L2']:.3e}  Linf {v['Linf']:.3e}")
for c in r.get("checks", []):  # a reference of 0 has no relative error: the JSON's rel_error is then |value| (docs/report.md)
    if c["value"] is None or c["reference"] is None:
        print(f"  {c['name']:18s} {c['value'] if c['value'] is not None else 'n/a'} (no reference)")
        continue
    kind = "abs." if c["reference"] == 0 else "rel."
    print(f"  {c['name']:18s} {c['value']:.6g} (exact {c['reference']:.6g}, {kind} error {c['rel_error']:.2e})")
c = r["conservation"]
print(f"  conservation: mass {c['mass']:.1e}, total energy {c['total_energy']:.1e}; min density {r['min_density']:.4g}; "
      f"non-finite {r['nonfinite']}")
