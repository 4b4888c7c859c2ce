"""What the benchmarks that start local processes share: a free loopback port and the Chromium executable."""
import shutil
import socket


def free_port(kind=socket.SOCK_STREAM) -> int:
    """A loopback port free right now (TCP by default; socket.SOCK_DGRAM for UDP)."""
    with socket.socket(socket.AF_INET, kind) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def chromium(bench: str) -> str:
    """The Chromium executable's path; SystemExit naming the benchmark when none is installed."""
    for name in ("chromium", "chromium-browser", "google-chrome"):
        if shutil.which(name):
            return shutil.which(name)
    raise SystemExit(f"{bench}: chromium is not installed (Debian package 'chromium')")
