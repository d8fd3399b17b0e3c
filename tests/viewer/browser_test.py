#!/usr/bin/python3
"""lcmtf-viewer's page in headless Chromium, end to end, with the real programs over udpm.

Cases (--case):
  demo             the demo robot sweeping: every link listed, the view drawn and moving, pausing
                   and scrubbing draws an earlier time; --screenshot saves a picture of the page
  joint_sliders    no joint publisher: the page's sliders drive the robot through the viewer
  reconnect        the viewer restarts: the page says so, reconnects, and keeps its fixed frame
  panda_meshes     the Panda with its COLLADA meshes: all load, none fail
  panda_stl_meshes the Panda drawn with its STL (collision) meshes
  missing_meshes   the G1, whose meshes are missing: warnings, and every frame still drawn
  broken_meshes    mesh files that are there but unreadable: a warning each, frames drawn;
                   a tree not connected to the robot is listed, not drawn
Exit status: 0 passed, 1 failed, 77 skipped (no Chromium, or a robot file is missing).
"""
import argparse
import math
import os
import socket
import sys
import time
import traceback
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
try:
    import cdp  # noqa: E402
except ImportError as missing:  # Debian's python3-websocket
    print(f"SKIPPED: {missing}")
    sys.exit(77)
from viewer_processes import Programs, add_test_arguments, lcm_url  # noqa: E402

SKIP = 77
WIDTH, HEIGHT = 1280, 800
# The 3D view's part of the page (the side panel is 360 px wide, the time bar 42 px high).
VIEW_CLIP = (0, 0, WIDTH - 360, HEIGHT - 50)


class Skip(Exception):
    """The case cannot run here."""


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def link_names(urdf):
    return [link.get("name") for link in ElementTree.parse(urdf).getroot().findall("link")]


def stats(page):
    return page.evaluate("JSON.parse(JSON.stringify(window.lcmtfViewer || null))")


def wait_for_frames_listed(page, names, timeout=30):
    """Waits until the tree lists every name; returns the names it never listed."""
    names_js = repr(list(names)).replace("'", '"')
    expression = (f"{names_js}.filter(n => !document.querySelector("
                  f"`#frame-tree li[data-frame=\"${{CSS.escape(n)}}\"]`))")
    deadline = time.monotonic() + timeout
    missing = names
    while time.monotonic() < deadline:
        missing = page.evaluate(expression)
        if not missing:
            return []
        time.sleep(0.2)
    return missing


def view_pixels(page, scale=0.5):
    """The 3D view's pixels at half size, as a list of (r, g, b)."""
    x, y, width, height = VIEW_CLIP
    png = page.screenshot(clip=(x, y, width, height), scale=scale)
    return cdp.pixels(png)


def describe_drawing(pixels):
    background = max(set(pixels[::7]), key=pixels[::7].count)
    near_background = sum(1 for p in pixels if sum(abs(a - b) for a, b in zip(p, background)) < 24)
    return {
        "colours": len(set(pixels)),
        "drawn_fraction": 1 - near_background / len(pixels),
        "background": background,
    }


def differing_fraction(first, second):
    changed = sum(1 for a, b in zip(first, second) if sum(abs(x - y) for x, y in zip(a, b)) > 30)
    return changed / max(1, len(first))


def quaternion_angle(q1, q2):
    """The angle in radians between two unit quaternions (x, y, z, w)."""
    dot = abs(sum(a * b for a, b in zip(q1, q2)))
    return 2 * math.acos(min(1.0, dot))


def relative_rotation(parent_pose, child_pose):
    """The child's rotation in the parent's, from two poses in the fixed frame."""
    px, py, pz, pw = parent_pose[3:]
    cx, cy, cz, cw = child_pose[3:]
    # conjugate(parent) * child
    x, y, z, w = -px, -py, -pz, pw
    return (w * cx + x * cw + y * cz - z * cy,
            w * cy - x * cz + y * cw + z * cx,
            w * cz + x * cy - y * cx + z * cw,
            w * cw - x * cx - y * cy - z * cz)


def open_viewer(browser, url, query=""):
    page = browser.open_page(url + "/" + query, WIDTH, HEIGHT)
    page.wait_for("window.lcmtfViewer && window.lcmtfViewer.connection === 'open'", 20,
                  what="the page to connect")
    return page


def check_no_page_errors(page):
    errors = page.errors()
    check(not errors, f"the page reported errors: {errors}")


# --- Cases -------------------------------------------------------------------------------------

def case_demo(args, browser, programs):
    urdf = os.path.join(args.source_dir, "examples", "mobile_manipulator.urdf")
    url = lcm_url(args.lcm_port)
    programs.start("lcmtf-urdf-publisher", "--lcm-url", url, urdf)
    programs.start("lcmtf-joint-publisher", "--lcm-url", url, "--sweep", "--sweep-period", "4", urdf)
    _, base = programs.start_viewer(args.lcm_port)
    # The picture is taken with smooth edges, which the page leaves off where WebGL runs on
    # the CPU.
    page = open_viewer(browser, base, "?antialias=1" if args.screenshot else "")

    links = link_names(urdf)
    missing = wait_for_frames_listed(page, links)
    check(not missing, f"the tree never listed {missing}")
    page.wait_for(f"lcmtfViewer.framesDrawn >= {len(links)}", 20, what="every link drawn")
    print(f"listed and drew all {len(links)} links")
    # Past the first scenes and the camera's fit; the first screenshot only warms up.
    page.wait_for("lcmtfViewer.sceneCount >= 20", 20, what="20 scenes drawn")
    view_pixels(page)

    first = view_pixels(page)
    drawing = describe_drawing(first)
    print(f"view: {drawing['colours']} colours, {drawing['drawn_fraction']:.1%} not background")
    check(drawing["colours"] >= 50, f"the view has only {drawing['colours']} colours")
    check(drawing["drawn_fraction"] > 0.02, "the view is almost all background")

    time.sleep(1.0)
    second = view_pixels(page)
    moved = differing_fraction(first, second)
    print(f"1 s later {moved:.2%} of the view changed")
    if moved <= 0.002:  # the robot may pass a turning point: once more
        time.sleep(1.0)
        moved = differing_fraction(second, view_pixels(page))
        print(f"1 s later still {moved:.2%} of the view changed")
    check(moved > 0.002, "the robot did not move between two screenshots 1 s apart")

    # Pause, then scrub back: the poses drawn are those of an earlier time.
    page.wait_for("lcmtfViewer.history.newest - lcmtfViewer.history.oldest > 3e6", 20,
                  what="3 s of history")
    live_pose = page.evaluate("lcmtfViewer.pose('tool_flange')")
    page.evaluate("document.getElementById('play-pause').click()")
    page.wait_for("lcmtfViewer.live === false", 10, what="the page to pause")
    target = page.evaluate(
        "(() => { const s = document.getElementById('time-slider');"
        " const t = Math.round(lcmtfViewer.history.newest - 2.5e6); s.value = String(t);"
        " s.dispatchEvent(new Event('input', {bubbles: true})); return t; })()")
    page.wait_for(f"Math.abs(lcmtfViewer.time - {target}) < 1000", 10, what="the scrubbed time drawn")
    paused = stats(page)
    check(not paused["live"], "the page went live while scrubbing")
    past_pose = page.evaluate("lcmtfViewer.pose('tool_flange')")
    check(past_pose is not None, "tool_flange is not drawn at the scrubbed time")
    distance = math.dist(live_pose[:3], past_pose[:3])
    print(f"scrubbed to {(paused['history']['newest'] - paused['time']) / 1e6:.1f} s ago: "
          f"tool_flange {distance * 100:.1f} cm from where it was live")
    check(distance > 0.01 or quaternion_angle(live_pose[3:], past_pose[3:]) > 0.02,
          "the scrubbed pose is the live one")
    label = page.evaluate("document.getElementById('time-label').textContent")
    check(label.startswith("paused"), f"the time label says {label!r} while paused")
    # Paused, the pose stays put while the robot moves on.
    time.sleep(0.5)
    check(page.evaluate("lcmtfViewer.pose('tool_flange')") == past_pose,
          "the paused pose changed")
    page.evaluate("document.getElementById('play-pause').click()")
    page.wait_for("lcmtfViewer.live === true", 10, what="the page to go live again")

    if args.screenshot:
        save_screenshot(page, args.screenshot)
    check_no_page_errors(page)


def save_screenshot(page, path):
    """The demo robot as the README shows it: paused when its gripper was highest in the
    history, so that the arm shows, framed, with labels on and a frame selected."""
    page.evaluate("document.getElementById('play-pause').click()")
    page.wait_for("lcmtfViewer.live === false", 10, what="the page to pause")
    history = page.evaluate("lcmtfViewer.history")
    best = None
    for step in range(16):
        stamp = scrub_to(page, history["oldest"] + (history["newest"] - history["oldest"]) * (step + 0.5) / 16)
        pose = page.evaluate("lcmtfViewer.pose('gripper_tcp')")
        if pose and (best is None or pose[2] > best[1]):
            best = (stamp, pose[2])
    if best:
        scrub_to(page, best[0])
    page.evaluate("lcmtfViewer.setLabels(true)")
    page.evaluate("lcmtfViewer.select('tool_flange')")
    page.evaluate("lcmtfViewer.fitView()")
    time.sleep(1.5)  # the fps figure is refreshed once a second
    png = page.screenshot()
    page.evaluate("document.getElementById('play-pause').click()")
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "wb") as file:
        file.write(png)
    print(f"saved {path}")


def scrub_to(page, stamp):
    """Moves the paused time slider to `stamp` and waits until the page drew that time. The
    history moves on while the page is paused: a stamp that has left it, or is about to, is
    taken from half a second inside its oldest end instead. Returns the stamp drawn."""
    history = page.evaluate("lcmtfViewer.history")
    stamp = round(min(max(stamp, history["oldest"] + 500_000), history["newest"]))
    page.evaluate(
        "(() => { const s = document.getElementById('time-slider');"
        f" s.value = '{stamp}'; s.dispatchEvent(new Event('input', {{bubbles: true}})); }})()")
    page.wait_for(f"Math.abs(lcmtfViewer.time - {stamp}) < 1000", 10, what="the scrubbed time drawn")
    return stamp


def case_joint_sliders(args, browser, programs):
    urdf = os.path.join(args.source_dir, "examples", "mobile_manipulator.urdf")
    programs.start("lcmtf-urdf-publisher", "--lcm-url", lcm_url(args.lcm_port), urdf)
    _, base = programs.start_viewer(args.lcm_port)
    page = open_viewer(browser, base)
    page.wait_for("document.querySelector('input[data-joint=\"base_x_joint\"]') !== null", 20,
                  what="the joint sliders")
    # With no joint states, the frames below a movable joint have no pose.
    time.sleep(1.0)
    check(page.evaluate("lcmtfViewer.pose('base_x_link')") is None,
          "base_x_link is drawn before any joint state")
    check(not page.evaluate("document.getElementById('joints-switch').checked"),
          "the joint switch is on before anyone turned it on")

    def set_slider(joint, value):
        page.evaluate(
            f"(() => {{ const s = document.querySelector('input[data-joint=\"{joint}\"]');"
            f" s.value = '{value}'; s.dispatchEvent(new Event('input', {{bubbles: true}})); }})()")

    page.evaluate("document.getElementById('joints-switch').click()")
    page.wait_for("lcmtfViewer.jointsPublishing", 10, what="the viewer to say it publishes")
    # Each message carries every slider, so once base_x_joint (moved last) shows, so does the
    # shoulder.
    set_slider("shoulder_pan_joint", 0.2)
    set_slider("base_x_joint", 0.5)
    page.wait_for("(p => p && Math.abs(p[0] - 0.5) < 1e-3)(lcmtfViewer.pose('base_x_link'))", 15,
                  what="base_x_link at x = 0.5")
    page.wait_for("lcmtfViewer.pose('shoulder_link') !== null", 10, what="shoulder_link drawn")
    before = relative_rotation(page.evaluate("lcmtfViewer.pose('arm_base_link')"),
                               page.evaluate("lcmtfViewer.pose('shoulder_link')"))
    set_slider("shoulder_pan_joint", 1.2)
    set_slider("base_x_joint", -0.7)
    page.wait_for("(p => p && Math.abs(p[0] + 0.7) < 1e-3)(lcmtfViewer.pose('base_x_link'))", 15,
                  what="base_x_link at x = -0.7")
    after = relative_rotation(page.evaluate("lcmtfViewer.pose('arm_base_link')"),
                              page.evaluate("lcmtfViewer.pose('shoulder_link')"))
    turned = quaternion_angle(before, after)
    print(f"the shoulder turned {turned:.3f} rad for a slider move of 1.0 rad")
    check(abs(turned - 1.0) < 0.01, f"the shoulder turned {turned} rad, not 1.0")

    # Off: the viewer stops publishing, and the robot stays where the sliders left it.
    page.evaluate("document.getElementById('joints-switch').click()")
    page.wait_for("lcmtfViewer.jointsPublishing === false", 10, what="the viewer to stop publishing")
    set_slider("base_x_joint", 1.0)
    time.sleep(1.0)
    x = page.evaluate("lcmtfViewer.pose('base_x_link')")
    check(x is None or abs(x[0] + 0.7) < 1e-3, f"a slider moved the robot while off: {x}")
    # With no joint states any more, the moving frames go stale (after 1 s) and are greyed.
    page.wait_for("document.querySelector('#frame-tree li[data-frame=\"base_x_link\"]')"
                  ".classList.contains('stale')", 10, what="base_x_link greyed as stale")
    check_no_page_errors(page)


def case_panda_meshes(args, browser, programs, stl=False):
    urdf = os.path.join(args.shared_urdf, "panda.urdf")
    packages = os.path.join(args.shared_urdf, "packages")
    if not os.path.isfile(urdf) or not os.path.isdir(packages):
        raise Skip(f"{urdf} or {packages} is missing")
    if stl:
        # The same robot drawn with its collision meshes, which are STL files.
        with open(urdf, encoding="utf-8") as file:
            text = file.read().replace("/meshes/visual/", "/meshes/collision/").replace(".dae", ".stl")
        urdf = os.path.join(programs.log_dir, "panda_stl.urdf")
        with open(urdf, "w", encoding="utf-8") as file:
            file.write(text)
    url = lcm_url(args.lcm_port)
    programs.start("lcmtf-urdf-publisher", "--lcm-url", url, urdf)
    programs.start("lcmtf-joint-publisher", "--lcm-url", url, "--sweep", urdf)
    _, base = programs.start_viewer(args.lcm_port, "--package-path", packages)
    page = open_viewer(browser, base)
    page.wait_for("lcmtfViewer.robotLoaded && lcmtfViewer.meshesLoaded > 0 &&"
                  " lcmtfViewer.meshesPending === 0", 60, what="the Panda's meshes")
    result = stats(page)
    print(f"meshes loaded {result['meshesLoaded']}, failed {result['meshesFailed']}, "
          f"warnings {result['warnings']}")
    check(result["meshesFailed"] == 0, f"meshes failed: {result['warnings']}")
    links = link_names(urdf)
    page.wait_for(f"lcmtfViewer.framesDrawn >= {len(links)}", 20, what="every Panda link drawn")
    drawing = describe_drawing(view_pixels(page))
    print(f"view: {drawing['colours']} colours, {drawing['drawn_fraction']:.1%} not background")
    check(drawing["drawn_fraction"] > 0.02, "the Panda is not drawn")
    check_no_page_errors(page)


def case_panda_stl_meshes(args, browser, programs):
    case_panda_meshes(args, browser, programs, stl=True)


def case_reconnect(args, browser, programs):
    urdf = os.path.join(args.source_dir, "examples", "mobile_manipulator.urdf")
    url = lcm_url(args.lcm_port)
    programs.start("lcmtf-urdf-publisher", "--lcm-url", url, urdf)
    programs.start("lcmtf-joint-publisher", "--lcm-url", url, "--sweep", urdf)
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    viewer, base = programs.start_viewer(args.lcm_port, port=port)
    page = open_viewer(browser, base)
    page.wait_for("lcmtfViewer.framesDrawn >= 26", 20, what="every link drawn")
    # The user's fixed frame outlives the connection.
    page.evaluate("(() => { const s = document.getElementById('fixed-frame'); s.value = 'base_link';"
                  " s.dispatchEvent(new Event('change')); })()")
    page.wait_for("lcmtfViewer.fixedFrame === 'base_link'", 10, what="the scene in base_link")

    programs.stop(viewer)
    programs.running.remove(viewer)
    page.wait_for("lcmtfViewer.connection === 'reconnecting'", 10, what="the page to see it gone")
    badge = page.evaluate("document.getElementById('connection-state').textContent")
    print(f"viewer stopped; the page says {badge!r}")
    check("retrying" in badge, f"the page says {badge!r} while the viewer is gone")
    time.sleep(2.0)
    programs.start_viewer(args.lcm_port, port=port)
    page.wait_for("lcmtfViewer.connection === 'open' && lcmtfViewer.framesDrawn >= 26 &&"
                  " lcmtfViewer.fixedFrame === 'base_link'", 30,
                  what="the page to reconnect and draw in base_link again")
    print("reconnected, drawing in base_link again")
    check_no_page_errors(page)


def case_missing_meshes(args, browser, programs):
    urdf = os.path.join(args.shared_urdf, "unitree_g1_29dof.urdf")
    if not os.path.isfile(urdf):
        raise Skip(f"{urdf} is missing")
    url = lcm_url(args.lcm_port)
    programs.start("lcmtf-urdf-publisher", "--lcm-url", url, urdf)
    programs.start("lcmtf-joint-publisher", "--lcm-url", url, "--sweep", urdf)
    _, base = programs.start_viewer(args.lcm_port)
    page = open_viewer(browser, base)
    page.wait_for("lcmtfViewer.robotLoaded", 20, what="the G1's description")
    links = link_names(urdf)
    missing = wait_for_frames_listed(page, links)
    check(not missing, f"the tree never listed {missing}")
    page.wait_for(f"lcmtfViewer.framesDrawn >= {len(links)}", 20, what="every G1 frame drawn")
    result = stats(page)
    panel = page.evaluate("document.querySelectorAll('#warnings li').length")
    print(f"{result['framesDrawn']} frames drawn, {len(result['warnings'])} warnings, "
          f"{panel} in the panel; first: {result['warnings'][:1]}")
    check(result["warnings"], "no warnings about the missing meshes")
    check(any("mesh" in warning for warning in result["warnings"]), "no warning names a mesh")
    check(panel >= len(result["warnings"]), "the panel does not list every warning")
    drawing = describe_drawing(view_pixels(page))
    check(drawing["colours"] >= 10, "the G1's frames are not drawn")
    check_no_page_errors(page)


def case_broken_meshes(args, browser, programs):
    """Mesh files that are found but cannot be read: each is a warning, the frames are drawn."""
    package = os.path.join(programs.log_dir, "packages", "broken")
    os.makedirs(package)
    with open(os.path.join(package, "short.stl"), "wb") as file:
        file.write(b"solid x\n")
    with open(os.path.join(package, "noise.stl"), "wb") as file:
        file.write(bytes(range(256)) * 4)
    with open(os.path.join(package, "text.dae"), "w", encoding="utf-8") as file:
        file.write("this is not XML")
    urdf = os.path.join(programs.log_dir, "broken.urdf")
    links = ["base", "a", "b", "c"]
    with open(urdf, "w", encoding="utf-8") as file:
        file.write('<robot name="broken"><link name="base"><visual><geometry><box size="0.2 0.2 0.2"/>'
                   "</geometry></visual></link>")
        for link, mesh in zip(links[1:], ["short.stl", "noise.stl", "text.dae"]):
            file.write(f'<link name="{link}"><visual><geometry><mesh filename="package://broken/{mesh}"/>'
                       f'</geometry></visual></link><joint name="{link}_joint" type="fixed">'
                       f'<parent link="base"/><child link="{link}"/><origin xyz="0.3 0 0"/></joint>')
        file.write("</robot>")
    programs.start("lcmtf-urdf-publisher", "--lcm-url", lcm_url(args.lcm_port), urdf)
    # A tree of its own, not connected to the robot: listed, not drawn.
    island = os.path.isfile(os.path.join(args.bin_dir, "lcmtf-static-publisher"))
    if island:
        programs.start("lcmtf-static-publisher", "--lcm-url", lcm_url(args.lcm_port),
                       "1", "0", "0", "0", "0", "0", "island_map", "island")
    _, base = programs.start_viewer(args.lcm_port, "--package-path",
                                    os.path.join(programs.log_dir, "packages"))
    page = open_viewer(browser, base)
    if island:
        page.wait_for("document.querySelector('#frame-tree li[data-frame=\"island\"]') !== null &&"
                      " document.getElementById('unconnected').textContent.includes('island_map')",
                      20, what="the unconnected tree listed")
        check(page.evaluate("lcmtfViewer.pose('island')") is None, "the unconnected frame is drawn")
        print("the unconnected tree island_map is listed, not drawn")
    page.wait_for("lcmtfViewer.robotLoaded && lcmtfViewer.meshesPending === 0 &&"
                  " lcmtfViewer.meshesFailed + lcmtfViewer.meshesLoaded === 3", 30,
                  what="the three meshes tried")
    page.wait_for(f"lcmtfViewer.framesDrawn >= {len(links)}", 20, what="every frame drawn")
    result = stats(page)
    print(f"meshes failed {result['meshesFailed']}: {result['warnings']}")
    check(result["meshesFailed"] == 3, f"{result['meshesFailed']} meshes failed, not 3")
    for mesh in ["short.stl", "noise.stl", "text.dae"]:
        check(any(mesh in warning for warning in result["warnings"]), f"no warning names {mesh}")
    check_no_page_errors(page)


CASES = {
    "demo": case_demo,
    "joint_sliders": case_joint_sliders,
    "reconnect": case_reconnect,
    "panda_meshes": case_panda_meshes,
    "panda_stl_meshes": case_panda_stl_meshes,
    "missing_meshes": case_missing_meshes,
    "broken_meshes": case_broken_meshes,
}


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    add_test_arguments(parser)
    parser.add_argument("--case", choices=sorted(CASES), action="append",
                        help="the case to run (repeatable; default: all)")
    parser.add_argument("--screenshot", help="where the demo case saves a picture of the page")
    args = parser.parse_args()

    chromium = cdp.find_chromium()
    if chromium is None:
        print("SKIPPED: chromium is not installed")
        return SKIP
    failed = skipped = 0
    cases = args.case or list(CASES)
    for name in cases:
        print(f"--- {name}")
        with Programs(args.bin_dir) as programs:
            browser = None
            try:
                browser = cdp.Browser(chromium, WIDTH, HEIGHT)
                CASES[name](args, browser, programs)
                programs.check_alive()
                print(f"--- {name}: passed")
            except Skip as reason:
                skipped += 1
                print(f"--- {name}: SKIPPED: {reason}")
            except Exception:  # pylint: disable=broad-except
                failed += 1
                programs.keep_logs = True
                traceback.print_exc(file=sys.stdout)
                for process in programs.running:
                    print(f"--- output of {process.name}:\n{programs.log(process)[-2000:]}")
                print(f"--- {name}: FAILED")
            finally:
                if browser is not None:
                    browser.close()
    if failed:
        return 1
    return SKIP if skipped == len(cases) else 0


if __name__ == "__main__":
    sys.exit(main())
