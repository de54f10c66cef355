// The page's own script: draws the three diagrams, the values and the sweep plots of the
// frame chosen by the slider, from the frame arrays in <script id="frames">. No library.
"use strict";
const D = JSON.parse(document.getElementById("frames").textContent);
const N = D.theta.length;
const SVGNS = "http://www.w3.org/2000/svg";
const PHASES = ["configuration", "velocity", "acceleration"];
const UNIT = {velocity: "m/s", acceleration: "m/s²"};
let frame = D.start;

// numbers as the tool writes them: four significant figures, no exponent for usual sizes
function fmt(x, digits = 4) {
  if (x === 0 || !isFinite(x)) return x === 0 ? "0" : String(x);
  let s = x.toPrecision(digits);
  if (s.includes("e")) s = Math.abs(x) >= 1 ? x.toFixed(0) : x.toFixed(digits - 1 - Math.floor(Math.log10(Math.abs(x))));
  if (s.includes(".")) s = s.replace(/0+$/, "").replace(/\.$/, "");
  return s === "-0" ? "0" : s;
}
function angular(x, unit) {
  const s = x > 0 ? " ccw" : (x < 0 ? " cw" : "");
  return fmt(Math.abs(x)) + " " + unit + s;
}
const deg = (t) => (((t % 360) + 360) % 360).toFixed(1);
// what the frames step through: the crank angle, or a driving block's place (D.param)
const PARAM = D.param || ["crank angle", "θ", "°"];
const at = (t) => D.param ? t.toFixed(1) + PARAM[2] : deg(t) + "°";
const dir = (x, y) => deg(Math.atan2(y, x) * 180 / Math.PI);

// a point's vector (position, velocity or acceleration) at frame k, SI
function vec(phase, p, k) {
  if (phase === "configuration") {
    if (p in D.ground) return D.ground[p];
    return [D.P[p][2 * k], D.P[p][2 * k + 1]];
  }
  if (!(p in D.P)) return [0, 0];   // a fixed point's image is the pole
  const t = phase === "velocity" ? D.V : D.A;
  return [t[p][2 * k], t[p][2 * k + 1]];
}
const scaleOf = (phase) => D.scales[PHASES.indexOf(phase)];
function cm(phase, p, k) {  // on the paper (cm), y down for SVG
  const v = vec(phase, p, k), s = scaleOf(phase).perCm;
  return [v[0] / s, -v[1] / s];
}
const r3 = (x) => Math.round(x * 1000) / 1000;
const label = (p, phase) => D.images[p] + (phase === "acceleration" ? "'" : "");

function el(parent, tag, attrs, tip) {
  const e = document.createElementNS(SVGNS, tag);
  for (const k in attrs) e.setAttribute(k, attrs[k]);
  if (tip) e.dataset.tip = tip;
  parent.appendChild(e);
  return e;
}
function line(e, a, b) {
  e.setAttribute("x1", r3(a[0])); e.setAttribute("y1", r3(a[1]));
  e.setAttribute("x2", r3(b[0])); e.setAttribute("y2", r3(b[1]));
}
function place(e, a) { e.setAttribute("x", r3(a[0])); e.setAttribute("y", r3(a[1])); }
function poly(e, pts) { e.setAttribute("points", pts.map((a) => r3(a[0]) + "," + r3(a[1])).join(" ")); }

// ---------------------------------------------------------------- the three diagrams
const drawn = {};
function setup(phase) {
  const svg = document.getElementById(phase);
  const s = scaleOf(phase), b = s.box, w = b[2] - b[0], h = b[3] - b[1];
  const pad = 0.08 * Math.max(w, h, 4), fs = 0.035 * Math.max(w + 2 * pad, h + 2 * pad, 8);
  svg.setAttribute("viewBox", [b[0] - pad, -b[3] - pad, w + 2 * pad, h + 2 * pad].map(r3).join(" "));
  svg.style.setProperty("--fs", fs);
  const g = {fs: fs, items: []};
  const defs = el(svg, "defs", {});
  const m = el(defs, "marker", {id: phase + "-head", viewBox: "0 0 10 10", refX: 10, refY: 5,
    markerWidth: 5, markerHeight: 5, orient: "auto-start-reverse"});
  el(m, "path", {d: "M0,1 L10,5 L0,9 z", class: "head"});
  if (phase === "configuration") {
    for (const [p, q, c] of D.plates) g.items.push([el(svg, "polygon", {class: "plate"}, "plate:" + c), "plate", [p, q, c]]);
    for (const s of D.sliders) {
      if (s.u) g.items.push([el(svg, "line", {class: "guide"}, "guide:" + s.key), "guide", s]);
    }
    for (const w of D.wheels) g.items.push([el(svg, "circle", {class: "pitch"}, "pitch circle about " + w[0]), "pitch", w]);
    for (const l of D.rollLines) g.items.push([el(svg, "line", {class: "guide"}, "the line a wheel rolls on"), "rollline", l]);
    for (const [p, q, key] of D.links) g.items.push([el(svg, "line", {class: "link", id: "c-link-" + key}, "link:" + key), "link", [p, q, key]]);
    for (const s of D.sliders) g.items.push([el(svg, "polygon", {class: "block"}, "slider:" + s.key), "block", s]);
    for (const p in D.ground) g.items.push([el(svg, "polygon", {class: "ground"}, "ground:" + p), "ground", p]);
    for (const p of Object.keys(D.ground).concat(D.points)) {
      g.items.push([el(svg, "circle", {class: "joint", r: r3(fs * 0.18)}, "point:" + p), "joint", p]);
      const t = el(svg, "text", {class: "label", id: "c-lab-" + p}, "point:" + p);
      t.textContent = p;
      g.items.push([t, "label", p]);
    }
  } else {
    const v = phase === "velocity" ? "v" : "a";
    for (const [p, q, c] of D.plates) g.items.push([el(svg, "polygon", {class: "image"}, "image:" + c), "plate", [p, q, c]]);
    if (v === "a") {
      for (const [p, q, key] of D.links) {
        g.items.push([el(svg, "line", {class: "centripetal", "marker-end": "url(#acceleration-head)"}, "cen:" + key), "cen", [p, q, key]]);
        g.items.push([el(svg, "line", {class: "tangential", "marker-end": "url(#acceleration-head)"}, "tan:" + key), "tan", [p, q, key]]);
      }
    }
    for (const [p, q, key] of D.links) g.items.push([el(svg, "line", {class: "relative", id: v + "-rel-" + key}, "rel:" + key), "rel", [p, q, key]]);
    for (const s of D.sliders) {  // a block on a moving link: the link's point under it
      if (!s.guide) continue;
      g.items.push([el(svg, "line", {class: "relative"}, "under:" + s.key), "under", s]);
      g.items.push([el(svg, "line", {class: "sliding", id: v + "-slide-" + s.key, "marker-end": "url(#" + phase + "-head)"}, "sliding:" + s.key), "sliding", s]);
      if (v === "a") g.items.push([el(svg, "line", {class: "coriolis", "marker-end": "url(#" + phase + "-head)"}, "coriolis:" + s.key), "coriolis", s]);
      const t = el(svg, "text", {class: "label image-label"}, "under:" + s.key);
      t.textContent = D.under[s.key] + (v === "a" ? "'" : "");
      g.items.push([t, "underlabel", s]);
    }
    for (const p of D.points) g.items.push([el(svg, "line", {class: "absolute", id: v + "-abs-" + p, "marker-end": "url(#" + phase + "-head)"}, "abs:" + p), "abs", p]);
    const o = el(svg, "text", {class: "label pole", id: v + "-lab-pole"}, "pole:" + phase);
    o.textContent = v === "a" ? "o'" : "o";
    g.items.push([o, "pole", null]);
    for (const p of D.points) {
      const t = el(svg, "text", {class: "label image-label", id: v + "-lab-" + p}, "abs:" + p);
      t.textContent = label(p, phase);
      g.items.push([t, "label", p]);
    }
  }
  drawn[phase] = g;
}

function blockCorners(c, u, size) {  // a square block at c, its sides along u
  const n = [-u[1], u[0]], h = size / 2;
  return [[1, 1], [1, -1], [-1, -1], [-1, 1]].map(([i, j]) =>
    [c[0] + h * (i * u[0] + j * n[0]), c[1] + h * (i * u[1] + j * n[1])]);
}
function unit(a, b) {
  const dx = b[0] - a[0], dy = b[1] - a[1], L = Math.hypot(dx, dy) || 1;
  return [dx / L, dy / L];
}

// the image of the guide's point under a sliding block, and (accelerations) the start of
// the Coriolis component: v_X = v_X1 + vs u; a_X = a_X1 + as u + coriolis
function under(phase, s, k) {
  const u = unit(vec("configuration", s.guide[0], k), vec("configuration", s.guide[1], k));
  const x = vec(phase, s.point, k), S = D.S[s.key];
  const cor = phase === "velocity" ? [0, 0] : [S[2][k], S[3][k]];
  const along = phase === "velocity" ? S[0][k] : S[1][k];
  const back = [x[0] - cor[0], x[1] - cor[1]];
  return [[back[0] - along * u[0], back[1] - along * u[1]], back];
}

function update(phase, k) {
  const g = drawn[phase], fs = g.fs, P = (p) => cm(phase, p, k), labels = [];
  for (const [e, kind, x] of g.items) {
    if (kind === "plate") poly(e, x.map(P));
    else if (kind === "link" || kind === "rel") line(e, P(x[0]), P(x[1]));
    else if (kind === "abs") line(e, [0, 0], P(x));
    else if (kind === "joint") { e.setAttribute("cx", r3(P(x)[0])); e.setAttribute("cy", r3(P(x)[1])); }
    else if (kind === "ground") {
      const c = P(x), h = fs * 0.45;
      poly(e, [c, [c[0] - h * 0.6, c[1] + h], [c[0] + h * 0.6, c[1] + h]]);
    } else if (kind === "guide") {
      const s = scaleOf("configuration").perCm, c = P(x.point), u = [x.u[0], -x.u[1]], L = 50;
      line(e, [c[0] - L * u[0], c[1] - L * u[1]], [c[0] + L * u[0], c[1] + L * u[1]]);
    } else if (kind === "pitch") {  // a pitch circle about a point, its radius to scale
      const c = P(x[0]);
      e.setAttribute("cx", r3(c[0])); e.setAttribute("cy", r3(c[1]));
      e.setAttribute("r", r3(x[1] / scaleOf("configuration").perCm));
    } else if (kind === "rollline") {  // a fixed line through a point of it
      const s = scaleOf("configuration").perCm, c = [x[0][0] / s, -x[0][1] / s];
      const u = [x[1][0], -x[1][1]], L = 50;
      line(e, [c[0] - L * u[0], c[1] - L * u[1]], [c[0] + L * u[0], c[1] + L * u[1]]);
    } else if (kind === "block") {
      const u = x.u ? [x.u[0], -x.u[1]] : unit(P(x.guide[0]), P(x.guide[1]));
      poly(e, blockCorners(P(x.point), u, fs * 0.9));
    } else if (kind === "cen" || kind === "tan") {
      // the relative acceleration of q to p: centripetal (towards p) then tangential
      const [p, q, key] = x, w = D.W[key][k], s = scaleOf("acceleration").perCm;
      const Pp = vec("configuration", p, k), Pq = vec("configuration", q, k);
      const ap = vec("acceleration", p, k);
      const knee = [(ap[0] - w * w * (Pq[0] - Pp[0])) / s, -(ap[1] - w * w * (Pq[1] - Pp[1])) / s];
      if (kind === "cen") line(e, P(p), knee); else line(e, knee, P(q));
    } else if (kind === "under" || kind === "sliding" || kind === "coriolis" || kind === "underlabel") {
      const sc = scaleOf(phase).perCm, [u1, back] = under(phase, x, k);
      const C = (a) => [a[0] / sc, -a[1] / sc];
      if (kind === "under") line(e, P(x.guide[0]), C(u1));
      else if (kind === "sliding") line(e, C(u1), C(back));
      else if (kind === "coriolis") line(e, C(back), P(x.point));
      else { const c = C(u1); place(e, [c[0] - 0.6 * fs, c[1] + 0.35 * fs]); }
    } else if (kind === "pole") {  // the pole's label, on the side away from the images
      let sx = 0, sy = 0;
      for (const p of D.points) { const c = P(p); const L = Math.hypot(c[0], c[1]) || 1; sx += c[0] / L; sy += c[1] / L; }
      const L = Math.hypot(sx, sy);
      const u = L > 1e-9 ? [-sx / L, -sy / L] : [-0.7, 0.7];
      place(e, [0.8 * fs * u[0], 0.8 * fs * u[1] + 0.35 * fs]);
    } else if (kind === "label") labels.push([e, x]);
  }
  placeLabels(labels, phase, k, fs);
}

// labels beside their points, each where it is clear of the labels already placed and of
// the other points (tried around the point, the preferred side first)
function placeLabels(labels, phase, k, fs) {
  const P = (p) => cm(phase, p, k);
  const pts = labels.map(([, p]) => P(p));
  if (phase !== "configuration") pts.push([0, 0]);
  const placed = [];
  const clear = (q, own) => placed.every((c) => Math.hypot(q[0] - c[0], q[1] - c[1]) > 1.1 * fs) &&
    pts.every((c, i) => i === own || Math.hypot(q[0] - c[0], q[1] - c[1]) > 0.6 * fs);
  labels.forEach(([e, p], i) => {
    const c = pts[i], L = Math.hypot(c[0], c[1]);
    const a0 = phase === "configuration" || L < 1e-9 ? -Math.PI / 4 : Math.atan2(c[1], c[0]);
    let best = null;
    for (const turn of [0, 1, -1, 2, -2, 3, -3, 4]) {
      const a = a0 + turn * Math.PI / 4, q = [c[0] + 0.75 * fs * Math.cos(a), c[1] + 0.75 * fs * Math.sin(a)];
      if (best === null) best = q;
      if (clear(q, i)) { best = q; break; }
    }
    placed.push(best);
    place(e, [best[0], best[1] + 0.35 * fs]);
  });
}

// ---------------------------------------------------------------- values and tooltips
function pointValues(p, k) {
  const v = vec("velocity", p, k), a = vec("acceleration", p, k);
  return {v: Math.hypot(v[0], v[1]), vdir: dir(v[0], v[1]), a: Math.hypot(a[0], a[1]), adir: dir(a[0], a[1])};
}
function valuesRows(k) {
  const rows = [["theta", PARAM[0] + " " + PARAM[1], at(D.theta[k])]];
  for (const p of D.points) {
    const pv = pointValues(p, k);
    rows.push(["v-" + p, "v_" + p + " (o" + label(p, "velocity") + ")", fmt(pv.v) + " m/s at " + pv.vdir + "°"]);
    rows.push(["a-" + p, "a_" + p + " (o'" + label(p, "acceleration") + ")", fmt(pv.a) + " m/s² at " + pv.adir + "°"]);
  }
  for (const [, , key] of D.links) {
    rows.push(["w-" + key, "ω_" + key, angular(D.W[key][k], "rad/s")]);
    rows.push(["al-" + key, "α_" + key, angular(D.Al[key][k], "rad/s²")]);
  }
  for (const s in D.S) {
    rows.push(["vs-" + s, "sliding velocity of " + s, fmt(D.S[s][0][k]) + " m/s"]);
    rows.push(["as-" + s, "sliding acceleration of " + s, fmt(D.S[s][1][k]) + " m/s²"]);
    const c = Math.hypot(D.S[s][2][k], D.S[s][3][k]);
    if (c > 0) rows.push(["ac-" + s, "Coriolis component at " + s, fmt(c) + " m/s²"]);
  }
  if (D.torque) rows.push(["torque", "input torque", angular(D.torque[k], "N m")]);
  if (D.condition) {
    const c = D.condition[k], why = D.stepLabels[D.conditionStep[k]];
    rows.push(["condition", "condition (sine of the angle between two direction lines)",
      fmt(c, 3) + " at " + why + (c < D.warnBelow ? ": below sin 5°, near a singular position, values sensitive" : "")]);
  }
  return rows;
}
function buildValues() {
  const body = document.querySelector("#values tbody");
  for (const [id, name] of valuesRows(frame)) {
    const tr = document.createElement("tr");
    tr.innerHTML = "<th></th><td></td>";
    tr.firstChild.textContent = name;
    tr.lastChild.id = "val-" + id;
    body.appendChild(tr);
  }
}
function tipText(tip, k) {
  const [kind, name] = tip.split(":");
  const u = D.units, f = D.unit;
  if (kind === "point" || kind === "ground") {
    const c = vec("configuration", name, k);
    return name + " at (" + fmt(c[0] / f) + ", " + fmt(c[1] / f) + ") " + u;
  }
  if (kind === "link") {
    const [p, q] = D.links.find((l) => l[2] === name);
    const a = vec("configuration", p, k), b = vec("configuration", q, k);
    return "link " + name + ": " + fmt(Math.hypot(b[0] - a[0], b[1] - a[1]) / f) + " " + u +
      ", ω = " + angular(D.W[name][k], "rad/s") + ", α = " + angular(D.Al[name][k], "rad/s²");
  }
  if (kind === "abs") {
    const pv = pointValues(name, k);
    return "v_" + name + " = o" + label(name, "velocity") + " = " + fmt(pv.v) + " m/s at " + pv.vdir +
      "°; a_" + name + " = o'" + label(name, "acceleration") + " = " + fmt(pv.a) + " m/s² at " + pv.adir + "°";
  }
  if (kind === "rel" || kind === "cen" || kind === "tan") {
    const [p, q] = D.links.find((l) => l[2] === name);
    const ph = kind === "rel" ? null : "acceleration";
    const one = (phase) => {
      const a = vec(phase, p, k), b = vec(phase, q, k);
      return fmt(Math.hypot(b[0] - a[0], b[1] - a[1])) + " " + UNIT[phase];
    };
    if (kind === "rel") return "v_" + q + p + " = " + label(p, "velocity") + label(q, "velocity") + " = " + one("velocity") +
      "; a_" + q + p + " = " + one("acceleration");
    const w = D.W[name][k], al = D.Al[name][k], a = vec("configuration", p, k), b = vec("configuration", q, k);
    const L = Math.hypot(b[0] - a[0], b[1] - a[1]);
    return kind === "cen" ? "centripetal a_" + q + p + " = ω²·" + p + q + " = " + fmt(w * w * L) + " m/s²"
      : "tangential a_" + q + p + " = α·" + p + q + " = " + fmt(Math.abs(al) * L) + " m/s²";
  }
  if (kind === "plate" || kind === "image") return "point " + name + " on its link: " + tipText("abs:" + name, k);
  if (kind === "pole") return (name === "velocity" ? "o" : "o'") + ": the pole, image of every fixed point (zero " + (name === "velocity" ? "velocity)" : "acceleration)");
  if (kind === "series") {
    const link = D.links.find((l) => l[2] === name);
    return link ? "ω_" + name + " = " + angular(D.W[name][k], "rad/s") : tipText("abs:" + name, k);
  }
  if (kind === "under") return "the point of link " + D.sliders.find((s) => s.key === name).link + " under the block " + name + " (" + D.under[name] + " on the velocity polygon)";
  if (kind === "sliding") return "sliding velocity of " + name + " = " + fmt(D.S[name][0][k]) + " m/s; sliding acceleration " + fmt(D.S[name][1][k]) + " m/s²";
  if (kind === "coriolis") return "Coriolis component at " + name + " = 2ωv = " + fmt(Math.hypot(D.S[name][2][k], D.S[name][3][k])) + " m/s²";
  if (kind === "slider" || kind === "guide") return "slider " + name + ": sliding velocity " + fmt(D.S[name][0][k]) + " m/s";
  return name;
}
const tooltip = document.getElementById("tooltip");
function showTip(ev) {
  const t = ev.target.closest("[data-tip]");
  if (!t) { tooltip.hidden = true; return; }
  tooltip.textContent = tipText(t.dataset.tip, frame);
  tooltip.hidden = false;
  tooltip.style.left = (ev.pageX + 12) + "px";
  tooltip.style.top = (ev.pageY + 12) + "px";
}
for (const kind of ["mouseover", "click"]) document.addEventListener(kind, showTip);

// ---------------------------------------------------------------- sweep plots
const PLOTS = [
  ["plot-v", "speeds (m/s)", () => D.points.map((p) => [p, (k) => pointValues(p, k).v])],
  ["plot-w", "angular velocities (rad/s, ccw +)", () => D.links.map(([, , key]) => [key, (k) => D.W[key][k]])],
  ["plot-a", "accelerations (m/s²)", () => D.points.map((p) => [p, (k) => pointValues(p, k).a])],
];
const COLORS = ["#1f5fa8", "#c2410c", "#15803d", "#7e22ce", "#b91c1c", "#0e7490", "#a16207", "#4b5563"];
const markers = [];
function buildPlots() {
  const W = 320, H = 190, L = 44, R = 16, T = 22, B = 28;
  const t0 = D.theta[0], t1 = D.theta[N - 1], lo = Math.min(t0, t1), hi = Math.max(t0, t1) || 1;
  const X = (t) => L + (W - L - R) * (t - lo) / ((hi - lo) || 1);
  for (const [id, title, series] of PLOTS) {
    const svg = document.getElementById(id), ss = series();
    // the range of most values (near a limit position they grow without bound: cut off)
    const all = [];
    for (const [, f] of ss) for (let k = 0; k < N; k++) all.push(f(k));
    all.sort((a, b) => a - b);
    const q = (x) => all[Math.min(all.length - 1, Math.floor(x * all.length))];
    const lo5 = q(0.05), hi95 = q(0.95), room = 0.5 * (hi95 - lo5);
    let ymin = Math.min(0, Math.max(all[0], lo5 - room)), ymax = Math.max(0, Math.min(all[all.length - 1], hi95 + room));
    if (ymax === ymin) ymax = ymin + 1;
    const clip = el(el(svg, "defs", {}), "clipPath", {id: id + "-clip"});
    el(clip, "rect", {x: L, y: T, width: W - L - R, height: H - T - B});
    const Y = (y) => T + (H - T - B) * (ymax - y) / (ymax - ymin);
    el(svg, "text", {x: L, y: 14, class: "plot-title"}).textContent = title;
    el(svg, "line", {x1: L, y1: Y(0), x2: W - R, y2: Y(0), class: "axis"});
    el(svg, "line", {x1: L, y1: T, x2: L, y2: H - B, class: "axis"});
    for (const y of [ymin, ymax]) el(svg, "text", {x: L - 3, y: Y(y) + 4, class: "tick", "text-anchor": "end"}).textContent = fmt(y, 3);
    for (const t of [lo, (lo + hi) / 2, hi]) el(svg, "text", {x: X(t), y: H - 10, class: "tick", "text-anchor": "middle"}).textContent = at(t);
    ss.forEach(([name, f], i) => {
      const pts = [];
      for (let k = 0; k < N; k++) pts.push(r3(X(D.theta[k])) + "," + r3(Y(f(k))));
      el(svg, "polyline", {points: pts.join(" "), class: "series", stroke: COLORS[i % COLORS.length], "clip-path": "url(#" + id + "-clip)"}, "series:" + name);
      el(svg, "text", {x: W - R - 4, y: T + 12 * (i + 1), class: "legend", fill: COLORS[i % COLORS.length], "text-anchor": "end"}).textContent = name;
    });
    markers.push([el(svg, "line", {class: "marker", y1: T, y2: H - B, id: id + "-marker"}), X]);
  }
}

// ---------------------------------------------------------------- the slider and play
const slider = document.getElementById("angle");
const play = document.getElementById("play");
function show(k) {
  frame = k;
  slider.value = k;
  for (const phase of PHASES) update(phase, k);
  for (const [id, , text] of valuesRows(k)) document.getElementById("val-" + id).textContent = text;
  document.getElementById("angle-now").textContent = PARAM[1] + " = " + at(D.theta[k]);
  for (const [m, X] of markers) { m.setAttribute("x1", r3(X(D.theta[k]))); m.setAttribute("x2", r3(X(D.theta[k]))); }
}
let timer = null, step = 1;
function tick() {
  let k = frame + step;
  if (D.fullTurn) k = (k + N) % N;
  else if (k < 0 || k >= N) { step = -step; k = frame + step; }  // back between the limits
  show(Math.max(0, Math.min(N - 1, k)));
}
play.addEventListener("click", () => {
  if (timer === null) { timer = setInterval(tick, 60); play.textContent = "❚❚ pause"; }
  else { clearInterval(timer); timer = null; play.textContent = "▶ play"; }
});
slider.max = N - 1;
slider.addEventListener("input", () => show(Number(slider.value)));
for (const phase of PHASES) setup(phase);
buildValues();
buildPlots();
show(D.start);
