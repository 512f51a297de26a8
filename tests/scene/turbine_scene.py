#!/usr/bin/env python3
"""The NREL 5-MW's scene opened by ParaView, and its surfaces.

`yamsc from-openfast` of the 16-DOF onshore deck, `yamsc sim --vtk` of 2 s
(rows every 0.5 s), then pvpython runs paraview_screenshot.py on the .pvd
(under xvfb-run when there is no display). Then the operating deck with AeroDyn
(`load blade_elements`, `--aero`): the blades' and the tower's surfaces, read
with VTK's reader (the tower's tube 6 m across at its foot, the blades' chord at
most 4.7 m, their tips about 63 m from the hub). Usage:
turbine_scene.py PVPYTHON REFERENCE_FOLDER OUT_DIR (YAMSC in the environment)
"""
import os
import shutil
import subprocess
import time
import sys

pvpython, deck, out = sys.argv[1:4]
yamsc = os.environ["YAMSC"]
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
model = os.path.join(out, "turbine.mbd")


def run(command):
    r = subprocess.run(command, capture_output=True, text=True)
    print(r.stdout + r.stderr)
    assert r.returncode == 0, " ".join(command)


run([yamsc, "from-openfast", os.path.join(deck, "land_16dof_free_decay",
                                          "NREL5MW_Onshore_FreeDecay.fst"), "-o", model])
run([yamsc, "sim", model, "--tmax", "2", "--dt", "0.01", "--dt-out", "0.5",
     "--vtk", os.path.join(out, "run")])
pvd = [f for f in os.listdir(os.path.join(out, "run")) if f.endswith(".pvd")]
assert len(pvd) == 1, pvd
script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "paraview_screenshot.py")
command = [pvpython, "--force-offscreen-rendering", script,
           os.path.join(out, "run", pvd[0]), os.path.join(out, "turbine.png")]
if not os.environ.get("DISPLAY") and shutil.which("xvfb-run"):
    command = ["xvfb-run", "-a", "-s", "-screen 0 1024x768x24"] + command
    # `xvfb-run -a` takes the first free display number; two runs starting at
    # once (two builds' suites on one machine) can both take it, and the one
    # that loses sees "bad X server connection". Such a start is tried again.
    for attempt in range(3):
        r = subprocess.run(command, capture_output=True, text=True)
        if r.returncode == 0 or "bad X server connection" not in r.stdout + r.stderr:
            break
        time.sleep(1 + attempt)
    print(r.stdout + r.stderr)
    assert r.returncode == 0, " ".join(command)
else:
    run(command)

# The operating deck: surfaces from its AeroDyn files.
import numpy as np  # noqa: E402
import vtk  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

operating = os.path.join(deck, "operating", "deck")
model = os.path.join(out, "operating.mbd")
run([yamsc, "from-openfast", os.path.join(operating, "NREL-5MW.fst"), "-o", model])
run([yamsc, "sim", model, "--aero", os.path.join(operating, "NRELOffshrBsline5MW_Onshore_AeroDyn15.dat"),
     "--wind", "8", "--tmax", "0.5", "--dt", "0.01", "--dt-out", "0.5",
     "--vtk", os.path.join(out, "operating")])
reader = vtk.vtkXMLPolyDataReader()
reader.SetFileName(os.path.join(out, "operating", "operating_000001.vtp"))
reader.Update()
poly = reader.GetOutput()
names = poly.GetFieldData().GetAbstractArray("part_names")
parts = [names.GetValue(i) for i in range(names.GetNumberOfValues())]
kind = vtk_to_numpy(poly.GetCellData().GetArray("kind"))
part = vtk_to_numpy(poly.GetCellData().GetArray("part"))
points = vtk_to_numpy(poly.GetPoints().GetData())
ids = vtk.vtkIdList()
surface = {}
for c in range(poly.GetNumberOfCells()):
    if kind[c] != 2:
        continue
    poly.GetCellPoints(c, ids)
    surface.setdefault(parts[part[c]], set()).update(ids.GetId(k) for k in range(4))
assert sorted(surface) == ["blade1", "blade2", "blade3", "tower"], sorted(surface)
tower = points[sorted(surface["tower"])]
foot = tower[tower[:, 2] < tower[:, 2].min() + 1e-6]
width = foot[:, 0].max() - foot[:, 0].min()
assert abs(width - 6.0) < 0.05, width  # TwrDiam 6 m at the foot
for b in ("blade1", "blade2", "blade3"):
    p = points[sorted(surface[b])]
    # 12 points a section: the widest section is the largest chord (4.652 m).
    rings = p.reshape(-1, 12, 3)
    chord = max(np.linalg.norm(r[:, None, :] - r[None, :, :], axis=2).max() for r in rings)
    assert 4.5 < chord < 4.8, (b, chord)
    span = np.linalg.norm(rings[-1].mean(axis=0) - rings[0].mean(axis=0))
    assert 60.0 < span < 62.0, (b, span)  # BlSpn from 0 to 61.5 m
print("ok: the blades' and the tower's surfaces")
