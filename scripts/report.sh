#!/usr/bin/env bash
# The main job, from a fresh Debian 12 machine: build e2d optimised and produce its report.
# The report (in report/, or $1) is the physics validation of e2d against Box2D 2.4
# (report/validation/report.html), the headless smoke run of core and the collision benchmark.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
root="$PWD"
"$root/scripts/install-deps.sh"
export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1
out="${1:-$root/report}"
mkdir -p "$out"

cmake --preset release >/dev/null
cmake --build --preset release

echo "=== core smoke run (headless game loop)"
"$root/build/release/apps/core_smoke/e2d-smoke" | tee "$out/smoke.txt"

echo "=== collision benchmark: e2d SAT, e2d GJK/EPA and Box2D 2.4 in one binary"
"$root/build/release/bench/e2d_bench_collision" --benchmark_min_time=0.2 \
  --benchmark_out="$out/bench_collision.json" --benchmark_out_format=json \
  --e2d_table="$out/bench_collision.md"

echo "=== physics validation: e2d and Box2D 2.4 side by side (all scenarios, full sweep)"
# Exit status 1 means some check failed: the report is still written and says which.
set +e
"$root/build/release/validation/e2d-validate" --all --out "$out/validation"
validation_status=$?
set -e
if [ "$validation_status" -ge 2 ]; then
  exit "$validation_status"
fi
echo
echo "Report written to $out/: validation/report.html (open it), validation/report.json,"
echo "bench_collision.md, bench_collision.json, smoke.txt"
