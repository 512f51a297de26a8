#!/usr/bin/python3
"""Where a step of the NREL 5-MW header run goes, against the budget that
100x OpenFAST leaves.

    speed_budget.py YAMSC_EXE [--runs 3] [--tmax 200] [--wind 16] [--workdir DIR]
                    [--json PATH] [--controllers BUILD/controllers]

The header's run (bench/bem_speed.py: the 16-DOF operating deck through
`yamsc from-openfast`, ABM4 at DT 0.00625 s, loose coupling, ROSCO with the
deck's DISCON.IN, rows every 0.025 s with OpenFAST's channel names) is taken
apart by running it without one piece at a time:
  1. the header's run: blade elements (BEM, UA_Mod 3, DBEMT_Mod 2);
  2. the same with the table rotor (`--aero table`): no blade elements;
  3. 2 with ROSCO not logging (LoggingLevel 0 in a copy of DISCON.IN);
  4. 3 without the rows (one row at the end);
  5. 4 with the NREL baseline controller (C, no file reading) instead of ROSCO.
The differences are the cost of each piece per step: the blade elements
(1 - 2), ROSCO's log (2 - 3), the rows (3 - 4), ROSCO's own work over the
baseline's (4 - 5), and 5 is the structure, the table rotor and the integrator.
The budget is OpenFAST's CPU time over 100 per step: 66-78 s for 200 s of the
header's run in steady wind, 86.3 s for 360 s in TurbSim's U18_s1.bts
(tests/data/reference/turbulence/openfast_cpu.txt). CPU time = user + system
of the whole `yamsc sim` process, the JIT cache warmed first, minimum of --runs.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "bench"))
from bem_speed import cpu  # noqa: E402  (CPU time of a child process)
DECK = ROOT / "tests/data/reference/operating/deck"
DT = 0.00625
OPENFAST_STEADY_CPU_PER_S = (66.0 / 200, 78.0 / 200)
OPENFAST_TURBULENT_CPU = ROOT / "tests/data/reference/turbulence/openfast_cpu.txt"
OPENFAST_TURBULENT_TMAX = 360.0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("yamsc")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--tmax", type=float, default=200.0)
    ap.add_argument("--wind", default="16")
    ap.add_argument("--workdir")
    ap.add_argument("--json")
    ap.add_argument("--controllers", default=str(ROOT / "build/controllers"))
    a = ap.parse_args()
    if Path(a.yamsc).exists():
        a.yamsc = str(Path(a.yamsc).resolve())
    rosco = Path(a.controllers) / "librosco_discon.so"
    baseline = Path(a.controllers) / "libnrel5mw_baseline_discon.so"
    if not rosco.exists() or not baseline.exists():
        sys.exit(f"speed_budget.py: needs ROSCO and the baseline controller in {a.controllers}")
    work = Path(a.workdir or tempfile.mkdtemp(prefix="speed_budget_"))
    work.mkdir(parents=True, exist_ok=True)
    logging = (DECK / "DISCON.IN").read_text()
    (work / "DISCON.IN").write_text(logging)
    (work / "DISCON_quiet.IN").write_text(re.sub(r"\n\s*\d+(\s+! LoggingLevel)", r"\n0\1", logging))
    (work / "Cp_Ct_Cq.NREL5MW.txt").write_text((DECK / "Cp_Ct_Cq.NREL5MW.txt").read_text())
    models = {}
    for rotor, extra in (("blade_elements", []), ("table", ["--aero", "table"])):
        models[rotor] = work / f"nrel5mw_{rotor}.mbd"
        subprocess.run([a.yamsc, "from-openfast", str(DECK / "NREL-5MW.fst"), "-o", str(models[rotor])] + extra,
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    aero = {"blade_elements": str(DECK / "NRELOffshrBsline5MW_Onshore_AeroDyn15.dat"),
            "table": str(work / "Cp_Ct_Cq.NREL5MW.txt")}

    def run(rotor: str, controller: list[str], dt_out: float) -> list[str]:
        return [a.yamsc, "sim", str(models[rotor]), "--aero", aero[rotor], "--wind", a.wind,
                "--tmax", str(a.tmax), "--dt", str(DT), "--method", "abm4", "--coupling", "loose",
                "--interp-order", "2", "--dt-out", str(dt_out), "--channels", "openfast",
                "-o", str(work / f"{rotor}.csv")] + controller

    rosco_logging = ["--controller", str(rosco), "--controller-input", str(work / "DISCON.IN")]
    rosco_quiet = ["--controller", str(rosco), "--controller-input", str(work / "DISCON_quiet.IN")]
    runs = {
        "header": run("blade_elements", rosco_logging, 0.025),
        "table": run("table", rosco_logging, 0.025),
        "table_quiet": run("table", rosco_quiet, 0.025),
        "table_quiet_no_rows": run("table", rosco_quiet, a.tmax),
        "table_baseline_no_rows": run("table", ["--controller", str(baseline)], a.tmax),
    }
    steps = a.tmax / DT
    us = {}
    for name, cmd in runs.items():
        cpu(cmd, work)  # the JIT cache
        us[name] = min(cpu(cmd, work) for _ in range(a.runs)) / steps * 1e6
        print(f"{name:24s} {us[name]:7.1f} us per step")
    parts = {
        "blade elements (BEM, UA, DBEMT)": us["header"] - us["table"],
        "ROSCO's log (LoggingLevel 1)": us["table"] - us["table_quiet"],
        "rows every 0.025 s": us["table_quiet"] - us["table_quiet_no_rows"],
        "ROSCO's work over the baseline controller's": us["table_quiet_no_rows"] - us["table_baseline_no_rows"],
        "structure, table rotor, integrator": us["table_baseline_no_rows"],
    }
    openfast_turbulent = float(OPENFAST_TURBULENT_CPU.read_text().split()[0]) + \
        float(OPENFAST_TURBULENT_CPU.read_text().split()[1])
    budgets = {
        "steady (66-78 s per 200 s)": [c * DT / 100 * 1e6 for c in OPENFAST_STEADY_CPU_PER_S],
        "turbulent (U18_s1, 360 s)": [openfast_turbulent / OPENFAST_TURBULENT_TMAX * DT / 100 * 1e6] * 2,
    }
    print()
    for part, cost in parts.items():
        print(f"{part:46s} {cost:7.1f} us per step")
    without_block = us["table"]
    for name, (low, high) in budgets.items():
        print(f"100x budget, {name}: {low:.1f}-{high:.1f} us per step; left for the blade elements "
              f"after the rest of the header's run: {low - without_block:.1f} to {high - without_block:.1f} us "
              f"(they cost {parts['blade elements (BEM, UA, DBEMT)']:.1f})")
    if a.json:
        Path(a.json).write_text(json.dumps({"load_average": os.getloadavg()[0], "tmax": a.tmax,
                                            "wind": a.wind, "us_per_step": us, "parts_us_per_step": parts,
                                            "budgets_us_per_step": budgets}, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
