#!/usr/bin/python3
"""Derivation time: yamsc against SymPy's KanesMethod on n-link 3D pendulum chains.

    derivation.py YAMSC_EXE [--n 5,10,20,40] [--sympy-timeout 300] [--yamsc-timeout 300]
                  [--compile-timeout 300] [--skip-compile] [--workdir DIR] [--json PATH]
                  [--seed 1] [--skip-sympy] [--reuse-sympy RESULTS.json]

For each n it writes the chain of tests/reference/chain.py (2 DOFs per link, full
inertia tensors, gravity, springs, a point force and a body-frame torque) as
DIR/chain<n>.mbd and times
  - `yamsc -v chain<n>.mbd -o chain<n>.cpp`: wall time of the whole compile (parse,
    Kane's method in GiNaC, Jacobians, code emission), median of 3 runs for n <= 10,
    killed after --yamsc-timeout seconds; the stage times come from its -v lines;
  - the size of the generated C++ and the time `c++ -std=c++17 -O2 -c` takes to
    compile it (CXX overrides the compiler), killed after --compile-timeout seconds;
  - SymPy: building the same system and `kanes_equations` + `mass_matrix` / `forcing`,
    no simplification (the PyDy default), one run in a subprocess that is killed
    after --sympy-timeout seconds. Importing SymPy is not counted.
Once a side times out for some n, it is not tried for larger n. With --reuse-sympy the
SymPy numbers are taken from an earlier results file instead of being measured again
(the JSON records where they came from).
It prints a markdown table and writes the same numbers as JSON (default
DIR/derivation.json). Note the two sides do not do the same work: yamsc also
emits code, SymPy stops at the expressions.
"""

from __future__ import annotations

import argparse
import json
import os
import datetime
import platform
import re
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import asdict, dataclass
from typing import List, Optional

REFERENCE_DIR = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                             "tests", "reference")
sys.path.insert(0, REFERENCE_DIR)
import chain  # noqa: E402

REPEAT_UP_TO_N = 10  # small models compile in milliseconds: take the median of 3 runs
REPEATS = 3


@dataclass
class Row:
    n: int
    dofs: int
    yamsc_s: Optional[float] = None
    yamsc_runs: int = 0
    yamsc_status: str = "not run"  # ok | failed: ... | timeout
    sympy_s: Optional[float] = None
    sympy_status: str = "not run"  # ok | timeout | skipped | failed: ...
    code_bytes: Optional[int] = None
    code_lines: Optional[int] = None
    derive_s: Optional[float] = None  # parse, check and Kane's method (yamsc -v)
    jacobians_s: Optional[float] = None  # the Jacobians alone
    codegen_s: Optional[float] = None  # code module and text (the rest of the wall time)
    compile_s: Optional[float] = None  # c++ -O2 -c of the generated file
    compile_status: str = "not run"  # ok | timeout | skipped | failed: ...
    sympy_source: str = "measured"  # or the results file the number was taken from
    sympy_cap_s: Optional[float] = None  # the time cap the SymPy number was measured with

    @property
    def ratio(self) -> Optional[float]:
        if self.yamsc_s and self.sympy_s is not None:
            return self.sympy_s / self.yamsc_s
        return None


STAGE_LINE = re.compile(r"^yamsc: (.*): ([0-9.]+) s$")


def stage_times(stderr: str) -> dict:
    """The cumulative clock readings of `yamsc -v` by stage name."""
    out = {}
    for line in stderr.splitlines():
        m = STAGE_LINE.match(line.strip())
        if m:
            out[m.group(1)] = float(m.group(2))
    return out


def yamsc_version(exe: str) -> str:
    """What `yamsc --version` prints (e.g. "yamsc 0.1.0"), or "unknown"."""
    try:
        run = subprocess.run([exe, "--version"], capture_output=True, text=True, timeout=60)
    except (OSError, subprocess.SubprocessError):
        return "unknown"
    return run.stdout.strip() if run.returncode == 0 and run.stdout.strip() else "unknown"


def time_yamsc(exe: str, model: str, output: str, runs: int, timeout: float, row: Row) -> None:
    seconds = []
    stages = []
    for _ in range(runs):
        start = time.perf_counter()
        try:
            run = subprocess.run([exe, "-v", model, "-o", output], capture_output=True, text=True,
                                 timeout=timeout)
        except subprocess.TimeoutExpired:
            row.yamsc_status = "timeout"
            return
        except OSError as error:
            row.yamsc_status = f"failed: {error}"
            return
        seconds.append(time.perf_counter() - start)
        stages.append(stage_times(run.stderr))
        if run.returncode != 0:
            last_line = (run.stderr.strip().splitlines() or ["(no message)"])[-1]
            row.yamsc_status = f"failed: exit {run.returncode}: {last_line}"
            return
    row.yamsc_s, row.yamsc_runs, row.yamsc_status = statistics.median(seconds), runs, "ok"
    median_run = stages[seconds.index(sorted(seconds)[len(seconds) // 2])]
    derived = median_run.get("derived the equations of motion")
    jacobians = median_run.get("derived the Jacobians",
                               median_run.get("derived the tangent (directional derivatives)"))
    if derived is not None and jacobians is not None:
        row.derive_s, row.jacobians_s = derived, jacobians - derived
        row.codegen_s = max(0.0, sorted(seconds)[len(seconds) // 2] - jacobians)
    with open(output, "rb") as f:
        code = f.read()
    row.code_bytes, row.code_lines = len(code), code.count(b"\n")


def time_compile(source: str, timeout: float, row: Row) -> None:
    """Compiles the generated file as a user would (-O2), object file only."""
    compiler = os.environ.get("CXX", "c++")
    command = [compiler, "-std=c++17", "-O2", "-c", source, "-o", source + ".o"]
    start = time.perf_counter()
    try:
        run = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        row.compile_status = "timeout"
        return
    except OSError as error:
        row.compile_status = f"failed: {error}"
        return
    if run.returncode != 0:
        last_line = (run.stderr.strip().splitlines() or ["(no message)"])[-1]
        row.compile_status = f"failed: {last_line}"
        return
    row.compile_s, row.compile_status = time.perf_counter() - start, "ok"
    os.remove(source + ".o")


def time_sympy(n: int, seed: int, timeout: float, row: Row) -> None:
    """Runs this script's --sympy-worker mode, which prints the derivation time."""
    command = [sys.executable, os.path.abspath(__file__), "--sympy-worker", str(n),
               "--seed", str(seed)]
    try:
        # On timeout subprocess.run kills the worker before raising.
        run = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        row.sympy_status = "timeout"
        return
    if run.returncode != 0:
        last_line = (run.stderr.strip().splitlines() or ["(no message)"])[-1]
        row.sympy_status = f"failed: {last_line}"
        return
    row.sympy_s, row.sympy_status = json.loads(run.stdout)["seconds"], "ok"


def sympy_worker(n: int, seed: int) -> int:
    import importlib

    importlib.import_module("sympy.physics.mechanics")  # imported before the clock starts

    desc = chain.make_chain(n, seed)
    start = time.perf_counter()
    chain.kane_equations(desc)
    print(json.dumps({"seconds": time.perf_counter() - start}))
    return 0


def _cell(value: Optional[float], status: str) -> str:
    if value is not None:
        return f"{value:.3g}" if value < 100 else f"{value:.0f}"
    return status


def _seconds(value: Optional[float], status: str) -> str:
    return f"{value:.3g} s" if value is not None else status


def markdown_table(rows: List[Row], sympy_timeout: float, yamsc_timeout: float,
                   compile_timeout: float) -> str:
    lines = [
        "| n | DOFs | yamsc [s] | derive / Jacobians / codegen [s] | SymPy [s] | SymPy / yamsc "
        "| code [MB] | code [lines] | c++ -O2 [s] |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        cap = r.sympy_cap_s or sympy_timeout
        sympy_cell = _cell(r.sympy_s, f"> {cap:g} (timeout)"
                           if r.sympy_status == "timeout" else r.sympy_status)
        yamsc_cell = _cell(r.yamsc_s, f"> {yamsc_timeout:g} (timeout)"
                           if r.yamsc_status == "timeout" else r.yamsc_status)
        if r.ratio is not None:
            ratio = f"{r.ratio:.3g}"
        elif r.sympy_status == "timeout" and r.yamsc_s:
            ratio = f"> {cap / r.yamsc_s:.3g}"
        else:
            ratio = "-"
        if r.sympy_source != "measured" and r.sympy_status in ("ok", "timeout"):
            sympy_cell += " *"
        stages = (f"{r.derive_s:.2f} / {r.jacobians_s:.2f} / {r.codegen_s:.2f}"
                  if r.derive_s is not None else "-")
        size = f"{r.code_bytes / 1e6:.2f}" if r.code_bytes else "-"
        compile_cell = _cell(r.compile_s, f"> {compile_timeout:g} (timeout)"
                             if r.compile_status == "timeout" else r.compile_status)
        lines.append(f"| {r.n} | {r.dofs} | {yamsc_cell} | {stages} | {sympy_cell} "
                     f"| {ratio} | {size} | {r.code_lines or '-'} | {compile_cell} |")
    return "\n".join(lines)


def main(argv: Optional[List[str]] = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("yamsc", nargs="?", help="path of the yamsc executable")
    parser.add_argument("--n", default="5,10,20,40", help="comma-separated link counts")
    parser.add_argument("--sympy-timeout", type=float, default=300.0,
                        help="seconds before a SymPy derivation is killed")
    parser.add_argument("--yamsc-timeout", type=float, default=300.0,
                        help="seconds before one yamsc compile is killed")
    parser.add_argument("--compile-timeout", type=float, default=300.0,
                        help="seconds before compiling one generated file is killed")
    parser.add_argument("--skip-compile", action="store_true",
                        help="do not compile the generated code")
    parser.add_argument("--reuse-sympy", metavar="RESULTS_JSON",
                        help="take the SymPy numbers from an earlier results file")
    parser.add_argument("--workdir", help="where models and generated code go (default: a "
                        "new temporary directory)")
    parser.add_argument("--json", help="results file (default: WORKDIR/derivation.json)")
    parser.add_argument("--seed", type=int, default=1, help="seed of the chain's numbers")
    parser.add_argument("--skip-sympy", action="store_true", help="time yamsc only")
    parser.add_argument("--sympy-worker", type=int, metavar="N", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.sympy_worker is not None:
        return sympy_worker(args.sympy_worker, args.seed)
    if not args.yamsc:
        parser.error("YAMSC_EXE is required")
    try:
        counts = [int(v) for v in args.n.split(",")]
    except ValueError:
        parser.error(f"--n expects comma-separated integers, got '{args.n}'")
    if any(n < 1 for n in counts):
        parser.error("--n values must be at least 1")
    if not (os.path.isfile(args.yamsc) and os.access(args.yamsc, os.X_OK)):
        print(f"error: yamsc executable not found or not executable: {args.yamsc}",
              file=sys.stderr)
        return 3
    workdir = args.workdir or tempfile.mkdtemp(prefix="yamsc-bench-")
    os.makedirs(workdir, exist_ok=True)

    reused = {}
    if args.reuse_sympy:
        with open(args.reuse_sympy) as f:
            earlier = json.load(f)
        for r in earlier.get("rows", []):
            if r.get("sympy_status") in ("ok", "timeout"):
                reused[r["n"]] = (r.get("sympy_s"), r["sympy_status"])
        earlier_cap = earlier.get("sympy_timeout_s")

    rows: List[Row] = []
    sympy_timed_out = yamsc_timed_out = False
    for n in counts:
        desc = chain.make_chain(n, args.seed)
        row = Row(n=n, dofs=len(desc.dofs))
        model = os.path.join(workdir, f"{desc.name}.mbd")
        with open(model, "w") as f:
            f.write(chain.to_mbd(desc))
        runs = REPEATS if n <= REPEAT_UP_TO_N else 1
        if yamsc_timed_out:
            row.yamsc_status = "timeout"  # a smaller chain already did
        else:
            time_yamsc(args.yamsc, model, os.path.join(workdir, f"{desc.name}.cpp"), runs,
                       args.yamsc_timeout, row)
            yamsc_timed_out = row.yamsc_status == "timeout"
        if row.yamsc_status == "ok" and not args.skip_compile:
            time_compile(os.path.join(workdir, f"{desc.name}.cpp"), args.compile_timeout, row)
        elif args.skip_compile:
            row.compile_status = "skipped"
        if n in reused:
            row.sympy_s, row.sympy_status = reused[n]
            row.sympy_source = args.reuse_sympy
            row.sympy_cap_s = earlier_cap
            sympy_timed_out = sympy_timed_out or row.sympy_status == "timeout"
        elif args.skip_sympy:
            row.sympy_status = "skipped"
        elif sympy_timed_out:
            row.sympy_status = "timeout"  # a smaller chain already did
            row.sympy_cap_s = rows[-1].sympy_cap_s if rows else args.sympy_timeout
        else:
            row.sympy_cap_s = args.sympy_timeout
            time_sympy(n, args.seed, args.sympy_timeout, row)
            sympy_timed_out = row.sympy_status == "timeout"
        rows.append(row)
        print(f"n={n}: yamsc {_seconds(row.yamsc_s, row.yamsc_status)}, "
              f"SymPy {_seconds(row.sympy_s, row.sympy_status)}", file=sys.stderr, flush=True)

    table = markdown_table(rows, args.sympy_timeout, args.yamsc_timeout, args.compile_timeout)
    if any(r.sympy_source != "measured" for r in rows):
        table += "\n\n\\* SymPy number taken from an earlier run (--reuse-sympy)."
    print(table)
    import sympy

    results = {
        "benchmark": "derivation time, n-link 3D pendulum chain (tests/reference/chain.py)",
        # The version, not the executable's path: a path names one machine's folders.
        "yamsc": yamsc_version(args.yamsc),
        "sympy_version": sympy.__version__,
        "python": platform.python_version(),
        "machine": platform.machine(),
        "processor": platform.processor() or platform.machine(),
        "cpus": os.cpu_count(),
        "date": datetime.date.today().isoformat(),
        "compiler": os.environ.get("CXX", "c++"),
        "seed": args.seed,
        "sympy_timeout_s": args.sympy_timeout,
        "yamsc_timeout_s": args.yamsc_timeout,
        "compile_timeout_s": args.compile_timeout,
        "rows": [dict(asdict(r), ratio=r.ratio) for r in rows],
        "markdown": table,
    }
    json_path = args.json or os.path.join(workdir, "derivation.json")
    with open(json_path, "w") as f:
        json.dump(results, f, indent=2)
        f.write("\n")
    print(f"\nresults: {json_path}", file=sys.stderr)
    # Non-zero when yamsc failed or timed out for some n, so a pipeline notices.
    failed = any(r.yamsc_status != "ok" for r in rows)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
