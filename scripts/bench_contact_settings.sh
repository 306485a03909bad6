#!/usr/bin/env bash
# What holding hair apart costs in `strands` mode (issue "hair-hair that holds strands apart"):
# the contact settings against ms per frame, penetration depth and crossings, one preset, one
# strand count, one run; writes OUT/contact_settings.csv for scripts/charts.py (chart
# "contact_settings") and prints it as a table.
#   scripts/bench_contact_settings.sh OUT [PRESET] [STRANDS] [FRAMES]
# Defaults: paper_fig1_straight, 10000 strands, 8 frames. SETTINGS (default below) lists the
# runs; each is `head` (head collisions only, the cost to compare with) or comma-separated
# changes to the preset's `strands` run (joined by + in the CSV):
#   itN     collision.iterations=N (contact Jacobi iterations a substep)
#   subN    sim.substeps=N
#   mX      collision.margin=X millimetres
#   listN   the candidates listed N times a frame: the run steps N times as many frames of
#           dt/N with substeps/N each (the same substeps a second), and its times are per
#           frame of the preset (N of its frames). Its crossings are counted between lists
#           1/N frame apart, and its depths over N times as many lists.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$1
preset=${2:-paper_fig1_straight}
strands=${3:-10000}
frames=${4:-8}
settings=${SETTINGS:-head it1 it2 it4 it8 it16 it1,sub8 it4,sub8 it1,sub16 it4,sub16 it4,m2 it1,list4 it4,list4 it16,list4}
bin=${CSMHAIR:-$root/build/app/csmhair}
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
presetFile=$root/presets/$preset.json
# The preset's own step, which the list runs divide.
read -r dt substeps < <(/usr/bin/python3 - "$presetFile" <<'PY'
import json, sys
sim = json.load(open(sys.argv[1])).get("sim", {})
print(sim.get("dt", 1.0 / 60.0), sim.get("substeps", 4))
PY
)
csv=$out/contact_settings.csv
echo "setting,mode,iterations,substeps,margin_mm,lists,strands,particles,frames,sim_ms,grid_ms,contacts_ms,pairs_2r,pairs_r,pairs_r_rest,crossings_per_s,crossings_close_per_s,depth_p50,depth_p99,depth_max" >"$csv"
echo "Load before: $(uptime | sed 's/.*load average: //'); $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"
for setting in $settings; do
  mode=strands iterations=1 subs=$substeps margin="" lists=1
  if [[ $setting == head ]]; then
    mode=head
  else
    IFS=, read -ra parts <<<"$setting"
    for part in "${parts[@]}"; do
      case $part in
        it*) iterations=${part#it} ;;
        sub*) subs=${part#sub} ;;
        m*) margin=${part#m} ;;
        list*) lists=${part#list} ;;
        *)
          echo "bench_contact_settings.sh: '$part' of '$setting' is none of itN, subN, mX, listN" >&2
          exit 2
          ;;
      esac
    done
  fi
  if ((subs % lists != 0)); then
    echo "bench_contact_settings.sh: $setting: $subs substeps do not split into $lists lists" >&2
    exit 2
  fi
  sets=(--set "collision.mode=$mode" --set "hairstyle.strands=$strands"
    --set "collision.iterations=$iterations" --set "sim.substeps=$((subs / lists))")
  [[ -n $margin ]] && sets+=(--set "collision.margin=$(/usr/bin/python3 -c "print($margin / 1000)")")
  ((lists > 1)) && sets+=(--set "sim.dt=$(/usr/bin/python3 -c "print($dt / $lists)")")
  if ! "$bin" "$presetFile" --headless --frames $((frames * lists)) --no-render --quiet \
    --solver gpu "${sets[@]}" --metrics "$tmp/m.json" >"$tmp/log" 2>&1; then
    echo "bench_contact_settings.sh: $setting failed:" >&2
    cat "$tmp/log" >&2
    exit 1
  fi
  /usr/bin/python3 - "$tmp/m.json" "${setting//,/+}" "$mode" "$iterations" "$subs" "${margin:-}" \
    "$lists" "$frames" >>"$csv" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
setting, mode, iterations, subs, margin, lists, frames = sys.argv[2:9]
a, ms = m["accuracy"], m["ms"]
st = ms["stages"]
n = int(lists)
if not margin:
    margin = ""
def get(k):
    return f"{a[k]}" if k in a else ""
# Crossings are counted against the last list: none when the lists did not fit (not measured).
def crossings(k):
    return "" if a.get("hair_list_overflows", 0) > 0 else get(k)
# Times per frame of the preset: n of the run's frames.
print(",".join([setting, mode, iterations, subs, margin, lists, str(m["strands"]),
                str(m["particles"]), frames, f"{ms['sim_mean'] * n:.2f}",
                f"{st.get('grid', 0) * n:.2f}", f"{st.get('contacts', 0) * n:.2f}",
                get("hair_contacts"), get("hair_penetrations"), get("hair_penetrations_rest"),
                crossings("hair_crossings_per_s"), crossings("hair_crossings_close_at_rest_per_s"),
                get("hair_depth_p50"), get("hair_depth_p99"), get("hair_depth_max")]))
PY
  tail -n 1 "$csv"
done
