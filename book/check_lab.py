#!/usr/bin/env python3
"""book/check_lab.py BOOKDIR BINDIR - drives the warp lab page (lab.html) in
Debian's headless Chromium, as a reader would, through its own controls.

  - the page loads, the WebAssembly module starts, and nothing is logged as
    an error, thrown, or requested from anywhere but file:, data: and blob:
    URLs (blob: is the page's own Worker script);
  - every widget has run its default case on load, before any click: the
    chi-square row passes, the own-warp box's example passes, and their
    pictures are drawn;
  - three catalog rows pass and a negative control fails, the verdicts read
    from the page;
  - for one row, seed and count the page's line (statistic, dof, p-value,
    verdict) is the one `BINDIR/warp chi2` prints, character for character;
    the times of the two are printed;
  - the estimator widget's estimates of pi and of the cos^3 integral lie
    within 4 standard errors of the exact values;
  - the own-warp box: Malley's cosine warp passes against the cosine
    hemisphere (all three checks, with its inverse); the uniform hemisphere
    with its own, right, density is caught against the cosine target ("do
    not follow"); the cosine warp with a pdf that lacks 1/pi fails on its
    integral; a syntax error, a thrown exception (with its line), a NaN and
    a wrong-shaped point each show the error panel and judge nothing; a pdf
    that never returns (inside the module's quadrature) is stopped at the
    box's time limit with its Worker, and the next run passes;
  - at phone width (390 px) the page is no wider than the screen;
  - with JavaScript off the live parts stay hidden and the static runs and
    figures remain.
Screenshots (whole page) go to BOOKDIR/screenshots/lab-desktop.png,
lab-phone.png and lab-nojs.png; of the own-warp box alone, caught and with an
error, to lab-own-warp-wrong.png and lab-own-warp-error.png. Prints one line per check and
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

# Own warps for the own-warp box (JavaScript, as a reader types it).
MALLEY_SAMPLE = """function sample(u1, u2) {
  const a = 2 * u1 - 1, b = 2 * u2 - 1;
  if (a === 0 && b === 0) return [0, 0, 1];
  let r, phi;
  if (Math.abs(a) > Math.abs(b)) { r = a; phi = (Math.PI / 4) * (b / a); }
  else { r = b; phi = Math.PI / 2 - (Math.PI / 4) * (a / b); }
  const x = r * Math.cos(phi), y = r * Math.sin(phi);
  return [x, y, Math.sqrt(Math.max(0, 1 - x * x - y * y))];
}
"""
MALLEY_INVERT = """function invert(w) {
  const x = w[0], y = w[1], r = Math.hypot(x, y);
  if (r === 0) return [0.5, 0.5];
  let a, b;
  if (Math.abs(x) >= Math.abs(y)) { a = x < 0 ? -r : r; b = a * Math.atan2(y / a, x / a) / (Math.PI / 4); }
  else { b = y < 0 ? -r : r; a = (Math.PI / 2 - Math.atan2(y / b, x / b)) * b / (Math.PI / 4); }
  return [(a + 1) / 2, (b + 1) / 2];
}
"""
OWN_MALLEY = MALLEY_SAMPLE + "function pdf(w) { return w[2] > 0 ? w[2] / Math.PI : 0; }\n" + MALLEY_INVERT
OWN_UNIFORM = """// the uniform hemisphere, with its own (right) density
function sample(u1, u2) {
  const z = u2, r = Math.sqrt(Math.max(0, 1 - z * z)), phi = 2 * Math.PI * u1;
  return [r * Math.cos(phi), r * Math.sin(phi), z];
}
function pdf(w) { return w[2] >= 0 ? 1 / (2 * Math.PI) : 0; }
"""
OWN_NO_PI = MALLEY_SAMPLE + "function pdf(w) { return w[2] > 0 ? w[2] : 0; }\n"
OWN_SYNTAX = "function sample(u1, u2) {\n  return [0, 0, 1];\n\nfunction pdf(w) { return 1; }\n"
OWN_THROWS = """function sample(u1, u2) {
  return [0, 0, 1];
}
function pdf(w) {
  if (w[2] > 0.5) throw new Error("a deliberate exception");
  return 1;
}
"""
OWN_NAN = "function sample(u1, u2) { return [0, 0, 1]; }\nfunction pdf(w) { return Math.sqrt(-1); }\n"
OWN_SHAPE = "function sample(u1, u2) { return [u1, u2]; }\nfunction pdf(w) { return 1; }\n"
# A pdf that answers the sample loop's 10,000 calls and then never returns:
# it hangs inside the module's quadrature, which calls it through an import.
OWN_HANGS = ("let calls = 0;\nfunction sample(u1, u2) { return [0, 0, 1]; }\n"
             "function pdf(w) { if (++calls > 10000) for (;;) {} return w[2] / Math.PI; }\n")


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

    def run_own(self, code, target, n, seed, limit_ms=30000):
        """The own-warp box: the code, target, count, seed and time limit;
        its verdict, the lines of its checks and the error panel's text
        (None when hidden)."""
        self.press("""document.getElementById('own-code').value = %s;
          const t = document.getElementById('own-target'); t.value = %s;
          t.dispatchEvent(new Event('change'));
          document.getElementById('own-n').value = '%d';
          document.getElementById('own-seed').value = '%d';
          document.getElementById('own-limit').value = '%d';"""
                   % (json.dumps(code), json.dumps(target), n, seed, limit_ms),
                   "lab-own", "own-run")
        return self.js("""(() => { const r = document.getElementById('lab-own');
          const panel = document.getElementById('own-error');
          return { state: r.dataset.state, verdict: r.dataset.verdict, ms: Number(r.dataset.ms),
                   pictures: !document.getElementById('own-pictures').hidden,
                   checks: Array.from(document.querySelectorAll('#own-checks li'))
                               .map(li => li.innerText.trim().replace(/\\s*\\n\\s*/g, ' / ')),
                   error: panel.hidden || getComputedStyle(panel).display === 'none' ? null : panel.textContent,
                   status: document.getElementById('own-status').textContent }; })()""")

    def screenshot_of(self, element_id, path):
        """A screenshot of one element, in page coordinates."""
        box = self.js("""(() => { const b = document.getElementById(%s).getBoundingClientRect();
          return { x: b.left + scrollX, y: b.top + scrollY, width: b.width, height: b.height }; })()"""
                      % json.dumps(element_id))
        clip = dict(box, scale=1)
        data = self.b.call("Page.captureScreenshot",
                           {"format": "png", "captureBeyondViewport": True, "clip": clip},
                           self.session, timeout=60)["data"]
        with open(path, "wb") as f:
            f.write(base64.b64decode(data))

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

        # Live on load: every widget ran its default case once, no click.
        s = page.js("""(() => { const d = (id) => document.getElementById(id).dataset;
          const inked = (id) => { const c = document.getElementById(id);
            const px = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
            let k = 0; for (let i = 0; i < px.length; i += 4) if (px[i] < 200 || px[i + 2] < 200) k++;
            return k; };
          return { chi2: [d('lab-chi2').runs, d('lab-chi2').state, document.getElementById('lab-verdict').textContent],
                   est: [d('lab-estimator').runs, d('lab-estimator').state],
                   own: [d('lab-own').runs, d('lab-own').state, d('lab-own').verdict],
                   ink: [inked('lab-marginal'), inked('lab-residual'), inked('own-top'), inked('own-residual')] }; })()""")
        report(s["chi2"] == ["1", "done", "pass"] and s["est"] == ["1", "done"]
               and s["own"] == ["1", "done", "pass"] and min(s["ink"]) > 500,
               "live on load, no click: chi-square (runs, state, verdict) %s, estimator %s, own warp %s; "
               "inked pixels of four pictures %s" % (s["chi2"], s["est"], s["own"], s["ink"]))
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

        # The own-warp box: a right warp, a wrong but consistent one, an
        # inconsistent one, and code that fails in four ways.
        o = page.run_own(OWN_MALLEY, "cosine", 100000, 1)
        report(o["verdict"] == "pass" and len(o["checks"]) == 3 and not o["error"]
               and all(c.startswith("[pass]") for c in o["checks"]) and "round trip" in o["checks"][0],
               "own warp, Malley against cosine hemisphere: %s, %.0f ms; %s"
               % (o["verdict"], o["ms"], " | ".join(o["checks"])))
        o = page.run_own(OWN_UNIFORM, "cosine", 100000, 1)
        caught = "do not follow cosine hemisphere" in "".join(o["checks"])
        report(o["verdict"] == "fail" and len(o["checks"]) == 3 and o["checks"][0].startswith("[pass]")
               and o["checks"][1].startswith("[FAIL]") and caught,
               "own warp, uniform hemisphere with its own pdf against cosine: %s; %s"
               % (o["verdict"], o["checks"][1] if len(o["checks"]) > 1 else o))
        page.screenshot_of("lab-own", os.path.join(shots, "lab-own-warp-wrong.png"))
        o = page.run_own(OWN_NO_PI, "cosine", 100000, 1)
        report(o["verdict"] == "fail" and len(o["checks"]) == 3 and o["checks"][0].startswith("[FAIL]")
               and "integrates to 3.14159" in o["checks"][0],
               "own warp, cosine samples with a pdf lacking 1/pi: %s; %s"
               % (o["verdict"], o["checks"][0] if o["checks"] else o))
        for what, code, want in (("a syntax error", OWN_SYNTAX, "does not compile"),
                                 ("a thrown exception", OWN_THROWS, "a deliberate exception (line 5 of your code)"),
                                 ("a NaN density", OWN_NAN, "returned NaN"),
                                 ("a 2D point for a direction", OWN_SHAPE, "needs [x, y, z]")):
            o = page.run_own(code, "cosine", 10000, 1)
            report(o["state"] == "error" and o["verdict"] == "error" and not o["checks"] and not o["pictures"]
                   and o["error"] is not None and want in o["error"],
                   "own warp, %s: error panel %s" % (what, json.dumps(o["error"])))
            if code is OWN_THROWS:
                page.screenshot_of("lab-own", os.path.join(shots, "lab-own-warp-error.png"))
        # Code that never returns: stopped at the limit, the page live all
        # along (press() polls it), and the next run starts a new Worker.
        t0 = time.time()
        o = page.run_own(OWN_HANGS, "cosine", 10000, 1, 5000)
        waited = time.time() - t0
        report(o["state"] == "error" and o["verdict"] == "error" and not o["checks"] and not o["pictures"]
               and o["error"] is not None and "did not finish within 5 s" in o["error"] and 4.5 <= waited < 30,
               "own warp, a pdf that never returns: stopped after %.1f s, error panel %s"
               % (waited, json.dumps(o["error"])))
        o = page.run_own(OWN_MALLEY, "cosine", 10000, 2)
        report(o["verdict"] == "pass" and o["error"] is None,
               "own warp after an error and a stopped run: the panel goes, %s" % o["verdict"])
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
    print("lab: screenshots lab-desktop.png, lab-phone.png, lab-nojs.png, lab-own-warp-wrong.png, "
          "lab-own-warp-error.png in " + shots)
    print("lab: %d passed, %d failed" % (passed, failed))
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
