#!/bin/sh
# SPDX-License-Identifier: MIT
# Instructions per support call, agjk against Coal, on identical problems
# (valgrind's callgrind: exact counts, unaffected by a noisy machine).
#
#   make bench-callgrind                        (builds the driver, runs this)
#   sh tools/bench/callgrind.sh DRIVER [PROBLEMS] [OUTDIR]
#
# DRIVER is out/tools/bench/agjk-callgrind-work; PROBLEMS per workload
# (default 40); OUTDIR (default: the driver's directory/callgrind) receives
# the dumps and summary.md. Workloads, plain GJK, tolerance 1e-8, the
# benchmark's generator: ellipsoids and boxes in close proximity (distance
# mode), ellipsoids and boxes distant (Boolean mode, one support call).
#
# How the counts are taken: the driver calls each query through one
# function (measured_agjk / measured_coal); callgrind collects only inside it
# (--collect-atstart=no --toggle-collect) and dumps after each call
# (--dump-after), so every dump is one query, set-up excluded. LD_BIND_NOW=1
# keeps the dynamic linker's lazy binding out of the first query. agjk is the
# normal -O2 -g build (nothing un-inlined); callgrind_split.py charges every
# instruction to the simplex projection, the support path or the rest by its
# source line's file and its function (see there), and splits the rest into
# loop bookkeeping per support call and a fixed cost per query by a least-
# squares fit over the queries. Coal is its PyPI libcoal.so (symbols, no line
# information), split by function name.
set -eu

driver=${1:?usage: callgrind.sh DRIVER [PROBLEMS] [OUTDIR]}
problems=${2:-40}
out=${3:-$(dirname "$driver")/callgrind}
here=$(dirname "$0")
python=${PYTHON:-python3}

command -v valgrind >/dev/null 2>&1 || { echo "callgrind.sh: valgrind not found" >&2; exit 1; }
command -v "$python" >/dev/null 2>&1 || { echo "callgrind.sh: $python not found" >&2; exit 1; }
mkdir -p "$out"
libs="agjk coal"
if ! "$driver" coal ellipsoids-close 1 >/dev/null 2>&1; then
    echo "callgrind.sh: no Coal in this build (tools/fetch-coal.sh, then make); agjk only" >&2
    libs=agjk
fi

summary=$out/summary.md
{
    echo "| workload | library | queries | support calls / query | instructions / query | simplex / call | support path / call | loop / call | fixed / query |"
    echo "|---|---|---|---|---|---|---|---|---|"
} >"$summary"

for w in ellipsoids-close boxes-close hulls-close ellipsoids-overlapping ellipsoids-distant boxes-distant hulls-distant; do
    for lib in $libs; do
        dir=$out/$w-$lib
        rm -rf "$dir"
        mkdir -p "$dir"
        "$driver" "$lib" "$w" "$problems" >"$dir/queries.txt"
        LD_BIND_NOW=1 valgrind --tool=callgrind --collect-atstart=no \
            --toggle-collect="measured_$lib" --dump-after="measured_$lib" \
            --compress-strings=no --compress-pos=no --dump-instr=yes \
            --callgrind-out-file="$dir/callgrind.out.%p" \
            "$driver" "$lib" "$w" "$problems" >"$dir/queries-valgrind.txt" 2>"$dir/valgrind.log"
        cmp -s "$dir/queries.txt" "$dir/queries-valgrind.txt" ||
            { echo "callgrind.sh: $w $lib answered differently under valgrind" >&2; exit 1; }
        # Dumps in query order: by the number after the file name's last dot
        # (the folder's own name may hold dots too).
        # shellcheck disable=SC2046
        "$python" "$here/callgrind_split.py" "$lib" "$dir/queries.txt" --binary "$driver" \
            $(ls "$dir"/callgrind.out.*.* | awk -F. '{print $NF "\t" $0}' | sort -n | cut -f2-) \
            >"$dir/split.json"
        "$python" - "$w" "$dir/split.json" >>"$summary" <<'PY'
import json, sys
w, path = sys.argv[1], sys.argv[2]
s = json.load(open(path))
f = lambda v: "-" if v is None else "%.0f" % v
print("| %s | %s | %d | %.2f | %s | %s | %s | %s | %s |" % (
    w, s["lib"], s["queries"], s["support_calls_per_query"], f(s["total_per_query"]),
    f(s["simplex_per_support_call"]), f(s["support_path_per_support_call"]),
    f(s["loop_per_support_call"]), f(s["fixed_per_query"])))
PY
    done
done
{
    echo
    echo "Instructions (callgrind Ir), plain GJK, tolerance 1e-8, $problems problems per workload"
    echo "(close: distance mode; distant: Boolean mode). simplex and support path: all their"
    echo "instructions / all support calls; loop / call and fixed / query: least-squares fit"
    echo "of the remaining instructions per query against its support calls (\"-\": the"
    echo "queries made (nearly) the same number of calls, so all of it is listed as fixed)."
} >>"$summary"
cat "$summary"
echo "callgrind.sh: dumps and $summary" >&2
