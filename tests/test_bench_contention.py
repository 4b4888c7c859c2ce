"""bench/_contention.py: a scaling figure is refused when another process kept a core busy during the run."""
import subprocess
import sys
import time

import pytest

from bench._contention import CONTENDED_CORES, Window, _busy_s, contended

pytestmark = pytest.mark.skipif(_busy_s() is None, reason="needs Linux /proc/stat")


def test_a_spinning_process_is_seen_and_this_process_is_not():
    # This process spins itself: its own CPU time is subtracted, so that alone is not "other processes".
    spin = "import time\nt = time.perf_counter()\nwhile time.perf_counter() - t < 1.5: pass\n"
    child = subprocess.Popen([sys.executable, "-c", spin])
    try:
        time.sleep(0.3)  # the child is running
        with Window() as w:
            t = time.perf_counter()
            while time.perf_counter() - t < 0.8:
                pass
    finally:
        child.wait()
    # The child spun through the whole window on one core (whatever else the machine ran adds to it).
    assert w.other_cores > 0.6, w.other_cores
    assert contended(0.0, w.other_cores)


def test_the_rule():
    assert not contended(0.0, CONTENDED_CORES)
    assert contended(CONTENDED_CORES + 0.01)
    assert not contended(None, None)  # unknown is not refused
