#!/usr/bin/env bash
# Regenerates tests/bad/X.expected, the whole diagnostic output (message, source
# line, caret, notes) of `yamsc check X.mbd` for every model of the bad-input
# corpus, with the built compiler (build/). The test (tests/cli/bad_inputs_test.cpp)
# compares the output byte for byte; review the diff before committing it.
set -euo pipefail
cd "$(dirname "$0")/.."
yamsc=$(realpath "${YAMSC:-build/compiler/yamsc}")
cd tests/bad
for model in *.mbd; do
  name=${model%.mbd}
  status=0
  "$yamsc" check "$model" >/dev/null 2>"$name.expected" || status=$?
  if [ "$status" -ne 1 ]; then
    echo "tests/bad/$model: expected exit status 1, got $status" >&2
    exit 1
  fi
done
echo "wrote $(ls *.expected | wc -l) files tests/bad/*.expected"
