#!/usr/bin/env bash
# Fuzzes the readers of everything csmhair takes from outside (tests/fuzz: presets, cyHair,
# TressFX, OBJ heads, OBJ hair curves, the research formats and PLY heads) with libFuzzer under
# ASan, LeakSanitizer and UBSan, in build-fuzz/
# (clang; configured and built here when needed, clang and libFuzzer installed when missing).
#   scripts/fuzz.sh short [SECONDS]          CI: every target SECONDS (12) on a copy of its
#                                            seeds, after every regression input once; as many
#                                            targets at once as there are cores (FUZZ_PARALLEL)
#   scripts/fuzz.sh long [SECONDS|-runs=N]   every target for SECONDS or N runs (default
#                                            -runs=10000000), one after the other, one process;
#                                            the corpus grows in build-fuzz/corpus/<target>/
#   scripts/fuzz.sh regressions              every input under tests/fuzz/regressions/ once
#   scripts/fuzz.sh build                    only build the targets
# FUZZ_TARGETS="preset obj" picks targets; FUZZ_JOBS sets the build's jobs (default: cores).
# Prints per target: executions, time, exec/s, coverage (libFuzzer's cov: edges, ft: features),
# corpus, findings. Exits non-zero on any finding (crash, leak, undefined behaviour, timeout
# over 10 s of a core, more than 2 GB); its input is kept in build-fuzz/findings/<target>/, and
#   build-fuzz/tests/fuzz/fuzz_<target> <input>
# reproduces it. A fixed finding's input goes to tests/fuzz/regressions/<target>/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build-fuzz"
fuzz="$root/tests/fuzz"
mode=${1:-short}
targets=(${FUZZ_TARGETS:-preset cyhair tressfx obj curves research})

case "$mode" in
  short)
    # One target a core at once (a target is one process, libFuzzer's default), each its own
    # SECONDS. (All five at once on two cores, for 75 s of the clock, ran 10-27 % fewer
    # executions a target than these three rounds of 30 s: five processes contend. 12 s a target
    # since the farm's tests joined CI, to keep it under 15 minutes: the long run,
    # scripts/fuzz.sh long, is where the corpus grows.)
    seconds=${2:-12}
    limit=(-max_total_time="$seconds") ;;
  long)
    arg=${2:--runs=10000000}
    if [[ "$arg" == -runs=* ]]; then limit=("$arg"); else limit=(-max_total_time="$arg"); fi ;;
  regressions | build) limit=() ;;
  *) echo "fuzz.sh: unknown mode '$mode' (short, long, regressions, build)" >&2; exit 2 ;;
esac

# Debian's clang and its libFuzzer runtime (libclang_rt.fuzzer), as scripts/setup.sh installs.
# shellcheck source=scripts/packages.sh
source "$root/scripts/packages.sh"
packages=(cmake make libeigen3-dev libglm-dev nlohmann-json3-dev libtinyobjloader-dev)
command -v clang++ >/dev/null || packages+=(clang)
compgen -G "/usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a" >/dev/null ||
  packages+=(libclang-rt-14-dev)
install_missing fuzz "${packages[@]}"

# Line tables only (a report's stack still names file and line): the same code as -O2 -g,
# built in 0.9x the time. (-O1 built in 0.8x but ran a half to a third of the executions.)
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCSM_FUZZ=ON \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" >/dev/null
fi
# Only the targets and what they link (not the tree's other libraries: the verification's
# torture and soak, the view's settings).
cmake --build "$build" -j "${FUZZ_JOBS:-$(nproc 2>/dev/null || echo 2)}" \
  --target "${targets[@]/#/fuzz_}"
[ "$mode" = build ] && exit 0

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
# A finding: a crash, a sanitizer report (UBSan aborts: -fno-sanitize-recover=all), a leak, one
# input over 10 s of a core (a hang) or over 2 GB. The regression inputs of every target run at
# once, sharing the cores, so their clock's limit grows by targets / cores (a full preset's
# scene alone takes 5 s here).
cores=${FUZZ_PARALLEL:-$(nproc 2>/dev/null || echo 1)}
shared=10
[ ${#targets[@]} -le "$cores" ] || shared=$(( (10 * ${#targets[@]} + cores - 1) / cores ))
# (libFuzzer keeps an input over -report_slow_units, 10 s by default, as a "slow unit": not a
# finding, and kept only past the limit.)
memory=(-rss_limit_mb=2048 -malloc_limit_mb=2048)
status=0

regressions() {
  local t=$1 dir="$fuzz/regressions/$1"
  compgen -G "$dir/*" >/dev/null || return 0
  local log="$build/logs/regressions_$t.log"
  rm -f "$build/logs/failed_$t"
  if "$build/tests/fuzz/fuzz_$t" "${memory[@]}" -timeout="$shared" -report_slow_units="$shared" \
    "$dir"/* >"$log" 2>&1; then
    echo "fuzz: $t: $(find "$dir" -type f | wc -l) regression inputs pass"
  else
    echo "fuzz: $t: a regression input fails again; see $log" >&2
    tail -n 30 "$log" >&2
    touch "$build/logs/failed_$t"  # the targets' inputs run at once, each in a subshell
  fi
}

run() {
  local t=$1 corpus findings="$build/findings/$1" log="$build/logs/${mode}_$1.log"
  mkdir -p "$findings"
  if [ "$mode" = long ]; then
    corpus="$build/corpus/$t"  # grows from run to run
  else
    corpus=$(mktemp -d)  # the seeds stay as they are
  fi
  mkdir -p "$corpus"
  cp -n "$fuzz/corpus/$t"/* "$corpus"/
  [ "$t" = preset ] && cp -n "$root/presets"/*.json "$corpus"/
  local opts=("${memory[@]}" -timeout=10 -report_slow_units=10 "${limit[@]}" -print_final_stats=1 -artifact_prefix="$findings/"
              -max_len=$([ "$t" = preset ] && echo 8192 || echo 4096))
  [ -f "$fuzz/$t.dict" ] && opts+=(-dict="$fuzz/$t.dict")
  local before after start end rc=0
  before=$(find "$findings" -type f ! -name "slow-unit-*" | wc -l)
  start=$(date +%s)
  "$build/tests/fuzz/fuzz_$t" "${opts[@]}" "$corpus" >"$log" 2>&1 || rc=$?
  end=$(date +%s)
  after=$(find "$findings" -type f ! -name "slow-unit-*" | wc -l)
  local runs eps last cov ft corp
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  eps=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
  last=$(grep -E '^#[0-9]+[[:space:]]+(DONE|pulse|NEW|REDUCE|INITED)' "$log" | tail -n 1 || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$last")
  corp=$(sed -n 's/.* corp: \([0-9]*\/[0-9]*[bKM]*\).*/\1/p' <<<"$last")
  local found=$((after - before))
  [ $rc -ne 0 ] && [ $found -eq 0 ] && found=1
  # Its row and verdict go to files: the targets may run at once, each in a subshell.
  printf '%-8s %12s %8s %8s %6s %7s %12s %8s\n' "$t" "${runs:-?}" "$((end - start))" \
    "${eps:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$found" >"$build/logs/row_$t"
  if [ $rc -ne 0 ]; then
    echo "fuzz: $t: FINDING (exit $rc); input in $findings/, log $log:" >&2
    grep -E 'ERROR|runtime error|fuzz target:|SUMMARY|Test unit written' "$log" | head -n 20 >&2
    touch "$build/logs/found_$t"
  fi
  [ "$mode" = long ] || rm -rf "$corpus"
}

mkdir -p "$build/logs"
for t in "${targets[@]}"; do rm -f "$build/logs/row_$t" "$build/logs/found_$t"; done
# Every target's regression inputs at once, then the fuzzing: the short run one target a core
# at once, the long run one after the other.
for t in "${targets[@]}"; do regressions "$t" & done
wait
for t in "${targets[@]}"; do [ ! -f "$build/logs/failed_$t" ] || status=1; done
if [ "$mode" != regressions ]; then
  parallel=1
  [ "$mode" = short ] && parallel=$cores
  for t in "${targets[@]}"; do
    run "$t" &
    while [ "$(jobs -rp | wc -l)" -ge "$parallel" ]; do wait -n || true; done
  done
  wait
  printf '%-8s %12s %8s %8s %6s %7s %12s %8s\n' target executions time_s exec/s cov ft corpus \
    findings
  for t in "${targets[@]}"; do
    cat "$build/logs/row_$t" 2>/dev/null || echo "$t: no report (see $build/logs/${mode}_$t.log)"
    [ -f "$build/logs/row_$t" ] && [ ! -f "$build/logs/found_$t" ] || status=1
  done
fi
exit $status
