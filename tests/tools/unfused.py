#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_unfused: no object of the core has a fused multiply-add (skipped, exit 77, without objdump).

usage: unfused.py BUILD_DIR SOURCE_DIR
"""
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import BUILD, check, main  # noqa: E402


def test_unfused():
    """No object of the core has a fused multiply-add: with -ffp-contract=off every build level (x86-64-v2 to
    -march=native) gives the same bits, which the regress and kernels comparisons rely on. GCC 12's straight-line
    vectorizer can still fuse a rotation pattern where the target has FMA (CMakeLists.txt keeps it out of mms.c);
    this catches another such place. Skipped where objdump is missing or the target has no FMA to fuse into."""
    lib_a = os.path.join(BUILD, "libpetmpmcore.a")
    if not shutil.which("objdump") or not os.path.exists(lib_a):
        print("SKIPPED: no objdump or no libpetmpmcore.a")
        sys.exit(77)
    asm = subprocess.run(["objdump", "-d", lib_a], capture_output=True, text=True, check=True).stdout
    fused = {}
    obj = None
    for line in asm.splitlines():
        m = re.match(r"^(\S+\.o):\s+file format", line)
        if m:
            obj = m.group(1)
        elif re.search(r"\tv?fn?m(add|sub)\w*", line):
            fused[obj] = fused.get(obj, 0) + 1
    check(len(asm) > 10000, f"objdump read the core library ({len(asm)} characters of assembly)")
    check(not fused, "no fused multiply-add instruction in the core's objects" + (f" (found: {fused})" if fused else ""))


if __name__ == "__main__":
    main(test_unfused)
