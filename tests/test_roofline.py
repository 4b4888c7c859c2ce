"""bench/roofline.py: each instruction's flops (the classifier against hand counts), the callgrind reader against a
small file in callgrind's compressed format, and the count against a loop whose flops are known."""
import shutil
import subprocess

import pytest

from bench.roofline import classify, flop_count, parse_callgrind


@pytest.mark.parametrize("mnemonic, operands, expected", [
    ("vfmadd231pd", "%ymm1,%ymm2,%ymm3", ("fma ymm", 8)),
    ("vfnmadd213sd", "%xmm1,%xmm2,%xmm3", ("fma scalar", 2)),
    ("vfmadd132pd", "0x20(%rax),%xmm2,%xmm3", ("fma xmm", 4)),
    ("vmulpd", "%ymm0,%ymm1,%ymm2", ("add/sub/mul ymm", 4)),
    ("vaddsd", "%xmm0,%xmm1,%xmm1", ("add/sub/mul scalar", 1)),
    ("subpd", "%xmm0,%xmm1", ("add/sub/mul xmm", 2)),
    ("vdivpd", "%ymm0,%ymm1,%ymm2", ("div/sqrt ymm", 4)),
    ("vsqrtsd", "%xmm0,%xmm0,%xmm0", ("div/sqrt scalar", 1)),
    ("vmaxpd", "%ymm0,%ymm1,%ymm2", ("min/max ymm", 0)),
    ("vhaddpd", "%ymm0,%ymm1,%ymm2", ("add/sub/mul ymm (horizontal)", 4)),
    ("vmulss", "%xmm0,%xmm1,%xmm2", ("add/sub/mul scalar single", 1)),
])
def test_classify_counts_each_instructions_operations(mnemonic, operands, expected):
    assert classify(mnemonic, operands) == expected


@pytest.mark.parametrize("mnemonic", ["vmovapd", "vpsubq", "vxorpd", "vcvtsi2sd", "vcmppd", "vblendvpd", "add"])
def test_classify_leaves_out_what_is_no_floating_point_arithmetic(mnemonic):
    assert classify(mnemonic, "%ymm0,%ymm1,%ymm2") is None


def test_parse_callgrind_keeps_self_costs_and_counts_the_steps_factor_calls(tmp_path):
    # Positions relative (+n), absolute (0x), repeated (*); the line after calls= is a call's inclusive cost and
    # must not count; jacobian_factor calls count only from ros2_stages (callgrind records calls outside
    # collection too).
    f = tmp_path / "cg.out"
    f.write_text("\n".join([
        "positions: instr", "events: Ir", "",
        "ob=(1) /lib/a.so", "fl=(1) a.cc", "fn=(1) armrt::ros2_stages(x)",
        "0x100 3", "+4 2", "* 1",
        "cfn=(2) armrt::jacobian_factor(y)", "calls=2 0x200", "+2 999",
        "+3 5",
        "fn=(3) other", "cfn=(2)", "calls=7 0x200", "0x300 888",
        "ob=(2) /lib/b.so", "fn=(2)", "0x200 4", ""]))
    counts, steps = parse_callgrind(f)
    assert steps == 2
    assert dict(counts["/lib/a.so"]) == {0x100: 3, 0x104: 3, 0x109: 5}
    assert dict(counts["/lib/b.so"]) == {0x200: 4}


@pytest.mark.skipif(not (shutil.which("valgrind") and shutil.which("g++") and shutil.which("objdump")),
                    reason="needs valgrind, g++ and objdump")
def test_flop_count_of_a_known_loop(tmp_path):
    # n scalar multiply-adds a[i] * b[i] + c kept scalar (-O1, no vectorisation, -mfma): 2 n flops.
    src = tmp_path / "k.c"
    src.write_text("""
        #include <stdlib.h>
        __attribute__((noinline)) double kernel(const double* a, const double* b, int n) {
          double s = 0.0;
          for (int i = 0; i < n; ++i) s = __builtin_fma(a[i], b[i], s);
          return s;
        }
        int main(int argc, char** argv) {
          int n = 1000; double* a = calloc(n, 8); double* b = calloc(n, 8);
          return (int)kernel(a, b, n);
        }""")
    exe = tmp_path / "k"
    subprocess.run(["gcc", "-O1", "-mfma", "-fno-tree-vectorize", str(src), "-o", str(exe)], check=True)
    out = tmp_path / "cg.out"
    subprocess.run(["valgrind", "--tool=callgrind", "--toggle-collect=kernel", "--dump-instr=yes", "--dump-line=no",
                    f"--callgrind-out-file={out}", str(exe)], check=True, capture_output=True)
    counts, _ = parse_callgrind(out)
    classes = flop_count(counts)["classes"]
    assert classes == {"fma scalar": {"instructions": 1000, "flops": 2000}}
