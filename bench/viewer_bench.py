#!/usr/bin/python3
"""How much lcmtf-viewer costs, and how its page keeps up, with one page open in headless Chromium.

Two workloads, each over udpm (ttl=0) on a port of its own:
  g1      the Unitree G1 (39 links) from lcmtf-urdf-publisher, joint states at 500 Hz
  1000    a generated tree of 1000 frames: 900 fixed, 100 turning at 50 Hz
For each: the viewer's CPU (% of one core, from /proc/<pid>/stat) and Chromium's over the
measured seconds, the page's frames per second (requestAnimationFrame) and drawings of the 3D
view per second, and how long a change of fixed frame, and a scrub back in time, take from the
page's request to the drawing of the new scene.
Targets: the viewer at most 15 % of a core, the page at least 30 fps.

  /usr/bin/python3 bench/viewer_bench.py --bin-dir build/bin [--seconds 10] [--workload g1]
"""
import argparse
import math
import os
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(SOURCE, "tests", "viewer"))
import cdp  # noqa: E402
from viewer_processes import Programs, lcm_url  # noqa: E402

TICKS = os.sysconf("SC_CLK_TCK")


def cpu_seconds(pids):
    """utime + stime of these processes, in seconds; processes gone count 0."""
    total = 0
    for pid in pids:
        try:
            with open(f"/proc/{pid}/stat", encoding="ascii") as file:
                fields = file.read().rsplit(")", 1)[1].split()
            total += int(fields[11]) + int(fields[12])
        except (FileNotFoundError, ProcessLookupError):
            pass
    return total / TICKS


def session_pids(leader):
    """Every process in the session `leader` started (Chromium's renderer, GPU process, ...)."""
    pids = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat", encoding="ascii") as file:
                fields = file.read().rsplit(")", 1)[1].split()
            if int(fields[3]) == leader:  # session id
                pids.append(int(entry))
        except (FileNotFoundError, ProcessLookupError, IndexError):
            pass
    return pids


def tree_urdf(frames, moving_every):
    """A robot of `frames` links in a ternary tree; every `moving_every`-th joint turns."""
    lines = ['<?xml version="1.0"?>', '<robot name="tree1000">', '  <link name="f0"/>']
    for i in range(1, frames):
        parent = (i - 1) // 3
        branch = (i - 1) % 3
        kind = "revolute" if i % moving_every == 0 else "fixed"
        lines.append(f'  <link name="f{i}"/>')
        lines.append(
            f'  <joint name="j{i}" type="{kind}"><parent link="f{parent}"/><child link="f{i}"/>'
            f'<origin xyz="0.25 0 0.05" rpy="0 0.3 {2 * math.pi * branch / 3 - 2 * math.pi / 3:.6f}"/>'
            '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>')
    lines.append("</robot>")
    return "\n".join(lines) + "\n"


def measure(page, viewer, browser, seconds):
    """CPU of the viewer and of Chromium, fps and drawings per second over `seconds`."""
    chromium = session_pids(browser.process.pid)
    fps, renders = [], []
    wall0, viewer0, chromium0 = time.monotonic(), cpu_seconds([viewer.pid]), cpu_seconds(chromium)
    while time.monotonic() - wall0 < seconds:
        time.sleep(1.0)
        sample = page.evaluate("[lcmtfViewer.fps, lcmtfViewer.rendersPerSecond]")
        fps.append(sample[0])
        renders.append(sample[1])
    wall = time.monotonic() - wall0
    return {
        "viewer_cpu": 100 * (cpu_seconds([viewer.pid]) - viewer0) / wall,
        "chromium_cpu": 100 * (cpu_seconds(chromium) - chromium0) / wall,
        "fps_mean": statistics.mean(fps), "fps_min": min(fps),
        "renders_mean": statistics.mean(renders),
    }


def view_latencies(page, frames, rounds):
    """Milliseconds from choosing a fixed frame in the page to drawing the scene in it."""
    latencies = []
    for i in range(rounds):
        frame = frames[i % len(frames)]
        page.evaluate("lcmtfViewer.viewLatencyMs = null")
        page.evaluate(
            f"(() => {{ const s = document.getElementById('fixed-frame'); s.value = '{frame}';"
            " s.dispatchEvent(new Event('change')); })()")
        page.wait_for(f"lcmtfViewer.fixedFrame === '{frame}' && lcmtfViewer.viewLatencyMs !== null",
                      10, interval=0.02, what=f"the scene in {frame}")
        latencies.append(page.evaluate("lcmtfViewer.viewLatencyMs"))
    return latencies


def scrub_latencies(page, rounds):
    """Milliseconds from moving the paused time slider to drawing the scene at that time."""
    page.evaluate("document.getElementById('play-pause').click()")
    page.wait_for("lcmtfViewer.live === false", 10, what="the page to pause")
    latencies = []
    for i in range(rounds):
        page.evaluate("lcmtfViewer.viewLatencyMs = null")
        target = page.evaluate(
            "(() => { const s = document.getElementById('time-slider'); const h = lcmtfViewer.history;"
            f" const t = Math.round(h.newest - (h.newest - h.oldest) * {0.2 + 0.6 * (i % 4) / 3});"
            " s.value = String(t); s.dispatchEvent(new Event('input')); return t; })()")
        page.wait_for(f"Math.abs(lcmtfViewer.time - {target}) < 1000 && lcmtfViewer.viewLatencyMs !== null",
                      10, interval=0.02, what="the scrubbed scene")
        latencies.append(page.evaluate("lcmtfViewer.viewLatencyMs"))
        time.sleep(0.1)
    page.evaluate("document.getElementById('play-pause').click()")
    return latencies


def run_workload(name, args, chromium, port):
    with Programs(args.bin_dir) as programs:
        url = lcm_url(port)
        if name == "g1":
            urdf = os.path.join(args.shared_urdf, "unitree_g1_29dof.urdf")
            frames_expected = 39
            view_frames = ["pelvis", "left_ankle_roll_link", "torso_link", "right_wrist_yaw_link"]
            publisher_args = ["--sweep", "--rate", "500"]
        else:
            urdf = os.path.join(programs.log_dir, "tree1000.urdf")
            with open(urdf, "w", encoding="utf-8") as file:
                file.write(tree_urdf(1000, 10))
            frames_expected = 1000
            view_frames = ["f0", "f500", "f999", "f123"]
            publisher_args = ["--sweep", "--rate", "50"]
        programs.start("lcmtf-urdf-publisher", "--lcm-url", url, urdf)
        programs.start("lcmtf-joint-publisher", "--lcm-url", url, *publisher_args, urdf)
        viewer, base = programs.start_viewer(port)
        browser = cdp.Browser(chromium, 1280, 800)
        try:
            page = browser.open_page(base + "/" + args.page_query, 1280, 800)
            page.wait_for(f"window.lcmtfViewer && lcmtfViewer.framesDrawn >= {frames_expected}"
                          f" && lcmtfViewer.framesListed >= {frames_expected}", 60,
                          what=f"{frames_expected} frames drawn and listed")
            time.sleep(2.0)  # past the first drawings and the camera fit
            result = measure(page, viewer, browser, args.seconds)
            result["view_ms"] = view_latencies(page, view_frames, args.rounds)
            result["scrub_ms"] = scrub_latencies(page, args.rounds)
            result["frames"] = page.evaluate("lcmtfViewer.framesDrawn")
            errors = page.errors()
            if errors:
                print(f"page errors: {errors}")
            programs.check_alive()
            return result
        finally:
            browser.close()


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bin-dir", default=os.path.join(SOURCE, "build", "bin"),
                        help="folder of lcmtf's programs (default: build/bin)")
    parser.add_argument("--shared-urdf", default=os.path.join(SOURCE, "..", "shared", "urdf"),
                        help="folder of the shared robot files")
    parser.add_argument("--seconds", type=float, default=10.0, help="seconds measured per workload")
    parser.add_argument("--rounds", type=int, default=12, help="view changes and scrubs timed")
    parser.add_argument("--workload", choices=["g1", "1000"], action="append",
                        help="workload to run (repeatable; default: both)")
    parser.add_argument("--lcm-port", type=int, default=17681, help="first udpm port to use")
    parser.add_argument("--page-query", default="", help="appended to the page URL, e.g. ?antialias=0")
    args = parser.parse_args()

    chromium = cdp.find_chromium()
    if chromium is None:
        print("chromium is not installed")
        return 1
    print(f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f} at start; "
          f"{args.seconds:.0f} s per workload, one page at 1280x800 in headless Chromium (SwiftShader)")
    header = (f"{'workload':<26}{'frames':>7}{'viewer CPU':>12}{'Chromium CPU':>14}"
              f"{'page fps':>14}{'draws/s':>9}{'view change ms':>22}{'scrub ms':>20}")
    rows = []
    for i, name in enumerate(args.workload or ["g1", "1000"]):
        result = run_workload(name, args, chromium, args.lcm_port + i)
        label = "G1, joints at 500 Hz" if name == "g1" else "1000 frames, 100 at 50 Hz"
        view = sorted(result["view_ms"])
        scrub = sorted(result["scrub_ms"])
        rows.append(
            f"{label:<26}{result['frames']:>7}{result['viewer_cpu']:>11.1f}%"
            f"{result['chromium_cpu']:>13.0f}%"
            f"{result['fps_mean']:>8.1f} (≥{result['fps_min']:>2})"
            f"{result['renders_mean']:>9.1f}"
            f"{statistics.median(view):>11.0f} (max {max(view):>4.0f})"
            f"{statistics.median(scrub):>9.0f} (max {max(scrub):>4.0f})")
        print(rows[-1], flush=True)
    print()
    print(header)
    for row in rows:
        print(row)
    print("viewer CPU: % of one core; page fps: mean (lowest 1 s sample); "
          "view change and scrub: median (max) from the page's request to its drawing")
    return 0


if __name__ == "__main__":
    sys.exit(main())
