#!/usr/bin/python3
"""Compare yamsc's equations of motion with SymPy's on a seeded n-link 3D pendulum chain.

    check_against_sympy.py YAMSC_EXE WORKDIR [--n 3] [--states 5] [--tol 1e-10] [--seed 1]
                           [--timeout 120]
    check_against_sympy.py --self-test

The first form writes WORKDIR/chain<n>.mbd, evaluates `yamsc eval` at random states
(one of them with parameters overridden by --set) and compares M and F with SymPy's
KanesMethod, error relative to the largest entry of SymPy's M (resp. F).
--self-test checks the SymPy side alone: a one-link compound pendulum against its
closed form, and a two-link universal-joint chain against Lagrange's equations
written with plain rotation matrices (lagrange.py).

Exit status: 0 all agree, 1 a mismatch, 2 usage error, 3 yamsc failed or printed
something that is not the expected JSON.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import random
import subprocess
import sys
from dataclasses import dataclass, field
from typing import Dict, List, Optional

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import chain  # noqa: E402


class YamscFailure(Exception):
    pass


@dataclass
class State:
    q: List[float]
    qd: List[float]
    t: float
    params: Dict[str, float] = field(default_factory=dict)  # overrides of the defaults


def random_states(desc: chain.ChainDescription, count: int, seed: int) -> List[State]:
    """Angles within +-1 rad, rates within +-2 rad/s; the last state also overrides
    gravity, a mass, an inertia product, a length and a spring so --set is covered."""
    rng = random.Random(seed)
    nq = len(desc.dofs)
    states = [
        State([rng.uniform(-1, 1) for _ in range(nq)], [rng.uniform(-2, 2) for _ in range(nq)],
              rng.uniform(0, 5))
        for _ in range(count)
    ]
    if states:
        last = desc.links[-1]
        states[-1].params = {
            desc.gravity: 3.71,
            last.mass: desc.params[last.mass] * 1.5,
            last.inertia[3]: -desc.params[last.inertia[3]],
            desc.links[0].length: desc.params[desc.links[0].length] * 0.8,
            desc.springs[0].stiffness: 0.0,
        }
    return states


def relative_error(got: np.ndarray, reference: np.ndarray) -> float:
    scale = float(np.max(np.abs(reference)))
    return float(np.max(np.abs(got - reference))) / (scale if scale > 0 else 1.0)


def _numbers(values) -> str:
    return ",".join(repr(float(v)) for v in values)


def yamsc_eval(exe: str, model: str, desc: chain.ChainDescription, state: State,
               timeout: float):
    """Runs `yamsc eval` and returns (M, F)."""
    command = [exe, "eval", model, "--q", _numbers(state.q), "--qd", _numbers(state.qd),
               "--t", repr(state.t)]
    if state.params:
        command += ["--set", ",".join(f"{k}={v!r}" for k, v in state.params.items())]
    command.append("--json")
    try:
        run = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        raise YamscFailure(f"yamsc did not finish within {timeout:g} s (killed)\n"
                           f"command: {' '.join(command)}") from None
    except OSError as error:
        raise YamscFailure(f"could not run {' '.join(command)}: {error}") from None
    if run.returncode != 0:
        raise YamscFailure(f"yamsc exited with status {run.returncode}\n"
                           f"command: {' '.join(command)}\nstderr:\n{run.stderr.strip()}")
    try:
        result = json.loads(run.stdout)
        dofs, mass, forcing = result["dofs"], np.array(result["M"], float), np.array(
            result["F"], float)
    except (ValueError, KeyError, TypeError) as error:
        raise YamscFailure(f"yamsc eval printed no valid {{nq, dofs, M, F}} JSON ({error})\n"
                           f"command: {' '.join(command)}\nstdout:\n{run.stdout[:2000]}")
    # The spec fixes the state vector to the `dof` declaration order, which is also the
    # order of --q and --qd; anything else is a yamsc bug, not a numerical difference.
    if dofs != desc.dofs or result.get("nq") != len(desc.dofs):
        raise YamscFailure(f"yamsc reports DOFs {dofs} (nq={result.get('nq')}), "
                           f"the model declares {desc.dofs} in this order")
    if mass.shape != (len(dofs), len(dofs)) or forcing.shape != (len(dofs),):
        raise YamscFailure(f"yamsc eval: M is {mass.shape} and F is {forcing.shape} "
                           f"for {len(dofs)} DOFs")
    return mass, forcing


def print_table(title: str, rows: List[List[str]], header: List[str]) -> None:
    widths = [max(len(h), *(len(r[i]) for r in rows)) for i, h in enumerate(header)]
    print(title)
    print("| " + " | ".join(h.ljust(w) for h, w in zip(header, widths)) + " |")
    print("|" + "|".join("-" * (w + 2) for w in widths) + "|")
    for row in rows:
        print("| " + " | ".join(c.ljust(w) for c, w in zip(row, widths)) + " |")
    sys.stdout.flush()  # keep the table before any verdict written to stderr


def check_yamsc(exe: str, workdir: str, n: int, count: int, tol: float, seed: int,
                timeout: float) -> int:
    if not (os.path.isfile(exe) and os.access(exe, os.X_OK)):
        print(f"error: yamsc executable not found or not executable: {exe}", file=sys.stderr)
        return 3
    desc = chain.make_chain(n, seed)
    os.makedirs(workdir, exist_ok=True)
    model = os.path.join(workdir, f"{desc.name}.mbd")
    with open(model, "w") as f:
        f.write(chain.to_mbd(desc))
    reference = chain.to_sympy(desc)

    rows, worst = [], 0.0
    for i, state in enumerate(random_states(desc, count, seed + 1000)):
        try:
            mass, forcing = yamsc_eval(exe, model, desc, state, timeout)
        except YamscFailure as failure:
            print(f"error: {failure}", file=sys.stderr)
            return 3
        ref_mass = reference.mass_matrix(state.q, state.qd, state.params, state.t)
        ref_forcing = reference.forcing(state.q, state.qd, state.params, state.t)
        err_m, err_f = relative_error(mass, ref_mass), relative_error(forcing, ref_forcing)
        worst = max(worst, err_m, err_f)
        rows.append([str(i), f"{state.t:.3f}", ",".join(state.params) or "-", f"{err_m:.2e}",
                     f"{err_f:.2e}", "ok" if max(err_m, err_f) <= tol else "MISMATCH"])
    print_table(f"yamsc eval vs SymPy KanesMethod, {model} ({len(desc.dofs)} DOFs), tol {tol:g}",
                rows, ["state", "t", "--set", "max rel err M", "max rel err F", ""])
    if worst > tol:
        print(f"FAIL: largest relative error {worst:.3e} exceeds {tol:g}", file=sys.stderr)
        return 1
    print(f"OK: largest relative error {worst:.3e}")
    return 0


def compound_pendulum(desc: chain.ChainDescription, state: State):
    """Closed form of a one-link chain with `rotate x q` only (a compound pendulum about
    ground x): the COM and the force point are turned by Rx(q)."""
    p = dict(desc.params, **state.params)
    (q,), (qd,), t = state.q, state.qd, state.t
    c, s = math.cos(q), math.sin(q)
    m, cy, cz = p["m1"], p["cy1"], p["cz1"]
    mass = p["Ixx1"] + m * (cy * cy + cz * cz)
    gravity = -m * p["g"] * (c * cy - s * cz)  # -dV/dq with V = m g (s cy + c cz)
    spring = -p["K_qa1"] * q - p["D_qa1"] * qd
    torque = p["Tx"]  # the torque's frame is link1 itself, whose x is the joint axis
    # Force in ground axes at Rx(q) (px, py, pz): d/dq = (0, -s py - c pz, c py - s pz).
    fz = p["Fz"] * math.cos(p["Omega_f"] * t)
    force = p["Fy"] * (-s * p["py"] - c * p["pz"]) + fz * (c * p["py"] - s * p["pz"])
    return np.array([[mass]]), np.array([gravity + spring + torque + force])


def self_test(tol: float, seed: int) -> int:
    rows, failed = [], False

    def record(case: str, err_m: float, err_f: float, limit: float) -> None:
        nonlocal failed
        bad = max(err_m, err_f) > limit
        failed |= bad
        rows.append([case, f"{err_m:.2e}", f"{err_f:.2e}", "MISMATCH" if bad else "ok"])

    pendulum = chain.make_chain(1, seed, axes=("x",))
    sym = chain.to_sympy(pendulum)
    for i, state in enumerate(random_states(pendulum, 4, seed)):
        mass, forcing = compound_pendulum(pendulum, state)
        record(f"1 link, rotate x: closed form, state {i}",
               relative_error(sym.mass_matrix(state.q, state.qd, state.params, state.t), mass),
               relative_error(sym.forcing(state.q, state.qd, state.params, state.t), forcing),
               tol)

    import lagrange  # slow to derive; only the self-test needs it

    for n in (1, 2):
        desc = chain.make_chain(n, seed)
        sym = chain.to_sympy(desc)
        lag_mass, lag_forcing = lagrange.lagrange_equations(desc)
        for i, state in enumerate(random_states(desc, 3, seed + n)):
            values = [dict(desc.params, **state.params)[k] for k in desc.params]
            record(f"{n} link universal: Lagrange, state {i}",
                   relative_error(sym.mass_matrix(state.q, state.qd, state.params, state.t),
                                  np.array(lag_mass(state.q, state.qd, values, state.t))),
                   relative_error(sym.forcing(state.q, state.qd, state.params, state.t),
                                  np.array(lag_forcing(state.q, state.qd, values,
                                                       state.t)).reshape(-1)),
                   tol)

    desc = chain.make_chain(3, seed)
    sym = chain.to_sympy(desc)
    for i, state in enumerate(random_states(desc, 3, seed)):
        mass = sym.mass_matrix(state.q, state.qd, state.params, state.t)
        asymmetry = relative_error(mass, mass.T)
        smallest = float(np.min(np.linalg.eigvalsh((mass + mass.T) / 2)))
        ok = asymmetry <= tol and smallest > 0
        failed |= not ok
        rows.append([f"3 links: M symmetric, min eig {smallest:.3g}, state {i}",
                     f"{asymmetry:.2e}", "-", "ok" if ok else "MISMATCH"])

    print_table(f"SymPy self-test, tol {tol:g}", rows,
                ["case", "max rel err M", "max rel err F", ""])
    print("FAIL" if failed else "OK")
    return 1 if failed else 0


def main(argv: Optional[List[str]] = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("yamsc", nargs="?", help="path of the yamsc executable")
    parser.add_argument("workdir", nargs="?", help="directory for the generated model")
    parser.add_argument("--n", type=int, default=3, help="number of links (2 DOFs each)")
    parser.add_argument("--states", type=int, default=5, help="number of random states")
    parser.add_argument("--tol", type=float, default=1e-10, help="relative tolerance")
    parser.add_argument("--seed", type=int, default=1, help="seed of the chain and states")
    parser.add_argument("--timeout", type=float, default=120.0,
                        help="seconds before one yamsc run counts as hung")
    parser.add_argument("--self-test", action="store_true", help="check the SymPy side only")
    args = parser.parse_args(argv)
    if args.self_test:
        return self_test(args.tol, args.seed)
    if not args.yamsc or not args.workdir:
        parser.error("YAMSC_EXE and WORKDIR are required unless --self-test is given")
    if args.n < 1 or args.states < 1:
        parser.error("--n and --states must be at least 1")
    return check_yamsc(args.yamsc, args.workdir, args.n, args.states, args.tol, args.seed,
                       args.timeout)


if __name__ == "__main__":
    sys.exit(main())
