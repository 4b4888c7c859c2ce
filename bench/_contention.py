"""How much of the machine other processes used while a benchmark ran: the test a scaling figure must pass.

The load average lags by a minute and counts this process's own threads, so it cannot tell whether a 2-thread
run had both cores. /proc/stat's busy time over the run, less this process's own CPU time over the same window,
is what everything else used, in cores (Linux only; elsewhere `other_cores` is None and nothing is refused).
"""
from __future__ import annotations

import os
import time

# A 2-thread run that shared its cores with more than this much other work is no scaling figure: a quarter of a core
# taken from a two-core run costs it up to 12 % of its rate, more than the run-to-run noise on a quiet machine.
CONTENDED_CORES = 0.25


def _busy_s() -> float | None:
    try:
        with open("/proc/stat") as f:
            fields = f.readline().split()
    except OSError:
        return None
    # cpu user nice system idle iowait irq softirq steal ...: busy is everything but idle and iowait.
    ticks = [int(x) for x in fields[1:]]
    busy = sum(ticks) - ticks[3] - (ticks[4] if len(ticks) > 4 else 0)
    return busy / os.sysconf("SC_CLK_TCK")


class Window:
    """with Window() as w: ...  then w.other_cores (cores other processes kept busy, on average) and w.wall_s.

    /proc/stat counts in clock ticks (10 ms): over a window shorter than about 0.3 s the figure is coarse."""

    def __enter__(self):
        self._busy0, self._cpu0, self._t0 = _busy_s(), time.process_time(), time.perf_counter()
        return self

    def __exit__(self, *exc):
        self.wall_s = time.perf_counter() - self._t0
        own = time.process_time() - self._cpu0
        busy1 = _busy_s()
        self.other_cores = None if busy1 is None or self._busy0 is None else max(
            0.0, (busy1 - self._busy0 - own) / max(self.wall_s, 1e-9))
        return False


def contended(*other_cores: float | None) -> bool:
    """True when any window's other processes used more than CONTENDED_CORES (unknown counts as not contended)."""
    return any(c is not None and c > CONTENDED_CORES for c in other_cores)
