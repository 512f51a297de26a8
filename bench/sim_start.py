#!/usr/bin/python3
"""Start-up cost of `yamsc sim` on the NREL 5-MW onshore model with all 16 DOFs.

    sim_start.py YAMSC_EXE [--workdir DIR] [--warm-runs 10] [--json PATH]

The model is written by `yamsc from-openfast` from the free-decay deck in
tests/data/reference/land_16dof_free_decay/. Each case runs with a model cache
of its own (YAMSC_CACHE_DIR), so "cold" includes the derivation, the code
generation and the C++ compiler:
  - cold `sim` (rk4), cold `sim --method cvode` (adds rhs_jacobian), cold `lin`;
  - warm `sim` start: the same command again, cache filled, median of
    --warm-runs runs (a 0.01 s simulation, so the start dominates);
  - for comparison, what compiling every routine costs: `yamsc m.mbd -o m.cpp`
    and `c++ -std=c++17 -O2 -shared -fPIC` of the whole file (what the JIT did
    before it compiled only what a command calls).
Wall times in one run on this machine; prints a markdown table and writes JSON.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DECK = ROOT / "tests/data/reference/land_16dof_free_decay/NREL5MW_Onshore_FreeDecay.fst"


def timed(cmd: list[str], env: dict | None = None, cwd: Path | None = None) -> float:
    start = time.perf_counter()
    subprocess.run(cmd, check=True, env=env, cwd=cwd, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("yamsc")
    ap.add_argument("--workdir", type=Path)
    ap.add_argument("--warm-runs", type=int, default=10)
    ap.add_argument("--json", type=Path)
    a = ap.parse_args()
    work = a.workdir or Path(tempfile.mkdtemp(prefix="yamsc-sim-start-"))
    work.mkdir(parents=True, exist_ok=True)
    model = work / "land16.mbd"
    subprocess.run([a.yamsc, "from-openfast", str(DECK), "-o", str(model)], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    sim = [a.yamsc, "sim", str(model), "--tmax", "0.01", "--dt", "0.005"]
    rows = []

    def cold(name: str, cmd: list[str]) -> tuple[float, dict]:
        cache = work / ("cache-" + name)
        shutil.rmtree(cache, ignore_errors=True)
        env = dict(os.environ, YAMSC_CACHE_DIR=str(cache))
        seconds = timed(cmd, env)
        rows.append((f"cold `{' '.join(['yamsc'] + cmd[1:2] + cmd[3:])}`", seconds))
        return seconds, env

    _, env = cold("sim", sim)
    warm = [timed(sim, env) for _ in range(a.warm_runs)]
    rows.append((f"warm `yamsc sim` start (median of {a.warm_runs})", statistics.median(warm)))
    cold("cvode", sim + ["--method", "cvode"])
    cold("lin", [a.yamsc, "lin", str(model)])

    everything = work / "land16_all.cpp"
    rows.append(("`yamsc m.mbd -o m.cpp` (every routine)",
                 timed([a.yamsc, str(model), "-o", str(everything)])))
    compiler = os.environ.get("CXX", "c++")
    rows.append((f"`{compiler} -O2 -shared` of it ({everything.stat().st_size / 1e6:.1f} MB)",
                 timed([compiler, "-std=c++17", "-O2", "-shared", "-fPIC", "-o",
                        str(work / "all.so"), str(everything)])))

    print("| case | wall [s] |\n|---|---|")
    for name, seconds in rows:
        print(f"| {name} | {seconds:.3f} |")
    out = a.json or work / "sim_start.json"
    out.write_text(json.dumps({"model": "NREL 5-MW onshore, 16 DOFs",
                               "rows": [{"case": n, "seconds": s} for n, s in rows],
                               "warm_runs": warm}, indent=1) + "\n")
    print(f"wrote {out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
