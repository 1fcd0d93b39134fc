#!/bin/sh
# SPDX-License-Identifier: MIT
# Build command wrapper for make's quiet mode (the default; `make V=1` shows
# the full commands instead): prints one short line, `  CC out/src/solver.o`,
# then runs the command. On failure it prints the full command too.
#
#   quiet.sh TAG COMMAND ARGS...    TAG: CC (compile or link) or AR
tag=$1
shift
target=
prev=
compile=0
for a in "$@"; do
    [ "$prev" = "-o" ] && target=$a
    [ "$a" = "-c" ] && compile=1
    prev=$a
done
case $tag in
    AR) target=$3 ;;                 # ar rcs ARCHIVE OBJECTS...
    CC) [ "$compile" -eq 1 ] || tag=LD ;;
esac
printf '  %-3s %s\n' "$tag" "${target:-$*}"
"$@" && exit 0
status=$?
echo "failed command: $*" >&2
exit $status
