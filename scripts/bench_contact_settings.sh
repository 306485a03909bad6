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
#   listN   collision.lists=N (candidate lists a frame; crossings are counted between
#           consecutive lists, so more lists see more of them)
#   jacobi  collision.solve=jacobi (each segment moved by the mean of what its pairs ask,
#           instead of the preset's sweep of its list)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$1
preset=${2:-paper_fig1_straight}
strands=${3:-10000}
frames=${4:-8}
settings=${SETTINGS:-head it1 it1,jacobi it2 it4 it4,jacobi it8 it16 it1,sub8 it4,sub8 it1,sub16 it4,sub16 it4,m2 it1,list2 it1,list4 it4,list4 it16,list4 it4,sub16,list16 it4,sub16,list16,jacobi}
bin=${CSMHAIR:-$root/build/app/csmhair}
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
presetFile=$root/presets/$preset.json
csv=$out/contact_settings.csv
columns=$root/scripts/contact_columns.py
echo "setting,mode,iterations,margin_mm,lists,solve,$(/usr/bin/python3 "$columns" --header substeps strands particles frames)" \
  >"$csv"
echo "Load before: $(uptime | sed 's/.*load average: //'); $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"
for setting in $settings; do
  mode=strands iterations=1 subs="" margin="" lists=1 solve=sweep
  if [[ $setting == head ]]; then
    mode=head solve=""
  else
    IFS=, read -ra parts <<<"$setting"
    for part in "${parts[@]}"; do
      case $part in
        it*) iterations=${part#it} ;;
        sub*) subs=${part#sub} ;;
        m*) margin=${part#m} ;;
        list*) lists=${part#list} ;;
        jacobi) solve=jacobi ;;
        *)
          echo "bench_contact_settings.sh: '$part' of '$setting' is none of itN, subN, mX, listN, jacobi" >&2
          exit 2
          ;;
      esac
    done
  fi
  sets=(--set "collision.mode=$mode" --set "hairstyle.strands=$strands"
    --set "collision.iterations=$iterations" --set "collision.lists=$lists")
  [[ -n $solve ]] && sets+=(--set "collision.solve=$solve")
  [[ -n $subs ]] && sets+=(--set "sim.substeps=$subs")
  [[ -n $margin ]] && sets+=(--set "collision.margin=$(/usr/bin/python3 -c "print($margin / 1000)")")
  if ! "$bin" "$presetFile" --headless --frames "$frames" --no-render --quiet \
    --solver gpu "${sets[@]}" --metrics "$tmp/m.json" >"$tmp/log" 2>&1; then
    echo "bench_contact_settings.sh: $setting failed:" >&2
    cat "$tmp/log" >&2
    exit 1
  fi
  echo "${setting//,/+},$mode,$iterations,${margin:-},$lists,$solve,$(/usr/bin/python3 "$columns" \
    "$tmp/m.json" substeps strands particles frames)" >>"$csv"
  tail -n 1 "$csv"
done
