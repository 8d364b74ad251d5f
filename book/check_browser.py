#!/usr/bin/env python3
"""book/check_browser.py BOOKDIR - loads every page of the built book in a real
browser (Debian's headless Chromium) and checks what a reader would see.

Chromium is driven over its DevTools pipe (--remote-debugging-pipe: JSON
messages separated by NUL bytes on file descriptors 3 and 4), so no network
port and no module beyond Python's own are needed. For every HTML page:
  - it loads, with no console error, no uncaught exception and no failed
    resource;
  - it requests nothing but file: and data: URLs (the book is offline);
  - every <math> element has a non-zero rendered width and height (MathML
    that a browser could not lay out collapses to nothing);
and a screenshot of each chapter page and of the contents page is written
to BOOKDIR/screenshots/ (1000 px wide, and one 390 px phone view of the
contents page and the first chapter).
Prints one line per page and "browser: N passed, N failed".
"""
import base64
import fcntl
import glob
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

LOG = subprocess.DEVNULL if not os.environ.get("BOOK_BROWSER_LOG") else open(os.environ["BOOK_BROWSER_LOG"], "w")
BROWSERS = ("chromium", "chromium-browser", "google-chrome")


class Browser:
    def __init__(self, exe, profile):
        # Our ends live above 10, so that the child's dup2 onto 3 and 4
        # cannot overwrite a descriptor it still has to copy.
        high = lambda fd: (fcntl.fcntl(fd, fcntl.F_DUPFD, 10), os.close(fd))[0]
        to_child_r, self.to_child = map(high, os.pipe())
        self.from_child, from_child_w = map(high, os.pipe())

        def wire():
            os.dup2(to_child_r, 3)
            os.dup2(from_child_w, 4)

        self.proc = subprocess.Popen(
            [exe, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
             "--no-first-run", "--disable-background-networking", "--disable-component-update",
             "--disable-sync", "--disable-extensions", "--hide-scrollbars",
             "--host-resolver-rules=MAP * ~NOTFOUND",
             "--user-data-dir=" + profile, "--remote-debugging-pipe", "about:blank"],
            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=LOG,
            preexec_fn=wire, close_fds=False)
        os.close(to_child_r)
        os.close(from_child_w)
        self.buf = b""
        self.next_id = 0
        self.events = []

    def _read_message(self, deadline):
        while b"\0" not in self.buf:
            if time.time() > deadline:
                raise TimeoutError("the browser did not answer")
            chunk = os.read(self.from_child, 65536)
            if not chunk:
                raise RuntimeError("the browser closed its pipe")
            self.buf += chunk
        msg, self.buf = self.buf.split(b"\0", 1)
        return json.loads(msg)

    def call(self, method, params=None, session=None, timeout=30):
        self.next_id += 1
        msg = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = session
        os.write(self.to_child, json.dumps(msg).encode() + b"\0")
        deadline = time.time() + timeout
        while True:
            m = self._read_message(deadline)
            if m.get("id") == self.next_id:
                if "error" in m:
                    raise RuntimeError(method + ": " + m["error"].get("message", "error"))
                return m.get("result", {})
            self.events.append(m)

    def wait_event(self, method, session, timeout=30):
        deadline = time.time() + timeout
        while True:
            for i, m in enumerate(self.events):
                if m.get("method") == method and m.get("sessionId") == session:
                    del self.events[i]
                    return m
            self.events.append(self._read_message(deadline))

    def close(self):
        try:
            self.call("Browser.close", timeout=5)
        except Exception:
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()


MATH_JS = """(() => {
  const all = Array.from(document.querySelectorAll('math'));
  const flat = all.filter(m => { const r = m.getBoundingClientRect();
                                 return !(r.width > 0 && r.height > 0); });
  return { math: all.length, flat: flat.length,
           first: flat.length ? flat[0].outerHTML.slice(0, 120) : '' };
})()"""


def event_problems(b, session):
    """What the browser reported for one session's page: exceptions, console
    errors, requests for anything but file:, data: and blob: URLs (a blob:
    URL holds what the page itself made: the lab's Worker script), failed
    loads."""
    out = []
    for e in b.events:
        if e.get("sessionId") != session:
            continue
        m, p = e.get("method"), e.get("params", {})
        if m == "Runtime.exceptionThrown":
            out.append("exception: " + p["exceptionDetails"].get("text", ""))
        elif m == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
            out.append("console error: " + " ".join(
                str(a.get("value", a.get("description", ""))) for a in p.get("args", [])))
        elif m == "Log.entryAdded" and p["entry"].get("level") == "error":
            out.append("console error: " + p["entry"].get("text", "") +
                       " " + p["entry"].get("url", ""))
        elif m == "Network.requestWillBeSent":
            url = p["request"]["url"]
            if not url.startswith(("file:", "data:", "blob:")):
                out.append("requests " + url)
        elif m == "Network.loadingFailed":
            out.append("failed to load: " + p.get("errorText", ""))
    return out


def check_page(b, session, path, shot, phone):
    """Loads one page; returns (problems, math count)."""
    problems = []
    b.events = [e for e in b.events if e.get("sessionId") != session]
    width, height, mobile = (390, 844, True) if phone else (1000, 1400, False)
    b.call("Emulation.setDeviceMetricsOverride",
           {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": mobile}, session)
    b.call("Page.navigate", {"url": "file://" + os.path.abspath(path)}, session)
    b.wait_event("Page.loadEventFired", session)
    time.sleep(0.15)  # layout of late fonts; errors reported after load
    info = b.call("Runtime.evaluate", {"expression": MATH_JS, "returnByValue": True},
                  session)["result"]["value"]
    if info["flat"]:
        problems.append("%d of %d <math> elements have no rendered size (first: %s)"
                        % (info["flat"], info["math"], info["first"]))
    problems += event_problems(b, session)
    if shot:
        data = b.call("Page.captureScreenshot", {"format": "png"}, session)["data"]
        with open(shot, "wb") as f:
            f.write(base64.b64decode(data))
    return problems, info["math"]


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: check_browser.py BOOKDIR")
    book = sys.argv[1]
    exe = next((shutil.which(x) for x in BROWSERS if shutil.which(x)), None)
    if not exe:
        print("browser: no chromium on PATH (make book-deps installs it)")
        print("browser: 0 passed, 1 failed")
        return 1
    shots = os.path.join(book, "screenshots")
    shutil.rmtree(shots, ignore_errors=True)
    os.makedirs(shots)
    pages = sorted(glob.glob(os.path.join(book, "*.html")))
    pages += sorted(glob.glob(os.path.join(book, "src", "**", "*.html"), recursive=True))
    profile = tempfile.mkdtemp(prefix="mcbox-chromium-")
    b = Browser(exe, profile)
    passed = failed = 0
    try:
        target = b.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = b.call("Target.attachToTarget",
                         {"targetId": target, "flatten": True})["sessionId"]
        for domain in ("Page", "Runtime", "Log", "Network"):
            b.call(domain + ".enable", {}, session)
        views = [(p, False) for p in pages]
        first_chapter = next((p for p in pages if os.path.basename(p)[:2].isdigit()), None)
        views += [(os.path.join(book, "index.html"), True)]
        if first_chapter:
            views.append((first_chapter, True))
        for path, phone in views:
            rel = os.path.relpath(path, book)
            name = os.path.basename(path)[:-5]
            shot = None
            if os.path.dirname(rel) == "":
                shot = os.path.join(shots, name + ("-phone" if phone else "") + ".png")
            problems, nmath = check_page(b, session, path, shot, phone)
            label = rel + (" (phone)" if phone else "")
            if problems:
                failed += 1
                print("FAIL  browser %s: %s" % (label, "; ".join(problems[:8])))
            else:
                passed += 1
                print("ok    browser %s: %d math elements, all rendered%s"
                      % (label, nmath, ", screenshot " + os.path.relpath(shot, book) if shot else ""))
    finally:
        b.close()
        shutil.rmtree(profile, ignore_errors=True)
    print("browser: %d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
