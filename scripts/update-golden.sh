#!/usr/bin/env bash
# Regenerates generated/ from models/*.mbd with the built compiler (build/):
# C++, C and the LaTeX document of each model.
# The golden test (tests/golden) fails until this has been run after a change
# to the generated code; review the diff before committing it.
set -euo pipefail
cd "$(dirname "$0")/.."
yamsc=${YAMSC:-build/compiler/yamsc}
mkdir -p generated
for model in models/*.mbd; do
  name=$(basename "$model" .mbd)
  "$yamsc" "$model" -o "generated/$name.cpp" --header "generated/$name.hpp"
  "$yamsc" "$model" -o "generated/$name.c" --header "generated/$name.h"
  "$yamsc" "$model" --lang latex -o "generated/$name.tex"
  echo "generated/$name.{cpp,hpp,c,h,tex}"
done
