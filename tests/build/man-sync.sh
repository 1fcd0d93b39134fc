#!/bin/sh
# SPDX-License-Identifier: MIT
# Keeps the agjk(1) man page in step with the tool:
#  - the options named by `agjk --help` and every `agjk COMMAND --help`,
#    together, are exactly the options the man page names;
#  - each "agjk COMMAND" subsection of the man page's COMMANDS names exactly
#    the options of `agjk COMMAND --help`;
#  - every key of the JSON and text outputs below, and every exit status of
#    `agjk --help`, appears in the man page;
#  - agjk(3) describes every public header (include/agjk/*.h), and both pages
#    carry the version of `agjk --version`;
#  - each sample session of README.md (a ```sh block holding one
#    `out/tools/cli/agjk ...` command, followed by a ``` block) shows what
#    that command prints, to the last digit.
# A new option or output key fails this test until man/agjk.1 documents it
# (a new JSON key: add the command line that prints it to QUERIES below).
#
#   tests/build/man-sync.sh [AGJK_BINARY [SOURCE_DIR]]
# Defaults: $OUT/tools/cli/agjk (OUT defaults to out) and this script's tree.
set -u
SRC=${2:-$(cd "$(dirname "$0")/../.." && pwd)}
case ${OUT:-out} in
    /*) AGJK=${1:-$OUT/tools/cli/agjk} ;;
    *) AGJK=${1:-$SRC/${OUT:-out}/tools/cli/agjk} ;;
esac
MAN=$SRC/man/agjk.1
COMMANDS="distance collide info hull"
C=$SRC/examples/meshes/cube.off
S=$SRC/examples/meshes/sphere.obj
# Command lines whose output keys must all be documented (one per line).
QUERIES="distance $C $S --pose-b 2 0 0 1 0 0 0
distance $C $C --pose-b 0.5 0 0 1 0 0 0
collide $C $S --pose-b 2 0 0 1 0 0 0
collide $C $C --pose-b 0.5 0 0 1 0 0 0
info $S"

[ -x "$AGJK" ] || { echo "man-sync: no agjk binary at $AGJK"; exit 1; }
[ -f "$MAN" ] || { echo "man-sync: no man page at $MAN"; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/agjk-man.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT INT TERM
pass=0
fail=0
bad() { fail=$((fail + 1)); echo "FAIL: $*"; }

# The man page as plain text: roff escapes and requests stripped.
sed -e 's/\\-/-/g' -e 's/\\f[BIRP]//g' -e 's/\\(em/--/g' -e '/^\.\\"/d' \
    -e 's/^\.[A-Za-z]* *//' "$MAN" >"$tmp/man.txt"

# options FILE: the options a text names: --long anywhere, -x at the start of
# a line, after '[' or after ', ' (so "q and -q" names no option).
options() {
    grep -oE '(^|[^A-Za-z0-9-])--[a-z][a-z-]*[a-z]|(^ *|\[|, )-[a-z]\b' "$1" |
        sed 's/^[^-]*//' | sort -u
}

"$AGJK" --help >"$tmp/help.main" 2>&1 || bad "agjk --help failed"
for c in $COMMANDS; do
    "$AGJK" "$c" --help >"$tmp/help.$c" 2>&1 || bad "agjk $c --help failed"
done
cat "$tmp"/help.* >"$tmp/help.all"
options "$tmp/help.all" >"$tmp/opts.help"
options "$tmp/man.txt" >"$tmp/opts.man"
missing=$(comm -23 "$tmp/opts.help" "$tmp/opts.man" | tr '\n' ' ')
extra=$(comm -13 "$tmp/opts.help" "$tmp/opts.man" | tr '\n' ' ')
[ -z "$missing" ] && pass=$((pass + 1)) || bad "options in agjk --help but not in agjk(1): $missing"
[ -z "$extra" ] && pass=$((pass + 1)) || bad "options in agjk(1) but in no agjk --help: $extra"

# Per command: the man page's subsection ".SS "agjk COMMAND"" up to the next
# .SS or .SH.
for c in $COMMANDS; do
    sed -e 's/\\-/-/g' -e 's/\\f[BIRP]//g' "$MAN" |
        awk -v want="agjk $c" '
            /^\.S[SH]/ { on = ($0 ~ "^\\.SS \"" want "\"$"); next }
            on { sub(/^\.[A-Za-z]* */, ""); print }' >"$tmp/man.$c"
    [ -s "$tmp/man.$c" ] || { bad "agjk(1) has no subsection \"agjk $c\""; continue; }
    options "$tmp/help.$c" >"$tmp/o.help"
    options "$tmp/man.$c" >"$tmp/o.man"
    if cmp -s "$tmp/o.help" "$tmp/o.man"; then
        pass=$((pass + 1))
    else
        bad "agjk $c: --help names [$(tr '\n' ' ' <"$tmp/o.help")], agjk(1) names [$(tr '\n' ' ' <"$tmp/o.man")]"
    fi
done

# Output keys: JSON keys and the keys of `key: value` lines.
echo "$QUERIES" | while read -r line; do
    # shellcheck disable=SC2086
    "$AGJK" $line --json >"$tmp/json" 2>/dev/null
    "$AGJK" $line >"$tmp/text" 2>/dev/null
    python3 -c 'import json, sys; print("\n".join(json.load(open(sys.argv[1]))))' "$tmp/json" ||
        echo "(no JSON from agjk $line --json)"
    sed -n 's/^\([a-z_]*\): .*/\1/p' "$tmp/text"
done | sort -u >"$tmp/keys"
for k in $(cat "$tmp/keys"); do
    if grep -qw -- "$k" "$tmp/man.txt"; then pass=$((pass + 1)); else bad "output key '$k' is not in agjk(1)"; fi
done
[ -s "$tmp/keys" ] || bad "no output keys found"

# Exit statuses: the lines "    N  ..." of agjk --help's EXIT STATUS.
for s in $(sed -n '/^EXIT STATUS/,/^$/s/^ *\([0-9]\)  .*/\1/p' "$tmp/help.main"); do
    if sed -n '/^EXIT STATUS/,/^EXAMPLES/p' "$tmp/man.txt" | grep -qx "$s"; then
        pass=$((pass + 1))
    else
        bad "exit status $s is not in agjk(1)'s EXIT STATUS"
    fi
done

# Both pages carry the version of the tool (.TH ... "agjk X.Y.Z").
version=$("$AGJK" --version | sed -n 's/^agjk \([0-9][0-9.]*\) .*/\1/p')
for page in "$MAN" "$SRC/man/agjk.3"; do
    if grep -q "^\.TH .*\"agjk $version\"" "$page"; then pass=$((pass + 1))
    else bad "$(basename "$page"): .TH does not say agjk $version (agjk --version)"; fi
done

# agjk(3) points to every public header.
for h in "$SRC"/include/agjk/*.h; do
    h=agjk/$(basename "$h")
    if grep -q "^\.I $h\$" "$SRC/man/agjk.3"; then pass=$((pass + 1)); else bad "agjk(3) does not describe <$h>"; fi
done

# README.md's sample sessions, run from the source tree (their paths are
# relative to it).
awk -v out="$tmp/readme" '
    /^```sh$/ { getline cmd; getline close_sh; getline open_out
        if (cmd ~ /^out\/tools\/cli\/agjk / && close_sh == "```" && open_out == "```") {
            n++; print substr(cmd, 20) > (out "." n ".cmd")
            while ((getline line) > 0 && line != "```") print line > (out "." n ".want")
        } }
    END { print n + 0 > (out ".count") }' "$SRC/README.md"
samples=$(cat "$tmp/readme.count")
# (The binary by an absolute path: meson passes one relative to its build
# directory, and the samples run from the source tree.)
agjk_abs=$(cd "$(dirname "$AGJK")" && pwd)/$(basename "$AGJK")
[ "$samples" -gt 0 ] || bad "README.md: no sample session of out/tools/cli/agjk found"
i=1
while [ "$i" -le "$samples" ]; do
    args=$(cat "$tmp/readme.$i.cmd")
    # shellcheck disable=SC2086
    (cd "$SRC" && "$agjk_abs" $args) >"$tmp/readme.$i.got" 2>/dev/null
    touch "$tmp/readme.$i.want"
    if cmp -s "$tmp/readme.$i.got" "$tmp/readme.$i.want"; then
        pass=$((pass + 1))
    else
        bad "README.md: 'agjk $args' prints otherwise than its sample"
        diff "$tmp/readme.$i.want" "$tmp/readme.$i.got" | sed 's/^/    /' | head -20
    fi
    i=$((i + 1))
done

echo "man page sync: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
