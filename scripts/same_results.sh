#!/usr/bin/env bash
# Compares two folders written by scripts/export_results.sh: the exported strands byte for byte
# and every metric but the timings (ms.*), the memory (memory.*) and the file's own name
# (source). Prints one line per run and exits non-zero when any differs.
#   scripts/same_results.sh BEFORE_DIR AFTER_DIR
set -u
a=$1
b=$2
fail=0
for hair in "$a"/*.hair; do
  run=$(basename "$hair" .hair)
  if cmp -s "$hair" "$b/$run.hair"; then bytes=same; else bytes=DIFFERENT; fail=1; fi
  metrics=$(python3 - "$a/$run.json" "$b/$run.json" <<'PY'
import json, sys
def flat(d, p=""):
    if isinstance(d, dict):
        out = {}
        for k, v in d.items():
            out.update(flat(v, f"{p}.{k}" if p else k))
        return out
    return {p: d}
x, y = (flat(json.load(open(f))) for f in sys.argv[1:3])
# Timings and memory (the process's peak varies from run to run) are the machine's, not results.
# The start-up time is a timing too.
skip = lambda k: (k.startswith("ms.") or k.startswith("memory.") or k == "source" or
                  k == "startup_s")
keys = sorted(k for k in set(x) & set(y) if not skip(k))
diff = [k for k in keys if x.get(k) != y.get(k)]
# A figure only one side has (the metrics grew a key) is said, not counted as a difference.
new = sorted(k for k in set(x) ^ set(y) if not skip(k))
print(("same" if not diff else "DIFFERENT: " + ", ".join(diff)) +
      (" (in one side only: " + ", ".join(new) + ")" if new else ""))
PY
)
  case $metrics in same*) ;; *) fail=1 ;; esac
  printf '%-28s hair %-9s metrics %s\n' "$run" "$bytes" "$metrics"
done
exit $fail
