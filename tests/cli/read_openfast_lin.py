#!/usr/bin/env python3
"""An independent reader of OpenFAST linearization files (.lin), numpy only,
for tests/cli/openfast_lin_test.cpp: it parses what `yamsc lin --format
openfast-lin` wrote the way OpenFAST's post-processing tools do (labels,
blank-separated columns), and prints, one per line:

  header <key> <value>        Rotor Speed, Azimuth, sizes
  x <row> <T|F> <order> <description>    the state table
  freq <Hz>                   |lambda|/2pi of the eigenvalues of A with Im >= 0
  mbc3 <Hz>                   (mode mbc3) the same for the azimuth-averaged
                              multi-blade-coordinate A of all files given
  matrix <name> <rows> <cols> <max |entry|>

Usage: read_openfast_lin.py single FILE | mbc3 FILE...
"""
import re
import sys

import numpy as np


def read_lin(path):
    with open(path) as f:
        lines = f.read().split("\n")
    out = {"header": {}, "tables": {}, "matrices": {}}
    keys = {"Rotor Speed:": "rotor_speed", "Azimuth:": "azimuth", "Wind Speed:": "wind_speed",
            "Simulation time:": "time", "Number of continuous states:": "nx",
            "Number of inputs:": "nu", "Number of outputs:": "ny"}
    i = 0
    while i < len(lines):
        line = lines[i]
        for label, key in keys.items():
            if line.strip().startswith(label):
                out["header"][key] = float(line.split(label)[1].split()[0])
        m = re.match(r"^Order of (continuous states|continuous state derivatives|inputs|outputs):",
                     line)
        if m:
            n = int(out["header"][{"continuous states": "nx",
                                   "continuous state derivatives": "nx",
                                   "inputs": "nu", "outputs": "ny"}[m.group(1)]])
            rows = []
            for row in lines[i + 3:i + 3 + n]:  # after the column titles and the rule
                parts = row.split()
                rows.append({"op": float(parts[1]), "rotating": parts[2],
                             "order": int(parts[3]), "description": " ".join(parts[4:])})
            out["tables"][m.group(1)] = rows
            i += 3 + n
            continue
        m = re.match(r"^([A-D]): (\d+) x (\d+)$", line)
        if m:
            r, c = int(m.group(2)), int(m.group(3))
            data = np.array([[float(v) for v in lines[i + 1 + k].split()] for k in range(r)])
            assert data.shape == (r, c), (m.group(1), data.shape)
            out["matrices"][m.group(1)] = data
            i += 1 + r
            continue
        i += 1
    return out


def frequencies(A):
    lam = np.linalg.eigvals(A)
    lam = lam[lam.imag >= 0]
    return sorted(np.abs(lam) / (2 * np.pi))


def blade_triplets(states):
    """Indices (into the displacement states) of each blade family: rotating
    states whose descriptions differ only in the blade number."""
    groups = {}
    for k, s in enumerate(states):
        if s["rotating"] != "T":
            continue
        d = re.sub(r"\(internal DOF index = [^)]*\)\)?", "", s["description"])
        m = re.search(r"blade (\d)|b(\d)", d)
        blade = int(m.group(1) or m.group(2))
        key = d[:m.start()] + "#" + d[m.end():]
        groups.setdefault(key, {})[blade] = k
    return [[g[1], g[2], g[3]] for g in groups.values()]


def mbc3(files):
    """Bir's MBC3 with x = T x_nr, T = [[T1, 0], [W T2, T1]], averaged over the files."""
    total = None
    for path in files:
        f = read_lin(path)
        A = f["matrices"]["A"]
        nx = A.shape[0]
        n = nx // 2
        states = f["tables"]["continuous states"][:n]
        psi, w = f["header"]["azimuth"], f["header"]["rotor_speed"]
        T1, T2, T3 = np.eye(n), np.zeros((n, n)), np.zeros((n, n))
        for fam in blade_triplets(states):
            for b, row in enumerate(fam):
                a = psi + 2 * np.pi * b / 3
                T1[row, fam] = [1, np.cos(a), np.sin(a)]
                T2[row, fam] = [0, -np.sin(a), np.cos(a)]
                T3[row, fam] = [0, -np.cos(a), -np.sin(a)]
        Z = np.zeros((n, n))
        T = np.block([[T1, Z], [w * T2, T1]])
        Tdot = w * np.block([[T2, Z], [w * T3, T2]])
        Anr = np.linalg.solve(T, A @ T - Tdot)
        total = Anr if total is None else total + Anr
    return total / len(files)


def main():
    mode, files = sys.argv[1], sys.argv[2:]
    if mode == "mbc3":
        for fr in frequencies(mbc3(files)):
            print("mbc3 %.17g" % fr)
        return
    f = read_lin(files[0])
    for k, v in f["header"].items():
        print("header %s %.17g" % (k, v))
    for k, s in enumerate(f["tables"].get("continuous states", [])):
        print("x %d %s %d %s" % (k + 1, s["rotating"], s["order"], s["description"]))
    for name, m in f["matrices"].items():
        print("matrix %s %d %d %.17g" % (name, m.shape[0], m.shape[1], np.abs(m).max()))
    for fr in frequencies(f["matrices"]["A"]):
        print("freq %.17g" % fr)


if __name__ == "__main__":
    main()
