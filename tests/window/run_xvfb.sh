#!/usr/bin/env bash
# Runs a command with a display: under xvfb-run when it is installed (Debian: xvfb, xauth),
# else on $DISPLAY. -noreset: the server must survive the gap between two windows of one test
# run (a last client closing otherwise resets it, and the next window fails to connect).
# Fails when there is neither: the window is part of what the tests check.
set -u
if command -v xvfb-run >/dev/null 2>&1; then
  exec xvfb-run -a -s "-screen 0 1600x900x24 -noreset" "$@"
fi
if [ -n "${DISPLAY:-}" ]; then
  exec "$@"
fi
echo "FAIL: no xvfb-run and no DISPLAY: cannot test the window (apt-get install xvfb xauth)" >&2
exit 1
