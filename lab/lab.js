/* lab/lab.js - the book's warp lab: the page's side of the WebAssembly
 * module built from the catalog, the samplers and the goodness-of-fit
 * harness (lab/lab.h lists what it exports).
 *
 * Every number the page shows comes from the module: this script only
 * reads the controls, passes them in, and draws what comes back. The
 * module arrives as base64 in lab-wasm.js (MCBOX_LAB_WASM), not by fetch,
 * because a page opened from disk may not fetch a file beside it; nothing
 * is loaded from the network. Without JavaScript the page keeps its static
 * figures and runs, and the live parts stay hidden.
 *
 * The page's checks (book/check_lab.py) drive it through the same
 * controls a reader uses and read the results from data attributes:
 * data-state ("ready", "running", "done", "error") and data-runs on each
 * widget, data-line with the statistic line as `warp chi2` prints it.
 * Every widget runs its default case once on load, before the body's
 * data-lab says "ready"; lab/own.js (the own-warp box) registers itself in
 * MCBOX_LAB_WIDGETS before this script runs.
 */
"use strict";

(function () {
  const SOURCES = ["independent", "jittered", "sobol"];
  const CHART_AXES = {
    line: ["x", ""], index: ["outcome", ""], xy: ["x", "y"], disc: ["r\u00b2", "\u03c6"],
    parallelogram: ["a", "b"], surface: ["cos \u03b8", "\u03c6"],
    direction: ["chart 1 (cos \u03b8)", "chart 2 (\u03c6)"], lobe: ["\u03b8/(\u03b8+s)", "\u03c6"],
  };
  const INK = "#1d1f21", MUTED = "#8a9096", ACCENT = "#1f5fa8", RED = "#b3261e";

  /* --- the module ------------------------------------------------------- */

  /* An instance of the module, from its base64 text or from the module
   * compiled already (`module` below: the own-warp box's Worker gets it by
   * postMessage and compiles nothing). The module is a WASI reactor that
   * never reads or writes a file: every import it names (the C library's
   * stdio) answers ENOSYS, but for those of "lab", the reader's pdf and
   * invert (lab/own.c), which call whatever the own-warp box put in hooks.
   * Self-contained, so that the Worker can take its source (loader, below)
   * and make an instance of its own. */
  async function loadModule(source) {
    let module = source;
    if (typeof source === "string") {
      const raw = atob(source), wasm = new Uint8Array(raw.length);
      for (let i = 0; i < raw.length; i++) wasm[i] = raw.charCodeAt(i);
      module = await WebAssembly.compile(wasm);
    }
    const imports = {}, hooks = { pdf: () => NaN, invert: () => {} };
    for (const imp of WebAssembly.Module.imports(module)) {
      (imports[imp.module] = imports[imp.module] || {})[imp.name] =
        imp.module === "lab" ? (...a) => hooks[imp.name](...a) : () => 52;
    }
    const instance = await WebAssembly.instantiate(module, imports);
    const e = instance.exports;
    e._initialize();
    const bytes = () => new Uint8Array(e.memory.buffer);
    return {
      e, hooks, module, loader: loadModule,
      str(p) {
        const b = bytes();
        let q = p;
        while (b[q]) q++;
        return new TextDecoder().decode(b.subarray(p, q));
      },
      put(s) {
        const b = new TextEncoder().encode(s + "\0");
        if (b.length > 4096) throw new Error("input too long");
        bytes().set(b, e.lab_input());
      },
      f64(p, n) { return new Float64Array(e.memory.buffer, p, n).slice(); },
    };
  }

  /* A seed typed as a decimal integer, as two 32-bit halves. */
  function seedHalves(text) {
    if (!/^\s*\d{1,20}\s*$/.test(text)) return null;
    const v = BigInt(text.trim());
    if (v >= 1n << 64n) return null;
    return [Number(v >> 32n), Number(v & 0xffffffffn)];
  }

  const $ = (id) => document.getElementById(id);

  function el(tag, attrs, text) {
    const x = document.createElement(tag);
    for (const k in attrs || {}) x.setAttribute(k, attrs[k]);
    if (text !== undefined) x.textContent = text;
    return x;
  }

  /* --- drawing ---------------------------------------------------------- */

  /* A canvas with its own scale: plot coordinates to pixels, y upward. */
  function frame(canvas, x0, x1, y0, y1, pad) {
    const ctx = canvas.getContext("2d"), w = canvas.width, h = canvas.height;
    const p = pad === undefined ? 28 : pad;
    ctx.clearRect(0, 0, w, h);
    ctx.fillStyle = "#fff";
    ctx.fillRect(0, 0, w, h);
    const sx = (w - 2 * p) / (x1 - x0 || 1), sy = (h - 2 * p) / (y1 - y0 || 1);
    return {
      ctx, w, h, p,
      X: (x) => p + (x - x0) * sx,
      Y: (y) => h - p - (y - y0) * sy,
    };
  }

  function axes(f, label, xl, yl) {
    const c = f.ctx;
    c.strokeStyle = MUTED;
    c.lineWidth = 1;
    c.strokeRect(f.p, f.p, f.w - 2 * f.p, f.h - 2 * f.p);
    c.fillStyle = INK;
    c.font = "13px sans-serif";
    c.textAlign = "left";
    c.fillText(label, f.p, f.p - 9);
    c.fillStyle = MUTED;
    c.font = "12px sans-serif";
    if (xl) { c.textAlign = "center"; c.fillText(xl, f.w / 2, f.h - 8); }
    if (yl) {
      c.save();
      c.translate(12, f.h / 2);
      c.rotate(-Math.PI / 2);
      c.textAlign = "center";
      c.fillText(yl, 0, 0);
      c.restore();
    }
  }

  /* Points coloured by u1 (the hue) so that a point and its image match. */
  function hue(u) { return "hsl(" + Math.round(280 * (Number.isFinite(u) ? u : 0.5)) + ",70%,45%)"; }

  function scatter(canvas, pts, n, ix, iy, box, label, xl, yl, circle) {
    const f = frame(canvas, box[0], box[1], box[2], box[3]);
    if (circle) {
      f.ctx.strokeStyle = "#c9ccd0";
      f.ctx.beginPath();
      f.ctx.ellipse(f.X(0), f.Y(0), f.X(1) - f.X(0), f.Y(0) - f.Y(1), 0, 0, 2 * Math.PI);
      f.ctx.stroke();
    }
    const r = n > 4000 ? 1 : 1.6;
    for (let k = 0; k < n; k++) {
      const q = k * 7, x = pts[q + ix], y = iy < 0 ? pts[q] : pts[q + iy];
      if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
      f.ctx.fillStyle = hue(pts[q]);
      f.ctx.fillRect(f.X(x) - r / 2, f.Y(y) - r / 2, r, r);
    }
    axes(f, label, xl, yl);
  }

  /* A symmetric box around the points' coordinates ix and iy. */
  function boxOf(pts, n, ix, iy) {
    let lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
    for (let k = 0; k < n; k++) {
      const a = pts[k * 7 + ix], b = pts[k * 7 + iy];
      if (!Number.isFinite(a) || !Number.isFinite(b)) continue;
      lo = [Math.min(lo[0], a), Math.min(lo[1], b)];
      hi = [Math.max(hi[0], a), Math.max(hi[1], b)];
    }
    const cx = (lo[0] + hi[0]) / 2, cy = (lo[1] + hi[1]) / 2;
    const half = 0.55 * Math.max(hi[0] - lo[0], hi[1] - lo[1], 1e-9);
    return [cx - half, cx + half, cy - half, cy + half];
  }

  /* A table of cells as a heat map: values mapped by colour(v). */
  function heat(canvas, vals, r, label, colour) {
    const f = frame(canvas, r.lo0, r.hi0, r.lo1, r.hi1);
    const cw = (f.w - 2 * f.p) / r.c0, ch = (f.h - 2 * f.p) / r.c1;
    for (let i = 0; i < r.c0; i++) {
      for (let j = 0; j < r.c1; j++) {
        f.ctx.fillStyle = colour(vals[i * r.c1 + j], i * r.c1 + j);
        f.ctx.fillRect(f.p + i * cw, f.h - f.p - (j + 1) * ch, Math.ceil(cw), Math.ceil(ch));
      }
    }
    axes(f, label, r.axes[0], r.axes[1]);
  }

  /* Observed counts as bars, expected as a line, along the first chart
   * coordinate (summed over the second). */
  function marginal(canvas, r, label) {
    const o = new Float64Array(r.c0), x = new Float64Array(r.c0);
    for (let i = 0; i < r.c0; i++) {
      for (let j = 0; j < r.c1; j++) { o[i] += r.obs[i * r.c1 + j]; x[i] += r.exp[i * r.c1 + j]; }
    }
    let top = 0;
    for (let i = 0; i < r.c0; i++) top = Math.max(top, o[i], x[i]);
    const f = frame(canvas, r.lo0, r.hi0, 0, 1.05 * top || 1);
    const w = (r.hi0 - r.lo0) / r.c0;
    f.ctx.fillStyle = "#9fb7d6";
    for (let i = 0; i < r.c0; i++) {
      const a = r.lo0 + i * w;
      f.ctx.fillRect(f.X(a), f.Y(o[i]), Math.max(1, f.X(a + w) - f.X(a) - 0.5), f.Y(0) - f.Y(o[i]));
    }
    f.ctx.strokeStyle = RED;
    f.ctx.lineWidth = 2;
    f.ctx.beginPath();
    for (let i = 0; i < r.c0; i++) {
      const a = r.lo0 + i * w;
      f.ctx[i ? "lineTo" : "moveTo"](f.X(a), f.Y(x[i]));
      f.ctx.lineTo(f.X(a + w), f.Y(x[i]));
    }
    f.ctx.stroke();
    axes(f, label, r.axes[0], "count");
  }

  /* The pictures of a test into the canvases PREFIX-marginal, -observed,
   * -expected and -residual: counts summed along the second chart
   * coordinate, then (a 2D chart) the two tables and the standardized
   * residuals. */
  function tables(prefix, out) {
    let top = 0;
    for (let c = 0; c < out.exp.length; c++) top = Math.max(top, out.obs[c], out.exp[c]);
    const shade = (v) => {
      const t = Math.pow(Math.min(1, v / (top || 1)), 0.5);
      return "rgb(" + Math.round(255 - 200 * t) + "," + Math.round(255 - 150 * t) + "," + Math.round(255 - 60 * t) + ")";
    };
    const twoD = out.c1 > 1, cv = (k) => $(prefix + "-" + k);
    cv("observed").hidden = cv("expected").hidden = cv("residual").hidden = !twoD;
    if (twoD) {
      heat(cv("observed"), out.obs, out, "observed counts on the chart", shade);
      heat(cv("expected"), out.exp, out, "expected: the density integrated per cell", shade);
      heat(cv("residual"), out.obs, out, "residuals (obs \u2212 exp) / \u221aexp", (v, c) => {
        const e = out.exp[c];
        if (!(e > 0)) return v > 0 ? "#000" : "#eee";
        const z = Math.max(-4, Math.min(4, (v - e) / Math.sqrt(e))) / 4;
        return z > 0 ? "rgb(255," + Math.round(255 * (1 - z)) + "," + Math.round(255 * (1 - z)) + ")"
                     : "rgb(" + Math.round(255 * (1 + z)) + "," + Math.round(255 * (1 + z)) + ",255)";
      });
    }
    marginal(cv("marginal"), out, "observed (bars), expected (line)");
  }

  /* --- the chi-square lab ----------------------------------------------- */

  function chi2Lab(lab, root, catalog) {
    const rows = catalog.rows.concat(catalog.negatives);
    const byName = {};
    rows.forEach((r) => { byName[r.name] = r; });
    const rowSel = $("lab-row"), params = $("lab-params"), srcSel = $("lab-source");
    const nSel = $("lab-n"), seedIn = $("lab-seed"), status = $("lab-status");
    const groups = [["Samplers of the catalog", catalog.rows],
                    ["Negative controls (wrong on purpose)", catalog.negatives]];
    for (const [title, list] of groups) {
      const g = el("optgroup", { label: title });
      for (const r of list) g.appendChild(el("option", { value: r.name }, r.name));
      rowSel.appendChild(g);
    }
    rowSel.value = "cosine";

    function showRow() {
      const r = byName[rowSel.value];
      params.textContent = "";
      for (const p of r.params) {
        const id = "lab-param-" + p.key;
        const wrap = el("label", { for: id }, p.key + " ");
        const input = el("input", { id, type: "text", value: p.def, "data-key": p.key,
                                    size: p.kind === "number" ? 6 : 14, spellcheck: "false" });
        wrap.appendChild(input);
        params.appendChild(wrap);
      }
      if (!r.params.length) params.appendChild(el("span", { class: "lab-muted" }, "no parameters"));
      for (let k = 0; k < SOURCES.length; k++) {
        srcSel.options[k].disabled = !(r.sources >> k & 1);
      }
      if (srcSel.selectedOptions[0].disabled) srcSel.value = "independent";
      $("lab-about").textContent = r.domain + ", density per unit " + r.measure +
        (r.wrong ? ". Wrong on purpose: " + r.wrong : "");
      $("lab-about").className = "lab-about" + (r.wrong ? " lab-wrong" : "");
    }

    function assignments() {
      return Array.from(params.querySelectorAll("input")).map(
        (i) => i.dataset.key + "=" + i.value.trim());
    }

    function command(r, seed) {
      const ps = assignments().map((a) => " --param " + a).join("");
      return "warp chi2 " + r.name + ps + " --n " + nSel.value + " --seed " + seed;
    }

    function fail(msg) {
      status.textContent = msg;
      status.className = "lab-status lab-error";
      root.dataset.state = "error";
    }

    function run() {
      const r = byName[rowSel.value], seed = seedIn.value.trim(), halves = seedHalves(seed);
      if (!halves) return fail("The seed is a whole number from 0 to 2^64 - 1.");
      lab.put([r.name].concat(assignments()).join("\n"));
      if (!lab.e.lab_select()) return fail(lab.str(lab.e.lab_error()));
      const n = Number(nSel.value), source = SOURCES.indexOf(srcSel.value);
      const t0 = performance.now();
      const ok = lab.e.lab_chi2(halves[0], halves[1], n, 0.01, source);
      const ms = performance.now() - t0;
      if (!ok) return fail(lab.str(lab.e.lab_error()));
      const res = lab.f64(lab.e.lab_result(), 17);
      const cells = res[13] * res[14];
      const out = {
        lo0: res[9], hi0: res[10], lo1: res[11], hi1: res[12], c0: res[13], c1: res[14],
        obs: lab.f64(lab.e.lab_observed(), cells), exp: lab.f64(lab.e.lab_expected(), cells),
        axes: CHART_AXES[r.chart],
      };
      const line = lab.str(lab.e.lab_line()), parts = line.split(" ");
      $("lab-stat").textContent = parts[0];
      $("lab-dof").textContent = parts[1];
      $("lab-p").textContent = parts[2];
      const verdict = $("lab-verdict");
      verdict.textContent = parts[3];
      verdict.className = "lab-verdict-" + parts[3];
      $("lab-command").textContent = "$ " + command(r, seed);
      $("lab-line").textContent = "chi2 dof p verdict\n" + line;
      const notes = [];
      if (res[4] > 0) notes.push(res[4] + " samples outside the chart");
      if (res[15] > 0) notes.push(res[15] + " samples where the density integrates to 0");
      if (source > 0) notes.push("a " + SOURCES[source] + " set is not independent: " +
                                 "the test's p-value assumes it is, so expect p near 1 for a right warp");
      status.textContent = n.toLocaleString("en") + " samples, " + out.c0 * out.c1 +
        " cells (" + res[5] + " pooled), " + ms.toFixed(0) + " ms in this browser" +
        (notes.length ? "; " + notes.join("; ") : "") + ".";
      status.className = "lab-status";
      root.dataset.line = line;
      root.dataset.ms = ms.toFixed(1);
      draw(r, n, halves, source, out);
      root.dataset.runs = String(Number(root.dataset.runs || 0) + 1);
      root.dataset.state = "done";
    }

    function draw(r, n, halves, source, out) {
      const m = Math.min(n, r.point === "index" ? 2048 : 4096);
      const pp = lab.e.lab_points(halves[0], halves[1], m, source);
      const pts = pp ? lab.f64(pp, m * 7) : new Float64Array(0);
      const count = pp ? m : 0;
      const hasU = count && Number.isFinite(pts[0]);
      const oneU = hasU && !Number.isFinite(pts[1]);
      const cv = (id) => $(id);
      const first = (source === 1 ? "a jittered set of " : "the first ") + count;
      if (!hasU) {
        const f = frame(cv("lab-square"), 0, 1, 0, 1);
        f.ctx.fillStyle = MUTED;
        f.ctx.textAlign = "center";
        f.ctx.fillText("drawn from a generator:", f.w / 2, f.h / 2 - 8);
        f.ctx.fillText("no unit-square points", f.w / 2, f.h / 2 + 10);
        axes(f, "uniforms", "", "");
      } else if (oneU) {
        let a = Infinity, b = -Infinity;
        for (let k = 0; k < count; k++) { a = Math.min(a, pts[k * 7 + 2]); b = Math.max(b, pts[k * 7 + 2]); }
        const pad = 0.05 * (b - a || 1);
        scatter(cv("lab-square"), pts, count, 0, 2, [0, 1, a - pad, b + pad],
                "u \u2192 x: " + first + " points", "u", "x");
      } else {
        scatter(cv("lab-square"), pts, count, 0, 1, [0, 1, 0, 1], "unit square: " + first, "u1", "u2");
      }
      if (r.point === "direction") {
        scatter(cv("lab-top"), pts, count, 2, 3, [-1.05, 1.05, -1.05, 1.05], "top view (x, y)", "x", "y", true);
        scatter(cv("lab-side"), pts, count, 2, 4, [-1.05, 1.05, -1.05, 1.05], "side view (x, z)", "x", "z", true);
      } else if (r.point === "point") {
        scatter(cv("lab-top"), pts, count, 2, 3, boxOf(pts, count, 2, 3), "top view (x, y)", "x", "y", false);
        scatter(cv("lab-side"), pts, count, 2, 4, boxOf(pts, count, 2, 4), "side view (x, z)", "x", "z", false);
      } else if (r.point === "planar") {
        scatter(cv("lab-top"), pts, count, 2, 3, boxOf(pts, count, 2, 3), "the points (x, y)", "x", "y", r.chart === "disc");
      }
      $("lab-side").hidden = !(r.point === "direction" || r.point === "point");
      $("lab-top").hidden = !(r.point === "direction" || r.point === "point" || r.point === "planar");
      tables("lab", out);
    }

    rowSel.addEventListener("change", showRow);
    const go = () => new Promise((resolve) => {
      root.dataset.state = "running";
      status.textContent = "running\u2026";
      status.className = "lab-status";
      // Let the page paint "running" before the module holds the thread.
      setTimeout(() => { try { run(); } finally { resolve(); } }, 20);
    });
    $("lab-form").addEventListener("submit", (ev) => { ev.preventDefault(); go(); });
    showRow();
    return go;
  }

  /* --- the estimator widget --------------------------------------------- */

  function estimatorLab(lab, root, catalog) {
    const kindSel = $("est-kind"), rowSel = $("est-row"), nSel = $("est-n"), seedIn = $("est-seed");
    const status = $("est-status");
    // Rows whose support covers the upper hemisphere, where cos^3 lives: a
    // cone or a light's solid angle would leave part of the integral out.
    const partial = ["cone", "quad-light", "sphere-light", "light-list"];
    for (const r of catalog.rows.concat(catalog.negatives)) {
      if (r.point === "direction" && partial.indexOf(r.name) < 0) {
        rowSel.appendChild(el("option", { value: r.name }, r.name + (r.wrong ? " (wrong on purpose)" : "")));
      }
    }
    rowSel.value = "cosine";
    const sync = () => { rowSel.disabled = $("est-params").disabled = kindSel.value === "pi"; };
    kindSel.addEventListener("change", sync);
    sync();

    function run() {
      const halves = seedHalves(seedIn.value);
      const fail = (msg) => { status.textContent = msg; status.className = "lab-status lab-error"; root.dataset.state = "error"; };
      if (!halves) return fail("The seed is a whole number from 0 to 2^64 - 1.");
      const kind = kindSel.value === "pi" ? 0 : 1;
      if (kind === 1) {
        lab.put([rowSel.value].concat($("est-params").value.trim().split(/\s+/).filter(Boolean)).join("\n"));
        if (!lab.e.lab_select()) return fail(lab.str(lab.e.lab_error()));
      }
      const t0 = performance.now();
      const k = lab.e.lab_estimate(kind, halves[0], halves[1], Number(nSel.value));
      const ms = performance.now() - t0;
      if (!k) return fail(lab.str(lab.e.lab_error()));
      const t = lab.f64(lab.e.lab_estimate_table(), 3 * k);
      const [est, se, exact, z] = lab.str(lab.e.lab_estimate_line()).split(" ");
      const ok = Math.abs(Number(z)) < 4;
      $("est-value").textContent = est + " \u00b1 " + se;
      $("est-exact").textContent = exact;
      $("est-z").textContent = z;
      const v = $("est-verdict");
      v.textContent = ok ? "ok" : "off";
      v.className = ok ? "lab-verdict-pass" : "lab-verdict-fail";
      status.textContent = Number(nSel.value).toLocaleString("en") + " samples in " + ms.toFixed(0) +
        " ms; ok when |z| < 4, as in the book's tables.";
      status.className = "lab-status";
      drawRunning(t, k, Number(exact));
      root.dataset.z = z;
      root.dataset.runs = String(Number(root.dataset.runs || 0) + 1);
      root.dataset.state = "done";
    }

    function drawRunning(t, k, exact) {
      const lx = (n) => Math.log10(n);
      const n0 = t[0], n1 = t[3 * (k - 1)];
      let lo = exact, hi = exact;
      for (let i = Math.floor(k / 4); i < k; i++) {
        lo = Math.min(lo, t[3 * i + 1] - 2.2 * t[3 * i + 2]);
        hi = Math.max(hi, t[3 * i + 1] + 2.2 * t[3 * i + 2]);
      }
      const f = frame($("est-running"), lx(n0), lx(n1), lo, hi);
      const c = f.ctx;
      c.fillStyle = "rgba(31,95,168,0.15)";
      c.beginPath();
      for (let i = 0; i < k; i++) c.lineTo(f.X(lx(t[3 * i])), f.Y(Math.min(hi, t[3 * i + 1] + 2 * t[3 * i + 2])));
      for (let i = k - 1; i >= 0; i--) c.lineTo(f.X(lx(t[3 * i])), f.Y(Math.max(lo, t[3 * i + 1] - 2 * t[3 * i + 2])));
      c.fill();
      c.strokeStyle = RED;
      c.setLineDash([5, 4]);
      c.beginPath();
      c.moveTo(f.X(lx(n0)), f.Y(exact));
      c.lineTo(f.X(lx(n1)), f.Y(exact));
      c.stroke();
      c.setLineDash([]);
      c.strokeStyle = ACCENT;
      c.lineWidth = 1.5;
      c.beginPath();
      for (let i = 0; i < k; i++) {
        const y = Math.max(lo, Math.min(hi, t[3 * i + 1]));
        c[i ? "lineTo" : "moveTo"](f.X(lx(t[3 * i])), f.Y(y));
      }
      c.stroke();
      axes(f, "running estimate, \u00b12 standard errors, exact (dashed)", "log10 N", "");

      // Log-log: the standard error, the actual error and sigma / sqrt(N).
      const sigma = t[3 * (k - 1) + 2] * Math.sqrt(n1);
      let ylo = Infinity, yhi = -Infinity;
      const pts = [];
      for (let i = 0; i < k; i++) {
        const n = t[3 * i], se = t[3 * i + 2], err = Math.abs(t[3 * i + 1] - exact);
        pts.push([lx(n), se > 0 ? Math.log10(se) : NaN, err > 0 ? Math.log10(err) : NaN]);
      }
      for (const p of pts) {
        for (const y of [p[1], p[2], Math.log10(sigma / Math.sqrt(Math.pow(10, p[0])))]) {
          if (Number.isFinite(y)) { ylo = Math.min(ylo, y); yhi = Math.max(yhi, y); }
        }
      }
      const g = frame($("est-error"), lx(n0), lx(n1), ylo - 0.1, yhi + 0.1);
      g.ctx.strokeStyle = MUTED;
      g.ctx.setLineDash([5, 4]);
      g.ctx.beginPath();
      g.ctx.moveTo(g.X(lx(n0)), g.Y(Math.log10(sigma / Math.sqrt(n0))));
      g.ctx.lineTo(g.X(lx(n1)), g.Y(Math.log10(sigma / Math.sqrt(n1))));
      g.ctx.stroke();
      g.ctx.setLineDash([]);
      g.ctx.strokeStyle = ACCENT;
      g.ctx.beginPath();
      let started = false;
      for (const p of pts) {
        if (!Number.isFinite(p[1])) continue;
        g.ctx[started ? "lineTo" : "moveTo"](g.X(p[0]), g.Y(p[1]));
        started = true;
      }
      g.ctx.stroke();
      g.ctx.fillStyle = RED;
      for (const p of pts) if (Number.isFinite(p[2])) g.ctx.fillRect(g.X(p[0]) - 1.5, g.Y(p[2]) - 1.5, 3, 3);
      axes(g, "standard error (line), |error| (dots), \u03c3/\u221aN (dashed)", "log10 N", "log10");
    }

    const go = () => new Promise((resolve) => {
      root.dataset.state = "running";
      status.textContent = "running\u2026";
      setTimeout(() => { try { run(); } finally { resolve(); } }, 20);
    });
    $("est-form").addEventListener("submit", (ev) => { ev.preventDefault(); go(); });
    return go;
  }

  /* --- start ------------------------------------------------------------ */

  /* What the widgets of other files draw with (lab/own.js). */
  const DRAW = { el, seedHalves, scatter, boxOf, tables };

  /* Starts every widget on the page, then runs each one's default case,
   * one after the other, so that the page opens with results. */
  async function start() {
    const widgets = [{ id: "lab-chi2", init: chi2Lab }, { id: "lab-estimator", init: estimatorLab }]
      .concat(window.MCBOX_LAB_WIDGETS || []).filter((w) => $(w.id));
    if (!widgets.length) return;
    const lab = await loadModule(window.MCBOX_LAB_WASM);
    const catalog = JSON.parse(lab.str(lab.e.lab_catalog()));
    for (const w of document.querySelectorAll(".lab-live")) w.hidden = false;
    document.body.classList.add("lab-js");
    const runs = [];
    for (const w of widgets) {
      runs.push(w.init(lab, $(w.id), catalog, DRAW));
      $(w.id).dataset.state = "ready";
    }
    for (const go of runs) await go();
    document.body.dataset.lab = "ready";
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
