#!/usr/bin/env python3
"""Instructions per call of one function in a benchmark, counted by callgrind.

On a machine whose timings drift by more than the difference being looked for, the
instruction count of the function a benchmark times is a steadier measure: it does not
depend on the load. It is not a time (cache misses and branch mispredictions are not in
it), so quote it beside timing ratios, not instead of them.

    tests/bench/instructions_per_call.py BENCH FILTER FUNCTION
    tests/bench/instructions_per_call.py build/test/tests/bezier_bench \
        'IntersectCubicPairs_Hybrid/3$' 'bezier::core::intersect('

FILTER selects the benchmarks (--benchmark_filter); FUNCTION is a substring of the
demangled name of the function called once per unit of work. Prints its calls and its
inclusive instruction count (Ir) per call. Needs valgrind.
"""
import re
import subprocess
import sys
import tempfile


def inclusive_cost_per_call(callgrind_file: str, function: str) -> tuple[int, float]:
    """Sums every call record whose callee's name contains `function`: a `calls=` line is
    followed by the line holding the inclusive cost of those calls."""
    names: dict[str, str] = {}
    callee = ""
    calls_pending = None
    calls = cost = 0
    with open(callgrind_file, errors="replace") as lines:
        for line in lines:
            named = re.match(r"(c?fn)=\((\d+)\)(?: (.*))?", line)
            if named:
                kind, ident, name = named.groups()
                if name:
                    names[ident] = name.strip()
                if kind == "cfn":
                    callee = names.get(ident, "")
                continue
            call = re.match(r"calls=(\d+)", line)
            if call:
                calls_pending = int(call.group(1)) if function in callee else None
                continue
            if calls_pending is not None and re.match(r"[+\-*0-9]", line):
                calls += calls_pending
                cost += int(line.split()[1])
                calls_pending = None
    return calls, cost / calls if calls else 0.0


def main() -> int:
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    bench, filter_, function = sys.argv[1:]
    with tempfile.NamedTemporaryFile(suffix=".callgrind") as out:
        subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out.name}",
                        "--dump-instr=no", bench, f"--benchmark_filter={filter_}",
                        "--benchmark_min_time=0.1"],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        calls, per_call = inclusive_cost_per_call(out.name, function)
    if calls == 0:
        print(f"no calls of a function matching {function!r}", file=sys.stderr)
        return 1
    print(f"{calls} calls, {per_call:.0f} instructions per call")
    return 0


if __name__ == "__main__":
    sys.exit(main())
