#!/usr/bin/env bash
# Runs a command with an X display: as it is when DISPLAY is set, otherwise under a private
# Xvfb (Mesa llvmpipe gives OpenGL 4.5 core). CTest runs every test that needs a window through
# this (e2d_add_tests ... NEEDS_DISPLAY), so a plain `ctest` works on a machine with no display.
# Key auto-repeat is slowed (-ardelay/-arinterval) so a held key sent by xdotool gives no
# repeat events unless a test asks for them.
set -euo pipefail
export MESA_SHADER_CACHE_DISABLE=true
if [ -n "${DISPLAY:-}" ]; then
  exec "$@"
fi
if ! command -v xvfb-run >/dev/null; then
  echo "with-display.sh: no DISPLAY and no xvfb-run (Debian package xvfb)" >&2
  exit 1
fi
exec xvfb-run -a -s "-screen 0 1280x720x24 -nolisten tcp -ardelay 5000 -arinterval 1000" "$@"
