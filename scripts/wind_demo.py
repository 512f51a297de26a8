#!/usr/bin/env python3
"""Blade 1's root moments over a revolution in sheared, yawed wind.

The NREL 5-MW deck (tests/data/reference/operating/deck) with every ElastoDyn DOF
off (the rotor turning at 8.9886 rpm, pitch 0; AeroDyn as the deck has it: BEM
with dynamic inflow and unsteady airfoils) is converted with `yamsc from-openfast`
and run twice with `yamsc sim --wind InflowWind.dat`: in the deck's steady 8 m/s
without shear, and with a power-law shear (PLexp 0.2) and the wind propagating at
20 deg (PropagationDir). The last revolution's RootMxb1 and RootMyb1 are plotted
against the azimuth into an SVG (standard library only).

    python3 scripts/wind_demo.py [--yamsc build/compiler/yamsc] [--work out/wind_demo]
                                 [-o docs/figures/root_moments_sheared_yawed.svg]
"""
import argparse
import csv
import math
import os
import re
import shutil
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DECK = os.path.join(ROOT, "tests", "data", "reference", "operating", "deck")
DOFS = ["FlapDOF1", "FlapDOF2", "EdgeDOF", "TeetDOF", "DrTrDOF", "GenDOF", "YawDOF",
        "TwFADOF1", "TwFADOF2", "TwSSDOF1", "TwSSDOF2"]
RPM = 8.9885664


def set_entry(text, key, value):
    """The value of `key` in an OpenFAST input file replaced."""
    edited, found = re.subn(r"\n\s*\S+(\s+)" + re.escape(key) + r"(?=\s)",
                            lambda m: "\n  " + value + m.group(1) + key, text, count=1)
    if not found:
        raise SystemExit("no entry %s to set" % key)
    return edited


def edit(path, **entries):
    with open(path) as f:
        text = f.read()
    for key, value in entries.items():
        text = set_entry(text, key, value)
    with open(path, "w") as f:
        f.write(text)


def run(cmd):
    print("+", " ".join(cmd), flush=True)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def last_revolution(path):
    """Azimuth [deg], RootMxb1 and RootMyb1 [kN m] over the run's last full turn."""
    with open(path) as f:
        rows = list(csv.reader(f))
    head = rows[0]
    col = {name: head.index(name) for name in ("Azimuth_[deg]", "RootMxb1_[kN-m]",
                                                "RootMyb1_[kN-m]")}
    data = [[float(r[col[n]]) for n in col] for r in rows[1:]]
    wraps = [i for i in range(1, len(data)) if data[i][0] < data[i - 1][0]]
    start, end = wraps[-2], wraps[-1]
    return [list(c) for c in zip(*data[start:end])]


def ticks(lo, hi, target=5):
    step = 10 ** math.floor(math.log10((hi - lo) / target))
    for m in (1, 2, 5, 10):
        if (hi - lo) / (m * step) <= target:
            step *= m
            break
    first = math.ceil(lo / step) * step
    return [first + i * step for i in range(int((hi - first) / step + 1e-9) + 1)]


def svg(panels, title, path):
    """Stacked panels sharing the azimuth axis; each: (label, [(name, x, y, colour, dash)])."""
    width, height, left, right, top = 760, 250, 80, 190, 40
    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" '
           'font-family="sans-serif" font-size="12">' % (width, top + height * len(panels) + 30),
           '<rect width="100%" height="100%" fill="white"/>',
           '<text x="%d" y="22" font-size="14">%s</text>' % (left, title)]
    for k, (label, curves) in enumerate(panels):
        y0 = top + k * height
        ys = [v for c in curves for v in c[2]]
        lo, hi = min(ys), max(ys)
        pad = 0.05 * (hi - lo)
        lo, hi = lo - pad, hi + pad
        w, h = width - left - right, height - 50
        px = lambda x: left + w * x / 360.0
        py = lambda y: y0 + h - h * (y - lo) / (hi - lo)
        out.append('<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="black"/>'
                   % (left, y0, w, h))
        for t in ticks(lo, hi):
            out.append('<line x1="%d" x2="%d" y1="%.1f" y2="%.1f" stroke="#ddd"/>'
                       % (left, left + w, py(t), py(t)))
            out.append('<text x="%d" y="%.1f" text-anchor="end">%g</text>'
                       % (left - 6, py(t) + 4, t))
        for t in range(0, 361, 60):
            out.append('<text x="%.1f" y="%d" text-anchor="middle">%d</text>'
                       % (px(t), y0 + h + 16, t))
        out.append('<text x="16" y="%d" transform="rotate(-90 16 %d)" text-anchor="middle">%s'
                   '</text>' % (y0 + h / 2, y0 + h / 2, label))
        for j, (name, x, y, colour, dash) in enumerate(curves):
            points = " ".join("%.1f,%.1f" % (px(a), py(b)) for a, b in zip(x, y))
            out.append('<polyline points="%s" fill="none" stroke="%s" stroke-width="1.6"%s/>'
                       % (points, colour, ' stroke-dasharray="6,4"' if dash else ""))
            ly = y0 + 16 + 18 * j
            out.append('<line x1="%d" x2="%d" y1="%d" y2="%d" stroke="%s" stroke-width="1.6"%s/>'
                       % (left + w + 12, left + w + 36, ly, ly, colour,
                          ' stroke-dasharray="6,4"' if dash else ""))
            out.append('<text x="%d" y="%d">%s</text>' % (left + w + 42, ly + 4, name))
    out.append('<text x="%d" y="%d" text-anchor="middle">Azimuth of blade 1 [deg] '
               '(0: up)</text>' % (left + (width - left - right) / 2,
                                   top + height * len(panels) + 10))
    out.append("</svg>\n")
    with open(path, "w") as f:
        f.write("\n".join(out))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--yamsc", default=os.path.join(ROOT, "build", "compiler", "yamsc"))
    p.add_argument("--work", default=os.path.join(ROOT, "out", "wind_demo"))
    p.add_argument("-o", "--output",
                   default=os.path.join(ROOT, "docs", "figures", "root_moments_sheared_yawed.svg"))
    p.add_argument("--tmax", default="30")
    a = p.parse_args()
    deck = os.path.join(a.work, "deck")
    shutil.rmtree(a.work, ignore_errors=True)
    shutil.copytree(DECK, deck)
    edit(os.path.join(deck, "NRELOffshrBsline5MW_Onshore_ElastoDyn.dat"),
         RotSpeed=str(RPM), **{d: "False" for d in DOFS})
    model = os.path.join(a.work, "rigid.mbd")
    run([a.yamsc, "from-openfast", os.path.join(deck, "NREL-5MW.fst"), "-o", model])
    inflow = os.path.join(deck, "NRELOffshrBsline5MW_InflowWind.dat")
    cases = [("uniform 8 m/s", "0", "0", "#1f77b4", True),
             ("PLexp 0.2, 20 deg", "0.2", "20", "#d62728", False)]
    curves = {"RootMxb1": [], "RootMyb1": []}
    for i, (name, plexp, direction, colour, dash) in enumerate(cases):
        wind = os.path.join(a.work, "InflowWind_%d.dat" % i)
        shutil.copy(inflow, wind)
        edit(wind, PLexp=plexp, PropagationDir=direction)
        out = os.path.join(a.work, "run_%d.csv" % i)
        run([a.yamsc, "sim", model, "--aero",
             os.path.join(deck, "NRELOffshrBsline5MW_Onshore_AeroDyn15.dat"), "--wind", wind,
             "--tmax", a.tmax, "--dt", "0.025", "--channels", "openfast", "-o", out])
        azimuth, mx, my = last_revolution(out)
        curves["RootMxb1"].append((name, azimuth, mx, colour, dash))
        curves["RootMyb1"].append((name, azimuth, my, colour, dash))
    svg([("RootMxb1 (edgewise) [kN m]", curves["RootMxb1"]),
         ("RootMyb1 (flapwise) [kN m]", curves["RootMyb1"])],
        "NREL 5-MW blade 1 root moments, 8 m/s at 90 m, rotor at 8.99 rpm, every DOF off",
        a.output)
    print("wrote", a.output)


if __name__ == "__main__":
    main()
