#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Splits callgrind dumps of agjk-callgrind-work (one dump per query) into
instructions per support call of the simplex projection, the support path and
the loop bookkeeping, and a fixed cost per query.

    callgrind_split.py LIB QUERIES_FILE DUMP...

LIB is agjk or coal; QUERIES_FILE is the driver's stdout ("query I
support_calls N verdict V" per query, in dump order). Prints one JSON object.

Attribution, instruction by instruction (self costs; --compress-pos=no and
--compress-strings=no dumps):
- agjk (built -O2 -g, the real code, nothing un-inlined): an instruction
  belongs to the *source file of its line* when that file is src/simplex*.c
  (simplex projection), src/shape_*.c or src/minkowski.h (support path: the
  shape callbacks and the inlined Minkowski support wrapper); otherwise to the
  file of its function: src/simplex*.c -> simplex, src/shape_*.c -> support,
  functions of src/minkowski.c named *support* -> support, the rest of src/
  and the driver's measured_agjk -> rest. If the Minkowski wrapper is itself
  inlined into the solver, the vec3.h helpers inlined into it carry vec3.h
  lines and count as rest (a small under-count of the support path). On agjk 0.1.0 (out-of-line
  agjk__simplex_project and agjk__minkowski_support) the two categories equal
  callgrind_annotate --inclusive=yes of those functions.
- Coal (libcoal.so has symbols, no line info): by function name:
  GJK::project*Origin and its helpers -> simplex; getSupportFuncTpl,
  getShapeSupport, getSupport -> support; the rest of coal:: and the
  driver's measured_coal / the adapter's query -> rest.
- Code outside both (libm, libc) is charged to its caller's category through
  the inclusive cost of the call.

"rest" is then split per query q by least squares, rest_q = fixed + loop * n_q
(n_q the query's support calls): loop is the bookkeeping per support call,
fixed the cost per query (validation, set-up, result). When the n_q hardly
vary (standard deviation below 0.5 call: one-iteration Boolean queries) the
split is not identifiable and all of rest is reported as fixed.
"""
import json
import re
import sys

SIMPLEX, SUPPORT, REST = "simplex", "support", "rest"


def agjk_file_category(path):
    if re.search(r"/src/simplex[a-z0-9_]*\.c$", path):
        return SIMPLEX
    if re.search(r"/src/shape_[a-z0-9_]*\.c$", path) or path.endswith("/src/minkowski.h"):
        return SUPPORT
    return None


def agjk_function_category(name, path):
    cat = agjk_file_category(path)
    if cat:
        return cat
    if re.search(r"/src/minkowski\.c$", path) and "support" in name:
        return SUPPORT
    if "/src/" in path or name == "measured_agjk":
        return REST
    return None


def coal_function_category(name, path):
    del path
    if re.search(r"GJK::project\w*Origin|originTo|Project::project", name):
        return SIMPLEX
    if re.search(r"getSupportFuncTpl|getShapeSupport|details::getSupport<|MinkowskiDiff::support",
                 name):
        return SUPPORT
    if "coal::" in name or name in ("measured_coal", "coal_adapter_query_run"):
        return REST
    return None


def function_files(path):
    """Each function's own file (the fl= in force at its fn= line)."""
    files, fl = {}, ""
    with open(path) as f:
        for line in f:
            if line.startswith("fl="):
                fl = line[3:].rstrip("\n")
            elif line.startswith("fn="):
                files.setdefault(line[3:].rstrip("\n"), fl)
    return files


def split_dump(path, lib):
    fn_cat = agjk_function_category if lib == "agjk" else coal_function_category
    files = function_files(path)
    totals = {SIMPLEX: 0, SUPPORT: 0, REST: 0}
    summary = None
    fl = fi = fn = None
    cat = None
    cfn = cfl = None
    pending_call = False
    with open(path) as f:
        for raw in f:
            line = raw.rstrip("\n")
            if not line or line.startswith("#"):
                continue
            if line.startswith("summary:"):
                summary = int(line.split()[1])
                continue
            if line.startswith("fl="):
                fl = fi = line[3:]
                continue
            if line.startswith(("fi=", "fe=")):
                fi = line[3:]
                continue
            if line.startswith("fn="):
                fn = line[3:]
                fi = fl
                cat = fn_cat(fn, fl or "")
                continue
            if line.startswith(("cfi=", "cfl=")):
                cfl = line[4:]
                continue
            if line.startswith("cfn="):
                cfn = line[4:]
                continue
            if line.startswith("calls="):
                pending_call = True
                continue
            if re.match(r"^[a-z]+[:=]", line):
                continue  # ob=, cob=, events:, ...
            parts = line.split()
            if len(parts) < 2 or not re.match(r"^[0-9]+$", parts[1]):
                continue
            cost = int(parts[1])
            if lib == "agjk":
                line_cat = agjk_file_category(fi or "") or cat
            else:
                line_cat = cat
            if pending_call:
                pending_call = False
                callee = cfn or ""
                callee_cat = fn_cat(callee, files.get(callee, cfl or ""))
                # A known caller pays for unknown code it calls (libm, libc).
                if callee_cat is None and line_cat is not None:
                    totals[line_cat] += cost
                cfn = cfl = None
                continue
            if line_cat is not None:
                totals[line_cat] += cost
    if summary is None:
        raise SystemExit("callgrind_split: no summary in %s" % path)
    totals["total"] = summary
    return totals


def main():
    if len(sys.argv) < 4:
        raise SystemExit(__doc__)
    lib, queries_file, dumps = sys.argv[1], sys.argv[2], sys.argv[3:]
    calls = []
    with open(queries_file) as f:
        for line in f:
            m = re.match(r"^query (\d+) support_calls (\d+) verdict (-?\d+)", line)
            if m:
                calls.append(int(m.group(2)))
    per = [split_dump(d, lib) for d in dumps]
    per = [p for p in per if p["total"] > 0]  # the final dump (program end) is empty
    if len(per) != len(calls):
        raise SystemExit("callgrind_split: %d queries but %d non-empty dumps"
                         % (len(calls), len(per)))
    n_q = len(per)
    n_calls = sum(calls)
    total = sum(p["total"] for p in per)
    simplex = sum(p[SIMPLEX] for p in per)
    support = sum(p[SUPPORT] for p in per)
    rest = [p["total"] - p[SIMPLEX] - p[SUPPORT] for p in per]
    unattributed = sum(p["total"] - p[SIMPLEX] - p[SUPPORT] - p[REST] for p in per)
    mean_n = n_calls / n_q
    mean_r = sum(rest) / n_q
    var_n = sum((c - mean_n) ** 2 for c in calls)
    if var_n / n_q >= 0.25:
        loop = sum((c - mean_n) * (r - mean_r) for c, r in zip(calls, rest)) / var_n
        fixed = mean_r - loop * mean_n
    else:
        loop, fixed = None, mean_r
    out = {
        "lib": lib,
        "queries": n_q,
        "support_calls_per_query": mean_n,
        "total_per_query": total / n_q,
        "total_per_support_call": total / n_calls,
        "simplex_per_support_call": simplex / n_calls,
        "support_path_per_support_call": support / n_calls,
        "loop_per_support_call": loop,
        "fixed_per_query": fixed,
        "rest_per_query": mean_r,
        "unattributed_per_query": unattributed / n_q,
    }
    print(json.dumps(out))


if __name__ == "__main__":
    main()
