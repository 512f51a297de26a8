"""ParaView opens a turbine's scene (`sim --vtk`) and renders it.

Run by pvpython (offscreen, or under xvfb-run): the collection's times, the
bounding box of the turbine (hub height about 90 m, rotor diameter about 126 m
for the NREL 5-MW) and a screenshot that is not empty (pixel statistics).
Usage: pvpython paraview_screenshot.py RUN.pvd SHOT.png
"""
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import (ColorBy, CreateView, GetAnimationScene, PVDReader, Render,
                             SaveScreenshot, Show)
from vtkmodules.vtkCommonCore import vtkIdList
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy

pvd, png = sys.argv[1:3]
reader = PVDReader(FileName=pvd)
times = list(reader.TimestepValues)
assert len(times) >= 2 and times[0] == 0.0, times
reader.UpdatePipeline(times[0])
info = reader.GetDataInformation()
xmin, xmax, ymin, ymax, zmin, zmax = info.GetBounds()
print("bounds at t = 0:", xmin, xmax, ymin, ymax, zmin, zmax)
# The tower's foot on the ground, blade 1 up at t = 0 (about 90 + 63 m).
assert -1.0 < zmin < 15.0, zmin
assert 145.0 < zmax < 158.0, zmax
# The hub's origin and the blades' farthest points, from the data ParaView read.
data = servermanager.Fetch(reader)
names = data.GetFieldData().GetAbstractArray("part_names")
assert names is not None, "part_names not in the FieldData ParaView reads"
parts = [names.GetValue(i) for i in range(names.GetNumberOfValues())]
print("parts:", parts)
part = vtk_to_numpy(data.GetCellData().GetArray("part"))
kind = vtk_to_numpy(data.GetCellData().GetArray("kind"))
points = vtk_to_numpy(data.GetPoints().GetData())
hub = parts.index("hub")
ids = vtkIdList()
origin = None
radius = 0.0
for c in range(data.GetNumberOfCells()):
    data.GetCellPoints(c, ids)
    cell = [ids.GetId(k) for k in range(ids.GetNumberOfIds())]
    if part[c] == hub and kind[c] == 0 and origin is None:
        origin = points[cell[0]]
for c in range(data.GetNumberOfCells()):
    data.GetCellPoints(c, ids)
    if parts[part[c]].startswith("blade") and kind[c] == 1:
        for k in range(ids.GetNumberOfIds()):
            radius = max(radius, float(np.linalg.norm(points[ids.GetId(k)] - origin)))
print("hub at", origin, "rotor diameter", 2 * radius)
assert 87.0 < origin[2] < 93.0, origin  # hub height about 90 m
assert 122.0 < 2 * radius < 130.0, radius  # rotor diameter about 126 m

view = CreateView("RenderView")
view.ViewSize = [640, 480]
view.Background = [1.0, 1.0, 1.0]
try:  # ParaView 5.10 and later draw the background from a palette unless told
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
view.OrientationAxesVisibility = 0
display = Show(reader, view)
ColorBy(display, ("CELLS", "part"))
display.LineWidth = 3.0
view.CameraPosition = [250.0, -150.0, 120.0]
view.CameraFocalPoint = [0.0, 0.0, 70.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera()
GetAnimationScene().AnimationTime = times[-1]
Render(view)
SaveScreenshot(png, view, ImageResolution=[640, 480])

image = vtkPNGReader()
image.SetFileName(png)
image.Update()
pixels = vtk_to_numpy(image.GetOutput().GetPointData().GetScalars())[:, :3].astype(float)
drawn = (pixels.sum(axis=1) < 3 * 250).mean()
print("pixels drawn: %.4f" % drawn)
assert 0.003 < drawn < 0.6, drawn  # something drawn, not all one colour
assert pixels.std() > 5.0
print("ok: ParaView read the turbine's scene, bounding box and screenshot as expected")
