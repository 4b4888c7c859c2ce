"""C++ emission helpers: deterministic printing of sympy expressions as straight-line code."""
from __future__ import annotations

import sympy as sp
from sympy.printing.c import C99CodePrinter


def fmt(x: float) -> str:
    """A double literal that round-trips exactly."""
    x = float(x)
    if x != x or x in (float("inf"), float("-inf")):
        raise ValueError(f"non-finite constant {x!r}")
    s = "%.17g" % x
    if "." not in s and "e" not in s and "n" not in s:
        s += ".0"
    return s


def cstr(s: str) -> str:
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


class _Printer(C99CodePrinter):
    def _print_Float(self, expr):
        return fmt(float(expr))

    def _print_Integer(self, expr):
        return fmt(int(expr))

    def _print_Rational(self, expr):
        return f"({fmt(expr.p)}/{fmt(expr.q)})"

    def _print_Pow(self, expr):
        base, exp = expr.as_base_exp()
        if exp.is_Integer and 1 <= abs(int(exp)) <= 4:
            b = self.parenthesize(base, 100)
            prod = "*".join([b] * abs(int(exp)))
            return prod if int(exp) > 0 else f"(1.0/({prod}))"
        if exp == sp.Rational(1, 2):
            return f"std::sqrt({self._print(base)})"
        if exp == -sp.Rational(1, 2):
            return f"(1.0/std::sqrt({self._print(base)}))"
        return f"std::pow({self._print(base)}, {self._print(exp)})"

    def _print_sin(self, expr):
        return f"std::sin({self._print(expr.args[0])})"

    def _print_cos(self, expr):
        return f"std::cos({self._print(expr.args[0])})"


_PRINTER = _Printer()


def cexpr(e) -> str:
    return _PRINTER.doprint(sp.sympify(e))


def emit_function(signature: str, inputs: list, outputs: list, trig_of: list | None = None) -> tuple[str, int]:
    """Straight-line C++ for `outputs` with common subexpressions eliminated.

    inputs: list of (array_name, [symbols]) - symbol k is read from array_name[k].
    outputs: list of (array_name, [expressions]) - array_name[k] = expression k.
    trig_of: symbols whose sin/cos are computed once up front.
    Returns (code, number of temporaries).
    """
    trig_of = trig_of or []
    rep = {}
    trig_lines = []
    for sym in trig_of:
        s, c = sp.Symbol(f"s_{sym.name}", real=True), sp.Symbol(f"c_{sym.name}", real=True)
        rep[sp.sin(sym)] = s
        rep[sp.cos(sym)] = c
        trig_lines.append((s, f"std::sin({sym.name})", sym))
        trig_lines.append((c, f"std::cos({sym.name})", sym))
    flat = []
    for _, exprs in outputs:
        flat.extend(sp.sympify(e).xreplace(rep) for e in exprs)
    counter = sp.numbered_symbols("x")
    temps, reduced = sp.cse(flat, symbols=counter, order="none")

    used = set()
    for _, e in temps:
        used |= e.free_symbols
    for e in reduced:
        used |= e.free_symbols

    lines = [signature + " {"]
    for arr, syms in inputs:
        any_used = False
        for k, sym in enumerate(syms):
            needs = sym in used or any(t[2] == sym and t[0] in used for t in trig_lines)
            if needs:
                lines.append(f"  const double {sym.name} = {arr}[{k}];")
                any_used = True
        if not any_used:
            lines.append(f"  (void){arr};")
    # sin and cos of one angle together, by the engine's library-free sin_cos (armrt/fast_math.h).
    for k in range(0, len(trig_lines), 2):
        (s, _, sym), (c, _, _) = trig_lines[k], trig_lines[k + 1]
        if s in used or c in used:
            lines.append(f"  double {s.name}, {c.name};")
            lines.append(f"  armrt::sin_cos({sym.name}, &{s.name}, &{c.name});")
    for sym, e in temps:
        lines.append(f"  const double {sym.name} = {cexpr(e)};")
    i = 0
    for arr, exprs in outputs:
        for k in range(len(exprs)):
            lines.append(f"  {arr}[{k}] = {cexpr(reduced[i])};")
            i += 1
    lines.append("}")
    return "\n".join(lines) + "\n", len(temps)
