#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_offcentre_blast_interior (a known failure, WILL_FAIL): the off-centre cylindrical Sedov blast on a full plane
(inputs/sedov_offcentre_2d.opts, scripts/blast2d.py) in the default method: the hot interior's pressure within 10% of
the similarity solution at 128^2 cells (issue 41's goal). Measured (2026-11-29): 0.42, 0.21 and 0.09 of the exact at
64^2, 128^2 and 256^2 (first-order Godunov 0.92, 0.95, 0.97), the points' volumes filling 1.40, 1.95 and 3.34 times the
blast's area: the seeded hot gas's points, split ten times over, overlap (docs/verification_2d.md, "Where the volumes
go"). What passes in the same runs is asserted by scene_offcentre_blast, the interior's energy per area among it
(0.91 and 0.94 of the exact pressure's: the flow is right, the points' volumes are not).

usage: offcentre_blast_interior.py BUILD_DIR SOURCE_DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import check, main, study  # noqa: E402


def test_offcentre_blast_interior():
    r = study("blast2d.py", "64,128")[1]
    check(abs(r["interior"] - 1.0) < 0.1, f"default, 128^2: interior pressure {r['interior']:.3f} of the exact (within 10%)")


if __name__ == "__main__":
    main(test_offcentre_blast_interior)
