#!/usr/bin/python3
"""Derivation time of the Whipple bicycle: yamsc against SymPy's KanesMethod.

    sympy_bicycle.py YAMSC_EXE [--model models/whipple_bicycle.mbd] [--sympy-timeout 900]
                     [--workdir DIR] [--json PATH] [--skip-sympy]

Both sides derive the same bicycle (the benchmark of Meijaard et al. 2007, the
coordinates of models/whipple_bicycle.mbd: rear contact point, yaw, lean, pitch, rear
wheel angle, steer, front wheel angle; the front contact's height a configuration
constraint with pitch dependent; four no-slip rows with five dependent speeds):
  - yamsc: `yamsc -v MODEL -o bike.cpp` (parse, check, Kane's method, the constraint
    rows and their derivatives, code), then `c++ -std=c++17 -O2 -c bike.cpp`; the
    wall time of each, median of 3 runs;
  - SymPy: building the system with sympy.physics.mechanics and
    KanesMethod.kanes_equations with the dependent coordinate and speeds eliminated
    (as SymPy does it: the dependent speeds solved symbolically from the constraint
    rows), no simplification; one run in a subprocess killed after --sympy-timeout
    seconds. Importing SymPy is not counted.
It prints a table and writes the numbers as JSON (default DIR/sympy_bicycle.json).
The two sides do not do the same work: yamsc also writes and compiles code; SymPy
stops at M and F of the independent speeds.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def sympy_derivation() -> dict:
    """Runs in a child process: builds the bicycle and times kanes_equations."""
    import sympy as sm
    import sympy.physics.mechanics as me

    t0 = time.perf_counter()
    w, c, lam, g = sm.symbols("w c lam g")
    rR, mR, IRxx, IRyy = sm.symbols("rR mR IRxx IRyy")
    xB, zB, mB, IBxx, IByy, IBzz, IBxz = sm.symbols("xB zB mB IBxx IByy IBzz IBxz")
    xH, zH, mH, IHxx, IHyy, IHzz, IHxz = sm.symbols("xH zH mH IHxx IHyy IHzz IHxz")
    rF, mF, IFxx, IFyy = sm.symbols("rF mF IFxx IFyy")
    q = me.dynamicsymbols("xP yP yaw lean pitch thR delta thF")
    u = me.dynamicsymbols("u1:9")
    xP, yP, yaw, lean, pitch, thR, delta, thF = q

    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (yaw, N.z))
    L = A.orientnew("L", "Axis", (lean, A.x))
    B = L.orientnew("B", "Axis", (pitch, L.y))
    R = B.orientnew("R", "Axis", (thR, B.y))
    H = B.orientnew("H", "Axis", (delta, sm.sin(lam) * B.x - sm.cos(lam) * B.z))
    F = H.orientnew("F", "Axis", (thF, H.y))

    O = me.Point("O")
    O.set_vel(N, 0)
    P = O.locatenew("P", xP * N.x + yP * N.y)  # rear contact
    Ro = P.locatenew("Ro", rR * L.z)  # rear wheel centre
    Bo = Ro.locatenew("Bo", xB * B.x + (-zB - rR) * B.z)
    S = Ro.locatenew("S", (w + c) * B.x - rR * B.z)  # steer axis on the ground
    Ho = S.locatenew("Ho", (xH - w - c) * H.x - zH * H.z)
    Fo = S.locatenew("Fo", -c * H.x + rF * H.z)
    # The front contact: the wheel plane's lowest point.
    down = -N.z + N.z.dot(H.y) * H.y
    d = down / sm.sqrt(down.dot(down))
    Fc = Fo.locatenew("Fc", rF * d)

    kd = [qi.diff() - ui for qi, ui in zip(q, u)]
    kd_map = sm.solve(kd, [qi.diff() for qi in q])
    for frame in (A, L, B, R, H, F):
        frame.set_ang_vel(N, frame.ang_vel_in(N).subs(kd_map))
    for point in (P, Ro, Bo, S, Ho, Fo):
        point.set_vel(N, point.pos_from(O).dt(N).subs(kd_map))

    holonomic = [Fc.pos_from(O).dot(N.z)]
    v_rear = Ro.vel(N) + R.ang_vel_in(N).cross(-rR * L.z)
    v_front = Fo.vel(N) + F.ang_vel_in(N).cross(rF * d)
    nonholonomic = [v_rear.dot(N.x), v_rear.dot(N.y), v_front.dot(N.x), v_front.dot(N.y)]
    holonomic_rate = [holonomic[0].diff(me.dynamicsymbols._t).subs(kd_map)]

    bodies = [
        me.RigidBody("rear_wheel", Ro, R, mR, (me.inertia(R, IRxx, IRyy, IRxx), Ro)),
        me.RigidBody("rear_frame", Bo, B, mB, (me.inertia(B, IBxx, IByy, IBzz, 0, 0, -IBxz), Bo)),
        me.RigidBody("front_frame", Ho, H, mH, (me.inertia(H, IHxx, IHyy, IHzz, 0, 0, -IHxz), Ho)),
        me.RigidBody("front_wheel", Fo, F, mF, (me.inertia(F, IFxx, IFyy, IFxx), Fo)),
    ]
    loads = [(b.masscenter, -b.mass * g * N.z) for b in bodies]

    q_ind = [xP, yP, yaw, lean, thR, delta, thF]
    u_ind = [u[3], u[5], u[6]]  # lean, rear wheel and steer rates
    u_dep = [u[0], u[1], u[2], u[4], u[7]]
    kane = me.KanesMethod(N, q_ind=q_ind, u_ind=u_ind, kd_eqs=kd, q_dependent=[pitch],
                          configuration_constraints=holonomic, u_dependent=u_dep,
                          velocity_constraints=holonomic_rate + nonholonomic)
    t_setup = time.perf_counter() - t0
    t1 = time.perf_counter()
    kane.kanes_equations(bodies, loads)
    t_kane = time.perf_counter() - t1
    t2 = time.perf_counter()
    M = kane.mass_matrix
    f = kane.forcing
    t_mf = time.perf_counter() - t2
    return {"setup_s": t_setup, "kanes_equations_s": t_kane, "mass_forcing_s": t_mf,
            "total_s": t_setup + t_kane + t_mf, "M_shape": list(M.shape),
            "forcing_ops": int(sm.count_ops(f)) if t_kane < 120 else None,
            "sympy": sm.__version__}


def run(cmd, cwd=None, timeout=None) -> float:
    t = time.perf_counter()
    subprocess.run(cmd, cwd=cwd, check=True, timeout=timeout, stdout=subprocess.DEVNULL,
                   stderr=subprocess.PIPE)
    return time.perf_counter() - t


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("yamsc")
    ap.add_argument("--model", default=os.path.join(ROOT, "models", "whipple_bicycle.mbd"))
    ap.add_argument("--sympy-timeout", type=float, default=900)
    ap.add_argument("--workdir")
    ap.add_argument("--json")
    ap.add_argument("--skip-sympy", action="store_true")
    ap.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    a = ap.parse_args()
    if a.child:
        print(json.dumps(sympy_derivation()))
        return 0
    work = a.workdir or tempfile.mkdtemp(prefix="sympy_bicycle_")
    os.makedirs(work, exist_ok=True)
    cxx = os.environ.get("CXX", "c++")
    derive, compile_ = [], []
    for _ in range(3):
        derive.append(run([a.yamsc, a.model, "-o", os.path.join(work, "bike.cpp")]))
        compile_.append(run([cxx, "-std=c++17", "-O2", "-c", "bike.cpp", "-o", "bike.o"], cwd=work))
    out = {"machine": platform.node(), "python": platform.python_version(),
           "yamsc_derive_s": statistics.median(derive), "yamsc_compile_s": statistics.median(compile_),
           "generated_bytes": os.path.getsize(os.path.join(work, "bike.cpp"))}
    out["yamsc_total_s"] = out["yamsc_derive_s"] + out["yamsc_compile_s"]
    if not a.skip_sympy:
        try:
            p = subprocess.run([sys.executable, os.path.abspath(__file__), a.yamsc, "--child"],
                               check=True, timeout=a.sympy_timeout, capture_output=True, text=True)
            out["sympy"] = json.loads(p.stdout.strip().splitlines()[-1])
            out["sympy_status"] = "ok"
        except subprocess.TimeoutExpired:
            out["sympy_status"] = f"timeout after {a.sympy_timeout:g} s"
        except subprocess.CalledProcessError as e:
            out["sympy_status"] = "failed: " + e.stderr.strip().splitlines()[-1]
    print("| step | wall [s] |\n|---|---|")
    print(f"| yamsc derive + write C++ | {out['yamsc_derive_s']:.2f} |")
    print(f"| c++ -O2 -c of the generated code | {out['yamsc_compile_s']:.2f} |")
    print(f"| yamsc total | {out['yamsc_total_s']:.2f} |")
    if "sympy" in out:
        s = out["sympy"]
        print(f"| SymPy {s['sympy']}: set-up | {s['setup_s']:.2f} |")
        print(f"| SymPy: kanes_equations | {s['kanes_equations_s']:.2f} |")
        print(f"| SymPy total | {s['total_s']:.2f} |")
    elif "sympy_status" in out:
        print(f"| SymPy | {out['sympy_status']} |")
    path = a.json or os.path.join(work, "sympy_bicycle.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
