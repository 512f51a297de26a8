#!/usr/bin/env bash
# Runs one libFuzzer target for a bounded time, starting from its seed corpus.
#   run_fuzz.sh BUILD_DIR TARGET SECONDS [libFuzzer options...]
# BUILD_DIR holds the target (tests/fuzz of a YAMSC_FUZZ=ON build). The working
# corpus is BUILD_DIR/corpus/TARGET: fresh from the seeds each run unless
# YAMSC_FUZZ_KEEP_CORPUS=1 (for long runs that build on earlier ones). Inputs
# that crash go to BUILD_DIR/artifacts/. Exits non-zero on any crash, hang
# (-timeout), out-of-memory, leak or sanitizer report, and prints one summary
# line (also appended to BUILD_DIR/fuzz-summary.txt).
set -euo pipefail
if [ $# -lt 3 ]; then
  echo "usage: $0 BUILD_DIR TARGET SECONDS [libFuzzer options...]" >&2
  exit 2
fi
build=$(cd "$1" && pwd)
target=$2
seconds=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)

# Seeds: the files every reader meets in the repository, plus the inputs that
# once crashed it (crashes/TARGET/), so they are replayed on every run.
shopt -s nullglob
case $target in
  fuzz_model)
    seeds=("$root"/models/*.mbd "$root"/tests/bad/*.mbd "$root"/tests/parse/*.mbd
           "$root"/tests/physics/models/*.mbd "$root"/tests/packaging/consumer/*.mbd)
    dict=$here/mbd.dict ;;
  fuzz_sid)
    seeds=("$root"/tests/sid/data/*.sid "$root"/tests/sid/data/bad/*.sid
           "$root"/tests/packaging/consumer/*.sid)
    dict=$here/sid.dict ;;
  fuzz_elastodyn)
    seeds=("$root"/models/data/*.dat "$here"/seeds/elastodyn/*)
    dict= ;;
  fuzz_values)
    seeds=("$here"/seeds/values/*)
    dict= ;;
  fuzz_openfast_deck)
    seeds=("$root"/models/data/*.dat "$here"/seeds/elastodyn/*)
    dict= ;;
  fuzz_wind)
    seeds=("$here"/seeds/wind/*)
    dict= ;;
  fuzz_inflowwind)
    seeds=("$root"/tests/data/reference/operating/deck/*InflowWind.dat "$here"/seeds/inflowwind/*)
    dict= ;;
  fuzz_turbsim_bts)
    seeds=("$here"/seeds/turbsim_bts/*)
    dict= ;;
  fuzz_hawc_box)
    seeds=("$here"/seeds/hawc_box/*)
    dict= ;;
  fuzz_aerodyn_primary)
    seeds=("$root"/tests/data/reference/operating/deck/*AeroDyn15.dat)
    dict= ;;
  fuzz_map_input)
    seeds=("$root"/tests/data/mooring/*.map)
    dict= ;;
  fuzz_hydrodyn_input)
    seeds=("$root"/tests/data/hydro/oc3_spar_*.dat "$here"/seeds/hydrodyn/*)
    dict= ;;
  fuzz_wamit)
    seeds=("$here"/seeds/wamit/*)
    dict= ;;
  fuzz_seastate_input)
    seeds=("$root"/tests/data/hydro/oc3_sea_state.dat "$here"/seeds/seastate/*)
    dict= ;;
  fuzz_aerodyn_blade)
    seeds=("$root"/tests/data/reference/operating/deck/*AeroDyn_blade.dat)
    dict= ;;
  fuzz_aerodyn_airfoil)
    seeds=("$root"/tests/data/reference/operating/deck/Airfoils/*.dat "$here"/seeds/aerodyn_airfoil/*)
    dict= ;;
  fuzz_performance_table)
    seeds=("$root"/models/data/Cp_Ct_Cq.*.txt)
    dict= ;;
  fuzz_openfast_outb)
    seeds=("$root"/tests/data/reference/loads/FASTOutBin.outb "$here"/seeds/openfast_outb/*)
    dict= ;;
  fuzz_turbsim_input)
    seeds=("$root"/tests/data/reference/turbulence/*.inp)
    dict= ;;
  fuzz_vtk)
    # The first byte chooses the reader: even .vtp, odd .pvd.
    seeds=("$here"/seeds/vtk/*)
    dict= ;;
  *)
    echo "run_fuzz.sh: unknown target '$target'" >&2
    exit 2 ;;
esac
seeds+=("$here"/crashes/"$target"/*)

corpus=$build/corpus/$target
artifacts=$build/artifacts
if [ "${YAMSC_FUZZ_KEEP_CORPUS:-0}" != 1 ]; then rm -rf "$corpus"; fi
mkdir -p "$corpus" "$artifacts"
for s in "${seeds[@]}"; do
  [ -f "$s" ] && cp "$s" "$corpus/seed_$(basename "$s")"
done
initial=$(ls "$corpus" | wc -l)

options=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384
         -print_final_stats=1 -artifact_prefix="$artifacts/$target-")
[ -n "$dict" ] && options+=(-dict="$dict")
log=$build/$target.log
status=0
started=$(date +%s)
"$build/$target" "${options[@]}" "$@" "$corpus" >"$log" 2>&1 || status=$?

elapsed=$(($(date +%s) - started))
executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
rss=$(sed -n 's/^stat::peak_rss_mb: *//p' "$log" | tail -1)
final=$(ls "$corpus" | wc -l)
bytes=$(( $(cat "$corpus"/* | wc -c) / 1024 ))
coverage=$(grep -o 'cov: [0-9]* ft: [0-9]*' "$log" | tail -1 || true)
summary="$target: ${executions:-?} executions in ${elapsed} s, corpus $initial -> $final inputs (${bytes} KiB), ${coverage:-no coverage line}, peak RSS ${rss:-?} MB, status $status"
echo "$summary" | tee -a "$build/fuzz-summary.txt"
if [ "$status" -ne 0 ]; then
  echo "---- $target failed; the end of its log ($log):" >&2
  tail -n 60 "$log" >&2
  echo "---- reproduce with: $build/$target $artifacts/$target-<crash file>" >&2
fi
exit "$status"
