#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""The core untangled: no files of src/ call each other round (scripts/callgraph.py finds no circle in the file call
graph). usage: callgraph.py BUILD_DIR SOURCE_DIR"""
import subprocess
import sys

src = sys.argv[2]
p = subprocess.run([sys.executable, f"{src}/scripts/callgraph.py", f"{src}/src"], capture_output=True, text=True)
print(p.stdout, end="")
print(("PASSED" if p.returncode == 0 else "FAILED") + ": circles in the call graph of src/: " + p.stdout.split(", ")[-1].split()[0] if p.stdout else "FAILED: no output")
sys.exit(p.returncode)
