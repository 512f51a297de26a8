#!/usr/bin/python3
"""Throughput of `yamsc batch` on the paper's 3-DOF models (docs/batch.md).

    batch.py YAMSC_EXE [--workdir DIR] [--cases 400] [--json PATH]

For the land and the floating 3-DOF model, all in one run on this machine:
  - per-case overhead: manifests of N cases and of 1 case that integrate a
    single RK4 step; (T(N) - T(1)) / (N - 1) is what a case costs besides
    its integration (binding the parameters, the view, writing its CSV and
    record, the bookkeeping), with the process start and model load removed;
  - a sweep of N cases of 20 s at dt = 0.01 (2000 RK4 steps, 2001 CSV rows)
    on 1 and 2 threads: wall time per case, the parallel efficiency
    T1 / (2 T2), the CPU time of 2 threads over 1 (1.0: the threads add no
    work) and cases per core-hour (from the CPU time of 1 thread);
  - for comparison, one `yamsc sim` process per case (warm cache).
The model is compiled (cached) before timing. Prints a markdown table and
writes JSON.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import subprocess
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
MODELS = {
    "land 3-DOF": ROOT / "models/nrel5mw_land_3dof.mbd",
    "floating 3-DOF": ROOT / "models/nrel5mw_floating_3dof.mbd",
}


def manifest(path: Path, model: Path, n: int, tmax: float, dt: float) -> None:
    lines = ["id,model,tmax,dt,ic"]
    for i in range(n):
        lines.append(f"c{i},{model},{tmax},{dt},\"{first_dof(model)}={0.001 * (i % 50)}\"")
    path.write_text("\n".join(lines) + "\n")


def first_dof(model: Path) -> str:
    for line in model.read_text().splitlines():
        if line.startswith("dof "):
            return line.split()[1]
    raise SystemExit(f"no dof in {model}")


def timed(cmd: list[str], env: dict, cwd: Path) -> float:
    return timed_cpu(cmd, env, cwd)[0]


def timed_cpu(cmd: list[str], env: dict, cwd: Path) -> tuple[float, float]:
    """Wall time and CPU time (user + system) of a command."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(cmd, check=True, env=env, cwd=cwd, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("yamsc")
    ap.add_argument("--workdir", type=Path)
    ap.add_argument("--cases", type=int, default=400)
    ap.add_argument("--json", type=Path)
    a = ap.parse_args()
    a.yamsc = str(Path(a.yamsc).resolve())
    work = a.workdir or Path(tempfile.mkdtemp(prefix="yamsc-batch-bench-"))
    work.mkdir(parents=True, exist_ok=True)
    env = dict(os.environ, YAMSC_CACHE_DIR=str(work / "cache"))
    n = a.cases
    results = {}
    for name, model in MODELS.items():
        key = name.split()[0]
        subprocess.run([a.yamsc, "sim", str(model), "--tmax", "0.01", "--dt", "0.01"], check=True,
                       env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

        def batch(cases: int, tmax: float, dt: float, threads: int) -> float:
            return batch_cpu(cases, tmax, dt, threads)[0]

        def batch_cpu(cases: int, tmax: float, dt: float, threads: int) -> tuple[float, float]:
            m = work / f"{key}-{cases}-{tmax}-{threads}.csv"
            manifest(m, model, cases, tmax, dt)
            out = work / (m.stem + ".out")
            shutil.rmtree(out, ignore_errors=True)
            return timed_cpu([a.yamsc, "batch", str(m), "-o", str(out), "--threads",
                              str(threads), "-q"], env, work)

        one = min(batch(1, 0.01, 0.01, 1) for _ in range(3))
        many = min(batch(n, 0.01, 0.01, 1) for _ in range(2))
        overhead = (many - one) / (n - 1)
        t1, cpu1 = min(batch_cpu(n, 20, 0.01, 1) for _ in range(2))
        t2, cpu2 = min(batch_cpu(n, 20, 0.01, 2) for _ in range(2))
        sims = 20
        t_sim = timed(["sh", "-c", " ".join(
            f"{a.yamsc} sim {model} --tmax 20 --dt 0.01 -o s.csv >/dev/null;" for _ in range(sims))],
            env, work) / sims
        results[name] = {
            "cases": n,
            "startup_s": one,
            "overhead_ms_per_case": 1e3 * overhead,
            "sweep_20s_1thread_s": t1,
            "sweep_20s_2threads_s": t2,
            "ms_per_case_1thread": 1e3 * t1 / n,
            "ms_per_case_2threads": 1e3 * t2 / n,
            "parallel_efficiency_2threads": t1 / (2 * t2),
            "cpu_s_1thread": cpu1,
            "cpu_s_2threads": cpu2,
            "load_average": os.getloadavg()[0],
            "sim_process_per_case_ms": 1e3 * t_sim,
            # CPU time, not wall: the machine may be shared while measuring.
            "cases_per_core_hour": 3600 * n / cpu1,
        }
    print("| model | overhead per case | 20 s case, 1 thread | 2 threads | efficiency (2) |"
          " CPU 2 threads / 1 | `yamsc sim` per case | cases per core-hour |")
    print("|---|---|---|---|---|---|---|---|")
    for name, r in results.items():
        print(f"| {name} | {r['overhead_ms_per_case']:.2f} ms | {r['ms_per_case_1thread']:.2f} ms |"
              f" {r['ms_per_case_2threads']:.2f} ms | {100 * r['parallel_efficiency_2threads']:.0f} % |"
              f" {r['cpu_s_2threads'] / r['cpu_s_1thread']:.2f} |"
              f" {r['sim_process_per_case_ms']:.1f} ms | {r['cases_per_core_hour']:.3g} |")
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    if a.json:
        a.json.write_text(json.dumps(results, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
