"""The ROS2 step's floating-point work against this core's peak: the roofline line (issue 26 item 1).

    python -m bench.roofline [--build build/dev] [--models das2,das3] [--reps 100]

This VM exposes no hardware counters (`perf stat -e instructions,cycles` says <not supported>), so the flops are
counted exactly instead of sampled: `armrt_bench` runs under `valgrind --tool=callgrind --dump-instr=yes` with
collection on inside ROS2 steps only, which gives every instruction address's execution count; `objdump -d` of each
object gives its mnemonic and register width, and each executed floating-point instruction is weighted by the
double-precision operations it does:

    add, sub, mul, div, sqrt, min, max (scalar sd: 1, xmm pd: 2, ymm pd: 4), fused multiply-add (2 per lane),
    horizontal add (one per result lane).

Division and square root count one flop each, as in the usual roofline convention, though they occupy the divider
for many cycles; they are reported apart. min/max are counted apart too and left out of the flop total.

The peak is the core's: 2 FMA pipes x 4 doubles x 2 = 16 double-precision flops per cycle on AMD Zen 2/3/4 (AMD,
Software Optimization Guide for AMD Family 19h Processors, pub. 56665, section 2.11: four FP pipes, two of them
FMA, 256 bits wide), times the clock /proc/cpuinfo reports. The achieved rate divides the flops of a step by the
median wall time of a step (armrt_bench in a plain run right after, with the machine's load average recorded).

The memory side of the roofline does not bind: a step's working set (Model and Data of one arm, a few tens of KB)
stays in L1/L2, so the step sits far right of the ridge and its ceiling is the compute peak; the distance below it
is dependency chains, scalar code and non-flop instructions, which the per-class table shows.

Writes bench/results/roofline.json and .md.
"""
from __future__ import annotations

import json
import os
import re
import subprocess
import tempfile
from collections import defaultdict
from pathlib import Path

from bench.profile_step import callgrind_bench_args

HERE = Path(__file__).resolve().parent
REPO = HERE.parent

FLOPS_PER_CYCLE = 16  # double precision, AMD Zen 2/3/4 (see the module docstring)

# AT&T mnemonics: v?(op)(p|s)(d|s), fused forms v(f|fn)(madd|msub)(132|213|231)(p|s)(d|s), horizontal adds.
ARITH = re.compile(r"^v?(add|sub|mul|div|sqrt|min|max)(p|s)(d|s)$")
FMA = re.compile(r"^vf(n?)(madd|msub|maddsub|msubadd)(132|213|231)(p|s)(d|s)$")
HADD = re.compile(r"^v?h(add|sub)p(d|s)$")
DISASM = re.compile(r"^\s*([0-9a-f]+):\s+(\S+)\s*(.*)$")


def classify(mnemonic: str, operands: str):
    """(class, flops) of one instruction, or None for a non-floating-point one. class: 'fma', 'add/sub/mul',
    'div/sqrt', 'min/max' (uncounted), with '-scalar' / '-xmm' / '-ymm'."""
    lanes_packed = 4 if "%ymm" in operands else 8 if "%zmm" in operands else 2
    m = FMA.match(mnemonic)
    if m:
        packed = m.group(4) == "p"
        lanes = lanes_packed if packed else 1
        width = ("ymm" if lanes == 4 else "xmm") if packed else "scalar"
        if m.group(5) == "s":
            width += " single"
        return f"fma {width}", 2 * lanes
    m = ARITH.match(mnemonic)
    if m:
        op, packed = m.group(1), m.group(2) == "p"
        lanes = lanes_packed if packed else 1
        width = ("ymm" if lanes == 4 else "xmm") if packed else "scalar"
        if m.group(3) == "s":
            width += " single"
        kind = "div/sqrt" if op in ("div", "sqrt") else "min/max" if op in ("min", "max") else "add/sub/mul"
        return f"{kind} {width}", (0 if kind == "min/max" else lanes)
    m = HADD.match(mnemonic)
    if m:
        lanes = lanes_packed
        return f"add/sub/mul {'ymm' if lanes == 4 else 'xmm'} (horizontal)", lanes
    return None


def parse_callgrind(path: Path):
    """({object: {address: executions}}, calls of jacobian_factor) from a --dump-instr=yes callgrind file with
    positions 'instr'. Call lines' inclusive costs (the line after calls=) are skipped: only self costs."""
    counts: dict = defaultdict(lambda: defaultdict(int))
    names: dict = {"ob": {}, "fn": {}}
    ob = fn = cfn = None
    addr = 0
    skip_next = False
    factor_calls = 0
    for line in path.read_text().splitlines():
        if not line or line[0] == "#":
            continue
        head = line.split("=", 1)[0]
        if head in ("ob", "cob", "fn", "cfn", "fl", "fi", "fe", "cfi", "cfl"):
            rest = line.split("=", 1)[1]
            m = re.match(r"\((\d+)\)\s*(.*)", rest)
            key = "ob" if head in ("ob", "cob") else "fn" if head in ("fn", "cfn") else None
            value = rest
            if m and key:
                if m.group(2):
                    names[key][m.group(1)] = m.group(2)
                value = names[key].get(m.group(1), m.group(1))
            if head == "ob":
                ob = value
            elif head == "fn":
                fn = value
            elif head == "cfn":
                cfn = value
            continue
        if head == "calls":
            n = int(line.split("=", 1)[1].split()[0])
            # Calls are counted while collection is off too (callgrind); ros2_stages runs inside steps only.
            if cfn and "jacobian_factor" in cfn and fn and "ros2_stages" in fn:
                factor_calls += n
            skip_next = True
            continue
        if line[0] in "0123456789+-*":
            pos, cost = line.split()[:2]
            if pos.startswith("0x"):
                addr = int(pos, 16)
            elif pos[0] in "+-":
                addr += int(pos)
            elif pos != "*":
                addr = int(pos)
            if skip_next:
                skip_next = False
                continue
            counts[ob][addr] += int(cost)
            continue
        # other header lines (summary, totals, jump=) carry no self cost
    return counts, factor_calls


def flop_count(counts: dict) -> dict:
    by_class: dict = defaultdict(lambda: {"instructions": 0, "flops": 0})
    total_ir = 0
    for ob, addrs in counts.items():
        total_ir += sum(addrs.values())
        if not ob or not Path(ob).is_file():
            continue
        dis = subprocess.run(["objdump", "-d", "--no-show-raw-insn", ob], check=True, capture_output=True,
                             text=True).stdout
        for line in dis.splitlines():
            m = DISASM.match(line)
            if not m:
                continue
            a = int(m.group(1), 16)
            n = addrs.get(a)
            if not n:
                continue
            c = classify(m.group(2), m.group(3))
            if c:
                by_class[c[0]]["instructions"] += n
                by_class[c[0]]["flops"] += n * c[1]
    return {"instructions": total_ir, "classes": dict(by_class)}


def cpu_clock_hz() -> float:
    for line in Path("/proc/cpuinfo").read_text().splitlines():
        if line.startswith("cpu MHz"):
            return float(line.split(":")[1]) * 1e6
    raise RuntimeError("no 'cpu MHz' in /proc/cpuinfo")


def cpu_name() -> str:
    info = Path("/proc/cpuinfo").read_text()
    get = lambda k: (re.search(rf"^{k}\s*:\s*(.*)$", info, re.M) or [None, "?"])[1]
    return f"{get('model name')} (family {get('cpu family')}, model {get('model')})"


def measure(bench: Path, model: str, reps: int) -> dict:
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "cg.out"
        subprocess.run(["valgrind", "--tool=callgrind", "--toggle-collect=armrt::step_ros2*", "--dump-instr=yes",
                        "--dump-line=no", f"--callgrind-out-file={out}", str(bench), "--model", model, "--reps",
                        str(reps), "--no-pin", "--json", str(Path(tmp) / "x.json")], check=True, capture_output=True)
        counts, steps = parse_callgrind(out)
        load_before = os.getloadavg()[0]
        subprocess.run([str(bench), "--model", model, "--reps", "20000", "--json", str(Path(tmp) / "t.json")],
                       check=True, capture_output=True)
        load_after = os.getloadavg()[0]
        timing = json.loads((Path(tmp) / "t.json").read_text())["cpp"]["ros2_step"]
    if steps == 0:
        raise RuntimeError("callgrind saw no jacobian_factor call: is the default step still ROS2?")
    fc = flop_count(counts)
    per = {k: {"instructions": v["instructions"] / steps, "flops": v["flops"] / steps}
           for k, v in sorted(fc["classes"].items())}
    flops = sum(v["flops"] for v in per.values())
    ns = timing["median"]
    clock = cpu_clock_hz()
    peak = FLOPS_PER_CYCLE * clock
    return {"model": model, "steps": steps, "instructions_per_step": fc["instructions"] / steps,
            "flops_per_step": flops, "classes": per, "wall_ns_per_step": ns, "wall_ns_min": timing.get("min"),
            "gflops": flops / ns, "peak_gflops": peak / 1e9, "fraction_of_peak": flops / ns / (peak / 1e9),
            "step_ns_at_peak": flops / (peak / 1e9), "clock_hz": clock, "load_avg_1min": [load_before, load_after]}


def markdown(results: list, command: str) -> str:
    r0 = results[0]
    lines = ["# The ROS2 step against the core's peak (the roofline line)", "", f"`{command}`", "",
             f"CPU: {cpu_name()}, {r0['clock_hz'] / 1e9:.3f} GHz; peak {FLOPS_PER_CYCLE} double-precision flops "
             f"per cycle = {r0['peak_gflops']:.1f} GFLOP/s per core. Flops counted exactly (callgrind per-"
             "instruction counts inside ROS2 steps x each instruction's operations, bench/roofline.py); time: "
             "armrt_bench's median step in a plain run right after.", "",
             "| model | flops per step | instructions per step | flops per instruction | ns per step (median) | "
             "GFLOP/s | of peak | step at peak (ns) | load (1 min) |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---|"]
    for r in results:
        lines.append(f"| {r['model']} | {r['flops_per_step']:,.0f} | {r['instructions_per_step']:,.0f} | "
                     f"{r['flops_per_step'] / r['instructions_per_step']:.2f} | {r['wall_ns_per_step']:,.0f} | "
                     f"{r['gflops']:.2f} | {100 * r['fraction_of_peak']:.1f} % | {r['step_ns_at_peak']:,.0f} | "
                     f"{r['load_avg_1min'][0]:.2f} -> {r['load_avg_1min'][1]:.2f} |")
    lines += ["", "Floating-point instructions per step by class (flops: double-precision operations; min/max "
              "are not counted as flops):", ""]
    classes = sorted({k for r in results for k in r["classes"]})
    lines += ["| class | " + " | ".join(f"{r['model']} instr. | {r['model']} flops" for r in results) + " |",
              "|---|" + "---:|---:|" * len(results)]
    for c in classes:
        cells = []
        for r in results:
            v = r["classes"].get(c, {"instructions": 0, "flops": 0})
            cells += [f"{v['instructions']:,.0f}", f"{v['flops']:,.0f}"]
        lines.append(f"| {c} | " + " | ".join(cells) + " |")
    for r in results:
        vec = sum(v["flops"] for k, v in r["classes"].items() if "ymm" in k or "xmm" in k)
        lines += ["", f"{r['model']}: {100 * vec / r['flops_per_step']:.1f} % of the flops are in vector (xmm/ymm) "
                  "instructions."]
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    args, bench, command = callgrind_bench_args(__doc__, "roofline", 100, argv)
    results = [measure(bench, m, args.reps) for m in args.models.split(",")]
    Path(args.json).write_text(json.dumps({"command": command, "cpu": cpu_name(), "results": results}, indent=1)
                               + "\n")
    text = markdown(results, command)
    Path(args.md).write_text(text)
    print(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
