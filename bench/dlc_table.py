#!/usr/bin/python3
"""Wall time of a whole DLC 1.2 fatigue table on this machine: the winds, the
runs and the reduction, each phase timed.

    dlc_table.py YAMSC_EXE --rosco libdiscon.so [--speeds 4,6,..,24 | default bins]
                 [--seeds 6] [--threads N] [--dt 0.00625] [--workdir DIR] [--json PATH]

The turbine is tests/data/reference/operating/deck through `yamsc from-openfast`
(16 DOFs, blade elements with UA_Mod 3 and DBEMT_Mod 2), ROSCO with the deck's
DISCON.IN as it is (logging), the deck's DT. `yamsc dlc --dlc 1.2 --class IB`
makes the 11 speeds from cut-in to cut-out (4 to 24 m/s) x --seeds winds of
660 s (600 s kept after a 60 s transient) with yamsc's own generator; `yamsc
batch` runs the cases --threads at a time; `yamsc loads` reduces them to
statistics, DELs and lifetime DELs with a plot. Each phase's wall time and the
CPU time of all of them are printed and written to --json.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DECK = ROOT / "tests/data/reference/operating/deck"


def timed(cmd: list[str], cwd: Path) -> float:
    start = time.monotonic()
    subprocess.run(cmd, check=True, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.monotonic() - start


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("yamsc")
    ap.add_argument("--rosco", required=True)
    ap.add_argument("--speeds")
    ap.add_argument("--seeds", type=int, default=6)
    ap.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--dt", default="0.00625")
    ap.add_argument("--workdir")
    ap.add_argument("--json")
    a = ap.parse_args()
    yamsc = str(Path(a.yamsc).resolve())
    work = Path(a.workdir or tempfile.mkdtemp(prefix="dlc_table_"))
    work.mkdir(parents=True, exist_ok=True)
    (work / "DISCON.IN").write_text((DECK / "DISCON.IN").read_text())
    (work / "Cp_Ct_Cq.NREL5MW.txt").write_text((DECK / "Cp_Ct_Cq.NREL5MW.txt").read_text())
    subprocess.run([yamsc, "from-openfast", str(DECK / "NREL-5MW.fst"), "-o", str(work / "turbine.mbd")],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    speeds = ["--speeds", a.speeds] if a.speeds else []
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    wall = {
        "winds": timed([yamsc, "dlc", "turbine.mbd", "-o", "table", "--dlc", "1.2", "--class", "IB",
                        "--hub-height", "90", "--rotor-diameter", "126", "--seeds", str(a.seeds),
                        "--controller", str(Path(a.rosco).resolve()),
                        "--controller-input", str(work / "DISCON.IN"),
                        "--aero", str(DECK / "NRELOffshrBsline5MW_Onshore_AeroDyn15.dat"),
                        "--dt", a.dt, "--dt-out", "0.05", "--threads", str(a.threads)] + speeds, work),
        "runs": timed([yamsc, "batch", "table/cases.csv", "--threads", str(a.threads), "-q"], work),
        "reduction": timed([yamsc, "loads", "--batch", "table/cases.out", "--speeds", "table/table.csv",
                            "--from", "60", "--class", "I", "--del",
                            "TwrBsMyt:4,LSShftMxa:4,RootMyc1:10,RootMxc1:10",
                            "-o", "table/loads.csv", "--plot", "table/loads.svg"], work),
    }
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cases = sum(1 for line in (work / "table/cases.csv").read_text().splitlines()
                if line and not line.startswith(("#", "id,")))
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    for phase, seconds in wall.items():
        print(f"{phase:10s} {seconds:7.1f} s wall")
    total = sum(wall.values())
    print(f"{cases} cases on {a.threads} threads: {total:.1f} s wall ({total / 60:.2f} min), "
          f"{cpu:.0f} s CPU; load average {os.getloadavg()[0]:.1f}")
    if a.json:
        Path(a.json).write_text(json.dumps({"cases": cases, "threads": a.threads, "dt": float(a.dt),
                                            "wall_s": wall, "total_wall_s": total, "cpu_s": cpu,
                                            "load_average": os.getloadavg()[0]}, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
