#!/usr/bin/python3
"""Cost of the blade-element rotor (`load blade_elements`) against the table
rotor and OpenFAST + AeroDyn + ServoDyn + ROSCO, on the NREL 5-MW deck.

    bem_speed.py YAMSC_EXE [--runs 3] [--tmax 200] [--winds 8,16] [--methods abm4]
                 [--couplings loose,tight] [--workdir DIR] [--json PATH]
                 [--controllers BUILD/controllers] [--quiet-controller]

Models: `yamsc from-openfast` of tests/data/reference/operating/deck (all 16
ElastoDyn DOFs), once with its blade elements (the default: BEM, UA_Mod 3,
DBEMT_Mod 2 as the deck says) and once with `--aero table`. Each runs as the
model's header writes the command: the deck's DT 0.00625 s, ElastoDyn's ABM4
(--methods abm4,rk4 adds RK4), ROSCO with the deck's DISCON.IN (it logs, as
the header's run does; --quiet-controller: a copy that does not log), rows
every 0.025 s with OpenFAST's channel names written to a CSV file. When ROSCO
is not built, the NREL baseline controller. CPU time = user + system of the
whole `yamsc sim` process, the JIT cache warmed first, minimum of --runs.
OpenFAST's CPU time for 200 s of this deck on this class of machine is 66-78 s
(tests/data/reference/operating); ratios are against both ends, scaled to
--tmax. --couplings: the deck's loose coupling (`--coupling loose
--interp-order 2`, as its header writes it: the block once per step) and, for
comparison, tight (the block at every stage). The block's cost per step is
the difference of the two rotors' costs over the steps; per evaluation, that
over the block's evaluations per step: 1 loosely coupled, else the
integrator's (4 per step with RK4, 2 with ABM4: predictor and corrector),
though a tightly coupled step also evaluates the block for the controller's
measurement and twice in its discrete update (the rotor keeps the solutions
it can reuse: rotor_cache.hpp).
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
OPENFAST_CPU_200S = (66.0, 78.0)
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
    ap.add_argument("--winds", default="8,16")
    ap.add_argument("--methods", default="abm4")
    ap.add_argument("--couplings", default="loose,tight")
    ap.add_argument("--workdir")
    ap.add_argument("--json")
    ap.add_argument("--controllers", default=str(ROOT / "build/controllers"))
    ap.add_argument("--quiet-controller", action="store_true")
    a = ap.parse_args()
    if Path(a.yamsc).exists():
        a.yamsc = str(Path(a.yamsc).resolve())  # the runs' working directory is --workdir
    work = Path(a.workdir or tempfile.mkdtemp(prefix="bem_speed_"))
    work.mkdir(parents=True, exist_ok=True)
    rosco = Path(a.controllers) / "librosco_discon.so"
    baseline = Path(a.controllers) / "libnrel5mw_baseline_discon.so"
    discon = work / "DISCON.IN"
    text = (DECK / "DISCON.IN").read_text()
    if a.quiet_controller:
        text = re.sub(r"\n\s*\d+(\s+! LoggingLevel)", r"\n0\1", text)
    discon.write_text(text)
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
               "controller": ("ROSCO" if rosco.exists() else "baseline") +
                             (", not logging" if a.quiet_controller else ", logging as the deck says"),
               "cases": {}}
    steps = a.tmax / dt
    openfast = [c * a.tmax / 200 for c in OPENFAST_CPU_200S]
    for wind in a.winds.split(","):
        for method in a.methods.split(","):
            for coupling in a.couplings.split(","):
                # Block evaluations per step: once (loose), else each stage's.
                evaluations = 1 if coupling == "loose" else {"rk4": 4, "abm4": 2}[method]
                label = f"{method}_{coupling}"
                times = {}
                for rotor, mbd in models.items():
                    cmd = [a.yamsc, "sim", str(mbd), "--aero", aero[rotor], "--wind", wind,
                           "--tmax", str(a.tmax), "--dt", str(dt), "--method", method,
                           "--coupling", coupling, "--dt-out", "0.025", "--channels", "openfast",
                           "-o", str(work / f"{rotor}_{wind}_{label}.csv")] + controller
                    if coupling == "loose":
                        cmd += ["--interp-order", "2"]
                    cpu(cmd, work)  # the JIT cache
                    times[rotor] = min(cpu(cmd, work) for _ in range(a.runs))
                    ratios = [o / times[rotor] for o in openfast]
                    results["cases"][f"{rotor}_{label}_{wind}"] = {"cpu_s": times[rotor],
                                                                  "openfast_ratio": ratios}
                    print(f"{wind:>3} m/s {rotor:15s} {method:5s} {coupling:5s} "
                          f"{times[rotor]:7.2f} s CPU  "
                          f"OpenFAST/yamsc {ratios[0]:5.1f}-{ratios[1]:5.1f}")
                per_step = (times["blade_elements"] - times["table"]) / steps
                per_call = per_step / evaluations
                results["cases"][f"block_{label}_{wind}"] = {
                    "us_per_step": per_step * 1e6, "us_per_evaluation": per_call * 1e6,
                    "ns_per_node_per_evaluation": per_call * 1e9 / AERODYN_NODES}
                print(f"{wind:>3} m/s block cost ({method}, {coupling}): "
                      f"{per_step * 1e6:.0f} us per step, "
                      f"{per_call * 1e6:.0f} us per evaluation, "
                      f"{per_call * 1e9 / AERODYN_NODES:.0f} ns per AeroDyn node")
    print(f"load average {results['load_average']:.1f}")
    if a.json:
        Path(a.json).write_text(json.dumps(results, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
