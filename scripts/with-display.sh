#!/usr/bin/env bash
# Runs a command with an X display: as it is when DISPLAY is set, otherwise under a private
# Xvfb (Mesa llvmpipe gives OpenGL 4.5 core). CTest runs every test that needs a window through
# this (e2d_add_tests ... NEEDS_DISPLAY), so a plain `ctest` works on a machine with no display.
# Key auto-repeat is slowed (-ardelay/-arinterval) so a held key sent by xdotool gives no
# repeat events unless a test asks for them.
#
# The server picks its own free display number (-displayfd), so tests started at the same
# moment (ctest -j) never race for one, as `xvfb-run -a` does. It takes only local connections
# from this user (-nolisten tcp, no other hosts allowed).
set -euo pipefail
export MESA_SHADER_CACHE_DISABLE=true
if [ -n "${DISPLAY:-}" ]; then
  exec "$@"
fi
if ! command -v Xvfb >/dev/null; then
  echo "with-display.sh: no DISPLAY and no Xvfb (Debian package xvfb)" >&2
  exit 1
fi
dir=$(mktemp -d "${TMPDIR:-/tmp}/e2d-display.XXXXXX")
Xvfb -displayfd 3 -screen 0 1280x720x24 -nolisten tcp -ardelay 5000 -arinterval 1000 \
  3>"$dir/display" >"$dir/server.log" 2>&1 &
server=$!
stop() {
  kill "$server" 2>/dev/null || true
  wait "$server" 2>/dev/null || true
  rm -rf "$dir"
}
trap stop EXIT
# The server writes its display number once it accepts connections.
for _ in $(seq 200); do
  [ -s "$dir/display" ] && break
  if ! kill -0 "$server" 2>/dev/null; then
    echo "with-display.sh: Xvfb did not start:" >&2
    cat "$dir/server.log" >&2
    exit 1
  fi
  sleep 0.05
done
if [ ! -s "$dir/display" ]; then
  echo "with-display.sh: Xvfb gave no display number within 10 s" >&2
  exit 1
fi
DISPLAY=":$(tr -d '[:space:]' <"$dir/display")" "$@"
