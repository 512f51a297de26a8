#!/usr/bin/env python3
"""`yamsc sim --vtk` read back with VTK's own XML reader (python3-vtk9).

The double pendulum's scene at t = 0 and t = 1 s: the marker of the point `tip`
equals the x_tip and z_tip of sim's driver to 1e-12 (the scene's points are the
generated model's outputs, written in their shortest exact text; the reference
is the Python module's run, the same driver with every digit, since the CSV
keeps 10 significant digits, which the CSV beside the scene is checked to); the
part names (FieldData, a vtkStringArray) are the bodies'; the topology is the
same in every step. Usage: vtk_read_back.py YAMSC MODEL OUT_DIR PYTHON_DIR
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
print("ok: the tip at t = 0 and t = 1 s equals x_tip, z_tip to 1e-12")
