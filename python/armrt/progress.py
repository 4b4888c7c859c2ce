"""Progress of long work on stderr: bars (tqdm) for loops, and Progress for jobs made of stages.

`bar(total, desc)` is a tqdm bar on stderr that stays silent when stderr is not a terminal (CI, pipes,
notebooks' captured output) or when `enabled` is False, and appears only after `delay` s, so short
calls print nothing. Without tqdm installed it is a no-op with the same methods.
`Progress(total)` announces the stages of a job (the paper's experiments, das3's, a participant's):
a bar on a terminal, one line per stage start and end elsewhere; it silences the bars inside (quiet()).
"""
from __future__ import annotations

import sys
import time
from contextlib import contextmanager


class _Silent:
    def __init__(self, *args, **kwargs):
        self.n = 0

    def update(self, n: int = 1) -> None:
        self.n += n

    def set_description(self, desc: str) -> None:
        pass

    def set_postfix_str(self, s: str) -> None:
        pass

    def write(self, s: str) -> None:
        print(s, file=sys.stderr)

    def close(self) -> None:
        pass

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


_quiet_depth = 0


@contextmanager
def quiet():
    """Inside: bars with enabled=None stay silent (a job with its own bar, e.g. experiments, keeps
    the simulate() calls it makes from drawing theirs)."""
    global _quiet_depth
    _quiet_depth += 1
    try:
        yield
    finally:
        _quiet_depth -= 1


def bar(total: float | None, desc: str, unit: str = "it", enabled: bool | None = None, delay: float = 1.0,
        leave: bool = False):
    """A progress bar: enabled None = only when stderr is a terminal (and not inside quiet());
    True = always; False = never."""
    if enabled is False or (enabled is None and _quiet_depth):
        return _Silent()
    try:
        from tqdm.auto import tqdm
    except ImportError:
        return _Silent()
    # disable=None: tqdm's own check that the stream is a terminal.
    return tqdm(total=total, desc=desc, unit=unit, file=sys.stderr, delay=delay, leave=leave,
                disable=None if enabled is None else False, dynamic_ncols=True)


class Progress:
    """Stages of a long job on stderr, announced when they start: on a terminal a tqdm bar whose
    description names the stage under way and whose postfix shows the step inside it (tick); elsewhere
    one line when a stage starts and one when it ends, with the elapsed time."""

    def __init__(self, total: int, enabled: bool = True, desc: str = "experiments"):
        self.total, self.done, self.enabled = total, 0, enabled
        self.t0 = time.perf_counter()
        self.tty = sys.stderr.isatty()
        self._bar = bar(total, desc, unit="stage", enabled=enabled and self.tty, delay=0.0, leave=True)

    def _elapsed(self) -> str:
        return f"{time.perf_counter() - self.t0:.0f} s"

    def start(self, what: str):
        """A stage begins (shown while it runs)."""
        if not self.enabled:
            return
        if self.tty:
            self._bar.set_description(what)
        else:
            print(f"[{self.done + 1}/{self.total}] {what} ... ({self._elapsed()})", file=sys.stderr, flush=True)

    def tick(self, what: str):
        """Progress inside a stage (terminal only: a postfix on the bar)."""
        if self.enabled and self.tty:
            self._bar.set_postfix_str(what)

    def step(self, what: str):
        """A stage ended."""
        self.done += 1
        if not self.enabled:
            return
        if self.tty:
            self._bar.set_postfix_str(f"done: {what}")
            self._bar.update(1)
        else:
            print(f"[{self.done}/{self.total}] {what} done ({self._elapsed()})", file=sys.stderr, flush=True)

    def close(self):
        self._bar.close()
