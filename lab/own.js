/* lab/own.js - the warp lab's own-warp box: a sampler the reader writes in
 * JavaScript, judged by the module's public check (lab/own.c) as the
 * exercises judge theirs: your points against your density (chi-square,
 * the density's integral, the round trip), the same points against the
 * target law picked from the catalog, your density against the law's on a
 * grid.
 *
 * The reader's code runs in a Worker of its own (judge below), with its
 * own instance of the module, so that the page stays live while it runs:
 * it is compiled there with `new Function`, and every way it can go wrong
 * (it does not compile, it throws, it returns NaN, infinity or something
 * of the wrong shape) ends in the error panel with the message, and for an
 * exception the line of the reader's code, never in a blank result or a
 * pass. Code that does not finish within the time limit the reader picked
 * (an endless loop) is stopped with its Worker, and says so in the same
 * panel; the next run starts a new Worker.
 *
 * Loaded before lab/lab.js, which calls init() once the module runs; the
 * checks (book/check_lab.py) read data-state, data-runs and data-verdict of
 * #lab-own and the texts of #own-checks and #own-error.
 */
"use strict";

(function () {
  /* The catalog rows a reader's warp of two uniforms can aim at (their
   * default parameters), as the page names them. */
  const TARGETS = [
    ["cosine", "cosine hemisphere"],
    ["hemisphere", "uniform hemisphere"],
    ["sphere-inverse", "uniform sphere"],
    ["cone", "uniform cone (cos \u03b8 \u2265 0.8)"],
    ["phong", "Phong lobe (n = 40)"],
    ["disc-polar", "uniform disc"],
    ["square", "uniform unit square"],
    ["linear", "linear on [0, 2] (density x/2)"],
  ];
  const MEASURE = { "solid-angle": "per unit solid angle", area: "per unit area", length: "per unit length" };
  const SHAPE = { 1: "a number x (or [x])", 2: "[x, y]", 3: "[x, y, z], a unit vector" };

  const EXAMPLE = [
    "// Cosine-weighted directions by Malley's method: a uniform point of the",
    "// unit disc (Shirley and Chiu's concentric map) lifted to the hemisphere.",
    "function sample(u1, u2) {",
    "  const a = 2 * u1 - 1, b = 2 * u2 - 1;",
    "  if (a === 0 && b === 0) return [0, 0, 1];",
    "  let r, phi;",
    "  if (Math.abs(a) > Math.abs(b)) { r = a; phi = (Math.PI / 4) * (b / a); }",
    "  else { r = b; phi = Math.PI / 2 - (Math.PI / 4) * (a / b); }",
    "  const x = r * Math.cos(phi), y = r * Math.sin(phi);",
    "  return [x, y, Math.sqrt(Math.max(0, 1 - x * x - y * y))];",
    "}",
    "",
    "// Its density per unit solid angle: cos(theta) / pi, and 0 below the horizon.",
    "function pdf(w) {",
    "  return w[2] > 0 ? w[2] / Math.PI : 0;",
    "}",
    "",
    "// Optional: the (u1, u2) that sample maps to w (the concentric map undone).",
    "function invert(w) {",
    "  const x = w[0], y = w[1], r = Math.hypot(x, y);",
    "  if (r === 0) return [0.5, 0.5];",
    "  let a, b;",
    "  if (Math.abs(x) >= Math.abs(y)) { a = x < 0 ? -r : r; b = a * Math.atan2(y / a, x / a) / (Math.PI / 4); }",
    "  else { b = y < 0 ? -r : r; a = (Math.PI / 2 - Math.atan2(y / b, x / b)) * b / (Math.PI / 4); }",
    "  return [(a + 1) / 2, (b + 1) / 2];",
    "}",
  ].join("\n");

  /* The judge: the Worker's whole program, made into its source text by
   * toString (startJudge), and given the module's loader (lab/lab.js,
   * loadModule) the same way. Everything that calls the reader's code is
   * here; it answers each run's message with the checks' results or with
   * the error to show. */
  function judge(loadModule) {
    "use strict";
    let lab = null, SHAPE = null, ready = null;

    /* A failure of the reader's code, with the line when the stack gives one. */
    class ReaderError extends Error {}

    /* The line of the reader's code where err was thrown: the innermost
     * frame in code made by new Function, less the lines put before it. */
    const PREFIX = '"use strict";\n';
    let lineOffset = null;
    function readerLine(err) {
      const frame = /(?:<anonymous>|> Function):(\d+):\d+/.exec(String(err && err.stack));
      if (lineOffset === null) {
        try { new Function(PREFIX + "throw new Error()")(); } catch (probe) {
          const m = /(?:<anonymous>|> Function):(\d+):\d+/.exec(String(probe.stack));
          lineOffset = m ? Number(m[1]) - 1 : NaN;
        }
      }
      const line = frame ? Number(frame[1]) - lineOffset : NaN;
      return Number.isFinite(line) && line >= 1 ? line : null;
    }

    function threw(what, err) {
      const line = readerLine(err);
      const name = err && err.name ? err.name : "exception";
      const msg = err && err.message !== undefined ? err.message : String(err);
      return new ReaderError(what + " threw " + name + ": " + msg + (line ? " (line " + line + " of your code)" : ""));
    }

    function show(v) {
      if (typeof v === "number" || v === undefined || v === null) return String(v);
      try { return JSON.stringify(v, (k, x) => (typeof x === "number" && !Number.isFinite(x) ? String(x) : x)).slice(0, 80); }
      catch (e) { return String(v); }
    }

    function compile(code) {
      let make;
      try {
        make = new Function(PREFIX + code + "\n;return {" +
          "sample: typeof sample === 'function' ? sample : undefined," +
          "pdf: typeof pdf === 'function' ? pdf : undefined," +
          "invert: typeof invert === 'function' ? invert : undefined };");
      } catch (err) {
        throw new ReaderError("your code does not compile: " + err.name + ": " + err.message);
      }
      let fns;
      try { fns = make(); } catch (err) { throw threw("the top level of your code", err); }
      if (!fns.sample || !fns.pdf) {
        throw new ReaderError("define function sample(u1, u2) and function pdf(x) (and optionally invert(x))");
      }
      return fns;
    }

    /* A point returned by sample as three coordinates (unused ones 0), or null. */
    function pointOf(v, dims) {
      if (dims === 1 && typeof v === "number") v = [v];
      if (!v || typeof v.length !== "number" || v.length !== dims) return null;
      const p = [0, 0, 0];
      for (let i = 0; i < dims; i++) {
        if (typeof v[i] !== "number" || !Number.isFinite(v[i])) return null;
        p[i] = v[i];
      }
      return p;
    }

    /* The reader's pdf at p (dims coordinates), a finite number or a ReaderError. */
    function density(fns, p, dims) {
      const x = p.slice(0, dims);
      let d;
      try { d = fns.pdf(x); } catch (err) { throw threw("pdf(" + show(x) + ")", err); }
      if (typeof d !== "number" || !Number.isFinite(d)) {
        throw new ReaderError("pdf(" + show(x) + ") returned " + show(d) + ", not a finite number");
      }
      return d;
    }

    /* The module's imports call these while the check runs: the reader's
     * pdf and invert, every failure kept (the first one shown) and NaN
     * handed to the check instead. */
    let hookError = null;
    function hooks(fns, dims) {
      lab.hooks.pdf = (a, b, c) => {
        if (hookError) return NaN;
        try { return density(fns, [a, b, c], dims); } catch (err) { hookError = err; return NaN; }
      };
      lab.hooks.invert = (a, b, c, ptr) => {
        const out = new Float64Array(lab.e.memory.buffer, ptr, 2);
        out[0] = out[1] = NaN;
        if (hookError) return;
        const x = [a, b, c].slice(0, dims);
        let u;
        try { u = fns.invert(x); } catch (err) { hookError = threw("invert(" + show(x) + ")", err); return; }
        // An interval's warp has one uniform that counts: u1, [u1] or [u1, u2].
        if (dims === 1 && typeof u === "number") u = [u];
        const nu = dims === 1 ? 1 : 2;
        const shaped = u && (u.length === nu || (nu === 1 && u.length === 2));
        if (!shaped || !Number.isFinite(u[0]) || (nu === 2 && !Number.isFinite(u[1]))) {
          hookError = new ReaderError("invert(" + show(x) + ") returned " + show(u) + ", not " +
                                      (nu === 1 ? "u1" : "[u1, u2]") + " of finite numbers");
          return;
        }
        out[0] = u[0], out[1] = nu === 2 ? u[1] : NaN;
      };
    }

    /* One run: m holds the code, the target row's name, label and domain,
     * the point's dimension, the count and the seed's halves. */
    function run(m) {
      const dims = m.dims, n = m.n, halves = m.halves;
      const t0 = performance.now();
      let fns;
      const pts = new Float64Array(Math.min(n, 4096) * 7);
      try {
        fns = compile(m.code);
        if (!lab.e.lab_own_prepare(halves[0], halves[1], n)) return { error: "no memory for " + n + " samples" };
        const buf = lab.e.memory.buffer;
        const U = new Float64Array(buf, lab.e.lab_own_uniforms(), 2 * n);
        const X = new Float64Array(buf, lab.e.lab_own_points(), 3 * n);
        const P = new Float64Array(buf, lab.e.lab_own_pdfs(), n);
        for (let k = 0; k < n; k++) {
          const u1 = U[2 * k], u2 = U[2 * k + 1];
          let v;
          try { v = fns.sample(u1, u2); } catch (err) { throw threw("sample(" + u1 + ", " + u2 + ")", err); }
          const p = pointOf(v, dims);
          if (!p) {
            throw new ReaderError("sample(" + u1 + ", " + u2 + ") returned " + show(v) + "; the target " +
                                  m.domain + " needs " + SHAPE[dims] + " of finite numbers");
          }
          X[3 * k] = p[0], X[3 * k + 1] = p[1], X[3 * k + 2] = p[2];
          P[k] = density(fns, p, dims);
          if (k < pts.length / 7) pts.set([u1, u2, p[0], p[1], p[2], NaN, NaN], 7 * k);
        }
      } catch (err) {
        return { error: err instanceof ReaderError ? err.message : "the page itself failed: " + err };
      }
      lab.put(m.name + "\n" + m.label);
      hookError = null;
      hooks(fns, dims);
      const ok = lab.e.lab_own_check(halves[0], halves[1], fns.invert ? 1 : 0);
      if (hookError) return { error: hookError.message };
      if (!ok) return { error: "the module could not run the check of " + m.name };
      const ms = performance.now() - t0;
      /* Each check's report, its numbers and its table of counts (for the
       * pictures), copied out of the module's memory. */
      const checks = [0, 1, 2].map((k) => {
        const f = lab.str(lab.e.lab_own_report(k)).split("\t");
        const v = lab.f64(lab.e.lab_own_result(k), 20), cells = v[14] * v[15];
        const obsP = lab.e.lab_own_observed(k), expP = lab.e.lab_own_expected(k);
        const table = obsP && expP && cells > 0;
        return { status: Number(f[0]), name: f[1], key: f[2], fig: f[3], why: f[4], xl: f[5], yl: f[6], v,
                 obs: table ? lab.f64(obsP, cells) : null, exp: table ? lab.f64(expP, cells) : null };
      });
      return { checks, pts, ms };
    }

    self.onmessage = (ev) => {
      const m = ev.data;
      if (m.module) {
        SHAPE = m.shape;
        ready = loadModule(m.module).then((l) => { lab = l; });
        return;
      }
      ready.then(() => {
        let answer;
        try { answer = run(m); } catch (err) { answer = { error: "the page itself failed: " + err }; }
        self.postMessage(answer);
      }, (err) => self.postMessage({ error: "the page itself failed: the module did not start: " + err }));
    };
  }

  function init(lab, root, catalog, draw) {
    const $ = (id) => document.getElementById(id);
    const rows = {};
    catalog.rows.forEach((r) => { rows[r.name] = r; });
    const code = $("own-code"), target = $("own-target"), nSel = $("own-n"), seedIn = $("own-seed");
    const limitSel = $("own-limit");
    const status = $("own-status"), panel = $("own-error"), view = $("own-view");
    for (const [name, label] of TARGETS) {
      if (rows[name]) target.appendChild(draw.el("option", { value: name }, label));
    }
    target.value = "cosine";
    code.value = EXAMPLE;
    let last = null; // the last run's tables, for the picture picker

    const pointDims = (r) => (r.point === "direction" || r.point === "point" ? 3 : r.point === "planar" ? 2 : 1);

    function about() {
      const r = rows[target.value];
      $("own-about").textContent = "Target: " + r.domain + "; sample(u1, u2) returns " + SHAPE[pointDims(r)] +
        "; pdf(x) is the density " + (MEASURE[r.measure] || "per unit " + r.measure) +
        ", 0 outside the domain; invert(x) returns " + (pointDims(r) === 1 ? "u1 (a warp of an interval uses u1 alone)." : "[u1, u2].");
    }

    function clear() {
      for (const id of ["own-mine", "own-integral", "own-round", "own-law", "own-verdict"]) {
        $(id).textContent = "\u2013";
        $(id).className = "";
      }
      $("own-checks").textContent = "";
    }

    function fail(msg) {
      clear();
      panel.hidden = false;
      $("own-pictures").hidden = true; // the last run's pictures would pass for this one's
      $("own-error-text").textContent = msg;
      $("own-verdict").textContent = "error";
      $("own-verdict").className = "lab-verdict-fail";
      status.textContent = "Nothing was judged: fix your code and run it again.";
      status.className = "lab-status lab-error";
      root.dataset.state = "error";
      root.dataset.verdict = "error";
      root.dataset.runs = String(Number(root.dataset.runs || 0) + 1);
    }

    /* The Worker that runs the reader's code, made when a run needs one:
     * the judge's source and the module's loader, as a script of the page's
     * own (a blob: URL, which a page opened from disk may start). */
    let worker = null;
    function startJudge() {
      const src = '"use strict";\nconst loadModule = ' + lab.loader.toString() + ";\n(" + judge.toString() +
                  ")(loadModule);\n";
      const url = URL.createObjectURL(new Blob([src], { type: "text/javascript" }));
      const w = new Worker(url);
      URL.revokeObjectURL(url); // the Worker holds the script from here on
      w.postMessage({ module: lab.module, shape: SHAPE });
      return w;
    }
    function stopJudge(w) {
      w.terminate();
      if (worker === w) worker = null;
    }

    /* One run in the Worker; resolves when it has been shown, whether it
     * answered, failed or ran out of time. */
    function run() {
      return new Promise((resolve) => {
        panel.hidden = true;
        about();
        const r = rows[target.value], dims = pointDims(r), n = Number(nSel.value), limit = Number(limitSel.value);
        const label = target.selectedOptions[0].textContent;
        const halves = draw.seedHalves(seedIn.value);
        if (!halves) {
          fail("the seed is a whole number from 0 to 2^64 - 1");
          return resolve();
        }
        const w = worker || (worker = startJudge());
        const done = (show) => {
          clearTimeout(timer);
          w.onmessage = w.onerror = null;
          show();
          resolve();
        };
        const timer = setTimeout(() => done(() => {
          stopJudge(w);
          fail("your code did not finish within " + limitSel.selectedOptions[0].textContent +
               " (an endless loop?), so it was stopped; pick a longer limit for slow code");
        }), limit);
        w.onmessage = (ev) => done(() => {
          if (ev.data.error) fail(ev.data.error);
          else results(r, label, dims, n, ev.data);
        });
        w.onerror = (ev) => {
          ev.preventDefault();
          done(() => {
            stopJudge(w);
            fail("the page itself failed: " + ev.message);
          });
        };
        w.postMessage({ code: code.value, name: r.name, label, domain: r.domain, dims, n, halves });
      });
    }

    function results(r, label, dims, n, answer) {
      const { checks, pts, ms } = answer;
      const list = $("own-checks");
      list.textContent = "";
      for (const c of checks) {
        const word = ["pass", "FAIL", "ERROR"][c.status] || "ERROR";
        const li = draw.el("li", { class: "lab-check-" + (c.status === 0 ? "pass" : "fail") });
        li.appendChild(draw.el("span", { class: c.status === 0 ? "lab-verdict-pass" : "lab-verdict-fail" }, "[" + word + "] "));
        li.appendChild(draw.el("span", {}, c.name + ": " + c.key));
        li.appendChild(draw.el("span", { class: "lab-muted lab-check-figure" }, c.fig));
        if (c.why) li.appendChild(draw.el("span", { class: "lab-check-why" }, c.why));
        list.appendChild(li);
      }
      const mine = checks[0].v, law = checks[1].v;
      const set = (id, text, good) => { $(id).textContent = text; $(id).className = good ? "lab-verdict-pass" : "lab-verdict-fail"; };
      set("own-mine", "p = " + mine[3].toPrecision(3) + " (" + mine[1].toFixed(1) + ", " + mine[2] + " dof)", mine[3] >= mine[4]);
      set("own-integral", mine[5].toFixed(9) + " \u00b1 " + mine[6].toExponential(1), Math.abs(mine[5] - 1) <= 1e-6 + mine[6]);
      if (Number.isNaN(mine[7])) { $("own-round").textContent = "no invert"; $("own-round").className = ""; }
      else set("own-round", "off by " + mine[7].toExponential(2), mine[7] <= 1e-6);
      set("own-law", "p = " + law[3].toPrecision(3) + "; pdf off by " + law[8].toExponential(1), checks[1].status === 0);
      const pass = checks.every((c) => c.status === 0);
      set("own-verdict", pass ? "pass" : "fail", pass);
      status.textContent = n.toLocaleString("en") + " samples in " + ms.toFixed(0) + " ms; each chi-square at level " +
        law[4].toPrecision(2) + " (0.01 shared by the two tests). " +
        (pass ? "A pass: your points follow your density, it integrates to 1" +
                (Number.isNaN(mine[7]) ? "" : ", invert undoes sample") + ", and it is " + label + "'s."
              : "Read the first failing check above.");
      status.className = "lab-status";
      last = { checks, r, dims, n, pts };
      $("own-pictures").hidden = false;
      view.value = checks[0].status !== 0 && checks[1].status === 0 ? "0" : "1";
      pictures();
      root.dataset.verdict = pass ? "pass" : "fail";
      root.dataset.ms = ms.toFixed(1);
      root.dataset.runs = String(Number(root.dataset.runs || 0) + 1);
      root.dataset.state = "done";
    }

    function pictures() {
      if (!last) return;
      const { checks, r, dims, n, pts } = last, m = Math.min(n, 4096), k = Number(view.value);
      if (dims === 1) {
        let a = Infinity, b = -Infinity;
        for (let i = 0; i < m; i++) { a = Math.min(a, pts[7 * i + 2]); b = Math.max(b, pts[7 * i + 2]); }
        const pad = 0.05 * (b - a || 1);
        draw.scatter($("own-square"), pts, m, 0, 2, [0, 1, a - pad, b + pad], "u1 \u2192 x: the first " + m, "u1", "x");
      } else {
        draw.scatter($("own-square"), pts, m, 0, 1, [0, 1, 0, 1], "unit square: the first " + m, "u1", "u2");
      }
      if (dims === 3) {
        draw.scatter($("own-top"), pts, m, 2, 3, [-1.05, 1.05, -1.05, 1.05], "top view (x, y)", "x", "y", true);
        draw.scatter($("own-side"), pts, m, 2, 4, [-1.05, 1.05, -1.05, 1.05], "side view (x, z)", "x", "z", true);
      } else if (dims === 2) {
        draw.scatter($("own-top"), pts, m, 2, 3, draw.boxOf(pts, m, 2, 3), "your points (x, y)", "x", "y", r.chart === "disc");
      }
      $("own-top").hidden = dims === 1;
      $("own-side").hidden = dims !== 3;
      const v = checks[k].v;
      if (!checks[k].obs) return;
      draw.tables("own", {
        lo0: v[16], hi0: v[17], lo1: v[18], hi1: v[19], c0: v[14], c1: v[15],
        obs: checks[k].obs, exp: checks[k].exp, axes: [checks[k].xl, checks[k].yl],
      });
    }

    /* A click while a run is on gets that run's promise, not a second run. */
    let pending = null;
    const go = () => {
      if (pending) return pending;
      root.dataset.state = "running";
      status.textContent = "running\u2026";
      status.className = "lab-status";
      pending = run().finally(() => { pending = null; });
      return pending;
    };
    $("own-form").addEventListener("submit", (ev) => { ev.preventDefault(); go(); });
    $("own-reset").addEventListener("click", () => { code.value = EXAMPLE; target.value = "cosine"; about(); });
    target.addEventListener("change", about);
    view.addEventListener("change", pictures);
    about();
    return go;
  }

  window.MCBOX_LAB_WIDGETS = (window.MCBOX_LAB_WIDGETS || []).concat([{ id: "lab-own", init }]);
})();
