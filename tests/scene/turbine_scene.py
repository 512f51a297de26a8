#!/usr/bin/env python3
"""The NREL 5-MW's scene opened by ParaView.

`yamsc from-openfast` of the 16-DOF onshore deck, `yamsc sim --vtk` of 2 s
(rows every 0.5 s), then pvpython runs paraview_screenshot.py on the .pvd
(under xvfb-run when there is no display). Usage:
turbine_scene.py PVPYTHON DECK_FOLDER OUT_DIR (YAMSC in the environment)
"""
import os
import shutil
import subprocess
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


run([yamsc, "from-openfast", os.path.join(deck, "NREL5MW_Onshore_FreeDecay.fst"), "-o", model])
run([yamsc, "sim", model, "--tmax", "2", "--dt", "0.01", "--dt-out", "0.5",
     "--vtk", os.path.join(out, "run")])
pvd = [f for f in os.listdir(os.path.join(out, "run")) if f.endswith(".pvd")]
assert len(pvd) == 1, pvd
script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "paraview_screenshot.py")
command = [pvpython, "--force-offscreen-rendering", script,
           os.path.join(out, "run", pvd[0]), os.path.join(out, "turbine.png")]
if not os.environ.get("DISPLAY") and shutil.which("xvfb-run"):
    command = ["xvfb-run", "-a", "-s", "-screen 0 1024x768x24"] + command
run(command)
