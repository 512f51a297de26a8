#!/usr/bin/env python3
"""The NREL 5-MW in TurbSim's turbulence: yamsc against OpenFAST's run.

The deck of tests/data/reference/operating/deck with InflowWind's WindType 3 on
tests/data/reference/turbulence/U18_s1.bts (18 m/s, class B, 360 s) and OpenFAST's
initial state of that run (rotor 12.1 rpm, pitch 14.9 deg, blade tips 2 m out of
plane, tower top 0.15 m fore-aft), all 16 DOFs, is converted with `yamsc
from-openfast` and run with `yamsc sim` under ROSCO at OpenFAST's time step. The
means and standard deviations after the first 60 s are printed beside OpenFAST's
(the CSV OpenFAST wrote of the same deck and wind: give it with --openfast).

    python3 scripts/turbulent_run.py --rosco libdiscon.so --openfast openfast_turb_U18.csv
        [--yamsc build/compiler/yamsc] [--work out/turbulent_run] [--tmax 360] [--start 60]
"""
import argparse
import csv
import math
import os
import shutil
import subprocess

from wind_demo import edit

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DECK = os.path.join(ROOT, "tests", "data", "reference", "operating", "deck")
WIND = os.path.join(ROOT, "tests", "data", "reference", "turbulence", "U18_s1.bts")
PITCH = 14.9  # deg: OpenFAST's initial pitch
CHANNELS = ["RotSpeed_[rpm]", "BlPitch1_[deg]", "GenPwr_[kW]", "RotThrust_[kN]",
            "TwrBsMyt_[kN-m]", "RootMyc1_[kN-m]", "RootMxc1_[kN-m]", "LSShftMxa_[kN-m]"]


def statistics(path, start, end):
    """Per channel the mean and standard deviation of the rows from `start` to `end`."""
    with open(path) as f:
        rows = list(csv.reader(f))
    head = rows[0]
    time = head.index("Time_[s]") if "Time_[s]" in head else head.index("time")
    out = {}
    for name in CHANNELS:
        if name not in head:
            continue
        c = head.index(name)
        values = [float(r[c]) for r in rows[1:] 
                  if start - 1e-9 <= float(r[time]) <= end + 1e-9]
        if not values:
            raise SystemExit("%s: no rows from t = %g s on" % (path, start))
        mean = sum(values) / len(values)
        std = math.sqrt(sum((v - mean) ** 2 for v in values) / len(values))
        out[name] = (mean, std)
    return out


def prepare(yamsc, work):
    """The deck in `work/deck` and its model `work/turbine.mbd` (from-openfast)."""
    deck = os.path.join(work, "deck")
    shutil.rmtree(work, ignore_errors=True)
    shutil.copytree(DECK, deck)
    edit(os.path.join(deck, "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"),
         RotSpeed="12.1", OoPDefl="2", TTDspFA="0.15",
         **{"BlPitch(%d)" % k: str(PITCH) for k in (1, 2, 3)})
    edit(os.path.join(deck, "NRELOffshrBsline5MW_InflowWind.dat"),
         WindType="3", FileName_BTS='"%s"' % WIND)
    model = os.path.join(work, "turbine.mbd")
    subprocess.run([yamsc, "from-openfast", os.path.join(deck, "NREL-5MW.fst"), "-o", model],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return model, deck


def sim_command(yamsc, model, deck, rosco, tmax, out):
    """The run as the model's header writes it (ROSCO given by its library)."""
    return [yamsc, "sim", model,
            "--aero", os.path.join(deck, "NRELOffshrBsline5MW_Onshore_AeroDyn15.dat"),
            "--wind", os.path.join(deck, "NRELOffshrBsline5MW_InflowWind.dat"),
            "--controller", rosco, "--controller-input", os.path.join(deck, "DISCON.IN"),
            # The controller's pitch starts where OpenFAST's run starts (ElastoDyn's BlPitch).
            "--u", "pitch=%.10g" % (PITCH * math.pi / 180),
            "--tmax", str(tmax), "--dt", "0.00625", "--method", "abm4",
            # The deck's ModCoupling 1 and InterpOrder 2, as the model's header writes them.
            "--coupling", "loose", "--interp-order", "2",
            "--dt-out", "0.05", "--channels", "openfast", "-o", out]


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--yamsc", default=os.path.join(ROOT, "build", "compiler", "yamsc"))
    p.add_argument("--rosco", required=True, help="ROSCO's libdiscon.so")
    p.add_argument("--openfast", required=True, help="OpenFAST's CSV of the same run")
    p.add_argument("--work", default=os.path.join(ROOT, "out", "turbulent_run"))
    p.add_argument("--tmax", default="360")
    p.add_argument("--start", type=float, default=60.0,
                   help="the statistics from this time on [s] (the start-up transient left out)")
    a = p.parse_args()
    model, deck = prepare(a.yamsc, a.work)
    out = os.path.join(a.work, "yamsc_turb_U18.csv")
    cmd = sim_command(a.yamsc, model, deck, a.rosco, a.tmax, out)
    print("+", " ".join(cmd), flush=True)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    end = float(a.tmax)
    ours, theirs = statistics(out, a.start, end), statistics(a.openfast, a.start, end)
    print("%g to %g s: %-18s %12s %12s %8s %12s %12s %8s" %
          (a.start, end, "channel", "mean yamsc", "OpenFAST", "diff", "std yamsc", "OpenFAST", "diff"))
    for name in CHANNELS:
        if name not in ours or name not in theirs:
            print("  %-18s missing in %s" % (name, "yamsc" if name not in ours else "OpenFAST"))
            continue
        (m, s), (mo, so) = ours[name], theirs[name]
        rel = lambda x, y: "%7.2f%%" % (100 * (x - y) / abs(y)) if y else "   -"
        print("  %-18s %12.5g %12.5g %8s %12.5g %12.5g %8s" %
              (name, m, mo, rel(m, mo), s, so, rel(s, so)))


if __name__ == "__main__":
    main()
