#!/usr/bin/env bash
# Builds (if needed) and runs every benchmark of a build directory, then prints
# the median wall and CPU time of each benchmark against its target.
#
#   scripts/bench.sh [BUILD_DIR]          # default: build (relative to the repo)
#
# Environment:
#   REPS=5          repetitions per benchmark (median over them)
#   MIN_TIME=0.2    minimum seconds per repetition
#   ONLY="a b"      run only these binaries (e.g. ONLY="bench_qp bench_sim")
#   JOBS=2          parallel build jobs
#   STRICT=1        also exit non-zero when a median misses its target
#
# Benchmarks are the handover_add_bench(NAME ...) calls in bench/*/CMakeLists.txt;
# each binary lands in BUILD_DIR/bench/<folder>/NAME. Raw results (JSON) go to
# BUILD_DIR/bench-results/. Exit status: 0 if every binary ran without error,
# 1 if one failed to build, crashed or reported an error (SkipWithError),
# 2 for bad usage. Figures go to docs/performance.md.
set -euo pipefail

usage() { sed -n '2,18p' "$0" | sed 's/^# \{0,1\}//'; }
case "${1:-}" in -h|--help) usage; exit 0 ;; esac
[ $# -le 1 ] || { usage >&2; exit 2; }

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-build}"
case "$build" in /*) ;; *) build="$repo/$build" ;; esac
reps="${REPS:-5}"
min_time="${MIN_TIME:-0.2}"
jobs="${JOBS:-2}"

# Targets (median wall time, us). The first four come from the issues; the
# others are the budgets the module owners set (see docs/performance.md).
target_us() {
  case "$1" in
    BM_QpSolve) echo 10 ;;
    BM_QpSolveCold) echo 10 ;;
    BM_ModelUpdate) echo 5 ;;
    BM_ControlStep) echo 40 ;;
    BM_ControlStepWithCollision) echo 40 ;;
    BM_Cycle) echo 50 ;;
    BM_Distances) echo 15 ;;
    BM_StepWaiting|BM_StepGrasping) echo 10 ;;
    BM_ScriptedHumanStep|BM_SensorObservePoll|BM_EstimatorAndTarget) echo 5 ;;
    BM_DecodeDatagram) echo 20 ;;
    BM_IkWarm) echo 20 ;;
    BM_SelectionMovingObject) echo 500 ;;
    *) echo "" ;;
  esac
}

# --- which benchmarks exist: folder + target name, from the CMake files
declare -a names=() dirs=()
for cml in "$repo"/bench/*/CMakeLists.txt; do
  folder="$(basename "$(dirname "$cml")")"
  while read -r name; do
    [ -n "$name" ] || continue
    if [ -n "${ONLY:-}" ] && ! [[ " $ONLY " == *" $name "* ]]; then continue; fi
    names+=("$name"); dirs+=("$folder")
  done < <(grep -o 'handover_add_bench( *[A-Za-z0-9_]*' "$cml" | sed 's/.*( *//' | sort -u)
done
if [ ${#names[@]} -eq 0 ]; then
  echo "bench.sh: no benchmarks found${ONLY:+ matching ONLY=\"$ONLY\"} in $repo/bench/*/CMakeLists.txt" >&2
  exit 2
fi

# --- configure (Release) if the build directory is new, then build
if [ ! -f "$build/CMakeCache.txt" ]; then
  echo "== configuring $build (Release)"
  cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release -DHANDOVER_BUILD_BENCH=ON >/dev/null
fi
# the benchmarks are off by default (CMakeLists.txt): switch them on here
if ! grep -q '^HANDOVER_BUILD_BENCH:BOOL=ON' "$build/CMakeCache.txt"; then
  echo "== switching the benchmarks on in $build (HANDOVER_BUILD_BENCH=ON)"
  cmake -S "$repo" -B "$build" -DHANDOVER_BUILD_BENCH=ON >/dev/null
fi
build_type="$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt")"
if [ "$build_type" != "Release" ]; then
  echo "bench.sh: warning: $build is a '${build_type:-no type}' build; figures are only comparable from Release" >&2
fi
echo "== building ${names[*]}"
status=0
if ! cmake --build "$build" -j"$jobs" --target "${names[@]}" >"$build/bench-build.log" 2>&1; then
  echo "bench.sh: build failed, see $build/bench-build.log:" >&2
  grep -m 20 -E 'error|Error' "$build/bench-build.log" >&2 || tail -20 "$build/bench-build.log" >&2
  status=1  # run whatever did build, but fail at the end
fi

# "<value> <unit>" -> microseconds
to_us() {
  awk -v v="$1" -v u="$2" 'BEGIN { f = (u == "ns") ? 1e-3 : (u == "us") ? 1 : (u == "ms") ? 1e3 : (u == "s") ? 1e6 : -1
                                   if (f < 0) print "?"; else printf "%.3f", v * f }'
}

# microseconds -> "0.084 us", "9.81 us", "16.9 ms" (3 significant digits)
pretty() {
  awk -v v="$1" 'BEGIN { if (v == "?") { print "?"; exit }
                         u = "us"; if (v >= 1000) { v /= 1000; u = "ms" }
                         d = (v >= 100) ? 0 : (v >= 10) ? 1 : (v >= 1) ? 2 : 3
                         printf "%.*f %s", d, v, u }'
}

# --- run
results="$build/bench-results"
mkdir -p "$results"
summary="$results/summary.txt"
host_cpu="$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)"
{
  echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')  commit: $(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo '?')"
  echo "machine: $(nproc) cores, ${host_cpu:-unknown cpu}; build type: ${build_type:-?}; repetitions: $reps x >= ${min_time}s"
  echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
  printf '%-52s %11s %11s %10s  %s\n' benchmark "median wall" "median CPU" target result
} | tee "$summary"

fails=0 misses=0
for i in "${!names[@]}"; do
  name="${names[$i]}"
  bin="$build/bench/${dirs[$i]}/$name"
  if [ ! -x "$bin" ]; then
    printf '%-52s %s\n' "$name" "FAILED: no binary at $bin" | tee -a "$summary"
    fails=$((fails + 1)); continue
  fi
  out="$results/$name.txt"
  load_before="$(cut -d' ' -f1 /proc/loadavg)"
  rc=0
  "$bin" --benchmark_repetitions="$reps" --benchmark_min_time="$min_time" \
         --benchmark_report_aggregates_only=true --benchmark_color=false \
         --benchmark_out="$results/$name.json" --benchmark_out_format=json >"$out" 2>&1 || rc=$?
  load_after="$(cut -d' ' -f1 /proc/loadavg)"
  if [ "$rc" -ne 0 ]; then
    printf '%-52s %s\n' "$name" "FAILED: exit code $rc (see $out)" | tee -a "$summary"
    fails=$((fails + 1)); continue
  fi
  if grep -q 'ERROR OCCURRED' "$out"; then
    grep 'ERROR OCCURRED' "$out" | sed "s/^/$name: /" | tee -a "$summary"
    fails=$((fails + 1))
  fi
  echo "-- $name (load ${load_before} -> ${load_after})" | tee -a "$summary"
  # console rows: NAME_median <wall> <unit> <cpu> <unit> <iterations> ...
  while read -r bm wall wunit cpu cunit; do
    w="$(to_us "$wall" "$wunit")"; c="$(to_us "$cpu" "$cunit")"
    base="${bm%%/*}"
    t="$(target_us "$base")"
    verdict="-"
    if [ -n "$t" ] && [ "$w" != "?" ]; then
      if awk -v w="$w" -v t="$t" 'BEGIN { exit !(w <= t) }'; then verdict="pass"; else verdict="FAIL"; misses=$((misses + 1)); fi
    fi
    printf '%-52s %11s %11s %10s  %s\n' "$bm" "$(pretty "$w")" "$(pretty "$c")" "${t:+<= $t us}" "$verdict" | tee -a "$summary"
  done < <(awk '$1 ~ /^BM_/ && NF >= 5 && $2 ~ /^[0-9.]+$/ {
                 if ($1 ~ /_median$/) { n = $1; sub(/_median$/, "", n); med[++m] = n " " $2 " " $3 " " $4 " " $5 }
                 else if ($1 !~ /_(mean|stddev|cv)$/) single[++s] = $1 " " $2 " " $3 " " $4 " " $5 }
               END { if (m) for (i = 1; i <= m; ++i) print med[i]; else for (i = 1; i <= s; ++i) print single[i] }' "$out")
done

echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)" | tee -a "$summary"
echo "results: $summary, $results/<binary>.json" | tee -a "$summary"
[ "$fails" -eq 0 ] || { echo "bench.sh: $fails binary(ies) failed" >&2; status=1; }
if [ "$misses" -gt 0 ]; then
  echo "bench.sh: $misses median(s) above target (wall time; check the load average above)" >&2
  [ "${STRICT:-0}" = 1 ] && status=1
fi
exit "$status"
