#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs the test programs of `make check`: one line per program (PASS, FAIL or
# SKIP, with the program's own last line), then `test programs: N passed,
# N failed`. Each program's full output goes to LOGDIR/NAME.log; the log of a
# failed program is printed. With V=1 every output is shown as it runs.
#
#   run-checks.sh LOGDIR PROGRAM...
#
# A program passes when it exits 0 and its log holds no sanitizer report (a
# test that passes with an AddressSanitizer, UndefinedBehaviorSanitizer,
# LeakSanitizer or ThreadSanitizer report fails here: crashes that a test
# provokes on purpose are kept from reporting by the test itself). Exit
# status 77 means skipped (a missing optional tool), as in automake and meson.
set -u
logdir=$1
shift
mkdir -p "$logdir"
sanitizer='^==[0-9]+==ERROR: [A-Za-z]+Sanitizer|^WARNING: ThreadSanitizer|^SUMMARY: [A-Za-z]+Sanitizer|runtime error: '
pass=0
fail=0
skip=0
failed=
for t in "$@"; do
    name=${t#"${OUT:-out}"/}
    log=$logdir/$(printf '%s' "$name" | tr '/' '_').log
    case $t in /*) path=$t ;; *) path=./$t ;; esac
    if [ "${V:-0}" = 1 ]; then
        echo "== $t"
        { "$path" 2>&1; echo $? >"$log.status"; } | tee "$log"
        status=$(cat "$log.status")
        rm -f "$log.status"
    else
        "$path" >"$log" 2>&1
        status=$?
    fi
    last=$(grep -v '^[[:space:]]*$' "$log" | tail -n 1 | cut -c 1-90)
    if [ "$status" -eq 77 ]; then
        skip=$((skip + 1))
        printf 'SKIP %-38s %s\n' "$name" "$last"
        continue
    fi
    if [ "$status" -eq 0 ] && grep -Eq "$sanitizer" "$log"; then
        status=sanitizer
    fi
    if [ "$status" = 0 ]; then
        pass=$((pass + 1))
        printf 'PASS %-38s %s\n' "$name" "$last"
    else
        fail=$((fail + 1))
        failed="$failed $name"
        if [ "$status" = sanitizer ]; then
            printf 'FAIL %-38s exit status 0, but a sanitizer report (log: %s)\n' "$name" "$log"
        else
            printf 'FAIL %-38s exit status %s (log: %s)\n' "$name" "$status" "$log"
        fi
        if [ "${V:-0}" != 1 ]; then
            lines=$(wc -l <"$log")
            if [ "$lines" -gt 300 ]; then
                echo "    ... (first $((lines - 300)) of $lines lines left out; see the log)"
            fi
            tail -n 300 "$log" | sed 's/^/    | /'
        fi
    fi
done
[ "$skip" -eq 0 ] || echo "skipped: $skip (see the SKIP lines above)"
[ "$fail" -eq 0 ] || echo "failed:$failed"
echo "test programs: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
