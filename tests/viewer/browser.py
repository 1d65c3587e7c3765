"""Headless Chromium for the viewer tests: screenshots, the page's DOM, and a small PNG reader.

Chromium draws WebGL with SwiftShader (on the CPU), so these tests need no GPU. `probe` and
`screenshot` run a page until its timers have had `budget_ms` of virtual time, then save what it
shows: deterministic for pages that load a whole replay. A live page streams from a match that
is being played, where virtual time is the wrong clock (Chromium holds it while the stream is
open, or races past data still on its way), so `LivePage` drives one over the DevTools protocol
in real time and waits for what the test asks for."""
import base64
import json
import os
import re
import select
import shutil
import struct
import subprocess
import tempfile
import time
import zlib

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
WIDTH, HEIGHT = 960, 600
FLAGS = ["--headless=new", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
         "--hide-scrollbars", "--force-device-scale-factor=1", f"--window-size={WIDTH},{HEIGHT}"]


def _run(url, *what, budget_ms=8000):
    if not CHROMIUM:
        raise RuntimeError("chromium is not installed (deploy/debian-test-packages.txt)")
    profile = tempfile.mkdtemp(prefix="olympics-chromium-")
    try:
        return subprocess.run(
            [CHROMIUM, *FLAGS, f"--virtual-time-budget={budget_ms}", f"--user-data-dir={profile}",
             *what, url],
            capture_output=True, text=True, timeout=180)
    finally:
        shutil.rmtree(profile, ignore_errors=True)


def probe(url, budget_ms=8000):
    """The viewer's #probe element (JSON: frame, roots on screen, scores, ...) and the DOM."""
    out = _run(url, "--dump-dom", budget_ms=budget_ms)
    m = re.search(r'<pre id="probe"[^>]*>(.*?)</pre>', out.stdout, re.S)
    if not m or not m.group(1).strip():
        raise AssertionError(f"the page wrote no probe; chromium said:\n{out.stderr[-3000:]}\n"
                             f"page:\n{out.stdout[-3000:]}")
    return json.loads(m.group(1).replace("&amp;", "&").replace("&lt;", "<")
                      .replace("&gt;", ">").replace("&quot;", '"')), out.stdout


def screenshot(url, path, budget_ms=8000):
    """Saves a WIDTH x HEIGHT PNG of the page and returns it decoded (see read_png)."""
    out = _run(url, f"--screenshot={path}", budget_ms=budget_ms)
    if not os.path.exists(path):
        raise AssertionError(f"chromium wrote no screenshot:\n{out.stderr[-3000:]}")
    return read_png(path)


class LivePage:
    """One page in a headless Chromium, driven over the DevTools protocol on a pipe
    (--remote-debugging-pipe: Chromium reads commands on fd 3 and answers on fd 4, each message
    JSON ended by a NUL). Use as a context manager; Chromium is closed on leaving."""

    def __init__(self, url):
        if not CHROMIUM:
            raise RuntimeError("chromium is not installed (deploy/debian-test-packages.txt)")
        self.profile = tempfile.mkdtemp(prefix="olympics-chromium-")
        to_chromium, self._commands = os.pipe()
        self._answers, from_chromium = os.pipe()
        # bash, not sh: dash takes only one-digit descriptors in a redirection.
        self.proc = subprocess.Popen(
            ["bash", "-c", f'exec "$0" "$@" 3<&{to_chromium} 4>&{from_chromium}', CHROMIUM,
             *FLAGS, "--remote-debugging-pipe", f"--user-data-dir={self.profile}", "about:blank"],
            pass_fds=(to_chromium, from_chromium), stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL)
        os.close(to_chromium)
        os.close(from_chromium)
        self._next_id, self._buffer, self.session = 0, b"", None
        target = self._call("Target.createTarget", url=url)["targetId"]
        self.session = self._call("Target.attachToTarget", targetId=target,
                                  flatten=True)["sessionId"]
        self._call("Emulation.setDeviceMetricsOverride", width=WIDTH, height=HEIGHT,
                   deviceScaleFactor=1, mobile=False)

    def __enter__(self):
        return self

    def __exit__(self, *_):
        try:
            self.session = None
            self._call("Browser.close", timeout_s=10)
        except (OSError, RuntimeError, TimeoutError):
            self.proc.kill()
        self.proc.wait(timeout=30)
        os.close(self._commands)
        os.close(self._answers)
        shutil.rmtree(self.profile, ignore_errors=True)

    def _call(self, method, timeout_s=60, **params):
        self._next_id += 1
        message = {"id": self._next_id, "method": method, "params": params}
        if self.session:
            message["sessionId"] = self.session
        os.write(self._commands, json.dumps(message).encode() + b"\0")
        give_up = time.monotonic() + timeout_s
        while True:
            while b"\0" not in self._buffer:
                left = give_up - time.monotonic()
                if left <= 0 or not select.select([self._answers], [], [], left)[0]:
                    raise TimeoutError(f"chromium did not answer {method} in {timeout_s} s")
                chunk = os.read(self._answers, 1 << 20)
                if not chunk:
                    raise RuntimeError(f"chromium exited while answering {method}")
                self._buffer += chunk
            raw, self._buffer = self._buffer.split(b"\0", 1)
            answer = json.loads(raw)
            if answer.get("id") == self._next_id:  # anything else is an event
                if "error" in answer:
                    raise RuntimeError(f"{method}: {answer['error']}")
                return answer["result"]

    def evaluate(self, expression):
        return self._call("Runtime.evaluate", expression=expression,
                          returnByValue=True)["result"].get("value")

    def wait_for_probe(self, accept, timeout_s=60):
        """The viewer's probe as soon as `accept(probe)` holds; fails after `timeout_s` saying
        what the page showed last."""
        give_up, shown = time.monotonic() + timeout_s, None
        while time.monotonic() < give_up:
            text = self.evaluate("(document.getElementById('probe') || {}).textContent || ''")
            if text:
                shown = json.loads(text)
                if accept(shown):
                    return shown
            time.sleep(0.1)
        message = self.evaluate("(document.getElementById('message') || {}).textContent || ''")
        raise AssertionError(f"the page did not show what was expected in {timeout_s} s; its "
                             f"probe: {shown}; its message: {message!r}")

    def screenshot(self, path):
        """Saves a PNG of the page as it is now and returns it decoded (see read_png)."""
        with open(path, "wb") as f:
            f.write(base64.b64decode(self._call("Page.captureScreenshot", format="png")["data"]))
        return read_png(path)


def read_png(path):
    """(width, height, rows): rows[y][x] = (r, g, b). 8-bit RGB or RGBA, not interlaced."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    at, idat, width = 8, b"", 0
    while at < len(data):
        size, kind = struct.unpack(">I4s", data[at:at + 8])
        chunk = data[at + 8:at + 8 + size]
        if kind == b"IHDR":
            width, height, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", chunk)
            assert depth == 8 and color in (2, 6) and interlace == 0, "unexpected PNG format"
            channels = 3 if color == 2 else 4
        elif kind == b"IDAT":
            idat += chunk
        at += 12 + size
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        prev = line
    return width, height, rows


def count_near(image, x, y, radius, predicate):
    """How many pixels within `radius` of (x, y) satisfy `predicate((r, g, b))`."""
    width, height, rows = image
    n = 0
    for yy in range(max(0, int(y) - radius), min(height, int(y) + radius + 1)):
        for xx in range(max(0, int(x) - radius), min(width, int(x) + radius + 1)):
            n += predicate(rows[yy][xx])
    return n


def reddish(p):
    r, g, b = p
    return r > 90 and r > g + 45 and r > b + 45


def bluish(p):
    r, g, b = p
    return b > 90 and b > r + 45 and b > g + 20
