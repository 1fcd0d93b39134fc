#!/bin/sh
# make globs src/*.c; meson lists the files in src/meson.build. They must agree,
# so that both build systems build the same library.
set -eu
cd "$(dirname "$0")/../.."
from_make=$(ls src/*.c | sed 's|^src/||' | sort)
from_meson=$(sed -n "s/^ *'\([a-z_0-9]*\.c\)',*$/\1/p" src/meson.build | sort)
if [ "$from_make" != "$from_meson" ]; then
    echo "src/meson.build and src/*.c differ:" >&2
    echo "make:  " $from_make >&2
    echo "meson: " $from_meson >&2
    exit 1
fi
echo "same sources: $(echo "$from_make" | wc -l) files; 1 passed, 0 failed"
