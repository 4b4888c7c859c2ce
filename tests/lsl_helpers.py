"""Shared by the LSL tests: pylsl or a skip naming why it cannot load, and a stream id unique to this run."""
import time

import pytest


def pylsl_or_skip():
    try:
        import pylsl
        pylsl.library_version()
        return pylsl
    except Exception as e:  # ImportError, or RuntimeError when liblsl cannot load
        pytest.skip(f"pylsl/liblsl cannot load: {type(e).__name__}: {e}")


def unique_id(prefix: str) -> str:
    return f"{prefix}{time.monotonic_ns() % 10**9}"
