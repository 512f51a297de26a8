#!/usr/bin/python3
"""Simulation speed of `yamsc sim` against OpenFAST, at OpenFAST's time step.

    sim_speed.py YAMSC_EXE [--runs 5] [--workdir DIR] [--json PATH]
                 [--controllers BUILD/controllers] [--before OLD_YAMSC_EXE]

Cases (CPU time = user + system of the whole `yamsc sim` process, start-up
included, minimum of --runs runs; the JIT cache is warmed first):
  - the NREL 5-MW onshore model with all 16 ElastoDyn DOFs (`from-openfast` of
    tests/data/reference/land_16dof_free_decay/), 30 s of free decay at
    DT 0.005 (and 0.01), RK4 and ABM4, without output (summary only) and
    with the CSV every 0.01 s (the deck's DT_Out), every column or
    `--channels openfast`;
  - models/nrel5mw_land_operating.mbd in 16 m/s with the rotor table, 200 s at
    DT 0.00625 under the baseline controller and under ROSCO (when built; with
    tests/data/rosco/DISCON.IN as OpenFAST ran it, which logs every call, and
    with a copy that does not log), without a file and with the CSV every
    0.025 s (the deck's DT_Out).
Ratios use OpenFAST's CPU times quoted in the reference READMEs: 4.75 s
(16 DOFs, DT 0.005), 2.35 s (DT 0.01), 66 s (operating, the low end of
66-78 s). --before times another yamsc on the cases it supports, its runs
alternating with the others (so both see the same load). Also prints the ns per call of the compiled rhs, outputs
and outputs_from_qdd (bench/jit_call_cost.cpp on the cached library) and the load average.
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
DECK = ROOT / "tests/data/reference/land_16dof_free_decay/NREL5MW_Onshore_FreeDecay.fst"
OPERATING = ROOT / "models/nrel5mw_land_operating.mbd"
TABLE = ROOT / "models/data/Cp_Ct_Cq.NREL5MW.txt"
ROSCO_INPUT = ROOT / "tests/data/rosco/DISCON.IN"
OPENFAST_CPU = {"16dof-0.005": 4.75, "16dof-0.01": 2.35, "operating": 66.0}


def cpu_seconds(cmd: list[str], cwd: Path) -> float:
    """User + system CPU of one run of cmd (a child process)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, check=True, cwd=cwd, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def cached_library(cmd: list[str], cwd: Path) -> str | None:
    """The JIT library a sim command loads (its -v line)."""
    out = subprocess.run(cmd + ["-v"], cwd=cwd, capture_output=True, text=True, check=True)
    m = re.search(r"cached in (\S+\.so)", out.stderr)
    return m.group(1) if m else None


def call_cost(library: str, work: Path) -> dict:
    exe = work / "jit_call_cost"
    if not exe.exists():
        cxx = os.environ.get("CXX", "c++")
        subprocess.run([cxx, "-std=c++17", "-O2", "-o", str(exe),
                        str(ROOT / "bench/jit_call_cost.cpp"), "-ldl"], check=True)
    out = subprocess.run([str(exe), library], capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("yamsc")
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--workdir", type=Path)
    ap.add_argument("--json", type=Path)
    ap.add_argument("--before", help="another yamsc executable to time on the same cases")
    ap.add_argument("--controllers", type=Path,
                    help="folder of libnrel5mw_baseline_discon.so and librosco_discon.so "
                         "(default: next to the yamsc executable's build folder)")
    a = ap.parse_args()
    yamsc = str(Path(a.yamsc).resolve())
    work = a.workdir or Path(tempfile.mkdtemp(prefix="yamsc-sim-speed-"))
    work.mkdir(parents=True, exist_ok=True)
    # Absolute: the cases run in the work directory.
    controllers = (a.controllers or Path(yamsc).parent.parent / "controllers").resolve()
    model = work / "land16.mbd"
    subprocess.run([yamsc, "from-openfast", str(DECK), "-o", str(model)], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

    rows: list[dict] = []

    before = str(Path(a.before).resolve()) if a.before else None

    # A yamsc from before the `load` statement reads the operating model without
    # its load declarations (the rotor block then bound by its fixed names).
    legacy = work / "legacy_models"
    legacy.mkdir(exist_ok=True)
    (legacy / OPERATING.name).write_text(
        re.sub(r"(?ms)^load \w+ \w+ \{.*?^\}\n?", "", OPERATING.read_text()))
    if not (legacy / "data").exists():
        (legacy / "data").symlink_to(OPERATING.parent / "data")

    def case(group: str, label: str, openfast: str, cmd: list[str]) -> None:
        subprocess.run(cmd, check=True, cwd=work, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL)  # warm the JIT cache and the files
        old = ([before] + [str(legacy / OPERATING.name) if c == str(OPERATING) else c
                           for c in cmd[1:]]) if before else None
        if old and subprocess.run(old, cwd=work, stdout=subprocess.DEVNULL,
                                  stderr=subprocess.DEVNULL).returncode != 0:
            old = None  # an option the other build does not have
        runs, old_runs = [], []
        for _ in range(a.runs):
            runs.append(cpu_seconds(cmd, work))
            if old:
                old_runs.append(cpu_seconds(old, work))
        best = min(runs)
        row = {"group": group, "case": label, "cpu_s": best, "runs": runs,
               "openfast_cpu_s": OPENFAST_CPU[openfast], "speedup": OPENFAST_CPU[openfast] / best}
        if old_runs:
            row["before_cpu_s"] = min(old_runs)
        rows.append(row)
        print(f"{group}: {label}: {best * 1e3:.1f} ms CPU, "
              f"{OPENFAST_CPU[openfast] / best:.0f}x OpenFAST"
              + (f" (before: {min(old_runs) * 1e3:.1f} ms)" if old_runs else ""), file=sys.stderr)

    l16 = [yamsc, "sim", str(model)]
    for method in ("rk4", "abm4"):
        for dt, key in (("0.005", "16dof-0.005"), ("0.01", "16dof-0.01")):
            base = l16 + ["--tmax", "30", "--dt", dt, "--method", method]
            case("16 DOFs", f"{method}, dt {dt}, no file, rows (outputs) every step", key, base)
            case("16 DOFs", f"{method}, dt {dt}, no file, rows every 0.01 s", key,
                 base + ["--dt-out", "0.01"])
            case("16 DOFs", f"{method}, dt {dt}, CSV every step (all columns)", key,
                 base + ["-o", str(work / "l16_all.csv")])
            case("16 DOFs", f"{method}, dt {dt}, CSV every 0.01 s (all columns)", key,
                 base + ["--dt-out", "0.01", "-o", str(work / "l16.csv")])
            case("16 DOFs", f"{method}, dt {dt}, CSV every 0.01 s (--channels openfast)", key,
                 base + ["--dt-out", "0.01", "-o", str(work / "l16_of.csv"),
                         "--channels", "openfast"])
    start = min(cpu_seconds(l16 + ["--tmax", "0.005", "--dt", "0.005"], work)
                for _ in range(a.runs))

    op = [yamsc, "sim", str(OPERATING), "--aero", str(TABLE), "--wind", "16",
          "--dt", "0.00625"]
    # ROSCO as OpenFAST ran it (DISCON.IN: LoggingLevel 1, a line of its .dbg
    # file per call) and without its log (a copy with LoggingLevel 0).
    quiet = work / "rosco_nolog"
    quiet.mkdir(exist_ok=True)
    for f in ROSCO_INPUT.parent.iterdir():
        text = f.read_text()
        if f.name == "DISCON.IN":
            text = re.sub(r"(?m)^\s*1(\s+! LoggingLevel)", r"0\1", text)
        (quiet / f.name).write_text(text)
    rosco = str(controllers / "librosco_discon.so")
    ctrl = [("baseline", [str(controllers / "libnrel5mw_baseline_discon.so")]),
            ("ROSCO", [rosco, "--controller-input", str(ROSCO_INPUT)]),
            ("ROSCO without its log", [rosco, "--controller-input", str(quiet / "DISCON.IN")])]
    for name, spec in ctrl:
        if not Path(spec[0]).exists():
            print(f"skipped {name}: no {spec[0]}", file=sys.stderr)
            continue
        for method in ("rk4", "abm4"):
            base = op + ["--tmax", "200", "--controller"] + spec + ["--method", method]
            case("operating", f"{name}, {method}, no file, rows every step", "operating", base)
            case("operating", f"{name}, {method}, CSV every step", "operating",
                 base + ["-o", str(work / "op_all.csv")])
            case("operating", f"{name}, {method}, CSV every 0.025 s", "operating",
                 base + ["--dt-out", "0.025", "-o", str(work / "op.csv")])

    costs = {}
    lib16 = cached_library(l16 + ["--tmax", "0.005", "--dt", "0.005"], work)
    if lib16:
        costs["16 DOFs"] = call_cost(lib16, work)
    libop = cached_library(op + ["--tmax", "0.00625"], work)
    if libop:
        costs["operating"] = call_cost(libop, work)

    load = os.getloadavg()
    print(f"load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}; start-up of a 16-DOF sim "
          f"(one step) {start * 1e3:.1f} ms CPU")
    for name, c in costs.items():
        print(f"{name}: rhs {c['rhs_ns']:.0f} ns, outputs {c['outputs_ns']:.0f} ns, "
              f"outputs_from_qdd {c.get('outputs_from_qdd_ns', 0):.0f} ns per call")
    print("| case | CPU [ms] | before [ms] | OpenFAST CPU [s] | speed-up |\n|---|---|---|---|---|")
    for r in rows:
        old = f"{r['before_cpu_s'] * 1e3:.1f}" if "before_cpu_s" in r else "-"
        print(f"| {r['group']}: {r['case']} | {r['cpu_s'] * 1e3:.1f} | {old} | "
              f"{r['openfast_cpu_s']} | {r['speedup']:.0f}x |")
    out = a.json or work / "sim_speed.json"
    out.write_text(json.dumps({"load_average": load, "startup_cpu_s": start,
                               "call_cost": costs, "rows": rows}, indent=1) + "\n")
    print(f"wrote {out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
