#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Splits callgrind dumps of agjk-callgrind-work (one dump per query) into
instructions per support call of the simplex projection, the support path and
the loop bookkeeping, and a fixed cost per query.

    callgrind_split.py LIB QUERIES_FILE [--binary BINARY] DUMP...

LIB is agjk or coal; QUERIES_FILE is the driver's stdout ("query I
support_calls N verdict V" per query, in dump order). Prints one JSON object.

Attribution, instruction by instruction (self costs; --dump-instr=yes
--compress-pos=no --compress-strings=no dumps):
- agjk (built -O2 -g, the real code, inlined as shipped): each instruction
  address is looked up with addr2line -i in BINARY (--binary), which gives the
  chain of functions inlined at that address. From the innermost frame out,
  the first frame in src/simplex*.c makes it simplex projection, the first
  in src/shape_*.c or in agjk__minkowski_support (the Minkowski support
  wrapper, wherever it was inlined) support path; otherwise it is rest (any
  frame in src/, or the driver's measured_agjk). Without --binary, by the
  source file of its line and the file of its function, as before inlining
  was forced: src/simplex*.c -> simplex, src/shape_*.c and src/minkowski.h ->
  support, the rest of src/ -> rest (vec3.h helpers inlined into the
  wrapper then count as rest).
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
import os
import re
import subprocess
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


# Functions that stand for a support call wherever they are inlined: the
# Minkowski wrapper, and the support values a Boolean query's first plane
# test takes instead of the points (src/solver.h).
SUPPORT_FUNCTIONS = ("agjk__minkowski_support", "agjk__support_value")


def frame_category(frames):
    """Category of an instruction from its inline chain [(function, file)],
    innermost first (addr2line -i)."""
    for fn, path in frames:
        if re.search(r"/src/simplex[a-z0-9_]*\.c$", path):
            return SIMPLEX
        if re.search(r"/src/shape_[a-z0-9_]*\.c$", path) or fn in SUPPORT_FUNCTIONS:
            return SUPPORT
    for fn, path in frames:
        if "/src/" in path or fn == "measured_agjk":
            return REST
    return None


def symbol_address(binary, name):
    out = subprocess.run(["nm", binary], capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[2] == name:
            return int(parts[0], 16)
    raise SystemExit("callgrind_split: no symbol %s in %s" % (name, binary))


def inline_chains(binary, addresses):
    """{address: [(function, file)]} by addr2line -i, innermost frame first."""
    addrs = sorted(addresses)
    if not addrs:
        return {}
    text = "\n".join("0x%x" % a for a in addrs) + "\n"
    out = subprocess.run(["addr2line", "-e", binary, "-a", "-f", "-i"], input=text,
                         capture_output=True, text=True, check=True).stdout.splitlines()
    chains, cur, i = {}, None, 0
    while i < len(out):
        line = out[i]
        if re.match(r"^0x[0-9a-f]+$", line):
            cur = int(line, 16)
            chains[cur] = []
            i += 1
            continue
        fn = line
        loc = out[i + 1] if i + 1 < len(out) else "??:0"
        chains[cur].append((fn, loc.rsplit(":", 1)[0]))
        i += 2
    return chains


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


def parse_dump(path, own_object=None):
    """The cost lines of a dump: (function, function's file, line's file,
    address or None, cost, callee or None for a call's inclusive cost).
    With own_object (the driver's path), addresses are kept only for code of
    that object: an address in the dynamic linker or libc means nothing in
    the driver's line table (and once fell inside agjk's code there)."""
    rows = []
    summary = None
    ob = None
    own = os.path.realpath(own_object) if own_object else None
    fl = fi = fn = None
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
            if line.startswith("ob="):
                ob = os.path.realpath(line[3:])
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
                continue  # ob=, cob=, events:, positions:, ...
            parts = line.split()
            addr = None
            if parts and parts[0].startswith("0x"):  # positions: instr line
                addr = int(parts[0], 16)
                parts = parts[1:]
            if len(parts) < 2 or not re.match(r"^[0-9]+$", parts[1]):
                continue
            cost = int(parts[1])
            callee = None
            if pending_call:
                pending_call = False
                callee = (cfn or "", cfl or "")
                cfn = cfl = None
            if own is not None and ob != own:
                addr = None
            rows.append((fn or "", fl or "", fi or "", addr, cost, callee))
    return summary, rows


def split_dump(path, lib, chains=None, bias=0, binary=None):
    fn_cat = agjk_function_category if lib == "agjk" else coal_function_category
    files = function_files(path)
    totals = {SIMPLEX: 0, SUPPORT: 0, REST: 0}
    summary, rows = parse_dump(path, binary)
    for fn, fl, fi, addr, cost, callee in rows:
        if lib == "agjk" and chains is not None and addr is not None and addr - bias in chains:
            line_cat = frame_category(chains[addr - bias])
        elif lib == "agjk":
            line_cat = agjk_file_category(fi) or fn_cat(fn, fl)
        else:
            line_cat = fn_cat(fn, fl)
        if callee is not None:
            callee_cat = fn_cat(callee[0], files.get(callee[0], callee[1]))
            # A known caller pays for unknown code it calls (libm, libc).
            if callee_cat is None and line_cat is not None:
                totals[line_cat] += cost
            continue
        if line_cat is not None:
            totals[line_cat] += cost
    if summary is None:
        raise SystemExit("callgrind_split: no summary in %s" % path)
    totals["total"] = summary
    return totals


def agjk_chains(binary, dumps):
    """Inline chains of every agjk address in the dumps, and the load bias of
    the (position-independent) binary under valgrind, from measured_agjk's
    entry: collection starts there, so its lowest address is the entry."""
    entry, addrs = None, set()
    for d in dumps:
        for fn, fl, fi, addr, cost, callee in parse_dump(d, binary)[1]:
            if addr is None:
                continue
            addrs.add(addr)
            if fn == "measured_agjk" and (entry is None or addr < entry):
                entry = addr
    if entry is None:
        raise SystemExit("callgrind_split: no instruction addresses (dump with --dump-instr=yes)")
    bias = entry - symbol_address(binary, "measured_agjk")
    return inline_chains(binary, [a - bias for a in addrs if a >= bias]), bias


def main():
    if len(sys.argv) < 4:
        raise SystemExit(__doc__)
    lib, queries_file, dumps = sys.argv[1], sys.argv[2], sys.argv[3:]
    binary = None
    if dumps[:1] == ["--binary"]:
        binary, dumps = dumps[1], dumps[2:]
    calls = []
    with open(queries_file) as f:
        for line in f:
            m = re.match(r"^query (\d+) support_calls (\d+) verdict (-?\d+)", line)
            if m:
                calls.append(int(m.group(2)))
    chains, bias = (agjk_chains(binary, dumps) if lib == "agjk" and binary else (None, 0))
    per = [split_dump(d, lib, chains, bias, binary) for d in dumps]
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
