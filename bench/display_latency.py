"""Participant display: frame rate and state-to-frame latency on this machine (issue 29 item 2; not a test).

Runs a live centre-out task (armrt.task_live.run_live, point cursor and simulated decoder, or with --arm the das2
hand through the endpoint controller) publishing its state at --fps to the participant page (armrt.display),
shown by a headless Chromium (software rendering: --use-angle=swiftshader, no GPU, no display vsync). Every state
the page draws is acknowledged at its next animation frame (DisplayServer.acks): latency = ack received - state
published, on the server's clock (an upper bound of state-to-frame: it includes the ack's loopback hop back).
Reports states published and drawn per second, the page's animation-frame rate, latency median / p95 / p99 /
max, the machine's load average before and after, and writes bench/results/display_latency.{json,md}.

    python -m bench.display_latency [--duration 20] [--fps 60] [--arm das2] [--json bench/results/display_latency.json]
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

from bench._local import chromium, free_port

ROOT = Path(__file__).resolve().parents[1]


def _pct(x, q):
    return float(np.percentile(x, q)) if len(x) else float("nan")


def run(duration: float, fps: float, arm_model: str | None, window=(1280, 800)) -> dict:
    from armrt import tasks
    from armrt.display import DisplayServer, fit_plane
    from armrt.task_live import ArmDriver, CursorDriver, run_live
    if arm_model:
        from armrt.arm import Arm
        from armrt.endpoint_control import EndpointController
        arm = Arm(arm_model)
        q0 = np.radians([30, 60, 10, 60, 80])
        arm.reset(q=q0)
        centre = arm.model.hand_position(q0)
        dec = tasks.SimulatedDecoder(4.0, 0.01, 0.05, arm.dt, seed=0)
        driver = ArmDriver(EndpointController(arm), dec)
        extra = [driver.shoulder()]
    else:
        centre = np.zeros(3)
        dec = tasks.SimulatedDecoder(4.0, 0.01, 0.05, 0.002, seed=0)
        driver = CursorDriver(centre, dec, 0.002)
        extra = []
    targets = tasks.centre_out_targets(centre, 0.1, 0.015, 8) * 1000   # more than the run needs: it stops on time
    task = tasks.TargetTask(targets, 0.3, 5.0, 0.2)
    load0 = os.getloadavg()
    with DisplayServer(fit_plane(targets[:8], centre=centre, points=extra), port=free_port()) as server, \
            tempfile.TemporaryDirectory() as profile:
        proc = subprocess.Popen([chromium("display_latency"), "--headless=new", "--no-sandbox", "--use-angle=swiftshader",
                                 "--enable-unsafe-swiftshader", "--no-first-run", "--disable-extensions",
                                 f"--window-size={window[0]},{window[1]}", f"--user-data-dir={profile}", server.url],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            if not server.wait_for_page("participant", 30):
                raise SystemExit("display_latency: the page did not connect within 30 s")
            time.sleep(1.0)   # first frames
            n0 = len(server.acks)
            t0 = time.perf_counter()
            stats = run_live(task, driver, display=server, fps=fps, max_time_s=duration, hold_s=0.0)
            wall = time.perf_counter() - t0
            time.sleep(0.3)   # the last acks
            acks = [a for a in server.acks[n0:] if a.page == "participant"]
        finally:
            proc.terminate()
            proc.wait(timeout=10)
    load1 = os.getloadavg()
    lat = np.array([a.latency_s for a in acks]) * 1e3
    d2f = np.array([a.draw_to_frame_s for a in acks]) * 1e3
    raf = ((acks[-1].ticks - acks[0].ticks) / ((acks[-1].page_time_ms - acks[0].page_time_ms) / 1e3)
           if len(acks) > 1 else float("nan"))
    return {"driver": f"{arm_model} hand (endpoint controller)" if arm_model else "point cursor",
            "duration_s": duration, "wall_s": wall, "fps_requested": fps,
            "states_published": stats["published"], "states_drawn": len(acks),
            "published_per_s": stats["published"] / wall, "drawn_per_s": len(acks) / wall,
            "page_animation_frames_per_s": raf, "task_largest_lateness_ms": stats["lag_s"] * 1e3,
            "latency_ms": {"median": _pct(lat, 50), "p95": _pct(lat, 95), "p99": _pct(lat, 99),
                           "max": float(lat.max()) if len(lat) else float("nan")},
            "draw_to_next_frame_ms": {"median": _pct(d2f, 50), "max": float(d2f.max()) if len(d2f) else float("nan")},
            "latency_to_draw_ms": {"median": _pct(lat - d2f, 50), "p99": _pct(lat - d2f, 99)},
            "window": list(window), "load_avg_before": list(load0), "load_avg_after": list(load1),
            "cpus": os.cpu_count(), "machine": platform.node(), "python": platform.python_version()}


def markdown(results: list[dict], cmd: str) -> str:
    r0 = results[0]
    lines = [f"# Participant display: frame rate and state-to-frame latency (`{cmd}`)", "",
             f"Headless Chromium (software rendering, SwiftShader; no GPU, no display vsync), window "
             f"{r0['window'][0]} x {r0['window'][1]}, {r0['cpus']} CPUs shared with other work: 1-min load average "
             + ", ".join(f"{r['load_avg_before'][0]:.2f} before / {r['load_avg_after'][0]:.2f} after" for r in results)
             + ". The machine was loaded: these are figures of this shared machine, not of a lab PC.", "",
             "Latency: state published -> the page's animation frame after the one that drew it, acknowledged back "
             "over the WebSocket (server clock; includes that loopback hop). To draw: the same minus the page's "
             "draw -> next frame interval (page clock), i.e. state published -> drawn into the canvas.", "",
             "| driver | states sent/s | drawn/s | page frames/s | latency median (ms) | p95 | p99 | max | "
             "to draw median (ms) | p99 | task lateness max (ms) |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in results:
        L = r["latency_ms"]
        lines.append(f"| {r['driver']} | {r['published_per_s']:.1f} | {r['drawn_per_s']:.1f} | "
                     f"{r['page_animation_frames_per_s']:.1f} | {L['median']:.1f} | {L['p95']:.1f} | {L['p99']:.1f} | "
                     f"{L['max']:.1f} | {r['latency_to_draw_ms']['median']:.1f} | {r['latency_to_draw_ms']['p99']:.1f} | "
                     f"{r['task_largest_lateness_ms']:.1f} |")
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m bench.display_latency", description=__doc__.split("\n\n")[0])
    ap.add_argument("--duration", type=float, default=20.0, help="s of task per driver")
    ap.add_argument("--fps", type=float, default=60.0, help="states published per second")
    ap.add_argument("--arm", default="das2", help="also run with this model's hand ('' to skip)")
    ap.add_argument("--json", default=str(ROOT / "bench" / "results" / "display_latency.json"))
    a = ap.parse_args(argv)
    results = [run(a.duration, a.fps, None)]
    if a.arm:
        results.append(run(a.duration, a.fps, a.arm))
    cmd = "python -m bench.display_latency" + (f" --duration {a.duration:g}" if a.duration != 20 else "") + \
        (f" --fps {a.fps:g}" if a.fps != 60 else "") + (f" --arm {a.arm!r}" if a.arm != "das2" else "")
    out = Path(a.json)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps({"command": cmd, "results": results}, indent=1))
    md = markdown(results, cmd)
    out.with_suffix(".md").write_text(md)
    print(md)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
