#!/usr/bin/python3
"""lcmtf-viewer against hostile HTTP requests and WebSocket messages, as a real process.

Paths are sent as raw bytes, unnormalised: every traversal is refused and never answered with
the file; methods other than GET and HEAD are refused; malformed WebSocket messages get `error`
replies, a message over the size limit closes the page with 1009, the 100th refused message
closes it with 1008; and the server still serves afterwards.
Exit status: 0 passed, 1 failed, 77 skipped (no websocket module for Python).
"""
import argparse
import json
import os
import socket
import struct
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
try:
    import websocket  # noqa: E402
except ImportError as missing:  # Debian's python3-websocket
    print(f"SKIPPED: {missing}")
    sys.exit(77)
from viewer_processes import Programs, add_test_arguments  # noqa: E402

TRAVERSALS = [
    "/../etc/passwd",
    "/../../../../../../etc/passwd",
    "/%2e%2e/%2e%2e/etc/passwd",
    "/%2E%2E/%2E%2E/%2E%2E/etc/passwd",
    "/.%2e/.%2e/.%2e/etc/passwd",
    "/%252e%252e/%252e%252e/etc/passwd",
    "/mesh/0/..%2f..%2f..%2f..%2fetc%2fpasswd",
    "/mesh/0/../../../../etc/passwd",
    "/mesh/0/%2e%2e%2f%2e%2e%2fetc%2fpasswd",
    "/three/../../../../etc/passwd",
    "/three/build/../../../../../../etc/passwd",
    "/three/%2e%2e/%2e%2e/%2e%2e/%2e%2e/etc/passwd",
    "/js/../../../../../etc/passwd",
    "/web/index.html%00",
    "/index.html%00.png",
    "/index.html\x00",
    "/..\\..\\..\\etc\\passwd",
    "/js\\..\\..\\..\\..\\etc\\passwd",
    "/%5c..%5c..%5c..%5cetc%5cpasswd",
    "/mesh/0/..%5c..%5c..%5cetc%5cpasswd",
    "//etc/passwd",
    "/etc/passwd",
    "http://127.0.0.1/../../etc/passwd",
    "/" + "../" * 200 + "etc/passwd",
]
METHODS = ["POST", "PUT", "DELETE", "PATCH", "OPTIONS", "TRACE", "CONNECT", "PROPFIND", "FOO"]
PASSWD_MARK = b"root:"


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def raw_request(port, data, timeout=5):
    """Sends bytes as they are and returns what came back before the server closed (b'' when
    it closed or reset at once)."""
    with socket.create_connection(("127.0.0.1", port), timeout=timeout) as connection:
        try:
            connection.sendall(data)
        except (BrokenPipeError, ConnectionResetError):
            return b""
        reply = b""
        try:
            while True:
                chunk = connection.recv(65536)
                if not chunk:
                    break
                reply += chunk
        except ConnectionResetError:
            pass
        except socket.timeout:
            reply += b"<no end>"
        return reply


def status_of(reply):
    try:
        return int(reply.split(b"\r\n", 1)[0].split(b" ")[1])
    except (IndexError, ValueError):
        return None


def get(port, target, method="GET"):
    if isinstance(target, str):
        target = target.encode("latin-1")
    return raw_request(port, method.encode() + b" " + target +
                       b" HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 0\r\n"
                       b"Connection: close\r\n\r\n")


def check_serves(port):
    reply = get(port, "/")
    check(status_of(reply) == 200 and b"lcmtf viewer" in reply,
          f"the page is no longer served: {reply[:200]!r}")


def check_http(port, mesh_url):
    for target in ["/", "/index.html", "/js/main.js", "/three/build/three.module.js", mesh_url]:
        if target:
            reply = get(port, target)
            check(status_of(reply) == 200, f"GET {target}: {reply[:100]!r}")
    check(status_of(get(port, "/", "HEAD")) == 200, "HEAD / is not answered")
    for target in TRAVERSALS:
        reply = get(port, target)
        status = status_of(reply)
        check(PASSWD_MARK not in reply, f"GET {target!r} sent /etc/passwd")
        check(status is None or 400 <= status < 500, f"GET {target!r} answered {status}")
    print(f"{len(TRAVERSALS)} traversals refused")
    for method in METHODS:
        status = status_of(get(port, "/", method))
        check(status is None or status in (400, 405, 501), f"{method} / answered {status}")
    print(f"{len(METHODS)} other methods refused")
    # Not HTTP at all, a request line too long, headers without end: the server lives on.
    for junk in [b"\x16\x03\x01\x02\x00\x01\x00\x01\xfc\x03\x03" + os.urandom(64),
                 b"GET /" + b"x" * 100000 + b" HTTP/1.1\r\n\r\n",
                 b"GET / HTTP/1.1\r\n" + b"X: y\r\n" * 5000 + b"\r\n",
                 b"\r\n\r\n\r\n", b"GET /ws HTTP/1.1\r\nUpgrade: websocket\r\n\r\n"]:
        reply = raw_request(port, junk)
        check(PASSWD_MARK not in reply and status_of(reply) in (None, 400, 404, 405, 413, 431),
              f"junk answered {reply[:100]!r}")
    check_serves(port)


class Page:
    """A WebSocket client speaking as a page."""

    def __init__(self, port):
        self.socket = websocket.create_connection(f"ws://127.0.0.1:{port}/ws", timeout=10,
                                                  suppress_origin=True)
        hello = self.next_message("hello")
        check(hello["max_message_bytes"] == 65536, f"hello: {hello}")

    def next_message(self, kind, timeout=5):
        """The next message of type `kind`, or ('closed', code, reason) if the server closes."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            self.socket.settimeout(max(0.05, deadline - time.monotonic()))
            try:
                opcode, data = self.socket.recv_data(control_frame=True)
            except websocket.WebSocketTimeoutException:
                break
            except (websocket.WebSocketConnectionClosedException, ConnectionError):
                return ("closed", None, "")
            if opcode == websocket.ABNF.OPCODE_CLOSE:
                code = struct.unpack("!H", data[:2])[0] if len(data) >= 2 else None
                return ("closed", code, data[2:].decode(errors="replace"))
            if opcode != websocket.ABNF.OPCODE_TEXT:
                continue
            message = json.loads(data)
            if message.get("type") == kind:
                return message
        raise AssertionError(f"no {kind} message within {timeout} s")

    def refused(self, data, binary=False):
        """Sends `data` and returns the server's error message."""
        if binary:
            self.socket.send_binary(data)
        else:
            self.socket.send(data)
        reply = self.next_message("error")
        check(isinstance(reply, dict), f"{data[:80]!r}: the server closed instead: {reply}")
        return reply["message"]

    def close(self):
        try:
            self.socket.close()
        except Exception:  # pylint: disable=broad-except
            pass


BAD_MESSAGES = [
    ("not JSON", "this is not JSON"),
    ("JSON array", "[1, 2, 3]"),
    ("JSON string", '"view"'),
    ("null", "null"),
    ("no type", '{"fixed_frame": "odom"}'),
    ("unknown type", '{"type": "shutdown"}'),
    ("type not a string", '{"type": 7}'),
    ("view.fixed_frame a number", '{"type": "view", "fixed_frame": 5, "time": null}'),
    ("view.time a string", '{"type": "view", "fixed_frame": "odom", "time": "now"}'),
    ("view.time negative", '{"type": "view", "fixed_frame": "odom", "time": -5}'),
    ("view.time outside the history", '{"type": "view", "fixed_frame": "odom", "time": 12}'),
    ("ack.seq a string", '{"type": "ack", "seq": "1"}'),
    ("ack.seq with a fraction", '{"type": "ack", "seq": 1.5}'),
    ("ack of no scene", '{"type": "ack", "seq": 987654321}'),
    ("NaN", '{"type": "joints", "enabled": true, "positions": {"shoulder_pan_joint": NaN}}'),
    ("infinity", '{"type": "joints", "enabled": true, "positions": {"shoulder_pan_joint": 1e999}}'),
    ("joints.enabled a string", '{"type": "joints", "enabled": "yes", "positions": {}}'),
    ("joints.positions an array", '{"type": "joints", "enabled": true, "positions": [1]}'),
    ("a joint value a string", '{"type": "joints", "enabled": true, "positions": {"elbow_joint": "1"}}'),
    ("an unknown joint", '{"type": "joints", "enabled": true, "positions": {"no_such_joint": 1}}'),
    ("a mimic joint", '{"type": "joints", "enabled": true, "positions": {"gripper_right_finger_joint": 0.01}}'),
    ("deep nesting", '{"type": "view", "x": ' + "[" * 5000 + "]" * 5000 + "}"),
    ("a frame name of 2000 bytes", '{"type": "view", "fixed_frame": "' + "f" * 2000 + '", "time": null}'),
]


def check_websocket(port):
    page = Page(port)
    try:
        for what, data in BAD_MESSAGES:
            message = page.refused(data)
            print(f"{what}: {message}")
        message = page.refused(b"\x00\x01\x02binary", binary=True)
        print(f"binary frame: {message}")
        # Invalid UTF-8 in a text frame: refused, or the connection failed as RFC 6455 says.
        page.socket.send(b'{"type": "view", "fixed_frame": "\xff\xfe", "time": null}',
                         websocket.ABNF.OPCODE_TEXT)
        reply = page.next_message("error")
        print(f"invalid UTF-8: {reply if isinstance(reply, tuple) else reply['message']}")
        if isinstance(reply, tuple):
            check(reply[1] in (1007, None), f"invalid UTF-8 closed the page with {reply}")
            page.close()
            page = Page(port)
        # Still a working page: a good view is answered with a full scene.
        page.socket.send(json.dumps({"type": "view", "fixed_frame": "odom", "time": None}))
        scene = page.next_message("scene")
        check(isinstance(scene, dict), f"no scene after the refusals: {scene}")
    finally:
        page.close()

    # Over the size limit: the page is closed with 1009 (message too big).
    page = Page(port)
    try:
        try:
            page.socket.send(json.dumps({"type": "view", "fixed_frame": "x" * 70000, "time": None}))
        except (BrokenPipeError, ConnectionResetError):
            pass
        closed = page.next_message("error")
        check(isinstance(closed, tuple) and closed[1] in (1009, None),
              f"a 70 kB message was answered {closed}")
        print(f"a 70 kB message closed the page: {closed}")
    finally:
        page.close()
    check_serves(port)

    # The 101st bad message finds the page closed with 1008 after the 100th.
    page = Page(port)
    try:
        for count in range(1, 102):
            page.socket.send("bad")
            reply = page.next_message("error")
            if isinstance(reply, tuple):
                check(reply[1] == 1008, f"closed with {reply} after {count} bad messages")
                check(count == 101, f"closed after {count} bad messages, not after 100 errors")
                print(f"closed with 1008 ({reply[2]}) after 100 refused messages")
                break
        else:
            raise AssertionError("101 bad messages did not close the page")
    finally:
        page.close()

    # Many pages at once, each dropped mid-message: the server lives on.
    for _ in range(20):
        with socket.create_connection(("127.0.0.1", port), timeout=5) as raw:
            raw.sendall(b"GET /ws HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                        b"Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n"
                        b"\x81\xff\x00\x00\x00\x00\x7f\xff\xff\xff")
    page = Page(port)
    page.close()
    check_serves(port)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    add_test_arguments(parser)
    args = parser.parse_args()

    urdf = os.path.join(args.source_dir, "examples", "mobile_manipulator.urdf")
    with Programs(args.bin_dir) as programs:
        try:
            # With the Panda, /mesh/0/... exists, so traversals below it are tried for real.
            panda = os.path.join(args.shared_urdf, "panda.urdf")
            extra = []
            mesh_url = None
            if os.path.isfile(panda):
                extra = ["--urdf", panda, "--package-path", os.path.join(args.shared_urdf, "packages")]
                mesh_url = "/mesh/0/link0.dae"
            viewer, base = programs.start_viewer(args.lcm_port, *extra)
            port = int(base.rsplit(":", 1)[1])
            check_http(port, mesh_url)
            if extra:
                # The messages name the demo robot's joints and frames.
                programs.stop(viewer)
                programs.running.remove(viewer)
                viewer, base = programs.start_viewer(args.lcm_port, "--urdf", urdf)
                port = int(base.rsplit(":", 1)[1])
            check_websocket(port)
            programs.check_alive()
            check_http(port, None)
            print("passed")
            return 0
        except Exception as error:  # pylint: disable=broad-except
            import traceback
            programs.keep_logs = True
            traceback.print_exc(file=sys.stdout)
            for process in programs.running:
                print(f"--- output of {process.name}:\n{programs.log(process)[-3000:]}")
            print(f"FAILED: {error}")
            return 1


if __name__ == "__main__":
    sys.exit(main())
