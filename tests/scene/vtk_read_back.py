#!/usr/bin/env python3
"""`yamsc sim --vtk` read back with VTK's own XML reader (VTK 9 of python3-paraview).

The double pendulum's scene at t = 0 and t = 1 s: the marker of the point `tip`
equals the x_tip and z_tip of sim's driver to 1e-12 (the scene's points are the
generated model's outputs, written in their shortest exact text; the reference
is the Python module's run, the same driver with every digit, since the CSV
keeps 10 significant digits, which the CSV beside the scene is checked to); the
part names (FieldData, a vtkStringArray) are the bodies'; the topology is the
same in every step. Then: the CSV beside the scene equals plain `sim -o`'s byte
for byte, a link among the run's files is refused, the box of inertia of
box.mbd has its closed-form sides, centre and axes, and the four-bar's loop
(CVODE, constraints) is closed in the scene.
Usage: vtk_read_back.py YAMSC MODEL OUT_DIR PYTHON_DIR
"""
import csv
import math
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

import vtk
from vtk.util.numpy_support import vtk_to_numpy

yamsc_exe, model, out, python_dir = sys.argv[1:5]
sys.path.insert(0, python_dir)
import yamsc  # noqa: E402  (the module of this build)

reference = yamsc.load(model).simulate(tmax=1.0, dt=0.01, ic={"th1": 0.5, "th2": -0.3},
                                       frame=False)
exact = {round(t, 9): (x, z) for t, x, z in
         zip(reference["time"], reference["x_tip"], reference["z_tip"])}
shutil.rmtree(out, ignore_errors=True)
os.makedirs(os.path.dirname(out), exist_ok=True)  # sim makes DIR, not its parents
run = subprocess.run([yamsc_exe, "sim", model, "--tmax", "1", "--dt", "0.01", "--dt-out", "0.1",
                      "--ic", "th1=0.5,th2=-0.3", "--vtk", out],
                     capture_output=True, text=True)
assert run.returncode == 0, run.stderr
name = "double_pendulum"
rows = list(csv.DictReader(open(os.path.join(out, name + ".csv"))))
collection = ET.parse(os.path.join(out, name + ".pvd")).getroot()
datasets = collection.find("Collection").findall("DataSet")
assert len(datasets) == len(rows) == 11, (len(datasets), len(rows))

first_cells = None
checked = 0
for dataset, row in zip(datasets, rows):
    t = float(dataset.get("timestep"))
    assert abs(t - float(row["time"])) <= 1e-12, (t, row["time"])  # the CSV: 10 digits
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(os.path.join(out, dataset.get("file")))
    reader.Update()
    poly = reader.GetOutput()
    names = poly.GetFieldData().GetAbstractArray("part_names")
    assert names is not None and names.GetNumberOfValues() == 2
    assert [names.GetValue(i) for i in range(2)] == ["link1", "link2"]
    kind = vtk_to_numpy(poly.GetCellData().GetArray("kind"))
    part = vtk_to_numpy(poly.GetCellData().GetArray("part"))
    cells = (poly.GetNumberOfPoints(), poly.GetNumberOfVerts(), poly.GetNumberOfLines(),
             poly.GetNumberOfPolys(), tuple(kind), tuple(part))
    if first_cells is None:
        first_cells = cells
    assert cells == first_cells, "the topology changed between steps"
    # The one declared point (tip, on link2): the one vertex cell, kind 3.
    assert poly.GetNumberOfVerts() == 1 and kind[0] == 3 and part[0] == 1
    ids = vtk.vtkIdList()
    poly.GetVerts().InitTraversal()
    poly.GetVerts().GetNextCell(ids)
    x, y, z = poly.GetPoint(ids.GetId(0))
    # The CSV beside the scene: sim's table, 10 significant digits.
    assert abs(x - float(row["x_tip"])) <= 1e-9 and abs(z - float(row["z_tip"])) <= 1e-9
    if abs(t) < 1e-12 or abs(t - 1.0) < 1e-12:
        x_ref, z_ref = exact[round(t, 9)]
        assert abs(x - x_ref) <= 1e-12, (t, x, x_ref)
        assert abs(z - z_ref) <= 1e-12, (t, z, z_ref)
        assert y == 0.0
        checked += 1
assert checked == 2
# The reference itself at t = 0: where the angles put the tip (L1 = 1, L2 = 0.8;
# a rotation about y turns -z towards -x).
x0, z0 = exact[0.0]
assert abs(x0 + math.sin(0.5) + 0.8 * math.sin(0.2)) < 1e-15
assert abs(z0 + math.cos(0.5) + 0.8 * math.cos(0.2)) < 1e-15
# The CSV beside the scene is the one `sim -o` writes without --vtk (the scene's
# outputs left out), byte for byte.
plain = os.path.join(out, "plain.csv")
args = ["--tmax", "1", "--dt", "0.01", "--dt-out", "0.1", "--ic", "th1=0.5,th2=-0.3"]
r = subprocess.run([yamsc_exe, "sim", model] + args + ["-o", plain], capture_output=True, text=True)
assert r.returncode == 0, r.stderr
assert open(plain, "rb").read() == open(os.path.join(out, name + ".csv"), "rb").read()
# A link among the run's files is refused (exit 2), and nothing is written.
linked = out + "_linked"
shutil.rmtree(linked, ignore_errors=True)
os.makedirs(linked)
os.symlink(plain, os.path.join(linked, name + ".pvd"))
r = subprocess.run([yamsc_exe, "sim", model] + args + ["--vtk", linked], capture_output=True,
                   text=True)
assert r.returncode == 2 and "not a regular file" in r.stderr, (r.returncode, r.stderr)
assert sorted(os.listdir(linked)) == [name + ".pvd"], os.listdir(linked)
# The box of inertia (tests/scene/box.mbd: a uniform 1 x 2 x 3 m box of 12 kg, its
# centre of mass at (0.5, 0, 0) in a body turning freely about ground z at 1 rad/s
# from 0.3 rad, so th = 0.3 + t): sides 1, 2 and 3 m, along the body's axes,
# about the centre of mass.
box_out = out + "_box"
shutil.rmtree(box_out, ignore_errors=True)
r = subprocess.run([yamsc_exe, "sim", os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                    "box.mbd"),
                    "--tmax", "1", "--dt", "0.01", "--dt-out", "1", "--ic", "th=0.3,th'=1",
                    "--vtk", box_out], capture_output=True, text=True)
assert r.returncode == 0, r.stderr
reader = vtk.vtkXMLPolyDataReader()
reader.SetFileName(os.path.join(box_out, "box_body_000001.vtp"))
reader.Update()
poly = reader.GetOutput()
kind = vtk_to_numpy(poly.GetCellData().GetArray("kind"))
points = vtk_to_numpy(poly.GetPoints().GetData())
ids = vtk.vtkIdList()
corners = set()
for c in range(poly.GetNumberOfCells()):
    if kind[c] == 4:
        poly.GetCellPoints(c, ids)
        corners.update(ids.GetId(k) for k in range(ids.GetNumberOfIds()))
assert len(corners) == 8 and list(kind).count(4) == 6
box = points[sorted(corners)]
th = 1.3
centre = box.mean(axis=0)
assert max(abs(centre - [0.5 * math.cos(th), 0.5 * math.sin(th), 1.0])) < 1e-12, centre
edges = sorted({round(float(d), 9) for d in
                (((box[:, None, :] - box[None, :, :]) ** 2).sum(axis=2) ** 0.5).ravel()})
# Between corners: the sides 1, 2, 3, the face diagonals and the space diagonal.
expected = sorted(round(math.sqrt(a * a + b * b + c * c), 9)
                  for a in (0, 1) for b in (0, 2) for c in (0, 3))
assert edges == sorted(set(expected)), edges
for a in box:
    for b in box:
        d = b - a
        if abs(float((d ** 2).sum()) ** 0.5 - 1.0) < 1e-12:  # the 1 m side: body x
            assert abs(abs(d[0] * math.cos(th) + d[1] * math.sin(th)) - 1.0) < 1e-12, d
# A constrained model under CVODE (models/four_bar.mbd): the loop's two ends, each a
# declared point on its own body, meet in every row (the pin's x and z rows), and
# the coupler's middle is x_coupler, z_coupler of the CSV.
bar_out = out + "_four_bar"
shutil.rmtree(bar_out, ignore_errors=True)
r = subprocess.run([yamsc_exe, "sim", os.path.join(os.path.dirname(model), "four_bar.mbd"),
                    "--tmax", "1", "--dt", "0.1", "--method", "cvode", "--vtk", bar_out],
                   capture_output=True, text=True)
assert r.returncode == 0, r.stderr
bar_rows = list(csv.DictReader(open(os.path.join(bar_out, "four_bar.csv"))))
for row, dataset in zip(bar_rows, ET.parse(os.path.join(bar_out, "four_bar.pvd")).getroot()
                        .find("Collection").findall("DataSet")):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(os.path.join(bar_out, dataset.get("file")))
    reader.Update()
    poly = reader.GetOutput()
    markers = []
    poly.GetVerts().InitTraversal()
    ids = vtk.vtkIdList()
    while poly.GetVerts().GetNextCell(ids):
        markers.append(poly.GetPoint(ids.GetId(0)))
    # In declaration order: coupler_end, rocker_end, coupler_mid.
    assert len(markers) == 3, markers
    end_a, end_b, mid = markers
    # The run projects onto the constraints after each step: closed to rounding (5e-15).
    assert abs(end_a[0] - end_b[0]) < 1e-12 and abs(end_a[2] - end_b[2]) < 1e-12, (end_a, end_b)
    assert abs(mid[0] - float(row["x_coupler"])) < 1e-9 and abs(mid[2] - float(row["z_coupler"])) < 1e-9
print("ok: the tip at t = 0 and t = 1 s equals x_tip, z_tip to 1e-12")
