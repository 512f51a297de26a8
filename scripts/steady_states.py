#!/usr/bin/env python3
"""Steady operating points of the NREL 5-MW on land under the baseline
controller, for `yamsc lin --sweep V_wind=.. --schedule`: at each wind speed,
a `yamsc sim` in steady wind with the table aerodynamics and the controller in
the loop, averaged over its last 30 s. Writes the schedule CSV: V_wind [m/s],
psi' [rad/s] (rotor speed), gen_torque [N m], pitch [rad].

    scripts/steady_states.py build/compiler/yamsc \\
        build/controllers/libnrel5mw_baseline_discon.so models/data/nrel5mw_steady_states.csv
"""
import csv
import os
import subprocess
import sys
import tempfile

MODEL = "models/nrel5mw_land_operating.mbd"
TABLE = "models/data/Cp_Ct_Cq.NREL5MW.txt"
WINDS = [float(v) for v in range(4, 25)]
TMAX, AVERAGE = 150.0, 30.0


def steady_state(yamsc, controller, wind, work):
    out = os.path.join(work, f"steady_{wind:g}.csv")
    subprocess.run([yamsc, "sim", MODEL, "--aero", TABLE, "--wind", f"{wind:g}", "--controller",
                    controller, "--tmax", f"{TMAX:g}", "--dt", "0.02", "-o", out],
                   check=True, stdout=subprocess.DEVNULL)
    with open(out) as f:
        rows = list(csv.DictReader(f))
    tail = [r for r in rows if float(r["time"]) >= TMAX - AVERAGE]

    def mean(name):
        return sum(float(r[name]) for r in tail) / len(tail)

    return mean("psi'"), mean("GenTq") * 1e3, mean("BldPitch1") * 3.141592653589793 / 180


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    yamsc, controller, output = sys.argv[1:]
    with tempfile.TemporaryDirectory() as work:
        lines = ["# NREL 5-MW on land, steady operation under the baseline controller",
                 "# (scripts/steady_states.py: yamsc sim, table aerodynamics, last 30 s of 150 s)",
                 "V_wind,psi',gen_torque,pitch"]
        for wind in WINDS:
            speed, torque, pitch = steady_state(yamsc, controller, wind, work)
            lines.append(f"{wind:g},{speed:.8g},{torque:.8g},{pitch:.8g}")
            print(lines[-1], file=sys.stderr)
    tmp = output + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, output)


if __name__ == "__main__":
    main()
