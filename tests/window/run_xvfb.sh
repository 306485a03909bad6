#!/usr/bin/env bash
# Runs a command with a display: under xvfb-run when it is installed (Debian: xvfb, xauth),
# else on $DISPLAY. -noreset: the server must survive the gap between two windows of one test
# run (a last client closing otherwise resets it, and the next window fails to connect).
# Exit 77 (ctest: skipped) when there is neither.
set -u
if command -v xvfb-run >/dev/null 2>&1; then
  exec xvfb-run -a -s "-screen 0 1600x900x24 -noreset" "$@"
fi
if [ -n "${DISPLAY:-}" ]; then
  exec "$@"
fi
echo "no xvfb-run and no DISPLAY: skipped (apt-get install xvfb xauth)" >&2
exit 77
