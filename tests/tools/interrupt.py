#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-2-Clause
"""ctest scene_interrupt: SIGTERM and SIGKILL during the time loop leave complete outputs.

usage: interrupt.py BUILD_DIR SOURCE_DIR
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))  # tests/common.py
from common import SRC, EXE, check, xdmf_times, signal_in_loop, main  # noqa: E402


def test_interrupt():
    """SIGTERM during the time loop (on one rank and on two): the step finishes, the last state is written as a complete
    output (every dataset as long as /time, the XDMF naming each output) and the run exits non-zero with a message
    naming the signal, the step and the output folder. SIGKILL (no chance to react): every output before it is
    complete, /time says which (it is written last in each output) and the XDMF names only complete ones."""
    import h5py
    import signal
    for ranks in (1, 2):
        with tempfile.TemporaryDirectory() as d:
            cmd = ([EXE] if ranks == 1 else ["mpiexec", "-n", "2", EXE]) + ["-options_file", os.path.join(SRC, "inputs", "dam_break_2d.opts"), "-mpm_cells", "240,100", "-mpm_progress", "0.2", "-mpm_output", d]
            rc, text = signal_in_loop(cmd, signal.SIGTERM)
            check(rc != 0 and "Interrupted by SIGTERM after step" in text and d in text, f"{ranks} rank(s): SIGTERM: exit {rc}, message names the signal, the step and the output")
            with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
                nt = f["time"].shape[0]
                lens = {k: f["particle_fields/" + k].shape[0] for k in f["particle_fields"]}
                counts = f["particle_count"][:]
            times = xdmf_times(d)
            check(nt >= 2 and all(n == nt for n in lens.values()) and len(counts) == nt and len(times) == nt, f"{ranks} rank(s): a complete last output: {nt} times, datasets {sorted(set(lens.values()))}, XDMF {len(times)}")
    with tempfile.TemporaryDirectory() as d:  # SIGKILL: the outputs before it stay complete and readable
        cmd = [EXE, "-options_file", os.path.join(SRC, "inputs", "dam_break_2d.opts"), "-mpm_cells", "240,100", "-mpm_progress", "0.2", "-mpm_output_interval", "3", "-mpm_output", d]
        signal_in_loop(cmd, signal.SIGKILL)
        with h5py.File(os.path.join(d, "petmpm.h5"), "r") as f:
            t = f["time"][:]
            lens = {k: f["particle_fields/" + k].shape[0] for k in f["particle_fields"]}
            counts = f["particle_count"][:]
        times = xdmf_times(d)
        ok = len(t) >= 2 and all(len(t) <= n <= len(t) + 1 for n in lens.values()) and len(counts) >= len(t) and len(times) <= len(t) and times == [float(x) for x in t[:len(times)]]
        check(ok, f"SIGKILL: the file opens, {len(t)} complete outputs by /time, datasets {sorted(set(lens.values()))} rows, XDMF {len(times)} outputs, all complete")


if __name__ == "__main__":
    main(test_interrupt)
