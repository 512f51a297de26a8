#!/usr/bin/python3
"""Cost of the 16-DOF NREL 5-MW in TurbSim's turbulence against OpenFAST's on the
same deck, file and time step.

    turbulent_speed.py YAMSC_EXE --rosco libdiscon.so [--runs 3] [--tmax 360]
                       [--workdir DIR] [--json PATH]

The run is scripts/turbulent_run.py's: tests/data/reference/turbulence/U18_s1.bts
(18 m/s, class B), the operating deck with WindType 3 converted by `yamsc
from-openfast`, run as its header writes the command (blade elements with UA_Mod 3
and DBEMT_Mod 2, ABM4 at DT 0.00625 s, loose coupling, ROSCO logging as the deck
says, rows every 0.05 s with OpenFAST's channel names to a CSV file). CPU time =
user + system of the whole `yamsc sim` process, the JIT cache warmed first, the
minimum of --runs. OpenFAST's CPU time for the same 360 s is in
tests/data/reference/turbulence/openfast_cpu.txt (user, system, wall).
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "scripts"))
import turbulent_run  # noqa: E402


def cpu(cmd: list[str]) -> float:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("yamsc")
    ap.add_argument("--rosco", required=True)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--tmax", type=float, default=360.0)
    ap.add_argument("--workdir")
    ap.add_argument("--json")
    a = ap.parse_args()
    yamsc = str(Path(a.yamsc).resolve())
    work = a.workdir or tempfile.mkdtemp(prefix="turbulent_speed_")
    model, deck = turbulent_run.prepare(yamsc, work)
    cmd = turbulent_run.sim_command(yamsc, model, deck, str(Path(a.rosco).resolve()), a.tmax,
                                    os.path.join(work, "run.csv"))
    cpu(cmd)  # the JIT cache
    seconds = min(cpu(cmd) for _ in range(a.runs))
    user, system, _ = (float(v) for v in
                       (ROOT / "tests/data/reference/turbulence/openfast_cpu.txt").read_text().split())
    openfast = (user + system) * a.tmax / 360.0
    result = {"load_average": os.getloadavg()[0], "tmax": a.tmax, "cpu_s": seconds,
              "openfast_cpu_s": openfast, "openfast_ratio": openfast / seconds}
    print(f"{a.tmax:g} s in turbulence: yamsc {seconds:.2f} s CPU, OpenFAST {openfast:.1f} s: "
          f"{openfast / seconds:.1f}x (load average {result['load_average']:.1f})")
    if a.json:
        Path(a.json).write_text(json.dumps(result, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
