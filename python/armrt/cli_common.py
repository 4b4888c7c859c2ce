"""What every `armrt` subcommand shares (cli.py, and view.py's view/animate/export): the user errors
reported in one line, CliError, and the parsing of NAME=VALUE pairs and file suffixes. Its own module
so that view.py can use it without importing cli.py, which registers view.py's subcommands."""
from __future__ import annotations

from pathlib import Path

# What a person can get wrong: reported in one line, never as a traceback (bugs still show one).
USER_ERRORS = (ValueError, KeyError, TypeError, OSError, MemoryError, OverflowError, RuntimeError)


class CliError(Exception):
    """A mistake in the command line itself (reported like argparse's errors)."""


def error_text(exc: BaseException) -> str:
    """One line for an exception: KeyError's repr quotes removed, first line only."""
    msg = exc.args[0] if isinstance(exc, KeyError) and exc.args else str(exc)
    if isinstance(exc, FileNotFoundError) and exc.filename and str(exc.filename) not in str(msg):
        msg = f"{exc.filename}: {exc.strerror or msg}"
    elif isinstance(exc, OSError) and exc.filename and exc.strerror:
        msg = f"{exc.filename}: {exc.strerror}"
    return " ".join(str(msg).split()) or type(exc).__name__


def parse_assignments(items: list[str]) -> dict[str, float]:
    """NAME=VALUE pairs; every malformed item reported at once."""
    out, bad = {}, []
    for item in items:
        name, sep, value = item.partition("=")
        if not sep or not name:
            bad.append(f"{item!r} is not NAME=VALUE")
            continue
        try:
            out[name] = float(value)
        except ValueError:
            bad.append(f"{item!r}: {value!r} is not a number")
    if bad:
        raise CliError("; ".join(bad))
    return out


def check_suffix(path: str | None, allowed: tuple[str, ...], what: str) -> None:
    if path is not None and Path(path).suffix.lower() not in allowed:
        raise CliError(f"{what} {path!r}: unsupported format {Path(path).suffix or '(no suffix)'!r}; "
                       f"use {' or '.join(allowed)}")
