#!/usr/bin/python3
"""Cost of the blade-element rotor (`load blade_elements`) against the table
rotor and OpenFAST + AeroDyn + ServoDyn + ROSCO, on the NREL 5-MW deck.

    bem_speed.py YAMSC_EXE [--runs 3] [--tmax 200] [--workdir DIR] [--json PATH]
                 [--controllers BUILD/controllers]

Models: `yamsc from-openfast` of tests/data/reference/operating/deck (all 16
ElastoDyn DOFs), once with its blade elements (the default) and once with
`--aero table`. Each runs 8 m/s for --tmax seconds at the deck's DT 0.00625
under ROSCO (the copy of DISCON.IN that does not log, when ROSCO is built;
else the NREL baseline controller), with RK4 and with ABM4 (ElastoDyn's), no
output file. CPU time = user + system of the whole `yamsc sim` process, the JIT
cache warmed first, minimum of --runs. OpenFAST's CPU time for 200 s of this
deck on this class of machine is 66-78 s (tests/data/reference/operating);
ratios use 66 s scaled to --tmax. The block's cost per call and per node is
the difference of the two rotors' costs over the right-hand-side evaluations
(4 per step with RK4, 2 with ABM4: predictor and corrector).
"""

from __future__ import annotations

import argparse
import json
import os
import re
import resource
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DECK = ROOT / "tests/data/reference/operating/deck"
OPENFAST_CPU_200S = 66.0
AERODYN_NODES = 3 * 19


def cpu(cmd: list[str], cwd: Path) -> float:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, check=True, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("yamsc")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--tmax", type=float, default=200.0)
    ap.add_argument("--workdir")
    ap.add_argument("--json")
    ap.add_argument("--controllers", default=str(ROOT / "build/controllers"))
    a = ap.parse_args()
    work = Path(a.workdir or tempfile.mkdtemp(prefix="bem_speed_"))
    work.mkdir(parents=True, exist_ok=True)
    rosco = Path(a.controllers) / "librosco_discon.so"
    baseline = Path(a.controllers) / "libnrel5mw_baseline_discon.so"
    discon = work / "DISCON.IN"
    text = (DECK / "DISCON.IN").read_text()
    discon.write_text(re.sub(r"\n\s*\d+(\s+! LoggingLevel)", r"\n0\1", text))
    (work / "Cp_Ct_Cq.NREL5MW.txt").write_text((DECK / "Cp_Ct_Cq.NREL5MW.txt").read_text())
    controller = (["--controller", str(rosco), "--controller-input", str(discon)] if rosco.exists()
                  else ["--controller", str(baseline)])
    models = {}
    for rotor, extra in (("blade_elements", []), ("table", ["--aero", "table"])):
        mbd = work / f"nrel5mw_{rotor}.mbd"
        subprocess.run([a.yamsc, "from-openfast", str(DECK / "NREL-5MW.fst"), "-o", str(mbd)] + extra,
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        models[rotor] = mbd
    aero = {"blade_elements": str(DECK / "NRELOffshrBsline5MW_Onshore_AeroDyn15.dat"),
            "table": str(work / "Cp_Ct_Cq.NREL5MW.txt")}
    dt = 0.00625
    results = {"load_average": os.getloadavg()[0], "tmax": a.tmax,
               "controller": "ROSCO" if rosco.exists() else "baseline", "cases": {}}
    steps = a.tmax / dt
    for method, evaluations in (("rk4", 4), ("abm4", 2)):
        times = {}
        for rotor, mbd in models.items():
            cmd = [a.yamsc, "sim", str(mbd), "--aero", aero[rotor], "--wind", "8", "--tmax",
                   str(a.tmax), "--dt", str(dt), "--method", method] + controller
            cpu(cmd, work)  # the JIT cache
            times[rotor] = min(cpu(cmd, work) for _ in range(a.runs))
            ratio = OPENFAST_CPU_200S * a.tmax / 200 / times[rotor]
            results["cases"][f"{rotor}_{method}"] = {"cpu_s": times[rotor], "openfast_ratio": ratio}
            print(f"{rotor:15s} {method:5s} {times[rotor]:7.2f} s CPU  OpenFAST/yamsc {ratio:6.1f}")
        per_call = (times["blade_elements"] - times["table"]) / (steps * evaluations)
        results["cases"][f"block_{method}"] = {"us_per_call": per_call * 1e6,
                                                "ns_per_node": per_call * 1e9 / AERODYN_NODES}
        print(f"block cost ({method}): {per_call * 1e6:.1f} us per call, "
              f"{per_call * 1e9 / AERODYN_NODES:.0f} ns per AeroDyn node")
    print(f"load average {results['load_average']:.1f}")
    if a.json:
        Path(a.json).write_text(json.dumps(results, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
