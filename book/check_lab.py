#!/usr/bin/env python3
"""book/check_lab.py BOOKDIR BINDIR - drives the warp lab page (lab.html) in
Debian's headless Chromium, as a reader would, through its own controls.

  - the page loads, the WebAssembly module starts, and nothing is logged as
    an error, thrown, or requested from anywhere but file: and data: URLs;
  - three catalog rows pass and a negative control fails, the verdicts read
    from the page;
  - for one row, seed and count the page's line (statistic, dof, p-value,
    verdict) is the one `BINDIR/warp chi2` prints, character for character;
    the times of the two are printed;
  - the estimator widget's estimates of pi and of the cos^3 integral lie
    within 4 standard errors of the exact values;
  - at phone width (390 px) the page is no wider than the screen;
  - with JavaScript off the live parts stay hidden and the static runs and
    figures remain.
Screenshots (whole page) go to BOOKDIR/screenshots/lab-desktop.png,
lab-phone.png and lab-nojs.png. Prints one line per check and
"lab: N passed, N failed". The browser is driven as in check_browser.py.
"""
import base64
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_browser import BROWSERS, Browser, event_problems  # noqa: E402

# Rows that must pass and the negative control that must fail, with the
# count and seed of `warp chi2 NAME --n N --seed S` (exit 0 pass, 1 fail).
CASES = [("cosine", "independent", 100000, 1, "pass"),
         ("disc-concentric", "independent", 100000, 1, "pass"),
         ("linear", "independent", 100000, 1, "pass"),
         ("cosine", "sobol", 100000, 1, "pass"),
         ("wrong-phong-exponent", "independent", 100000, 1, "fail")]
COMPARE = ("cosine", 100000, 1)


class Page:
    def __init__(self, b, session, url):
        self.b, self.session, self.url = b, session, url

    def js(self, expr):
        r = self.b.call("Runtime.evaluate", {"expression": expr, "returnByValue": True},
                        self.session, timeout=120)
        if "exceptionDetails" in r:
            raise RuntimeError("page script: " + r["exceptionDetails"].get("text", "?"))
        return r["result"].get("value")

    def wait_for(self, expr, timeout=60):
        deadline = time.time() + timeout
        while time.time() < deadline:
            v = self.js(expr)
            if v:
                return v
            time.sleep(0.05)
        raise TimeoutError("waited %d s for %s" % (timeout, expr))

    def load(self, width, height, mobile):
        self.b.events = [e for e in self.b.events if e.get("sessionId") != self.session]
        self.b.call("Emulation.setDeviceMetricsOverride",
                    {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": mobile},
                    self.session)
        self.b.call("Page.navigate", {"url": self.url}, self.session)
        self.b.wait_event("Page.loadEventFired", self.session)

    def problems(self):
        return event_problems(self.b, self.session)

    def screenshot(self, path):
        size = self.b.call("Page.getLayoutMetrics", {}, self.session)["cssContentSize"]
        clip = {"x": 0, "y": 0, "width": size["width"], "height": size["height"], "scale": 1}
        data = self.b.call("Page.captureScreenshot",
                           {"format": "png", "captureBeyondViewport": True, "clip": clip},
                           self.session, timeout=60)["data"]
        with open(path, "wb") as f:
            f.write(base64.b64decode(data))

    def press(self, setup, result_id, button_id):
        """Runs the script `setup` (which sets a widget's controls), presses
        its button and waits until the result element `result_id` counts one
        more run or reports an error."""
        before = self.js("""(() => { %s
          const runs = Number(document.getElementById(%s).dataset.runs || 0);
          document.getElementById(%s).click();
          return runs; })()""" % (setup, json.dumps(result_id), json.dumps(button_id)))
        self.wait_for("(() => { const r = document.getElementById(%s).dataset;"
                      " return r.state === 'error' || Number(r.runs || 0) > %d; })()"
                      % (json.dumps(result_id), before), 120)

    def run_chi2(self, row, source, n, seed):
        """Sets the controls, presses the button, returns the page's result."""
        self.press("""const s = document.getElementById('lab-row');
          s.value = %s; s.dispatchEvent(new Event('change'));
          document.getElementById('lab-source').value = %s;
          document.getElementById('lab-n').value = '%d';
          document.getElementById('lab-seed').value = '%d';""" % (json.dumps(row), json.dumps(source), n, seed),
                   "lab-chi2", "lab-run")
        return self.js("""(() => { const r = document.getElementById('lab-chi2');
          return { state: r.dataset.state, line: r.dataset.line, ms: Number(r.dataset.ms),
                   verdict: document.getElementById('lab-verdict').textContent,
                   stat: document.getElementById('lab-stat').textContent,
                   status: document.getElementById('lab-status').textContent }; })()""")

    def run_estimate(self, kind, row, n, seed):
        self.press("""const k = document.getElementById('est-kind'); k.value = %s;
          k.dispatchEvent(new Event('change'));
          document.getElementById('est-row').value = %s;
          document.getElementById('est-n').value = '%d';
          document.getElementById('est-seed').value = '%d';""" % (json.dumps(kind), json.dumps(row), n, seed),
                   "lab-estimator", "est-run")
        return self.js("""(() => { const r = document.getElementById('lab-estimator');
          return { state: r.dataset.state, z: Number(r.dataset.z),
                   value: document.getElementById('est-value').textContent,
                   status: document.getElementById('est-status').textContent }; })()""")


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: check_lab.py BOOKDIR BINDIR")
    book, bindir = sys.argv[1], sys.argv[2]
    passed = failed = 0

    def report(ok, what):
        nonlocal passed, failed
        if ok:
            passed += 1
        else:
            failed += 1
        print(("ok    " if ok else "FAIL  ") + "lab " + what)

    exe = next((shutil.which(x) for x in BROWSERS if shutil.which(x)), None)
    page_path = os.path.join(book, "lab.html")
    if not exe or not os.path.isfile(page_path):
        report(False, "no chromium on PATH or no lab.html in " + book)
        print("lab: %d passed, %d failed" % (passed, failed))
        return 1
    shots = os.path.join(book, "screenshots")
    os.makedirs(shots, exist_ok=True)
    profile = tempfile.mkdtemp(prefix="mcbox-lab-chromium-")
    b = Browser(exe, profile)
    try:
        target = b.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = b.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        for domain in ("Page", "Runtime", "Log", "Network"):
            b.call(domain + ".enable", {}, session)
        page = Page(b, session, "file://" + os.path.abspath(page_path))

        # Desktop: load, the module starts, the rows run.
        t0 = time.perf_counter()
        page.load(1000, 1400, False)
        try:
            page.wait_for("document.body.dataset.lab === 'ready'", 30)
            report(True, "loads and starts its module in %.2f s" % (time.perf_counter() - t0))
        except TimeoutError as e:
            report(False, "module never started: %s; %s" % (e, "; ".join(page.problems()[:5])))
            return 1
        for row, source, n, seed, want in CASES:
            r = page.run_chi2(row, source, n, seed)
            report(r["state"] == "done" and r["verdict"] == want,
                   "%s (%s, n=%d, seed %d): %s, want %s; statistic %s, %.0f ms"
                   % (row, source, n, seed, r["verdict"] or r["status"], want, r["stat"], r["ms"]))

        # The same numbers as the command line, and the time of each.
        row, n, seed = COMPARE
        cmd = [os.path.join(bindir, "warp"), "chi2", row, "--n", str(n), "--seed", str(seed)]
        t0 = time.perf_counter()
        native = subprocess.run(cmd, capture_output=True, text=True)
        native_ms = 1000 * (time.perf_counter() - t0)
        native_line = native.stdout.strip().splitlines()[-1] if native.stdout.strip() else "(nothing)"
        r = page.run_chi2(row, "independent", n, seed)
        report(r["line"] == native_line,
               "page prints `%s`, `%s` prints `%s`" % (r["line"], " ".join(cmd[1:]), native_line))
        print("      time of a %d-sample chi-square of %s: %.0f ms in the page (WebAssembly), "
              "%.0f ms for the native program (a process, several threads)" % (n, row, r["ms"], native_ms))

        # The estimator widget.
        for kind, erow in (("pi", "cosine"), ("cos3", "cosine"), ("cos3", "hemisphere")):
            e = page.run_estimate(kind, erow, 100000, 1)
            report(e["state"] == "done" and abs(e["z"]) < 4,
                   "estimator %s%s: %s, z = %s" % (kind, "" if kind == "pi" else " from " + erow,
                                                   e["value"], e["z"]))
        page.screenshot(os.path.join(shots, "lab-desktop.png"))
        probs = page.problems()
        report(not probs, "desktop: no console error, no request off the disk" +
               ("" if not probs else ": " + "; ".join(probs[:5])))

        # A phone: the same page at 390 px, one run, nothing wider than the screen.
        page.load(390, 844, True)
        page.wait_for("document.body.dataset.lab === 'ready'", 30)
        r = page.run_chi2("hemisphere", "jittered", 10000, 3)
        page.run_estimate("cos3", "cosine", 10000, 1)
        wide = page.js("document.documentElement.scrollWidth")
        report(r["verdict"] == "pass" and wide <= 390,
               "phone width: hemisphere (jittered) %s, page %d px wide" % (r["verdict"], wide))
        page.screenshot(os.path.join(shots, "lab-phone.png"))
        probs = page.problems()
        report(not probs, "phone: no console error" + ("" if not probs else ": " + "; ".join(probs[:5])))

        # JavaScript off: the static parts remain, the live ones stay hidden.
        b.call("Emulation.setScriptExecutionDisabled", {"value": True}, session)
        page.load(1000, 1400, False)
        time.sleep(0.3)
        s = page.js("""(() => ({
          live: Array.from(document.querySelectorAll('.lab-live'))
                     .filter(x => getComputedStyle(x).display !== 'none').length,
          runs: document.querySelectorAll('.run pre').length,
          figures: Array.from(document.querySelectorAll('figure img'))
                        .filter(i => i.complete && i.naturalWidth > 0).length }))()""")
        report(s["live"] == 0 and s["runs"] >= 2 and s["figures"] >= 2,
               "without JavaScript: %d live widgets shown, %d runs and %d figures"
               % (s["live"], s["runs"], s["figures"]))
        page.screenshot(os.path.join(shots, "lab-nojs.png"))
        b.call("Emulation.setScriptExecutionDisabled", {"value": False}, session)
    finally:
        b.close()
        shutil.rmtree(profile, ignore_errors=True)
    print("lab: screenshots lab-desktop.png, lab-phone.png, lab-nojs.png in " + shots)
    print("lab: %d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
