#!/usr/bin/env bash
# Installs the Debian packages yamsc needs, only those that are missing.
set -euo pipefail
packages=(build-essential cmake pkg-config libginac-dev libcln-dev tao-pegtl-dev libeigen3-dev
          libfmt-dev libsundials-dev doctest-dev python3 python3-sympy python3-numpy
          pybind11-dev python3-pybind11 python3-pytest python3-pandas # the Python module (docs/python.md)
          gfortran # ROSCO, the reference controller (third_party/rosco/README.md)
          python3-distributed # yamsc.dask (docs/batch.md); its test is skipped without it
          clang libclang-rt-14-dev # clang + libFuzzer: the fuzz targets (docs/robustness.md)
          paraview python3-paraview xvfb) # ParaView, and VTK's Python reader with it (python3-paraview provides vtk and conflicts with python3-vtk9): the scene's tests (docs/visualization.md)
missing=()
# yamsc view (docs/viewer.md): the page is bundled by npm at build time and tested
# in headless Chromium; a nodejs from elsewhere (NodeSource) brings its own npm.
packages+=(nodejs chromium)
command -v npm >/dev/null || packages+=(npm)
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi
