#!/usr/bin/env bash
# No file includes a header of ours that it does not use: include-what-you-use (Debian's iwyu)
# over every source of the program and the benchmarks (and the header named after each), through
# the build's compile_commands.json. Only its "should remove" lines for our own headers count
# (what it would add, and its views on system headers, are left to taste). Exits 1 naming each.
#   scripts/unused_includes.sh [--write] [BUILD_DIR]   (default build; needs iwyu installed)
# A file whose verdict cannot have changed is not parsed again: scripts/unused_includes.ok holds,
# for each source found clean, a hash of it and of every file of ours it includes (through any
# depth) and of iwyu's version. The check parses the sources with no such line (a parse costs
# seconds, the whole tree minutes); --write records the ones it finds clean, for a commit.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
write=0
if [ "${1:-}" = --write ]; then
  write=1
  shift
fi
build=${1:-$here/build}
command -v iwyu_tool >/dev/null || { echo "iwyu_tool not found: apt-get install iwyu" >&2; exit 2; }
[ -f "$build/compile_commands.json" ] || { echo "no $build/compile_commands.json" >&2; exit 2; }
cd "$here"
manifest=scripts/unused_includes.ok
sources=$(git ls-files 'sim/*.cpp' 'render/*.cpp' 'app/*.cpp' 'gl/*.cpp' 'tools/*.cpp')
# "hash file" for each source: its content and every file of ours it reaches through #include.
keys=$(python3 - "$(iwyu --version 2>&1 | head -1)" $sources <<'PY'
import hashlib, os, re, sys
version, files = sys.argv[1], sys.argv[2:]
include = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.M)
reached = {}
def deps(path):
    if path in reached: return reached[path]
    reached[path] = set()
    found = {path}
    text = open(path, encoding="utf-8", errors="replace").read()
    for name in include.findall(text):
        for candidate in (name, os.path.join(os.path.dirname(path), name)):
            if os.path.isfile(candidate):
                found |= deps(os.path.normpath(candidate))
                break
    reached[path] = found
    return found
for f in files:
    h = hashlib.sha256(version.encode())
    for d in sorted(deps(f)):
        h.update(d.encode() + b"\0" + open(d, "rb").read() + b"\0")
    print(h.hexdigest(), f)
PY
)
known=$( [ -f "$manifest" ] && cat "$manifest" || true)
stale=$(printf '%s\n' "$keys" | grep -vxF -f <(printf '%s\n' "$known") | awk '{print $2}' || true)
total=$(printf '%s\n' "$keys" | wc -l)
count=$(printf '%s' "$stale" | grep -c . || true)
unused=""
checked=0
if [ "$count" -gt 0 ]; then
  out=$(iwyu_tool -j "$(nproc)" -p "$build" $stale -- -Xiwyu --no_fwd_decls 2>&1 || true)
  unused=$(printf '%s\n' "$out" | awk '
    / should remove these lines:$/ { file = $1; removing = 1; next }
    / should add these lines:$/ || /^The full include-list/ || /^---$/ { removing = 0 }
    removing && /^- #include "(sim|render|app|gl|tools|shaders|tests)\// { print file ": " substr($0, 3) }')
  checked=$(printf '%s\n' "$out" | grep -cE 'has correct #includes|should remove these lines|should add these lines' || true)
fi
if [ -n "$unused" ]; then
  echo "FAIL: includes of ours that the file does not use:"
  echo "$unused"
  exit 1
fi
if [ "$write" = 1 ]; then
  printf '%s\n' "$keys" | sort -k2 > "$manifest"
  echo "wrote $manifest: $total sources clean"
fi
echo "ok: no unused include of ours ($count of $total sources parsed, $checked files checked; the rest unchanged since $manifest)"
