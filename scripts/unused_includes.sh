#!/usr/bin/env bash
# No file includes a header of ours that it does not use: include-what-you-use (Debian's iwyu)
# over every source of the program and the benchmarks (and the header named after each), through
# the build's compile_commands.json. Only its "should remove" lines for our own headers count
# (what it would add, and its views on system headers, are left to taste). Exits 1 naming each.
#   scripts/unused_includes.sh [BUILD_DIR]   (default build; needs iwyu installed)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
command -v iwyu_tool >/dev/null || { echo "iwyu_tool not found: apt-get install iwyu" >&2; exit 2; }
[ -f "$build/compile_commands.json" ] || { echo "no $build/compile_commands.json" >&2; exit 2; }
cd "$here"
sources=$(git ls-files 'sim/*.cpp' 'render/*.cpp' 'app/*.cpp' 'gl/*.cpp' 'tools/*.cpp')
out=$(iwyu_tool -j "$(nproc)" -p "$build" $sources -- -Xiwyu --no_fwd_decls 2>&1 || true)
unused=$(printf '%s\n' "$out" | awk '
  / should remove these lines:$/ { file = $1; removing = 1; next }
  / should add these lines:$/ || /^The full include-list/ || /^---$/ { removing = 0 }
  removing && /^- #include "(sim|render|app|gl|tools|shaders|tests)\// { print file ": " substr($0, 3) }')
checked=$(printf '%s\n' "$out" | grep -cE 'has correct #includes|should remove these lines|should add these lines' || true)
if [ -n "$unused" ]; then
  echo "FAIL: includes of ours that the file does not use:"
  echo "$unused"
  exit 1
fi
echo "ok: no unused include of ours ($checked files checked)"
