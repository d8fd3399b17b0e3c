#!/usr/bin/python3
"""Lookups per second from Python: lcmtf's binding next to the same lookups in C++ (timed in the
same run by pr2_lookup_reference) and next to ROS tf2's own binding (tf2_py.BufferCore, from
Debian's python3-tf2, when installed), all on buffer_core_bench's PR2-scale tree; then
transform_points on a cloud of a million points.

usage: bench/python_lookup_bench.py [--build-dir build/release]
"""

import argparse
import json
import pathlib
import statistics
import subprocess
import sys
import time

ROUNDS = 7
CLOUD_POINTS = 1_000_000


def best_ns_per_call(call, arguments):
    """The best of ROUNDS passes over `arguments`, in nanoseconds a call, loop included."""
    best = float("inf")
    for _ in range(ROUNDS):
        start = time.perf_counter_ns()
        for argument in arguments:
            call(*argument)
        best = min(best, (time.perf_counter_ns() - start) / len(arguments))
    return best


def load_lcmtf(lcmtf, workload):
    buffer = lcmtf.Buffer()
    names = workload["frames"]
    static_stamp = lcmtf.from_utime(workload["static_utime"])
    for edge in workload["edges"]:
        parent, child = names[edge["parent"]], names[edge["child"]]
        if not edge["dynamic"]:
            pose = edge["samples"][0]
            buffer.set_transform(
                lcmtf.TransformStamped(parent, child, static_stamp, pose[:3], pose[3:]),
                "bench", is_static=True)
            continue
        buffer.set_transforms(
            [lcmtf.TransformStamped(parent, child,
                                    lcmtf.from_utime(edge["first_utime"] + k * edge["period"]),
                                    pose[:3], pose[3:])
             for k, pose in enumerate(edge["samples"])], "bench")
    return buffer


def load_tf2(workload):
    """tf2_py.BufferCore with the same tree, and its time type; None where it is missing."""
    try:
        import rospy
        import tf2_py
        from geometry_msgs.msg import TransformStamped
    except ImportError:
        return None, None
    buffer = tf2_py.BufferCore(rospy.Duration(20))
    names = workload["frames"]

    def message(parent, child, utime, pose):
        m = TransformStamped()
        m.header.frame_id, m.child_frame_id = parent, child
        m.header.stamp = rospy.Time(utime // 1_000_000, (utime % 1_000_000) * 1000)
        t, r = m.transform.translation, m.transform.rotation
        t.x, t.y, t.z, r.x, r.y, r.z, r.w = pose
        return m

    for edge in workload["edges"]:
        parent, child = names[edge["parent"]], names[edge["child"]]
        if not edge["dynamic"]:
            buffer.set_transform_static(
                message(parent, child, workload["static_utime"], edge["samples"][0]), "bench")
            continue
        for k, pose in enumerate(edge["samples"]):
            utime = edge["first_utime"] + k * edge["period"]
            buffer.set_transform(message(parent, child, utime, pose), "bench")
    return buffer, lambda utime: rospy.Time(utime // 1_000_000, (utime % 1_000_000) * 1000)


def lookup_table(lcmtf, workload, tf2_buffer, tf2_time):
    names = workload["frames"]
    random, deepest = workload["random_pairs"], workload["deepest_chain"]
    seconds = lcmtf.from_utime
    kinds = {
        "lookup_random": [(names[t], names[s], seconds(u)) for t, s, u, _, _ in random],
        "lookup_latest": [(names[t], names[s], 0.0) for t, s, _, _, _ in random],
        "lookup_deepest": [(names[t], names[s], seconds(u)) for t, s, u, _, _ in deepest],
        "lookup_time_travel": [(names[t], seconds(u), names[s], seconds(v), names[f])
                               for t, s, u, v, f in random],
    }
    tf2_kinds = {}
    if tf2_buffer is not None:
        zero = tf2_time(0)
        tf2_kinds = {
            "lookup_random": [(names[t], names[s], tf2_time(u)) for t, s, u, _, _ in random],
            "lookup_latest": [(names[t], names[s], zero) for t, s, _, _, _ in random],
            "lookup_deepest": [(names[t], names[s], tf2_time(u)) for t, s, u, _, _ in deepest],
            "lookup_time_travel": [(names[t], tf2_time(u), names[s], tf2_time(v), names[f])
                                   for t, s, u, v, f in random],
        }
    return kinds, tf2_kinds


def check_same_answers(buffer, tf2_buffer, kinds, tf2_kinds):
    """Both bindings give the same translation for the first queries of each kind, to 1e-5 m:
    tf2_py passes times to C++ as float seconds, which at 1.7e9 s are ~0.2 us apart."""
    for kind, arguments in kinds.items():
        tf2_call = (tf2_buffer.lookup_transform_full_core if kind == "lookup_time_travel"
                    else tf2_buffer.lookup_transform_core)
        for ours, theirs in zip(arguments[:50], tf2_kinds[kind][:50]):
            a = buffer.lookup_transform(*ours).translation
            b = tf2_call(*theirs).transform.translation
            if max(abs(a[0] - b.x), abs(a[1] - b.y), abs(a[2] - b.z)) > 1e-5:
                sys.exit(f"{kind}: lcmtf and tf2 disagree for {ours}: {a} vs {b}")


def cloud_rates(lcmtf, numpy, buffer, workload):
    """M points/s of transform_points on 1 M points (first call, then best and median of 20),
    and of numpy's own `points @ R.T + t` for comparison."""
    names = workload["frames"]
    target, source = names[0], names[workload["random_pairs"][0][1]]
    points = numpy.random.default_rng(7).uniform(-30, 30, size=(CLOUD_POINTS, 3))
    rates = []
    for _ in range(21):
        start = time.perf_counter()
        buffer.transform_points(points, source, target)
        rates.append(CLOUD_POINTS / (time.perf_counter() - start) / 1e6)
    moved = buffer.lookup_transform(target, source).matrix()
    start = time.perf_counter()
    points @ moved[:3, :3].T + moved[:3, 3]
    numpy_rate = CLOUD_POINTS / (time.perf_counter() - start) / 1e6
    return rates[0], max(rates[1:]), statistics.median(rates[1:]), numpy_rate


def main():
    repository = pathlib.Path(__file__).resolve().parent.parent
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build-dir", type=pathlib.Path, default=repository / "build/release")
    build = parser.parse_args().build_dir.resolve()
    sys.path.insert(0, str(build / "python"))
    import lcmtf
    import numpy

    def reference():
        return json.loads(subprocess.run([build / "bin/pr2_lookup_reference"], check=True,
                                         capture_output=True, text=True).stdout)

    workload = reference()
    buffer = load_lcmtf(lcmtf, workload)
    tf2_buffer, tf2_time = load_tf2(workload)
    kinds, tf2_kinds = lookup_table(lcmtf, workload, tf2_buffer, tf2_time)
    if tf2_buffer is not None:
        check_same_answers(buffer, tf2_buffer, kinds, tf2_kinds)

    dynamic = [edge for edge in workload["edges"] if edge["dynamic"]]
    print(f"PR2-scale tree: {len(workload['frames'])} frames, {len(dynamic)} dynamic edges of "
          f"{len(dynamic[0]['samples'])} samples, {len(kinds['lookup_random'])} queries a kind, "
          f"best of {ROUNDS}")
    floor = best_ns_per_call(slice, [arguments[:3] for arguments in kinds["lookup_random"]])
    print(f"Python's own loop and a 3-argument call of a C builtin (slice): {floor:.0f} ns\n")
    ours = {kind: best_ns_per_call(buffer.lookup_transform, arguments)
            for kind, arguments in kinds.items()}
    cpp_after = reference()["cpp_ns"]  # the better of a C++ run before and one after Python's
    print(f"{'ns per lookup':<20}{'C++':>8}{'Python':>9}{'added':>8}{'tf2_py':>9}"
          f"{'tf2_py / Python':>17}")
    for kind, python in ours.items():
        cpp = min(workload["cpp_ns"][kind], cpp_after[kind])
        row = f"{kind:<20}{cpp:>8.0f}{python:>9.0f}{python - cpp:>8.0f}"
        if tf2_buffer is not None:
            tf2_call = (tf2_buffer.lookup_transform_full_core if kind == "lookup_time_travel"
                        else tf2_buffer.lookup_transform_core)
            theirs = best_ns_per_call(tf2_call, tf2_kinds[kind])
            row += f"{theirs:>9.0f}{theirs / python:>16.1f}x"
        print(row)
    if tf2_buffer is None:
        print("(tf2_py not found: apt-get install python3-tf2 to compare)")

    first, best, median, numpy_rate = cloud_rates(lcmtf, numpy, buffer, workload)
    print(f"\ntransform_points, {CLOUD_POINTS:,} points: {best:.0f} M points/s best, "
          f"{median:.0f} median, {first:.0f} on the first call (fresh output pages); "
          f"numpy's points @ R.T + t: {numpy_rate:.0f}")


if __name__ == "__main__":
    main()
