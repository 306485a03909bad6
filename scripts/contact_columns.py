#!/usr/bin/python3
"""The CSV columns that scripts/bench_modes.sh and scripts/bench_contact_settings.sh take from a
`csmhair --metrics` file: the run's top-level fields named on the command line, then its cost
and what hair-hair leaves.

usage: contact_columns.py --header [FIELD...]    the column names
       contact_columns.py METRICS.json [FIELD...] the row's columns
"""
import json
import sys

COLUMNS = ["sim_ms", "grid_ms", "contacts_ms", "pairs_2r", "pairs_r", "pairs_r_rest",
           "crossings_per_s", "crossings_close_per_s", "depth_p50", "depth_p99", "depth_max"]


def row(m, fields):
    a, ms = m["accuracy"], m["ms"]
    st = ms["stages"]

    def get(k):
        return f"{a[k]}" if k in a else ""

    # Crossings are counted against the last list: none when the lists did not fit (not
    # measured).
    def crossings(k):
        return "" if a.get("hair_list_overflows", 0) > 0 else get(k)

    return [str(m[f]) for f in fields] + [
        f"{ms['sim_mean']:.2f}", f"{st.get('grid', 0):.2f}", f"{st.get('contacts', 0):.2f}",
        get("hair_contacts"), get("hair_penetrations"), get("hair_penetrations_rest"),
        crossings("hair_crossings_per_s"), crossings("hair_crossings_close_at_rest_per_s"),
        get("hair_depth_p50"), get("hair_depth_p99"), get("hair_depth_max")]


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    fields = sys.argv[2:]
    if sys.argv[1] == "--header":
        print(",".join(fields + COLUMNS))
    else:
        with open(sys.argv[1]) as f:
            print(",".join(row(json.load(f), fields)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
