#!/usr/bin/env python3
"""Opens a pounding HTML report in headless Chromium and fails if the page logs a console message of level
warning or error, throws, or makes any network request (anything but the report file itself).

Usage:  python3 tools/check_report.py out/two-sdof/report.html [--screenshot report.png]

Needs only Python 3 and Chromium (Debian: apt-get install chromium). It drives Chromium through the DevTools
protocol over a pipe (--remote-debugging-pipe), so no Python package and no open port are needed.
Exit code 0: clean; 1: problems (listed); 2: could not run.
"""

import argparse
import base64
import fcntl
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time

CHROMIUM_FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-extensions",
    "--remote-debugging-pipe",
]


class Browser:
    """A headless Chromium spoken to in DevTools protocol messages (NUL-terminated JSON on fds 3 and 4)."""

    def __init__(self, exe, profile):
        # Move every pipe end above 9 first, so that placing the child's ends on fds 3 and 4 (where Chromium
        # reads commands and writes replies) cannot overwrite one of them.
        def high(fd):
            new = fcntl.fcntl(fd, fcntl.F_DUPFD, 10)
            os.close(fd)
            return new

        to_child_r, self.to_child = map(high, os.pipe())
        self.from_child, from_child_w = map(high, os.pipe())
        os.dup2(to_child_r, 3)
        os.dup2(from_child_w, 4)
        self.proc = subprocess.Popen(
            [exe, *CHROMIUM_FLAGS, f"--user-data-dir={profile}", "about:blank"],
            pass_fds=(3, 4),
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
        for fd in (3, 4, to_child_r, from_child_w):
            os.close(fd)
        self.buf = b""
        self.next_id = 0
        self.events = []

    def send(self, method, params=None, session=None):
        self.next_id += 1
        msg = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = session
        os.write(self.to_child, json.dumps(msg).encode() + b"\0")
        return self.wait_reply(self.next_id)

    def read_message(self):
        while b"\0" not in self.buf:
            chunk = os.read(self.from_child, 1 << 16)
            if not chunk:
                raise RuntimeError("Chromium closed the DevTools pipe")
            self.buf += chunk
        raw, self.buf = self.buf.split(b"\0", 1)
        return json.loads(raw)

    def wait_reply(self, msg_id):
        while True:
            m = self.read_message()
            if m.get("id") == msg_id:
                if "error" in m:
                    raise RuntimeError(f"DevTools error: {m['error']}")
                return m.get("result", {})
            self.events.append(m)

    def wait_event(self, method, timeout):
        end = time.time() + timeout
        while time.time() < end:
            for e in self.events:
                if e.get("method") == method:
                    return e
            self.events.append(self.read_message())
        raise RuntimeError(f"no {method} within {timeout} s")

    def close(self):
        try:
            self.send("Browser.close")
        except Exception:
            pass
        self.proc.wait(timeout=10)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("report", type=pathlib.Path)
    ap.add_argument("--screenshot", type=pathlib.Path, help="write a full-page PNG of the report here")
    ap.add_argument("--chromium", default=shutil.which("chromium") or "/usr/bin/chromium")
    a = ap.parse_args()
    if not a.report.is_file():
        print(f"error: {a.report} is not a file", file=sys.stderr)
        return 2
    if not os.path.exists(a.chromium):
        print("error: Chromium not found (apt-get install chromium, or --chromium PATH)", file=sys.stderr)
        return 2
    url = a.report.resolve().as_uri()
    with tempfile.TemporaryDirectory() as profile:
        b = Browser(a.chromium, profile)
        try:
            target = b.send("Target.createTarget", {"url": "about:blank"})["targetId"]
            session = b.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
            for domain in ("Page", "Runtime", "Log", "Network"):
                b.send(f"{domain}.enable", session=session)
            b.send("Emulation.setDeviceMetricsOverride",
                   {"width": 1280, "height": 900, "deviceScaleFactor": 1, "mobile": False}, session=session)
            b.send("Page.navigate", {"url": url}, session=session)
            b.wait_event("Page.loadEventFired", timeout=30)
            # Let late console messages and requests arrive.
            b.send("Runtime.evaluate", {"expression": "new Promise(r => setTimeout(r, 500))", "awaitPromise": True},
                   session=session)
            metrics = b.send("Runtime.evaluate", {
                "expression": "JSON.stringify({svgs: document.querySelectorAll('svg').length,"
                              " tables: document.querySelectorAll('table').length,"
                              " height: document.documentElement.scrollHeight})",
                "returnByValue": True}, session=session)["result"]["value"]
            if a.screenshot:
                shot = b.send("Page.captureScreenshot", {"format": "png", "captureBeyondViewport": True},
                              session=session)
                a.screenshot.write_bytes(base64.b64decode(shot["data"]))
        finally:
            b.close()

    problems = []
    requests = []
    for e in b.events:
        m, p = e.get("method"), e.get("params", {})
        if m == "Network.requestWillBeSent":
            requests.append(p["request"]["url"])
            if p["request"]["url"] != url:
                problems.append(f"network request: {p['request']['url']}")
        elif m == "Runtime.consoleAPICalled" and p.get("type") in ("error", "warning", "assert"):
            problems.append(f"console {p['type']}: {[x.get('value') for x in p.get('args', [])]}")
        elif m == "Runtime.exceptionThrown":
            problems.append(f"exception: {p['exceptionDetails'].get('text')}")
        elif m == "Log.entryAdded" and p["entry"]["level"] in ("error", "warning"):
            problems.append(f"log {p['entry']['level']}: {p['entry']['text']}")
    info = json.loads(metrics)
    print(f"{a.report}: loaded {url}; {info['svgs']} figures, {info['tables']} tables, "
          f"page height {info['height']} px; {len(requests)} request(s): {', '.join(requests)}")
    for p in problems:
        print("  " + p)
    if a.screenshot:
        print(f"screenshot: {a.screenshot}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
