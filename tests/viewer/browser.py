"""Headless Chromium for the viewer tests: screenshots, the page's DOM, and a small PNG reader.

Chromium draws WebGL with SwiftShader (on the CPU), so these tests need no GPU. Each call runs
the page until its timers have had `budget_ms` of virtual time, then saves what it shows."""
import json
import os
import re
import shutil
import struct
import subprocess
import tempfile
import zlib

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
WIDTH, HEIGHT = 960, 600


def _run(url, *what, budget_ms=8000):
    if not CHROMIUM:
        raise RuntimeError("chromium is not installed (deploy/debian-test-packages.txt)")
    profile = tempfile.mkdtemp(prefix="olympics-chromium-")
    try:
        return subprocess.run(
            [CHROMIUM, "--headless=new", "--no-sandbox", "--use-angle=swiftshader",
             "--enable-unsafe-swiftshader", "--hide-scrollbars", "--force-device-scale-factor=1",
             f"--window-size={WIDTH},{HEIGHT}", f"--virtual-time-budget={budget_ms}",
             f"--user-data-dir={profile}", *what, url],
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
