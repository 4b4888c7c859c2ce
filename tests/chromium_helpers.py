"""Shared by the browser tests (test_view, test_display): a headless Chromium tab driven over the DevTools protocol
(websocket-client), screenshots as arrays, a free TCP port."""
import base64
import contextlib
import io
import json
import shutil
import socket
import subprocess
import time
import urllib.request

import numpy as np
import pytest


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def chromium() -> str | None:
    for name in ("chromium", "chromium-browser", "google-chrome"):
        if shutil.which(name):
            return shutil.which(name)
    return None


needs_chromium = pytest.mark.skipif(chromium() is None, reason="chromium is not installed (Debian package 'chromium')")


class Page:
    """A Chromium tab driven over the DevTools protocol (websocket-client)."""

    def __init__(self, ws_url: str):
        import websocket
        self.ws = websocket.create_connection(ws_url, timeout=30, suppress_origin=True)
        self.n = 0

    def call(self, method: str, **params):
        self.n += 1
        self.ws.send(json.dumps({"id": self.n, "method": method, "params": params}))
        while True:
            msg = json.loads(self.ws.recv())
            if msg.get("id") == self.n:
                if "error" in msg:
                    raise RuntimeError(f"{method}: {msg['error']}")
                return msg["result"]

    def eval(self, js: str):
        return self.call("Runtime.evaluate", expression=js, returnByValue=True)["result"].get("value")

    def wait_for(self, js: str, what: str, timeout: float = 30.0) -> None:
        """Polls the expression js until it is true; AssertionError naming `what` after timeout s."""
        deadline = time.monotonic() + timeout
        while not self.eval(js):
            assert time.monotonic() < deadline, what
            time.sleep(0.2)

    def screenshot(self) -> tuple[np.ndarray, bytes]:
        from PIL import Image
        png = base64.b64decode(self.call("Page.captureScreenshot", format="png")["data"])
        return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")), png


@contextlib.contextmanager
def chromium_page(url: str, tmp_path, window=(1000, 700)):
    """A headless Chromium showing url, driven over DevTools; yields a Page."""
    pytest.importorskip("websocket", reason="websocket-client is not installed (pip install websocket-client)")
    pytest.importorskip("PIL", reason="Pillow is not installed")
    port = free_port()
    profile = tmp_path / "profile"
    cmd = [chromium(), "--headless=new", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
           "--no-first-run", "--disable-extensions", f"--window-size={window[0]},{window[1]}",
           f"--remote-debugging-port={port}", "--remote-allow-origins=*", f"--user-data-dir={profile}", url]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 20
        ws_url = None
        while ws_url is None:
            assert time.monotonic() < deadline, "chromium did not open its DevTools endpoint"
            try:
                with urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list", timeout=2) as r:
                    ws_url = next((t["webSocketDebuggerUrl"] for t in json.load(r) if t.get("type") == "page"), None)
            except OSError:
                pass
            time.sleep(0.2)
        page = Page(ws_url)
        try:
            yield page
        finally:
            # Closed here, not left to the garbage collector: an unclosed socket's ResourceWarning would
            # surface in whatever test runs when it is collected (test_gym's warning-free check did).
            page.ws.close()
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            proc.kill()
