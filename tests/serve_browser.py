"""`mechplan serve` driven by a real browser (headless Chromium over the
DevTools protocol): a plan drawn on a sheet and "photographed" in
perspective (this script's own drawing: a PNG written with the standard
library), opened in the page, its frame's corners and points clicked with
real mouse events where the photo shows them, checked; the page's verdict
must equal `mechplan check` of the same plan typed as a JSON answer in
millimetres (the JSON twin) — for the right plan and for one with a point
10 mm off. A screenshot of the page with its overlay goes to
docs/gallery/serve-page.png.

Usage: serve_browser.py MECHPLAN_BINARY OUT_DIR
"""

import base64
import json
import math
import os
import struct
import subprocess
import sys
import time
import urllib.request
import zlib

import websocket  # websocket-client

MECHPLAN, OUT = sys.argv[1], sys.argv[2]
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE, PLAN, POSITION = "four_bar", "velocity", 3
FRAME = (185.0, 287.0)  # the A4 frame, mm
PX_PER_MM = 3.6


def homography(src, dst):
    """The 3x3 projective map taking the four points src onto dst."""
    a, b = [], []
    for (x, y), (u, v) in zip(src, dst):
        a.append([x, y, 1, 0, 0, 0, -u * x, -u * y])
        b.append(u)
        a.append([0, 0, 0, x, y, 1, -v * x, -v * y])
        b.append(v)
    n = 8
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(a[r][c]))
        a[c], a[p] = a[p], a[c]
        b[c], b[p] = b[p], b[c]
        for r in range(c + 1, n):
            f = a[r][c] / a[c][c]
            for k in range(c, n):
                a[r][k] -= f * a[c][k]
            b[r] -= f * b[c]
    h = [0.0] * n
    for r in range(n - 1, -1, -1):
        h[r] = (b[r] - sum(a[r][k] * h[k] for k in range(r + 1, n))) / a[r][r]
    return lambda p: (
        (h[0] * p[0] + h[1] * p[1] + h[2]) / (h[6] * p[0] + h[7] * p[1] + 1),
        (h[3] * p[0] + h[4] * p[1] + h[5]) / (h[6] * p[0] + h[7] * p[1] + 1),
    )


def photograph(points, path):
    """Draw the frame and the plan's vectors from the pole in pencil on a
    sheet seen in perspective (about 8 degrees of tilt); write a PNG and
    return the pixel places of the frame's corners and of every point."""
    w, h = FRAME
    s = PX_PER_MM
    # The pole where the plan sits in the middle of the frame (mm from its
    # bottom-left corner, y up).
    xs = [0.0] + [p[0] for p in points.values()]
    ys = [0.0] + [p[1] for p in points.values()]
    pole = (w / 2 - (min(xs) + max(xs)) / 2, h / 2 - (min(ys) + max(ys)) / 2)
    # The frame's corners in the photo: a trapezoid (the camera tilted).
    corners_px = [(60.5, 40 + h * s), (60 + w * s + 30, 40 + h * s - 12), (60 + w * s - 8, 52.5), (80.5, 40.5)]
    to_px = homography([(0, 0), (w, 0), (w, h), (0, h)], corners_px)
    width, height = int(60 + w * s + 90), int(40 + h * s + 60)
    img = bytearray([246]) * (width * height)

    def line(p, q):
        n = int(math.hypot(q[0] - p[0], q[1] - p[1]) / 0.05) + 1
        for i in range(n + 1):
            t = i / n
            x, y = to_px((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])))
            for dx in (0, 1):
                for dy in (0, 1):
                    xi, yi = int(x - 0.5) + dx, int(y - 0.5) + dy
                    if 0 <= xi < width and 0 <= yi < height:
                        img[yi * width + xi] = 70

    frame = [(0, 0), (w, 0), (w, h), (0, h)]
    for i in range(4):
        line(frame[i], frame[(i + 1) % 4])
    places = {}
    for name, (x, y) in points.items():
        end = (pole[0] + x, pole[1] + y)
        line(pole, end)
        places[name] = to_px(end)
    places["p_v"] = to_px(pole)
    raw = b"".join(b"\0" + bytes(img[r * width:(r + 1) * width]) for r in range(height))
    chunk = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(png)
    return [to_px(c) for c in frame], places


def cli_check(points, mu):
    """`mechplan check` of the JSON twin: the status and the grade line."""
    twin = {"plan": PLAN, "position": POSITION, "mu": mu, "points": points}
    path = os.path.join(OUT, "twin.json")
    with open(path, "w") as f:
        json.dump(twin, f)
    r = subprocess.run([MECHPLAN, "check", os.path.join(ROOT, "fixtures", SCENE + ".json"), path], capture_output=True, text=True)
    grade = next((l for l in r.stdout.splitlines() if l.startswith("Grade")), r.stderr)
    return r.returncode, grade


class Browser:
    def __init__(self, url):
        profile = os.path.join(OUT, "profile")
        self.proc = subprocess.Popen(
            ["/usr/bin/chromium", "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
             "--disable-background-networking", "--remote-debugging-port=0", "--user-data-dir=" + profile,
             "--window-size=1600,1400", "about:blank"],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        port_file = os.path.join(profile, "DevToolsActivePort")
        for _ in range(200):
            if os.path.exists(port_file) and open(port_file).read().strip():
                break
            time.sleep(0.1)
        port = open(port_file).read().split()[0]
        targets = json.load(urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list"))
        page = next(t for t in targets if t["type"] == "page")
        self.ws = websocket.create_connection(page["webSocketDebuggerUrl"], timeout=60)
        self.n = 0
        self.call("Page.enable")
        self.call("Runtime.enable")
        self.call("Page.navigate", url=url)
        self.wait("document.readyState === 'complete' && document.querySelectorAll('#scene option').length > 0")

    def call(self, method, **params):
        self.n += 1
        self.ws.send(json.dumps({"id": self.n, "method": method, "params": params}))
        while True:
            m = json.loads(self.ws.recv())
            if m.get("id") == self.n:
                if "error" in m:
                    raise RuntimeError(f"{method}: {m['error']}")
                return m.get("result", {})
            if m.get("method") == "Runtime.exceptionThrown":
                raise RuntimeError("the page threw: " + json.dumps(m["params"])[:400])

    def eval(self, js):
        r = self.call("Runtime.evaluate", expression=js, returnByValue=True)
        if "exceptionDetails" in r:
            raise RuntimeError(f"{js}: {r['exceptionDetails']}")
        return r["result"].get("value")

    def wait(self, js, seconds=30):
        for _ in range(seconds * 10):
            if self.eval(js):
                return
            time.sleep(0.1)
        raise RuntimeError("timed out waiting for " + js)

    def click(self, x, y):
        for kind in ("mousePressed", "mouseReleased"):
            self.call("Input.dispatchMouseEvent", type=kind, x=x, y=y, button="left", clickCount=1)

    def close(self):
        self.ws.close()
        self.proc.kill()


def grade_in_page(b, photo, corners, places, mu):
    """Open `photo`, click as a student does, press Check: the status the
    page shows and its grade line."""
    b.eval("document.getElementById('scene').value = '%s'; document.getElementById('scene').dispatchEvent(new Event('change'))" % SCENE)
    b.wait("document.getElementById('prompt').textContent.length > 0")
    b.eval("document.getElementById('plan').value = '%s'; document.getElementById('plan').dispatchEvent(new Event('change'))" % PLAN)
    b.eval("document.getElementById('position').value = '%d'; document.getElementById('position').dispatchEvent(new Event('change'))" % POSITION)
    b.wait("document.getElementById('positions').textContent.includes('11')")
    b.eval("document.getElementById('mu').value = '%s'" % mu)
    doc = b.call("DOM.getDocument")
    node = b.call("DOM.querySelector", nodeId=doc["root"]["nodeId"], selector="#file")
    b.call("DOM.setFileInputFiles", files=[photo], nodeId=node["nodeId"])
    b.wait("document.getElementById('prompt').textContent.includes('bottom-left')")
    rect = b.eval("JSON.stringify(document.getElementById('photo').getBoundingClientRect())")
    rect = json.loads(rect)
    # The page shows the photo at `scale` of its pixels.
    k = b.eval("scale")
    for (x, y) in corners:
        b.click(rect["left"] + x * k, rect["top"] + y * k)
    clicked = 0
    for _ in range(3 * len(places) + 10):
        prompt = b.eval("document.getElementById('prompt').textContent")
        if prompt.startswith("All points"):
            break
        if "Click point " not in prompt:
            raise RuntimeError(f"the page prompts {prompt!r} after {clicked} points")
        letter = prompt.split("Click point ")[1].split(" ")[0].rstrip(".")
        if letter in places:
            x, y = places[letter]
            b.click(rect["left"] + x * k, rect["top"] + y * k)
            clicked += 1
        else:
            b.eval("document.getElementById('skip').click()")
    assert clicked == len(places), (clicked, places)
    b.eval("document.getElementById('check').click()")
    b.wait("document.getElementById('verdict').dataset.status !== undefined || document.getElementById('error').textContent !== ''")
    err = b.eval("document.getElementById('error').textContent")
    if err:
        raise RuntimeError("the page says: " + err)
    status = int(b.eval("document.getElementById('verdict').dataset.status"))
    text = b.eval("document.getElementById('report').textContent")
    grade = next((l for l in text.splitlines() if l.startswith("Grade")), "")
    b.eval("delete document.getElementById('verdict').dataset.status")
    return status, grade


def main():
    os.makedirs(OUT, exist_ok=True)
    server = subprocess.Popen([MECHPLAN, "serve", "--listen", "127.0.0.1:0"], stdout=subprocess.PIPE, text=True)
    try:
        url = server.stdout.readline().split()[2]
        plan = json.load(urllib.request.urlopen(f"{url}api/plan?scene={SCENE}&plan={PLAN}&position={POSITION}"))
        mu = plan["mu"]
        right = {k: v for k, v in plan["points"].items() if not k.startswith(("n_", "k_"))}
        wrong = dict(right)
        bx, by = wrong["b"]
        wrong["b"] = [bx + 10.0, by]
        b = Browser(url)
        try:
            results = []
            for tag, points in (("right", right), ("wrong", wrong)):
                photo = os.path.join(OUT, f"plan-{tag}.png")
                corners, places = photograph(points, photo)
                page = grade_in_page(b, photo, corners, places, mu)
                twin = cli_check({k: [round(v[0], 2), round(v[1], 2)] for k, v in points.items()}, mu)
                results.append((tag, page, twin))
                print(f"serve_browser: {tag}: page {page}, mechplan check of the JSON twin {twin}")
                if page[0] != twin[0]:
                    raise SystemExit(f"serve_browser FAIL: {tag}: the page's verdict {page} is not check's {twin}")
                if tag == "wrong":
                    shot = b.call("Page.captureScreenshot", format="png")["data"]
                    with open(os.path.join(ROOT, "docs", "gallery", "serve-page.png"), "wb") as f:
                        f.write(base64.b64decode(shot))
            if [r[1][0] for r in results] != [0, 1]:
                raise SystemExit(f"serve_browser FAIL: expected RIGHT then WRONG, got {results}")
            print("serve_browser PASS")
        finally:
            b.close()
    finally:
        server.kill()


main()
