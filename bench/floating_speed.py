#!/usr/bin/python3
"""Cost of the OC3-Hywind spar in irregular waves against OpenFAST's regression run.

    floating_speed.py YAMSC_EXE [--runs 3] [--tmax 60,600] [--before OLD_YAMSC_EXE]
                      [--workdir DIR] [--json PATH]

The run: models/oc3_spar_hydrodyn.mbd (6 platform DOFs, tower and rotor-nacelle
rigid, rotor parked) with HydroDyn's strip theory (tests/data/hydro/oc3_spar_strip.dat),
SeaState's JONSWAP sea (tests/data/hydro/oc3_sea_state.dat: Hs 6 m, Tp 10 s, seed
123456789, one wave elevation point) and MAP++'s three lines
(tests/data/mooring/oc3_hywind.map), at OpenFAST's DT 0.0125 s with RK4 and ABM4,
the summary only (no file).

CPU time = user + system of the whole `yamsc sim` process, minimum of --runs, the
JIT cache warmed first. "Simulation alone" subtracts the same command run for one
step (start-up: the cached library, the files, the wave field and its tabulated
points). Per-part costs (the first --tmax, the simulation alone): the structure
alone (no files: the blocks are absent and the platform falls freely, the same
generated code), + strip theory in still water, + the JONSWAP sea (and its
elevation output), + the mooring lines (the full run).

OpenFAST: its own log of the OC3-Hywind regression case 5MW_OC3Spar_DLL_WTurb_WavesIrr
(OpenFAST v3.2, GCC 10.3, 2022): "Simulation CPU Time: 1.8323 minutes" for 60 s at
DT 0.0125 (109.9 s), with 22 ElastoDyn DOFs, AeroDyn in turbulent wind, ServoDyn's
DLL, HydroDyn (WAMIT potential flow + strip-theory drag) and MAP++; scaled by
tmax / 60 for longer runs. docs/benchmarks.md says what differs.

--before times another yamsc on the same cases, its runs alternating with these.
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
MODEL = ROOT / "models/oc3_spar_hydrodyn.mbd"
HYDRO = ROOT / "tests/data/hydro/oc3_spar_strip.dat"
SEA = ROOT / "tests/data/hydro/oc3_sea_state.dat"
MOORING = ROOT / "tests/data/mooring/oc3_hywind.map"
DT = 0.0125
OPENFAST_CPU_60S = 1.8323 * 60.0  # s, OpenFAST's log of the regression run

PARTS = {
    "structure": [],
    "strip theory, still water": ["--hydro", str(HYDRO)],
    "strip theory, JONSWAP": ["--hydro", str(HYDRO), "--sea-state", str(SEA)],
    "strip theory, JONSWAP, mooring": ["--hydro", str(HYDRO), "--sea-state", str(SEA),
                                       "--mooring", str(MOORING)],
}
FULL = "strip theory, JONSWAP, mooring"


def cpu(cmd: list[str]) -> float:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def command(yamsc: str, tmax: float, method: str, files: list[str]) -> list[str]:
    return [yamsc, "sim", str(MODEL), "--tmax", f"{tmax:g}", "--dt", f"{DT:g}",
            "--method", method] + files


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("yamsc")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--tmax", default="60,600")
    ap.add_argument("--before", help="another yamsc executable to time on the same cases")
    ap.add_argument("--workdir")
    ap.add_argument("--json")
    a = ap.parse_args()
    builds = {"now": str(Path(a.yamsc).resolve())}
    if a.before:
        builds["before"] = str(Path(a.before).resolve())
    json_path = Path(a.json).resolve() if a.json else None
    os.chdir(a.workdir or tempfile.mkdtemp(prefix="floating_speed_"))
    tmaxes = [float(v) for v in a.tmax.split(",")]

    cases = []  # (name, tmax, method, files)
    for tmax in tmaxes:
        for method in ("rk4", "abm4"):
            cases.append((FULL, tmax, method, PARTS[FULL]))
    for name, files in PARTS.items():
        if name != FULL:
            for method in ("rk4", "abm4"):
                cases.append((name, tmaxes[0], method, files))

    results = []
    for name, tmax, method, files in cases:
        row = {"case": name, "tmax": tmax, "method": method}
        for build, exe in builds.items():
            cpu(command(exe, DT, method, files))  # the JIT cache
        best = {b: [float("inf"), float("inf")] for b in builds}
        for _ in range(a.runs):
            for build, exe in builds.items():  # alternating: both see the same load
                best[build][0] = min(best[build][0], cpu(command(exe, tmax, method, files)))
                best[build][1] = min(best[build][1], cpu(command(exe, DT, method, files)))
        for build in builds:
            total, start = best[build]
            row[build] = {"cpu_s": total, "start_s": start, "sim_s": total - start}
        if name == FULL:
            openfast = OPENFAST_CPU_60S * tmax / 60.0
            row["openfast_cpu_s"] = openfast
            row["openfast_ratio"] = openfast / row["now"]["sim_s"]
            row["openfast_ratio_whole"] = openfast / row["now"]["cpu_s"]
        results.append(row)
        line = (f"{name:32s} {tmax:5g} s {method:4s}: now {row['now']['cpu_s']:.3f} s CPU "
                f"(start {row['now']['start_s']:.3f}, sim {row['now']['sim_s']:.3f})")
        if "before" in row:
            line += f", before sim {row['before']['sim_s']:.3f} s"
        if "openfast_ratio" in row:
            line += (f", OpenFAST {row['openfast_cpu_s']:.1f} s: {row['openfast_ratio']:.0f}x "
                     f"({row['openfast_ratio_whole']:.0f}x whole process)")
        print(line, flush=True)
    out = {"load_average": os.getloadavg()[0], "dt": DT, "cases": results}
    print(f"load average {out['load_average']:.1f}")
    if json_path:
        json_path.write_text(json.dumps(out, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
