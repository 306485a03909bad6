#!/usr/bin/env bash
# scripts/bench_contact_settings.sh end to end on a small Fig. 1: a row per setting with the
# settings it names applied (iterations, substeps, lists a frame), the same measures as the
# run it stands for, its chart drawn; a setting it does not know, or a value csmhair refuses,
# stop it with a message naming them.
set -eu
bin=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
CSMHAIR=$bin SETTINGS="head it2 it1,sub8 it1,list2 it2,jacobi" \
  bash "$src/scripts/bench_contact_settings.sh" "$tmp/out" paper_fig1_straight 300 2 >"$tmp/log"
cat "$tmp/log"
# The run `it1,list2` stands for.
"$bin" "$src/presets/paper_fig1_straight.json" --headless --frames 2 --no-render --quiet \
  --solver gpu --set collision.mode=strands --set hairstyle.strands=300 \
  --set collision.iterations=1 --set collision.lists=2 --metrics "$tmp/list2.json"
python3 - "$tmp/out/contact_settings.csv" "$tmp/list2.json" <<'PY'
import csv, json, sys
rows = {r["setting"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert list(rows) == ["head", "it2", "it1+sub8", "it1+list2", "it2+jacobi"], list(rows)
head, it2, sub8, list2, jacobi = (rows[k] for k in rows)
assert head["mode"] == "head" and it2["mode"] == "strands", rows
assert (it2["iterations"], it2["substeps"], it2["lists"]) == ("2", "4", "1"), it2
assert (sub8["iterations"], sub8["substeps"]) == ("1", "8"), sub8
assert (list2["iterations"], list2["substeps"], list2["lists"]) == ("1", "4", "2"), list2
assert (it2["solve"], jacobi["solve"], jacobi["iterations"]) == ("sweep", "jacobi", "2"), rows
for r in rows.values():
    assert r["strands"] == "300" and float(r["sim_ms"]) > 0, r
assert float(it2["grid_ms"]) > 0 and float(it2["contacts_ms"]) > 0, it2
# Head only has no strand contacts: no grid, no contact solve.
assert float(head["grid_ms"]) == 0 and float(head["contacts_ms"]) == 0, head
# The list run's measures are those of the run it stands for.
m = json.load(open(sys.argv[2]))
a = m["accuracy"]
assert int(list2["pairs_r"]) == a["hair_penetrations"], (list2, a["hair_penetrations"])
assert abs(float(list2["depth_p99"]) - a["hair_depth_p99"]) < 1e-9, (list2, a)
assert float(list2["crossings_per_s"]) == a["hair_crossings_per_s"], (list2, a)
# Different settings, different hair: iterations and substeps reach the runs.
assert (it2["pairs_2r"], it2["depth_p50"]) != (sub8["pairs_2r"], sub8["depth_p50"]), rows
assert (it2["pairs_2r"], it2["depth_p50"]) != (jacobi["pairs_2r"], jacobi["depth_p50"]), rows
print("rows ok")
PY
/usr/bin/python3 "$src/scripts/charts.py" "$tmp/out" contact_settings
test -s "$tmp/out/contact_settings.png" && test -s "$tmp/out/contact_settings.svg"
# Bad settings: named, and a non-zero exit before any run.
check_bad() {
  if CSMHAIR=$bin SETTINGS="$1" bash "$src/scripts/bench_contact_settings.sh" "$tmp/bad" \
    paper_fig1_straight 300 1 >"$tmp/bad.log" 2>&1; then
    echo "bench_contact_settings.sh took '$1'" >&2
    exit 1
  fi
  cat "$tmp/bad.log"
  grep -qF "$2" "$tmp/bad.log"
  if [ "$(wc -l <"$tmp/bad/contact_settings.csv")" != 1 ]; then
    echo "bench_contact_settings.sh ran '$1'" >&2
    exit 1
  fi
}
check_bad "it2,x3" "'x3' of 'it2,x3' is none of itN, subN, mX, listN, jacobi"
check_bad "it1,list0" "value 0 is out of range [1, 16]"
echo "bench_contact_settings ok"
