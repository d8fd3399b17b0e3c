"""A small Chrome DevTools Protocol client: headless Chromium, pages, script, screenshots.

Only what the viewer's browser tests and benchmark need, over Debian's python3-websocket.
"""
import base64
import json
import os
import shutil
import signal
import struct
import subprocess
import tempfile
import time
import zlib

import websocket


class CdpError(RuntimeError):
    """A DevTools command failed, or the page threw."""


def find_chromium():
    """The Chromium program, or None where it is not installed."""
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


class Session:
    """One DevTools connection (to the browser or to a page): commands and collected events."""

    def __init__(self, url, timeout=30):
        self.socket = websocket.create_connection(url, timeout=timeout, suppress_origin=True,
                                                  enable_multithread=False)
        self.next_id = 0
        self.events = []

    def close(self):
        try:
            self.socket.close()
        except Exception:  # pylint: disable=broad-except
            pass

    def call(self, method, params=None, timeout=30):
        """Sends a command and returns its result; events that arrive meanwhile are kept."""
        self.next_id += 1
        command_id = self.next_id
        self.socket.send(json.dumps({"id": command_id, "method": method, "params": params or {}}))
        deadline = time.monotonic() + timeout
        while True:
            self.socket.settimeout(max(0.05, deadline - time.monotonic()))
            try:
                message = json.loads(self.socket.recv())
            except websocket.WebSocketTimeoutException as error:
                raise CdpError(f"{method}: no answer within {timeout} s") from error
            if message.get("id") == command_id:
                if "error" in message:
                    raise CdpError(f"{method}: {message['error']}")
                return message.get("result", {})
            if "method" in message:
                self.events.append(message)
                del self.events[:-1000]


class Page:
    """A browser tab: evaluate script, wait for conditions, take screenshots."""

    def __init__(self, session):
        self.session = session
        session.call("Runtime.enable")
        session.call("Page.enable")

    def evaluate(self, expression, timeout=30):
        """The value of a JavaScript expression (promises awaited); raises if it throws."""
        result = self.session.call("Runtime.evaluate", {
            "expression": expression, "returnByValue": True, "awaitPromise": True,
        }, timeout=timeout)
        if "exceptionDetails" in result:
            details = result["exceptionDetails"]
            text = details.get("exception", {}).get("description") or details.get("text")
            raise CdpError(f"{expression!r} threw: {text}")
        return result.get("result", {}).get("value")

    def wait_for(self, expression, timeout=20.0, interval=0.1, what=None):
        """Polls until `expression` is truthy and returns its value; raises after `timeout`."""
        deadline = time.monotonic() + timeout
        value = None
        while time.monotonic() < deadline:
            value = self.evaluate(expression)
            if value:
                return value
            time.sleep(interval)
        raise CdpError(f"timed out after {timeout} s waiting for {what or expression} (last: {value!r})")

    def navigate(self, url):
        self.session.call("Page.navigate", {"url": url})

    def set_size(self, width, height):
        self.session.call("Emulation.setDeviceMetricsOverride", {
            "width": width, "height": height, "deviceScaleFactor": 1, "mobile": False,
        })

    def screenshot(self, clip=None, scale=1.0):
        """The page as PNG bytes; `clip` (x, y, width, height) in CSS pixels takes part of it."""
        params = {"format": "png"}
        if clip is not None:
            x, y, width, height = clip
            params["clip"] = {"x": x, "y": y, "width": width, "height": height, "scale": scale}
        result = self.session.call("Page.captureScreenshot", params)
        return base64.b64decode(result["data"])

    def errors(self):
        """Uncaught exceptions and console errors seen so far, as text."""
        found = []
        for event in self.session.events:
            if event["method"] == "Runtime.exceptionThrown":
                details = event["params"]["exceptionDetails"]
                found.append(details.get("exception", {}).get("description") or details.get("text"))
            elif event["method"] == "Runtime.consoleAPICalled" and event["params"]["type"] == "error":
                found.append(" ".join(str(arg.get("value", arg.get("description", "")))
                                      for arg in event["params"]["args"]))
        return found


class Browser:
    """Headless Chromium with remote debugging on a port it chooses; close() ends it."""

    def __init__(self, chromium, width=1280, height=800, extra_args=()):
        self.profile = tempfile.mkdtemp(prefix="lcmtf-chromium-")
        self.log = open(os.path.join(self.profile, "chromium.log"), "wb")
        self.process = subprocess.Popen(
            [chromium, "--headless", "--no-sandbox", "--use-angle=swiftshader",
             "--enable-unsafe-swiftshader", "--remote-debugging-port=0",
             f"--user-data-dir={self.profile}", f"--window-size={width},{height}",
             "--no-first-run", "--no-default-browser-check", "--disable-extensions",
             "--disable-background-timer-throttling", "--disable-renderer-backgrounding",
             "--disable-backgrounding-occluded-windows", *extra_args, "about:blank"],
            stdout=self.log, stderr=subprocess.STDOUT, start_new_session=True)
        self.sessions = []
        try:
            self.port, browser_path = self._read_devtools_port()
            self.browser = Session(f"ws://127.0.0.1:{self.port}{browser_path}")
            self.sessions.append(self.browser)
        except Exception:
            self.close()
            raise

    def _read_devtools_port(self, timeout=30):
        path = os.path.join(self.profile, "DevToolsActivePort")
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.process.poll() is not None:
                raise CdpError(f"chromium exited with {self.process.returncode}: {self.log_text()}")
            try:
                with open(path, encoding="utf-8") as file:
                    lines = file.read().split("\n")
                if len(lines) >= 2 and lines[0].strip() and lines[1].strip():
                    return int(lines[0]), lines[1].strip()
            except FileNotFoundError:
                pass
            time.sleep(0.05)
        raise CdpError(f"chromium did not write {path} within {timeout} s: {self.log_text()}")

    def log_text(self):
        try:
            with open(os.path.join(self.profile, "chromium.log"), "rb") as file:
                return file.read()[-4000:].decode(errors="replace")
        except OSError:
            return ""

    def open_page(self, url, width=1280, height=800):
        """A new tab showing `url`."""
        target = self.browser.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = Session(f"ws://127.0.0.1:{self.port}/devtools/page/{target}")
        self.sessions.append(session)
        page = Page(session)
        page.set_size(width, height)
        page.navigate(url)
        return page

    def close(self):
        for session in self.sessions:
            session.close()
        if self.process.poll() is None:
            try:
                os.killpg(self.process.pid, signal.SIGTERM)
                self.process.wait(timeout=5)
            except (ProcessLookupError, subprocess.TimeoutExpired):
                try:
                    os.killpg(self.process.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                self.process.wait()
        self.log.close()
        shutil.rmtree(self.profile, ignore_errors=True)


def decode_png(data):
    """(width, height, rows) of an 8-bit RGB or RGBA PNG; each row a bytes of RGB(A) pixels."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    position = 8
    compressed = []
    width = height = channels = None
    while position < len(data):
        length, kind = struct.unpack(">I4s", data[position:position + 8])
        body = data[position + 8:position + 8 + length]
        position += 12 + length
        if kind == b"IHDR":
            width, height, depth, color_type, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or color_type not in (2, 6) or interlace != 0:
                raise ValueError(f"unsupported PNG: depth {depth}, colour type {color_type}")
            channels = 3 if color_type == 2 else 4
        elif kind == b"IDAT":
            compressed.append(body)
        elif kind == b"IEND":
            break
    raw = zlib.decompress(b"".join(compressed))
    stride = width * channels
    rows = []
    previous = bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind = raw[start]
        row = bytearray(raw[start + 1:start + 1 + stride])
        if kind == 1:
            for i in range(channels, stride):
                row[i] = (row[i] + row[i - channels]) & 0xFF
        elif kind == 2:
            for i in range(stride):
                row[i] = (row[i] + previous[i]) & 0xFF
        elif kind == 3:
            for i in range(stride):
                left = row[i - channels] if i >= channels else 0
                row[i] = (row[i] + ((left + previous[i]) >> 1)) & 0xFF
        elif kind == 4:
            for i in range(stride):
                a = row[i - channels] if i >= channels else 0
                b = previous[i]
                c = previous[i - channels] if i >= channels else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                predictor = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                row[i] = (row[i] + predictor) & 0xFF
        elif kind != 0:
            raise ValueError(f"bad PNG filter {kind}")
        rows.append(bytes(row))
        previous = row
    return width, height, channels, rows


def pixels(png, region=None):
    """The RGB pixels of a PNG as a list of (r, g, b), optionally of a region (x0, y0, x1, y1)."""
    width, height, channels, rows = decode_png(png)
    x0, y0, x1, y1 = region or (0, 0, width, height)
    out = []
    for y in range(max(0, y0), min(height, y1)):
        row = rows[y]
        for x in range(max(0, x0), min(width, x1)):
            i = x * channels
            out.append((row[i], row[i + 1], row[i + 2]))
    return out
