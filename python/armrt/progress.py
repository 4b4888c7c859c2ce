"""Progress bars for long work (tqdm), shown only on a terminal.

`bar(total, desc)` is a tqdm bar on stderr that stays silent when stderr is not a terminal (CI, pipes,
notebooks' captured output) or when `enabled` is False, and appears only after `delay` s, so short
calls print nothing. Without tqdm installed it is a no-op with the same methods.
"""
from __future__ import annotations

import sys
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
