#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_methods: inputs/methods/cpdi1.opts, the program's default method spelled out (scripts/bench.py composes it
with the linear benchmark bars to time the default method), sets every option it names to the program's default as
`petmpm -help` reports it (the value after the colon in <now : default>); a changed default fails here until the file
follows it.

usage: methods.py BUILD_DIR SOURCE_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SRC, check, run, main  # noqa: E402


def defaults():
    """{option: its default} from -help: '-opt <now X : formerly Y>', '-opt <X : Y>' or '-opt: <X : Y>' give Y."""
    out = run(["-help"]).stdout
    found = {}
    for m in re.finditer(r"^\s+(-\w+):? <(?:now )?[^:>]*: (?:formerly )?([^>]*)>", out, re.M):
        found.setdefault(m.group(1), m.group(2).strip())
    return found


def test_methods():
    dflt = defaults()
    path = os.path.join(SRC, "inputs", "methods", "cpdi1.opts")
    with open(path) as f:
        lines = [ln.split() for ln in f if ln.strip() and not ln.startswith("#")]
    check(len(lines) >= 8, f"cpdi1.opts names {len(lines)} options")
    for words in lines:
        opt, val = words[0], (words[1] if len(words) > 1 else "TRUE")
        have = dflt.get(opt)
        same = have is not None and (have == val or (have.upper() in ("TRUE", "FALSE") and have.upper() == val.upper()))
        if not same:
            try:
                same = have is not None and float(have) == float(val)
            except ValueError:
                pass
        check(same, f"cpdi1.opts {opt} {val}: the program's default is {have}")


main(test_methods)
