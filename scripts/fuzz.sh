#!/bin/sh
# Fuzzes the input decoders for a bounded time: the scenario parser, the
# tracker CSV reader and the tracker's UDP datagram decoder (fuzz/*.cpp), with
# libFuzzer and address/undefined-behaviour sanitizers. Seeds: the shipped
# scenarios, the CLI test inputs and fuzz/seeds/. Findings (crash-*, leak-*,
# timeout-*) are written to build-fuzz/findings/<target>/ and fail the script.
#
# Usage: scripts/fuzz.sh [RUNS] [SECONDS]
#   RUNS     executions per target (default 100000)
#   SECONDS  time cap per target (default 600)
# Installs clang and its libFuzzer runtime from Debian when they are missing
# (the normal build does not need them).
set -eu
cd "$(dirname "$0")/.."
RUNS=${1:-100000}
SECONDS_CAP=${2:-600}
BUILD=build-fuzz

if ! command -v clang++ >/dev/null 2>&1 || ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1; then
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO=sudo
  $SUDO apt-get update
  $SUDO apt-get install -y clang libclang-rt-14-dev
fi

CC=clang CXX=clang++ cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHANDOVER_FUZZ=ON \
  -DHANDOVER_BUILD_TESTS=OFF -DHANDOVER_BUILD_BENCH=OFF >/dev/null
cmake --build "$BUILD" -j"${JOBS:-2}" --target fuzz_scenario fuzz_pose_csv fuzz_pose_datagram

seed() {  # target, then seed files
  t=$1; shift
  mkdir -p "$BUILD/corpus/$t" "$BUILD/findings/$t"
  for f in "$@"; do [ -f "$f" ] && cp "$f" "$BUILD/corpus/$t/"; done
}
seed fuzz_scenario scenes/scenarios/*.yaml scenes/scenarios/paper/*.yaml tests/app/cli/data/*.yaml
seed fuzz_pose_csv fuzz/seeds/pose_csv/*
seed fuzz_pose_datagram fuzz/seeds/pose_datagram/*

status=0
for t in fuzz_scenario fuzz_pose_csv fuzz_pose_datagram; do
  echo "== $t: $RUNS runs (at most $SECONDS_CAP s)"
  if ! "$BUILD/fuzz/$t" "$BUILD/corpus/$t" -runs="$RUNS" -max_total_time="$SECONDS_CAP" -max_len=4096 \
      -timeout=10 -rss_limit_mb=2048 -artifact_prefix="$BUILD/findings/$t/" -print_final_stats=1 \
      2>"$BUILD/findings/$t.log"; then
    status=1
    echo "$t: FINDING (see $BUILD/findings/$t/ and $BUILD/findings/$t.log)"
  fi
  grep -E "stat::number_of_executed_units|Done [0-9]+ runs" "$BUILD/findings/$t.log" || true
done
exit $status
