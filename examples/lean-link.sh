#!/bin/sh
# "Leave out what a scene does not need": a program using only spheres and
# boxes, linked against libagjk.a with --gc-sections (a dynamically linked
# program with the library linked in statically), must contain no polytope,
# hull, adjacency, ellipsoid, cylinder or cone code, and no penetration depth
# (EPA) or warm-start cache code. Prints its text size.
#
#   examples/lean-link.sh [PROGRAM]
# Default: $OUT/examples/spheres_and_boxes (OUT defaults to out), built first
# with make when no program is given.
set -eu
if [ $# -ge 1 ]; then
    bin=$1
else
    top=$(cd "$(dirname "$0")/.." && pwd)
    target=${OUT:-out}/examples/spheres_and_boxes
    # Up to date already under `make check`; built here when run alone.
    make -s -C "$top" OUT="${OUT:-out}" "$target" >/dev/null
    case $target in /*) bin=$target ;; *) bin=$top/$target ;; esac
fi
# Defined symbols only: the Minkowski support refers to the simplest
# built-in shapes' callbacks weakly (src/minkowski.h), and such a reference
# (nm's "w") to a shape the program never creates links none of its code.
unwanted=$(nm --defined-only "$bin" | grep -i -E 'polytope|adjacency|hull|ellipsoid|cylinder|cone_|capsule|segment_support|(^| |_)epa|signed_distance|penetration|_cache' || true)
if [ -n "$unwanted" ]; then
    echo "lean link: unexpected symbols in $bin:" >&2
    echo "$unwanted" >&2
    exit 1
fi
"$bin" >/dev/null
text=$(size -A "$bin" | awk '$1 == ".text" {print $2}')
# Code kept from libagjk.a, from the linker map: sum of the input .text
# sections of its members (a long section name puts the numbers on the next line).
lib_text=$(awk '
    function hex(h,   i, c, v) { v = 0; h = tolower(substr(h, 3))
        for (i = 1; i <= length(h); ++i) { c = index("0123456789abcdef", substr(h, i, 1)) - 1; v = v * 16 + c }
        return v }
    /^Linker script and memory map/ { kept = 1 }   # before it: discarded sections
    !kept { next }
    /^ \.text/ && NF == 1 { name = $1; getline; $0 = " " name " " $0 }
    /^ \.text/ && /libagjk\.a\(/ { s += hex($3) }
    END { print s + 0 }' "$bin.map")
members=$(sed -n '/^Linker script and memory map/,$p' "$bin.map" | grep -o 'libagjk\.a([a-z_]*\.o)' | sort -u | sed 's/.*(\(.*\))/\1/' | tr '\n' ' ')
echo "lean link: spheres+boxes program (libagjk.a linked in): .text $text bytes, of which agjk $lib_text bytes"
echo "lean link: agjk objects linked: $members"
echo "lean link: 1 passed, 0 failed"
