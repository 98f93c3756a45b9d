#!/usr/bin/env bash
# The main job, from a fresh Debian 12 machine: build e2d optimised and produce its report.
# The report (in report/, or $1) is the physics validation of e2d against Box2D 2.4
# (report/validation/report.html), the headless smoke run of core, the collision benchmark, the
# solver benchmark (whole steps against Box2D 2.4) and the sprite-batching benchmark (whole
# frames against SFML 2.5 and SDL2's renderer, headless: Xvfb and Mesa llvmpipe).
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
"$root/build/release/apps/tools/core_smoke/e2d-smoke" | tee "$out/smoke.txt"

echo "=== collision benchmark: e2d SAT, e2d GJK/EPA and Box2D 2.4 in one binary"
"$root/build/release/bench/e2d_bench_collision" --benchmark_min_time=0.2 \
  --benchmark_out="$out/bench_collision.json" --benchmark_out_format=json \
  --e2d_table="$out/bench_collision.md"

echo "=== solver benchmark: whole steps, e2d (soft step, 4 sub-steps) and Box2D 2.4 (8/3), sleeping off"
# Checks the large pyramid after 10 s, then settles each scene for 2 s and times steps; exit
# status 1 when e2d's pyramid top drifted >= 0.1 m or sagged >= 0.75 m (the table is written).
"$root/build/release/bench/e2d_bench_solver" --benchmark_min_time=0.5 \
  --benchmark_out="$out/bench_solver.json" --benchmark_out_format=json \
  --e2d_table="$out/bench_solver.md" || echo "e2d_bench_solver: exit status $? (see above)"

echo "=== sprite batching benchmark: whole frames of e2d, SFML 2.5 and SDL2 in one binary (Xvfb, llvmpipe)"
# Each engine's best path and its one-call-per-sprite path, two scenes; every case's last frame
# is written to batching_frames/ (the engines must cover the same pixels, or the exit status
# is 1). The naive and OpenGL 3.3 variants are left to the full run (bench/README.md).
"$root/scripts/with-display.sh" "$root/build/release/bench/e2d_bench_batching" \
  --benchmark_filter='^frame/.*/(e2d|sfml_vertexarray|sfml_sprite|sdl_geometry|sdl_copy)/' \
  --benchmark_min_time=0.05 --e2d_warmup=1 --e2d_shots="$out/batching_frames" \
  --benchmark_out="$out/bench_batching.json" --benchmark_out_format=json \
  --e2d_table="$out/bench_batching.md" || echo "e2d_bench_batching: exit status $? (see above)"

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
echo "bench_collision.md, bench_collision.json, bench_solver.md, bench_solver.json,"
echo "bench_batching.md, bench_batching.json, batching_frames/*.png, smoke.txt"
