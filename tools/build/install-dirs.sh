#!/bin/sh
# SPDX-License-Identifier: MIT
# Creates the installation directories and appends the ones it had to create
# (parents before children) to MANIFEST, so that `make uninstall` removes only
# directories that the installation created.
#
#   install-dirs.sh MANIFEST DIR...
set -eu
manifest=$1
shift
created=
for d in "$@"; do
    case $d in /*) p= ;; *) p=. ;; esac
    for c in $(printf '%s\n' "$d" | tr '/' ' '); do
        p=$p/$c
        if [ ! -d "$p" ]; then
            mkdir "$p"
            created="$created $p"
        fi
    done
done
for p in $created; do printf '%s\n' "$p"; done >>"$manifest"
