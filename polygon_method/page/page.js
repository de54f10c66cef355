// The page's own script: draws the three diagrams, the values and the sweep plots of the
// frame chosen by the slider, from the frame arrays in <script id="frames">. No library.
//
// Each diagram is drawn in millimetres of the screen (one SVG unit is a CSS millimetre,
// 96 px = 25.4 mm; tiny font sizes would render badly in centimetres). The configuration diagram keeps one scale over the cycle; each
// polygon gets, at each frame, the smallest round scale (1, 2 or 5 x 10^k per cm) at which
// it fits its panel, stated beside the panel. Colours and dashes are the drawings' own
// (D.style, from polygon_method/draw/style.py).
"use strict";
const D = JSON.parse(document.getElementById("frames").textContent);
const N = D.theta.length;
const SVGNS = "http://www.w3.org/2000/svg";
const PHASES = ["configuration", "velocity", "acceleration"];
const UNIT = {velocity: "m/s", acceleration: "m/s²"};
const MM = 96 / 25.4;         // px in a CSS millimetre: the diagrams' unit
const PT = 25.4 / 72;         // a point (line widths, dashes) in mm
const FS = 3.6;               // the labels' size (mm)
const FILL = {configuration: 0.86, velocity: 0.8, acceleration: 0.8};  // most of a panel a diagram takes
const REST = 0.01;            // a polygon under this share of its median size is at rest
const TOL = D.tol;            // the tolerances, by name: same, rounding, floor
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
// a crank angle as shown: modulo the cycle (720 for a four-stroke engine: 390 is not 30)
const CYCLE = D.cycle || 360, inCycle = (t) => ((t % CYCLE) + CYCLE) % CYCLE;
const MANY_TURNS = !D.param && CYCLE > 360;  // a four-stroke's 720°, a train's period of turns
// what the frames step through: the crank angle, or a driving block's place (D.param)
const PARAM = D.param || ["crank angle", "θ", "°"];
const at = (t) => D.param ? t.toFixed(1) + PARAM[2] : inCycle(t).toFixed(1) + "°";
const dir = (x, y) => deg(Math.atan2(y, x) * 180 / Math.PI);
const esc = (s) => String(s).replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;");
const sub = (base, s) => base + "<sub>" + esc(s) + "</sub>";  // v_B typeset: v with B below
const r3 = (x) => Math.round(x * 1000) / 1000;
const label = (p, phase) => D.images[p] + (phase === "acceleration" ? "'" : "");

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
function unit(a, b) {
  const dx = b[0] - a[0], dy = b[1] - a[1], L = Math.hypot(dx, dy) || 1;
  return [dx / L, dy / L];
}
const pair = (flat, k) => [flat[2 * k], flat[2 * k + 1]];
// the image of the guide's point under a sliding block, and where the next component starts
// (velocities: x itself; accelerations: the Coriolis component's start), as the data gives
// them: v_X = v_X1 + vs u; a_X = a_X1 + as u + coriolis (SI)
function under(phase, s, k) {
  const g = D.guidePoints[s.key];
  return phase === "velocity" ? [pair(g[0], k), vec(phase, s.point, k)] : [pair(g[1], k), pair(g[2], k)];
}
// where a link's centripetal component (of q about p) ends and its tangential one starts (SI)
const knee = ([, , key], k) => pair(D.knees[key], k);

// ---------------------------------------------------------------- scales and panels
// every point a diagram draws at frame k (SI): what its panel must hold
function vertices(phase, k) {
  if (phase === "configuration") {
    const out = Object.values(D.ground).concat(D.points.map((p) => vec(phase, p, k)));
    for (const [c, r] of D.wheels) { const x = vec(phase, c, k); out.push([x[0] - r, x[1] - r], [x[0] + r, x[1] + r]); }
    return out;
  }
  const out = [[0, 0]].concat(D.points.map((p) => vec(phase, p, k)));
  if (phase === "acceleration") for (const l of D.links) out.push(knee(l, k));
  for (const s of D.sliders) if (s.guide) out.push(...under(phase, s, k));
  return out;
}
function bbox(pts) {
  const b = [Infinity, Infinity, -Infinity, -Infinity];
  for (const [x, y] of pts) { b[0] = Math.min(b[0], x); b[1] = Math.min(b[1], y); b[2] = Math.max(b[2], x); b[3] = Math.max(b[3], y); }
  return b;
}
const span = (b) => Math.max(b[2] - b[0], b[3] - b[1]);
function roundUp(x) {  // the smallest 1, 2 or 5 x 10^k that is at least x
  const e = Math.floor(Math.log10(x)), m = x / 10 ** e;
  return [1, 2, 5, 10].find((s) => s >= m * (1 - TOL.same)) * 10 ** e;
}
const factor = (phase) => phase === "configuration" ? D.unit : 1;  // SI per unit of the scale's text
const unitText = (phase) => phase === "configuration" ? D.units : UNIT[phase];

const view = {};  // per diagram: the panel (mm), the size below which it is at rest, the scale now
function layout() {
  for (const phase of PHASES) {
    const svg = document.getElementById(phase);
    const W = (svg.clientWidth || 320) / MM, H = (svg.clientHeight || 320) / MM;
    const v = view[phase] || (view[phase] = {});
    v.W = W; v.H = H;
    if (v.rest === undefined) {
      const sizes = [];
      let all = [Infinity, Infinity, -Infinity, -Infinity];
      for (let k = 0; k < N; k++) {
        const b = bbox(vertices(phase, k));
        sizes.push(span(b));
        all = [Math.min(all[0], b[0]), Math.min(all[1], b[1]), Math.max(all[2], b[2]), Math.max(all[3], b[3])];
      }
      sizes.sort((a, b) => a - b);
      v.rest = Math.max(REST * sizes[Math.floor(N / 2)], TOL.rounding);
      v.all = all;  // the configuration's box over the cycle
    }
  }
}
// the scale (SI per cm) and the panel's box (mm, y down) of a diagram at frame k
function frameView(phase, k) {
  const v = view[phase], b = phase === "configuration" ? v.all : bbox(vertices(phase, k));
  const w = Math.max(b[2] - b[0], v.rest), h = Math.max(b[3] - b[1], v.rest);
  const need = 10 * Math.max(w / (FILL[phase] * v.W), h / (FILL[phase] * v.H)) / factor(phase);
  v.per = roundUp(need) * factor(phase);
  if (phase === "configuration" && (D.inertia || D.forces)) return withArrows(v, need);
  v.text = "1 cm = " + fmt(v.per / factor(phase)) + " " + unitText(phase);
  v.box = [5 * (b[0] + b[2]) / v.per - v.W / 2, -5 * (b[1] + b[3]) / v.per - v.H / 2];
  v.box.push(v.box[0] + v.W, v.box[1] + v.H);  // [x0, y0, x1, y1] in mm, y down
  return v;
}
// the configuration with the inertia forces' arrows (their own scale, in mm of the panel):
// the smallest round scale at which the mechanism and every arrow over the cycle fit
const FORCES = D.forces || D.inertia;  // one force scale for every arrow on the configuration
const COUPLE_MM = 1.8;                 // a couple's curved arrow: its radius (mm)
// whether the layer of the joints' forces, loads and couples is shown (its toggle)
const forcesOn = () => { const c = document.getElementById("show-forces"); return !!(c && c.checked); };
function arrowsBox(per) {  // [x0, y0, x1, y1] in mm, y down
  const b = [Infinity, Infinity, -Infinity, -Infinity], f = 10 / FORCES.perCm;
  const put = (x, y) => { b[0] = Math.min(b[0], x); b[1] = Math.min(b[1], y); b[2] = Math.max(b[2], x); b[3] = Math.max(b[3], y); };
  const from = (at, F, k) => {  // an arrow from its point of application along its force
    const x = 10 * at[2 * k] / per, y = -10 * at[2 * k + 1] / per;
    put(x, y); put(x + f * F[2 * k], y - f * F[2 * k + 1]);
  };
  for (let k = 0; k < N; k++) {
    for (const [x, y] of vertices("configuration", k)) put(10 * x / per, -10 * y / per);
    for (const a of (D.inertia ? D.inertia.bodies : [])) {
      put(10 * a.G[2 * k] / per, -10 * a.G[2 * k + 1] / per);
      from(a.H, a.F, k);
    }
    if (!forcesOn()) continue;  // the layer off: the inertia forces alone
    for (const a of (D.forces ? D.forces.arrows : [])) from(a.at, a.F, k);
    for (const c of (D.forces ? D.forces.couples : [])) {
      const x = 10 * c.at[2 * k] / per, y = -10 * c.at[2 * k + 1] / per, r = COUPLE_MM + 1;
      put(x - r, y - r); put(x + r, y + r);
    }
  }
  return b;
}
function withArrows(v, need) {
  if (v.fitted === undefined || v.fitted[0] !== v.W || v.fitted[1] !== v.H || v.fitted[4] !== forcesOn()) {
    let per = roundUp(need) * factor("configuration"), b = arrowsBox(per);
    for (let i = 0; i < 60 && (b[2] - b[0] > FILL.configuration * v.W || b[3] - b[1] > FILL.configuration * v.H); i++) {
      per = roundUp(per / factor("configuration") * 1.000001) * factor("configuration");
      b = arrowsBox(per);
    }
    v.fitted = [v.W, v.H, per, b, forcesOn()];
  }
  const [, , per, b] = v.fitted;
  v.per = per;
  v.text = "1 cm = " + fmt(per / factor("configuration")) + " " + unitText("configuration");
  v.box = [(b[0] + b[2]) / 2 - v.W / 2, (b[1] + b[3]) / 2 - v.H / 2];
  v.box.push(v.box[0] + v.W, v.box[1] + v.H);
  return v;
}
// a point (SI) in mm of the panel, y down
const toMm = (phase, a) => [10 * a[0] / view[phase].per, -10 * a[1] / view[phase].per];
const mm = (phase, p, k) => toMm(phase, vec(phase, p, k));

// ---------------------------------------------------------------- the three diagrams
function el(parent, tag, attrs, tip) {
  const e = document.createElementNS(SVGNS, tag);
  for (const k in attrs) e.setAttribute(k, attrs[k]);
  parent.appendChild(e);
  if (tip) titled(e, tip);
  return e;
}
// a tooltip that needs no script to show: an SVG <title>, rewritten at each frame
const titles = [];
function titled(e, tip) {
  e.dataset.tip = tip;
  const t = document.createElementNS(SVGNS, "title");
  e.insertBefore(t, e.firstChild);
  titles.push([t, tip]);
}
function text(parent, attrs, words, tip) {
  const t = el(parent, "text", attrs);
  t.textContent = words;
  if (tip) titled(t, tip);
  return t;
}
function styled(kind, extra) {  // a kind's colour, width and dashes as the drawings have them
  const [c, w, dash] = D.style.lines[kind], a = {stroke: c, "stroke-width": r3(w * PT), fill: "none"};
  if (dash) a["stroke-dasharray"] = dash.map((d) => r3(d * w * PT)).join(" ");
  return Object.assign(a, extra || {});
}
function line(e, a, b) {
  e.setAttribute("x1", r3(a[0])); e.setAttribute("y1", r3(a[1]));
  e.setAttribute("x2", r3(b[0])); e.setAttribute("y2", r3(b[1]));
}
function place(e, a) { e.setAttribute("x", r3(a[0])); e.setAttribute("y", r3(a[1])); }
function dot(e, a) { e.setAttribute("cx", r3(a[0])); e.setAttribute("cy", r3(a[1])); }
function poly(e, pts) { e.setAttribute("points", pts.map((a) => r3(a[0]) + "," + r3(a[1])).join(" ")); }
// the part of the line through c along u inside the rectangle r (null where none is)
function clipLine(c, u, r) {
  let t0 = -Infinity, t1 = Infinity;
  for (const [p, q, lo, hi] of [[c[0], u[0], r[0], r[2]], [c[1], u[1], r[1], r[3]]]) {
    if (Math.abs(q) < TOL.rounding) { if (p < lo || p > hi) return null; continue; }
    const a = (lo - p) / q, b = (hi - p) / q;
    t0 = Math.max(t0, Math.min(a, b)); t1 = Math.min(t1, Math.max(a, b));
  }
  return t0 < t1 ? [[c[0] + t0 * u[0], c[1] + t0 * u[1]], [c[0] + t1 * u[0], c[1] + t1 * u[1]]] : null;
}

const drawn = {};
function setup(phase) {
  const svg = document.getElementById(phase);
  const items = [], add = (e, kind, x) => { items.push([e, kind, x]); return e; };
  const defs = el(svg, "defs", {});
  const head = (kind) => {  // an arrowhead of the kind's colour, as long as the drawings'
    const id = phase + "-head-" + kind, [L, half] = D.style.head.map((x) => 10 * x);  // cm -> mm
    const m = el(defs, "marker", {id: id, viewBox: [0, 0, L, 2 * half].map(r3).join(" "), refX: r3(L), refY: r3(half),
      markerWidth: r3(L), markerHeight: r3(2 * half), markerUnits: "userSpaceOnUse", orient: "auto"});
    el(m, "path", {d: "M0,0 L" + r3(L) + "," + r3(half) + " L0," + r3(2 * half) + " z", fill: D.style.lines[kind][0]});
    return "url(#" + id + ")";
  };
  if (phase === "configuration") {
    for (const [p, q, c] of D.plates) add(el(svg, "polygon", {class: "plate", fill: D.style.body[0], stroke: D.style.body[1]}, "plate:" + c), "plate", [p, q, c]);
    for (const s of D.sliders) if (s.u) add(el(svg, "line", styled("line"), "guide:" + s.key), "guide", s);
    for (const s of D.sliders) if (s.offset) {  // an offset slot: the link a plate carrying it
      add(el(svg, "polygon", {class: "plate bracket", fill: D.style.body[0], stroke: D.style.body[1], id: "c-bracket-" + s.key}, "link:" + s.link), "bracket", s);
    }
    for (const w of D.wheels) add(el(svg, "circle", styled("pitch"), w[2] || "pitch circle about " + w[0]), "pitch", w);
    for (const l of D.rollLines) add(el(svg, "line", styled("line"), "the line a wheel rolls on"), "rollline", l);
    for (const [p, q, key] of D.links) add(el(svg, "line", {class: "link", stroke: D.style.body[1], id: "c-link-" + key}, "link:" + key), "link", [p, q, key]);
    for (const s of D.sliders) add(el(svg, "polygon", {class: "block", fill: D.style.body[0], stroke: D.style.body[1], id: "c-block-" + s.key}, "slider:" + s.key), "block", s);
    for (const p in D.ground) add(el(svg, "polygon", {class: "ground"}, "ground:" + p), "ground", p);
    const heads = {}, headOf = (kind) => heads[kind] || (heads[kind] = head(kind));
    if (D.inertia) for (const b of D.inertia.bodies) {  // each inertia force -m a_G, along
      // its line offset from G by h = I alpha / (m a_G) (the couple taken into the force)
      add(el(svg, "line", styled("inertia", {"stroke-width": r3(0.6 * PT), "stroke-dasharray": r3(2 * PT) + " " + r3(1.5 * PT)}), "offset:" + b.body), "offset", b);
      add(el(svg, "line", styled("inertia", {"marker-end": headOf("inertia"), class: "inertia-force", "data-on": b.body}), "inertia:" + b.body), "inertia", b);
      // where no line carries the couple (the force nearly nil): the couple alone, at G
      add(el(svg, "path", styled("inertia", {"marker-end": headOf("inertia"), class: "inertia-couple", "data-on": b.body}), "icouple:" + b.body), "icouple", b);
    }
    if (D.forces) {  // the layer of the joints' forces, loads, weights and couples
      const g = el(svg, "g", {id: "force-layer"});  // (each element hidden while the layer is off)
      D.forces.arrows.forEach((a, i) => add(el(g, "line", styled(a.what, {"marker-end": headOf(a.what), class: "force",
        "data-what": a.what, "data-on": a.on, "data-by": a.by || ""}), "force:" + i), "force", a));
      D.forces.couples.forEach((c, i) => add(el(g, "path", styled("pin", {"marker-end": headOf("pin"), class: "couple",
        "data-what": c.what, "data-on": c.on}), "couple:" + i), "couple", c));
    }
    for (const p of Object.keys(D.ground).concat(D.points)) {
      add(el(svg, "circle", {class: "joint point", r: r3(FS * 0.18), stroke: D.style.body[1]}, "point:" + p), "joint", p);
      add(text(svg, {class: "label", id: "c-lab-" + p}, p, "point:" + p), "label", p);
    }
  } else {
    const v = phase === "velocity" ? "v" : "a";
    for (const [p, q, c] of D.plates) add(el(svg, "polygon", {class: "image", fill: D.style.image}, "image:" + c), "plate", [p, q, c]);
    if (v === "a") {
      for (const l of D.links) {
        add(el(svg, "line", styled("centripetal", {"marker-end": head("centripetal")}), "cen:" + l[2]), "cen", l);
        add(el(svg, "line", styled("tangential", {"marker-end": head("tangential")}), "tan:" + l[2]), "tan", l);
      }
    }
    for (const [p, q, key] of D.links) add(el(svg, "line", styled("relative", {id: v + "-rel-" + key}), "rel:" + key), "rel", [p, q, key]);
    for (const s of D.sliders) {  // a block on a moving link: the link's point under it
      if (!s.guide) continue;
      add(el(svg, "line", styled("relative"), "under:" + s.key), "under", s);
      add(el(svg, "line", styled("sliding", {id: v + "-slide-" + s.key, "marker-end": head("sliding")}), "sliding:" + s.key), "sliding", s);
      if (v === "a") add(el(svg, "line", styled("coriolis", {"marker-end": head("coriolis")}), "coriolis:" + s.key), "coriolis", s);
      add(el(svg, "circle", {class: "point", r: r3(FS * 0.12)}, "under:" + s.key), "underdot", s);
      add(text(svg, {class: "label image-label"}, D.under[s.key] + (v === "a" ? "'" : ""), "under:" + s.key), "underlabel", s);
    }
    if (v === "v") for (const l of D.least) {  // vmin_XY asked: op square to xy, its foot p
      add(el(svg, "line", styled("least", {id: "v-least-op-" + l.key}), "least:" + l.key), "leastop", l);
      add(el(svg, "line", styled("least", {id: "v-least-ext-" + l.key}), "least:" + l.key), "leastext", l);
      add(el(svg, "circle", {class: "point", r: r3(FS * 0.1), id: "v-least-dot-" + l.key}, "least:" + l.key), "leastdot", l);
      add(text(svg, {class: "label image-label", id: "v-least-lab-" + l.key}, l.p, "least:" + l.key), "leastlabel", l);
    }
    for (const p of D.points) add(el(svg, "line", styled("absolute", {id: v + "-abs-" + p, "marker-end": head("absolute")}), "abs:" + p), "abs", p);
    add(el(svg, "circle", {class: "point pole", r: r3(FS * 0.14), cx: 0, cy: 0}, "pole:" + phase), "poledot", null);
    add(text(svg, {class: "label pole", id: v + "-lab-pole"}, v === "a" ? "o'" : "o", "pole:" + phase), "pole", null);
    for (const p of D.points) {
      add(el(svg, "circle", {class: "point", r: r3(FS * 0.1), id: v + "-dot-" + p}, "abs:" + p), "dot", p);
      add(text(svg, {class: "label image-label", id: v + "-lab-" + p}, label(p, phase), "abs:" + p), "label", p);
    }
  }
  drawn[phase] = items;
}

function blockCorners(c, u, size) {  // a square block at c, its sides along u
  const n = [-u[1], u[0]], h = size / 2;
  return [[1, 1], [1, -1], [-1, -1], [-1, 1]].map(([i, j]) =>
    [c[0] + h * (i * u[0] + j * n[0]), c[1] + h * (i * u[1] + j * n[1])]);
}

// an offset slot's bracket: the link's two ends and the slot along the link through the
// block at c, a little past the block (of side size) each way; their convex hull
function bracket(a, b, c, size) {
  const u = unit(a, b), h = 0.5 * size + 0.15 * FS;
  const pts = [a, b, [c[0] - h * u[0], c[1] - h * u[1]], [c[0] + h * u[0], c[1] + h * u[1]]];
  return hull(pts);
}
function hull(pts) {  // the convex hull (monotone chain), its corners in turn
  const s = pts.slice().sort((p, q) => p[0] - q[0] || p[1] - q[1]);
  const cross = (o, a, b) => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  const half = (list) => {
    const h = [];
    for (const p of list) {
      while (h.length >= 2 && cross(h[h.length - 2], h[h.length - 1], p) <= 0) h.pop();
      h.push(p);
    }
    h.pop();
    return h;
  };
  return half(s).concat(half(s.slice().reverse()));
}

function update(phase, k) {
  const v = frameView(phase, k), fs = FS, P = (p) => mm(phase, p, k), C = (a) => toMm(phase, a), labels = [];
  let pole = null;
  const svg = document.getElementById(phase);
  svg.setAttribute("viewBox", [v.box[0], v.box[1], v.W, v.H].map(r3).join(" "));
  svg.dataset.perCm = v.per;
  document.getElementById("scale-" + phase).textContent = v.text;
  const inside = [v.box[0] + 0.2, v.box[1] + 0.2, v.box[2] - 0.2, v.box[3] - 0.2];
  const along = (e, c, u) => {  // a line through c along u, as far as the panel goes
    const seg = clipLine(c, u, inside);
    e.style.display = seg ? "" : "none";
    if (seg) line(e, seg[0], seg[1]);
  };
  for (const [e, kind, x] of drawn[phase]) {
    if (kind === "plate") poly(e, x.map(P));
    else if (kind === "bracket") poly(e, bracket(P(x.guide[0]), P(x.guide[1]), P(x.point), fs * 0.9));
    else if (kind === "link" || kind === "rel") line(e, P(x[0]), P(x[1]));
    else if (kind === "abs") line(e, [0, 0], P(x));
    else if (kind === "joint" || kind === "dot") dot(e, P(x));
    else if (kind === "ground") {
      const c = P(x), h = fs * 0.45;
      poly(e, [c, [c[0] - h * 0.6, c[1] + h], [c[0] + h * 0.6, c[1] + h]]);
    } else if (kind === "guide") along(e, P(x.point), [x.u[0], -x.u[1]]);
    else if (kind === "rollline") along(e, C(x[0]), [x[1][0], -x[1][1]]);
    else if (kind === "pitch") {  // a pitch circle about a point, its radius to scale
      dot(e, P(x[0]));
      e.setAttribute("r", r3(10 * x[1] / v.per));
    } else if (kind === "block") {
      const u = x.u ? [x.u[0], -x.u[1]] : unit(P(x.guide[0]), P(x.guide[1]));
      poly(e, blockCorners(P(x.point), u, fs * 0.9));
    } else if (kind === "cen" || kind === "tan") {
      // the relative acceleration of q to p: centripetal (towards p) then tangential
      const b = C(knee(x, k));
      if (kind === "cen") line(e, P(x[0]), b); else line(e, b, P(x[1]));
    } else if (["under", "sliding", "coriolis", "underdot", "underlabel"].includes(kind)) {
      const [u1, back] = under(phase, x, k).map(C);
      if (kind === "under") line(e, P(x.guide[0]), u1);
      else if (kind === "sliding") line(e, u1, back);
      else if (kind === "coriolis") line(e, back, P(x.point));
      else if (kind === "underdot") dot(e, u1);
      else labels.push([e, u1]);
    } else if (kind === "pole") {  // the pole's label, on the side away from the images
      let sx = 0, sy = 0;
      for (const p of D.points) { const c = P(p); const L = Math.hypot(c[0], c[1]) || 1; sx += c[0] / L; sy += c[1] / L; }
      const L = Math.hypot(sx, sy);
      pole = [e, L > TOL.same ? Math.atan2(-sy, -sx) : 0.75 * Math.PI];  // (placed first)
    } else if (kind === "label") labels.push([e, P(x)]);
    else if (kind.startsWith("least")) {  // p, the foot of op square to xy, as the data gives it
      const f = footAt(x, k), t = x.t[k], show = f !== null && (kind !== "leastext" || t < 0 || t > 1);
      e.style.display = show ? "" : "none";
      if (!show) continue;
      if (kind === "leastop") line(e, [0, 0], C(f));
      else if (kind === "leastext") line(e, P(t < 0 ? x.x : x.y), C(f));
      else if (kind === "leastdot") dot(e, C(f));
      else labels.push([e, C(f)]);
    }
    else if (kind === "inertia") arrowAt(e, x.H, x.F, k, 0.5);  // on its line h from G
    else if (kind === "force") { arrowAt(e, x.at, x.F, k, 0.3); if (!forcesOn()) e.style.display = "none"; }
    else if (kind === "icouple") coupleAt(e, x.G, x.C, k);
    else if (kind === "couple") { coupleAt(e, x.at, x.C, k); if (!forcesOn()) e.style.display = "none"; } else if (kind === "offset") {  // G to the force's line, where it is off G
      const g = C([x.G[2 * k], x.G[2 * k + 1]]), h = C([x.H[2 * k], x.H[2 * k + 1]]);
      e.style.display = Math.hypot(h[0] - g[0], h[1] - g[1]) < 0.5 ? "none" : "";
      line(e, g, h);
    }
  }
  placeLabels(labels, phase, v.box, pole);
}
// the foot p of a vmin_XY asked at frame k (SI), or null: the link does not turn there (no
// foot), or p lies farther than a quarter of the polygon's size beyond it (as draw leaves it:
// the values and the steps say where)
function footAt(l, k) {
  if (l.t[k] === null) return null;
  const f = pair(l.foot, k), b = bbox(vertices("velocity", k)), room = span(b) / 4;
  return f[0] < b[0] - room || f[0] > b[2] + room || f[1] < b[1] - room || f[1] > b[3] + room ? null : f;
}
// a force's arrow from its point of application, at the forces' scale (cm of the panel);
// its numbers (SI, every bit) kept on the element, as drawn, for a reader or a test
function arrowAt(e, at, F, k, least) {
  const a = [at[2 * k], at[2 * k + 1]], f = [F[2 * k], F[2 * k + 1]], p = toMm("configuration", a);
  const d = [10 * f[0] / FORCES.perCm, -10 * f[1] / FORCES.perCm];
  e.style.display = Math.hypot(d[0], d[1]) < least ? "none" : "";
  line(e, p, [p[0] + d[0], p[1] + d[1]]);
  Object.assign(e.dataset, {x: a[0], y: a[1], fx: f[0], fy: f[1]});
}
// a couple: three quarters of a circle round its point, the head showing its sense
function coupleAt(e, at, C, k) {
  const a = [at[2 * k], at[2 * k + 1]], c = C[k], p = toMm("configuration", a), r = COUPLE_MM;
  e.dataset.x = a[0]; e.dataset.y = a[1]; e.dataset.c = c;
  e.style.display = Math.abs(c) <= TOL.same * FORCES.perCm ? "none" : "";
  const s = c > 0 ? 1 : -1, a0 = c > 0 ? -0.75 * Math.PI : -0.25 * Math.PI, a1 = a0 + s * 1.5 * Math.PI;
  const q = (t) => [p[0] + r * Math.cos(t), p[1] - r * Math.sin(t)];  // (y down on the screen)
  const [x0, y0] = q(a0), [x1, y1] = q(a1);
  e.setAttribute("d", "M" + r3(x0) + "," + r3(y0) + " A" + r3(r) + "," + r3(r) + " 0 1 " + (c > 0 ? 0 : 1) + " " + r3(x1) + "," + r3(y1));
}
// a label's place moved inside the panel (its text is about 0.6 fs wide a letter)
function keepIn(q, box, letters) {
  const hw = 0.35 * FS * letters + 0.5;
  return [Math.min(Math.max(q[0], box[0] + hw), box[2] - hw),
    Math.min(Math.max(q[1], box[1] + 0.5 * FS), box[3] - 0.6 * FS) + 0.35 * FS];
}
// labels beside their points, each where it is clear of the labels already placed, of
// the other points and of the lines drawn (links, vectors, components, guides), tried
// around the point, the preferred side first, then a little farther off; where no place
// is clear of the lines, the first clear of the labels and points
function placeLabels(labels, phase, box, pole) {
  const pts = labels.map(([, c]) => c);
  if (phase !== "configuration") pts.push([0, 0]);
  const placed = [], fs = FS, segs = segmentsOf(document.getElementById(phase));
  // the pole's first, on the side away from the images where that is clear
  const todo = (pole ? [[pole[0], pts.length - 1, pole[1]]] : []).concat(labels.map(([e], i) => [e, i, null]));
  const apart = (p, q) => p[2] + 0.5 < q[0] || q[2] + 0.5 < p[0] || p[3] + 1 < q[1] || q[3] + 1 < p[1];
  for (const [e, i, away] of todo) {
    const c = pts[i], L = Math.hypot(c[0], c[1]), letters = e.lastChild.nodeValue.length;  // (the text after its <title>)
    const a0 = away !== null ? away : phase === "configuration" || L < TOL.same ? -Math.PI / 4 : Math.atan2(c[1], c[0]);
    const hw = 0.3 * fs * letters + 0.2, hh = 0.4 * fs;  // half the text's box
    // the text's box where it is placed at q (moved inside the panel; y is its baseline)
    const boxAt = (q) => { const k = keepIn(q, box, letters); return [k[0] - hw, k[1] - 0.35 * fs - hh, k[0] + hw, k[1] - 0.35 * fs + hh]; };
    const clear = (b) => placed.every((p) => apart(p, b)) &&
      pts.every((p, j) => j === i || p[0] < b[0] - 0.3 || p[0] > b[2] + 0.3 || p[1] < b[1] - 0.3 || p[1] > b[3] + 0.3);
    let least = null, free = null, best = null;  // (least: the place that overlaps least)
    for (const r of [0.75, 1.15, 1.6]) {
      for (const turn of [0, 1, -1, 2, -2, 3, -3, 4]) {
        const a = a0 + turn * Math.PI / 4;
        // (a place at its distance from the point to the nearer side of the text's box)
        const d = r * fs + Math.min(Math.abs(hw / Math.cos(a)), Math.abs(hh / Math.sin(a))) - 0.35 * fs;
        const q = [c[0] + d * Math.cos(a), c[1] + d * Math.sin(a)], b = boxAt(q);
        if (!clear(b)) {
          const o = overlap(b, placed, pts, i);
          if (least === null || o < least[1]) least = [q, o];
          continue;
        }
        if (free === null) free = q;
        const wide = [b[0] - 0.3, b[1] - 0.3, b[2] + 0.3, b[3] + 0.3];  // (a line's half width and a little)
        if (segs.every((sg) => !crosses(sg, wide))) { best = q; break; }
      }
      if (best !== null) break;
    }
    best = best || free || least[0];
    placed.push(boxAt(best));
    place(e, keepIn(best, box, letters));
  }
}
// how much a box b overlaps the boxes placed (their area in common) and the other points
function overlap(b, placed, pts, own) {
  let o = 0;
  for (const p of placed) o += Math.max(0, Math.min(b[2], p[2]) - Math.max(b[0], p[0])) * Math.max(0, Math.min(b[3], p[3]) - Math.max(b[1], p[1]));
  pts.forEach((p, j) => { if (j !== own && p[0] >= b[0] && p[0] <= b[2] && p[1] >= b[1] && p[1] <= b[3]) o += FS * FS; });
  return o;
}
// the lines drawn in a panel, as segments [x1, y1, x2, y2] (the forces' layer left out)
// and the sides of the blocks and the ground's marks
function segmentsOf(svg) {
  const out = [];
  for (const e of svg.querySelectorAll("line, polygon.block, polygon.ground")) {
    if (e.style.display === "none" || e.closest("#force-layer")) continue;
    if (e.tagName === "line") {
      const s = ["x1", "y1", "x2", "y2"].map((a) => Number(e.getAttribute(a)));
      if (s.every(Number.isFinite)) out.push(s);
      continue;
    }
    const p = (e.getAttribute("points") || "").split(" ").filter(Boolean).map((q) => q.split(",").map(Number));
    p.forEach((a, i) => out.push([a[0], a[1], p[(i + 1) % p.length][0], p[(i + 1) % p.length][1]]));
  }
  return out;
}
// whether the segment s crosses the box b [x0, y0, x1, y1] (clipped to it, Liang-Barsky)
function crosses(s, b) {
  let t0 = 0, t1 = 1;
  const d = [s[2] - s[0], s[3] - s[1]];
  for (const [p, q] of [[-d[0], s[0] - b[0]], [d[0], b[2] - s[0]], [-d[1], s[1] - b[1]], [d[1], b[3] - s[1]]]) {
    if (p === 0) { if (q < 0) return false; continue; }
    const t = q / p;
    if (p < 0) { if (t > t1) return false; if (t > t0) t0 = t; } else { if (t < t0) return false; if (t < t1) t1 = t; }
  }
  return t0 <= t1;
}

// ---------------------------------------------------------------- values and tooltips
function pointValues(p, k) {
  const v = vec("velocity", p, k), a = vec("acceleration", p, k);
  return {v: Math.hypot(v[0], v[1]), vdir: dir(v[0], v[1]), a: Math.hypot(a[0], a[1]), adir: dir(a[0], a[1])};
}
function valuesRows(k) {  // [id, name (HTML), value]
  const rows = [["theta", PARAM[0] + " " + PARAM[1], at(D.theta[k])]];
  for (const p of D.points) {
    const pv = pointValues(p, k);
    rows.push(["v-" + p, sub("v", p) + " (o" + esc(label(p, "velocity")) + ")", fmt(pv.v) + " m/s at " + pv.vdir + "°"]);
    rows.push(["a-" + p, sub("a", p) + " (o'" + esc(label(p, "acceleration")) + ")", fmt(pv.a) + " m/s² at " + pv.adir + "°"]);
  }
  for (const [, , key] of D.links) {
    rows.push(["w-" + key, sub("ω", key), angular(D.W[key][k], "rad/s")]);
    rows.push(["al-" + key, sub("α", key), angular(D.Al[key][k], "rad/s²")]);
  }
  for (const s in D.S) {
    rows.push(["vs-" + s, "sliding velocity of " + esc(s), fmt(D.S[s][0][k]) + " m/s"]);
    rows.push(["as-" + s, "sliding acceleration of " + esc(s), fmt(D.S[s][1][k]) + " m/s²"]);
    const c = Math.hypot(D.S[s][2][k], D.S[s][3][k]);
    if (c > 0) rows.push(["ac-" + s, "Coriolis component at " + esc(s), fmt(c) + " m/s²"]);
  }
  for (const c of D.asked) rows.push(["asked-" + c.key, esc(c.key) + " (" + (c.kind === "ar" ? "radial, ω²·" : "tangential, α·") +
    esc(two(c.x, c.y)) + ")", fmt(c.values[k]) + " m/s²"]);
  for (const l of D.least) rows.push(["least-" + l.key, esc(l.key) + " (the slowest point " + esc(l.P) + " of " + esc(two(l.x, l.y)) + ")", leastWords(l, k)]);
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
    tr.innerHTML = "<th>" + name + "</th><td></td>";
    tr.lastChild.id = "val-" + id;
    body.appendChild(tr);
  }
}
// the least speed of segment XY at frame k, and where (its distance from X), as the data says
// two names as one, as the steps join them: "AB", "O2-A" where a name is longer than a letter
const two = (a, b) => a.length === 1 && b.length === 1 ? a + b : a + "-" + b;
function leastWords(l, k) {
  const xy = two(l.x, l.y);
  if (l.t[k] === null) return fmt(l.speed[k]) + " m/s: " + xy + " does not turn, every point of it moves alike";
  const at = two(l.x, l.P) + " = " + fmt(l.from[k] / D.unit) + " " + D.units;
  if (l.t[k] >= 0 && l.t[k] <= 1) return fmt(l.speed[k]) + " m/s at " + at;
  return fmt(l.speed[k]) + " m/s at the end " + (l.t[k] < 0 ? l.x : l.y) + " (" + l.p + " falls beyond " +
    D.images[l.t[k] < 0 ? l.x : l.y] + ")";
}
function tipText(tip, k) {
  if (!tip.includes(":")) return tip;
  const [kind, name] = tip.split(":");
  const u = D.units, f = D.unit;
  if (kind === "point" || kind === "ground") {
    const c = vec("configuration", name, k);
    return (kind === "ground" ? "fixed pivot " : "") + name + " at (" + fmt(c[0] / f) + ", " + fmt(c[1] / f) + ") " + u +
      (kind === "point" && !(name in D.ground) ? "; " + tipText("abs:" + name, k) : "");
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
  if (kind === "least") {
    const l = D.least.find((x) => x.key === name), f = pair(l.foot, k);
    const op = l.t[k] === null ? "" : "; o" + l.p + " = " + fmt(Math.hypot(f[0], f[1])) + " m/s, o" + l.p + " square to " +
      two(D.images[l.x], D.images[l.y]) + (l.t[k] < 0 || l.t[k] > 1 ? " produced" : "");
    return name + " = " + leastWords(l, k) + op;
  }
  if (kind === "plate" || kind === "image") return "point " + name + " on its link: " + tipText("abs:" + name, k);
  if (kind === "pole") return (name === "velocity" ? "o" : "o'") + ": the pole, image of every fixed point (zero " + (name === "velocity" ? "velocity)" : "acceleration)");
  if (kind === "under") {
    const s = D.sliders.find((x) => x.key === name), [uv] = under("velocity", s, k), [ua] = under("acceleration", s, k);
    return D.under[name] + ": the point of link " + s.link + " under the block " + s.point + " (coincident with it), v = o" +
      D.under[name] + " = " + fmt(Math.hypot(uv[0], uv[1])) + " m/s, a = o'" + D.under[name] + "' = " + fmt(Math.hypot(ua[0], ua[1])) + " m/s²";
  }
  if (kind === "sliding") return "sliding velocity of " + name + " = " + fmt(D.S[name][0][k]) + " m/s; sliding acceleration " + fmt(D.S[name][1][k]) + " m/s²";
  if (kind === "coriolis") return "Coriolis component at " + name + " = 2ωv = " + fmt(Math.hypot(D.S[name][2][k], D.S[name][3][k])) + " m/s²";
  if (kind === "inertia") {
    const b = D.inertia.bodies.find((x) => x.body === name);
    const h = Math.hypot(b.H[2 * k] - b.G[2 * k], b.H[2 * k + 1] - b.G[2 * k + 1]);
    return "inertia force " + b.label + " of " + name + " = m·a_G = " + fmt(Math.hypot(b.F[2 * k], b.F[2 * k + 1])) +
      " N, opposite to a_G, " + (h > 0 ? "along the line h = " + fmt(h / f) + " " + u + " from G that carries the couple I·α" : "through G") +
      " (drawn at " + D.inertia.text + ")";
  }
  if (kind === "force") {
    const a = D.forces.arrows[Number(name)], F = [a.F[2 * k], a.F[2 * k + 1]];
    const dir = Math.round(10 * Math.atan2(F[1], F[0]) * 180 / Math.PI) / 10;
    return a.label + ": the " + ({pin: "pin force", guide: "guide's force", contact: "contact force", driver: "driver's force",
      load: "load", gas: "gas force", weight: "weight", friction: "friction force"}[a.what] || "force") + " on " + a.on +
      (a.by ? " by " + a.by + " (" + a.by + " feels its opposite)" : "") + " = " + fmt(Math.hypot(F[0], F[1])) +
      " N at " + dir + "° (drawn at " + FORCES.text + ")";
  }
  if (kind === "couple" || kind === "icouple") {
    const c = kind === "couple" ? D.forces.couples[Number(name)] : D.inertia.bodies.find((x) => x.body === name);
    const C = c.C[k];
    return (kind === "couple" ? c.label + ": the " + ({torque: "driver's torque", guide: "guide's couple", load: "couple",
      friction: "friction couple"}[c.what] || "couple") + " on " + c.on : "the inertia couple −I·α of " + name + ", no single force carrying it") +
      " = " + fmt(Math.abs(C)) + " N m " + (C > 0 ? "ccw" : C < 0 ? "cw" : "");
  }
  if (kind === "offset") {
    const b = D.inertia.bodies.find((x) => x.body === name);
    return "the inertia force of " + name + " is offset from G by h = I·α / (m·a_G) = " +
      fmt(Math.hypot(b.H[2 * k] - b.G[2 * k], b.H[2 * k + 1] - b.G[2 * k + 1]) / f) + " " + u;
  }
  if (kind === "slider" || kind === "guide") return "slider " + name + ": sliding velocity " + fmt(D.S[name][0][k]) + " m/s";
  return name;
}
// a tap or a click shows the same words in a box (touch screens show no <title>)
const tooltip = document.getElementById("tooltip");
document.addEventListener("click", (ev) => {
  const t = ev.target.closest("[data-tip]");
  if (!t) { tooltip.hidden = true; return; }
  tooltip.textContent = tipText(t.dataset.tip, frame);
  tooltip.hidden = false;
  const w = tooltip.offsetWidth;
  tooltip.style.left = Math.max(4, Math.min(ev.pageX + 12, document.documentElement.clientWidth - w - 4)) + "px";
  tooltip.style.top = (ev.pageY + 12) + "px";
});

// ---------------------------------------------------------------- sweep plots
// each series: [name as SVG text parts [base, subscript], f(k)]
const PLOTS = [
  ["plot-v", "speeds of the points", "speed (m/s)", () => D.points.map((p) => [["v", p], (k) => pointValues(p, k).v])
    .concat(D.least.map((l) => [["v", "min," + two(l.x, l.y)], (k) => l.speed[k]]))],
  ["plot-w", "angular velocities of the links", "ω (rad/s, ccw +)", () => D.links.map(([, , key]) => [["ω", key], (k) => D.W[key][k]])],
  ["plot-a", "accelerations of the points", "acceleration (m/s²)", () => D.points.map((p) => [["a", p], (k) => pointValues(p, k).a])
    .concat(D.asked.map((c) => [[c.key.slice(0, 2), c.key.slice(3)], (k) => c.values[k]]))],
];
function roundTicks(lo, hi, most) {  // round ticks (1, 2, 5 x 10^k apart) over [lo, hi]
  const step = roundUp((hi - lo) / most), out = [];
  for (let t = Math.ceil(lo / step - TOL.same) * step; t <= hi + TOL.same * step; t += step) out.push(Math.abs(t) < TOL.same * step ? 0 : t);
  return out;
}
function typeset(parent, attrs, [base, s]) {
  const t = el(parent, "text", attrs);
  t.textContent = base;
  const e = el(t, "tspan", {"baseline-shift": "sub", "font-size": "75%"});
  e.textContent = s;
  return t;
}
const markers = [];
function buildPlots() {
  const W = 320, H = 210, L = 50, R = 12, B = 34, t0 = D.theta[0], t1 = D.theta[N - 1];
  // frame order, left to right: the marker moves as the crank turns (cw or ccw)
  const X = (t) => L + (W - L - R) * (t - t0) / ((t1 - t0) || 1);
  for (const [id, title, ytitle, series] of PLOTS) {
    const svg = document.getElementById(id), ss = series();
    svg.setAttribute("viewBox", "0 0 " + W + " " + H);
    // legend rows under the title, then the plot's area
    let lx = L, rows = 0;
    const place = ss.map(([name]) => {
      const w = 24 + 6 * (name[0].length + 0.75 * name[1].length);
      if (lx + w > W - R && lx > L) { lx = L; rows++; }
      const at = [lx, 28 + 12 * rows];
      lx += w;
      return at;
    });
    const T = 36 + 12 * rows;
    // the range of most values (near a limit position they grow without bound: cut off)
    const all = [];
    for (const [, f] of ss) for (let k = 0; k < N; k++) all.push(f(k));
    all.sort((a, b) => a - b);
    const q = (x) => all[Math.min(all.length - 1, Math.floor(x * all.length))];
    const lo5 = q(0.05), hi95 = q(0.95), room = 0.5 * (hi95 - lo5);
    let ymin = Math.min(0, Math.max(all[0], lo5 - room)), ymax = Math.max(0, Math.min(all[all.length - 1], hi95 + room));
    if (!(ymax - ymin > TOL.rounding * Math.max(Math.abs(ymin), Math.abs(ymax), TOL.floor))) { ymax = ymin + Math.max(1, Math.abs(ymin)); }
    const yt = roundTicks(ymin, ymax, 4), step = yt.length > 1 ? yt[1] - yt[0] : ymax - ymin;
    ymin = Math.min(ymin, Math.floor(ymin / step + TOL.same) * step); ymax = Math.max(ymax, Math.ceil(ymax / step - TOL.same) * step);
    const Y = (y) => T + (H - T - B) * (ymax - y) / (ymax - ymin);
    const clip = el(el(svg, "defs", {}), "clipPath", {id: id + "-clip"});
    el(clip, "rect", {x: L, y: T, width: W - L - R, height: H - T - B});
    text(svg, {x: L, y: 13, class: "plot-title"}, title);
    for (const y of roundTicks(ymin, ymax, 4)) {
      el(svg, "line", {x1: L, y1: r3(Y(y)), x2: W - R, y2: r3(Y(y)), class: y === 0 ? "axis" : "grid"});
      text(svg, {x: L - 3, y: r3(Y(y) + 3.5), class: "tick", "text-anchor": "end"}, fmt(y, 3));
    }
    // at most 6 steps: whole turns, 2 or 5 of them, ... over a period of many turns (a
    // differential's 10 turns once had 11 ticks, 0° to 3600°, running together)
    const turned = Math.abs(t1 - t0), dstep = [5, 10, 15, 30, 45, 60, 90, 180, 360, 720, 1800, 3600, 7200, 18000].find((s) => turned / s <= 6) || 36000;
    const xt = [];  // a round angle, written between 0 and the cycle (360); a block's
    // place: round numbers (1, 2 or 5 x 10^k apart), its unit in the axis' title; over a
    // cycle of more than a turn (a four-stroke's 720°) the angle turned from the first
    // frame, in order (written within the cycle it read 540°, 0°, 180°, 360°)
    const sg = t1 < t0 ? -1 : 1;
    if (D.param) for (const t of roundTicks(Math.min(t0, t1), Math.max(t0, t1), 6)) xt.push([t, fmt(t, 3)]);
    else if (MANY_TURNS) for (let j = 0; j * dstep <= turned + TOL.same * dstep; j++) xt.push([t0 + sg * j * dstep, String(j * dstep) + "°"]);
    else for (let j = Math.ceil(Math.min(t0, t1) / dstep - TOL.same); j * dstep <= Math.max(t0, t1) + TOL.same; j++) xt.push([j * dstep, String(inCycle(j * dstep)) + "°"]);
    for (const [t, words] of xt) {
      el(svg, "line", {x1: r3(X(t)), y1: T, x2: r3(X(t)), y2: H - B, class: "grid"});
      text(svg, {x: r3(X(t)), y: H - B + 11, class: "tick", "text-anchor": "middle"}, words);
    }
    el(svg, "line", {x1: L, y1: T, x2: L, y2: H - B, class: "axis"});
    text(svg, {x: (L + W - R) / 2, y: H - 6, class: "axis-title", "text-anchor": "middle"},
      D.param ? PARAM[0] + " " + PARAM[1] + " (" + PARAM[2].trim() + ")" : MANY_TURNS ? "crank angle turned (" + (t1 < t0 ? "cw" : "ccw") + ") from θ = " + at(t0) : D.fullTurn ? "crank angle θ, as the crank turns (" + (t1 < t0 ? "cw" : "ccw") + ")" : "crank angle θ, between the limit positions");
    text(svg, {x: 0, y: 0, class: "axis-title", "text-anchor": "middle", transform: "translate(10," + r3((T + H - B) / 2) + ") rotate(-90)"}, ytitle);
    const [ic, iw, idash] = D.style.marks.instant;
    el(svg, "line", {x1: r3(X(D.theta[D.start])), x2: r3(X(D.theta[D.start])), y1: T, y2: H - B, stroke: ic, "stroke-width": iw,
      "stroke-dasharray": idash.join(" ")}, "the stated instant, " + PARAM[1] + " = " + at(D.theta[D.start]));
    ss.forEach(([name, f], i) => {
      const pts = [], color = D.style.series[i % D.style.series.length];
      for (let k = 0; k < N; k++) pts.push(r3(X(D.theta[k])) + "," + r3(Y(f(k))));
      el(svg, "polyline", {points: pts.join(" "), class: "series", stroke: color, "clip-path": "url(#" + id + "-clip)"}, "series:" + name[1]);
      el(svg, "line", {x1: place[i][0], x2: place[i][0] + 12, y1: place[i][1] - 3.5, y2: place[i][1] - 3.5, stroke: color, "stroke-width": 2});
      typeset(svg, {x: place[i][0] + 15, y: place[i][1], class: "legend"}, name);
    });
    const [mc, mw] = D.style.marks.now;
    markers.push([el(svg, "line", {class: "marker", stroke: mc, "stroke-width": mw, y1: T, y2: H - B, id: id + "-marker"}), X]);
  }
}

// ---------------------------------------------------------------- the slider and play
const slider = document.getElementById("angle");
const play = document.getElementById("play");
function show(k) {
  frame = k;
  slider.value = k;
  for (const phase of PHASES) update(phase, k);
  for (const [t, tip] of titles) t.textContent = tipText(tip, k);
  for (const [id, , words] of valuesRows(k)) document.getElementById("val-" + id).textContent = words;
  document.getElementById("angle-now").textContent = PARAM[1] + " = " + at(D.theta[k]);
  for (const [m, X] of markers) { m.setAttribute("x1", r3(X(D.theta[k]))); m.setAttribute("x2", r3(X(D.theta[k]))); }
  document.dispatchEvent(new CustomEvent("pm-frame", {detail: k}));  // an engine's cycle follows
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
const showForces = document.getElementById("show-forces");
if (showForces) showForces.addEventListener("change", () => show(frame));
slider.addEventListener("input", () => show(Number(slider.value)));
window.addEventListener("resize", () => { layout(); show(frame); });
layout();
for (const phase of PHASES) setup(phase);
buildValues();
buildPlots();
show(D.start);

// printed: the folded parts (the step table, the problem) opened for the paper, and
// folded again after (one handler, whichever of the page's scripts comes first)
if (!window.pmPrint) {
  window.pmPrint = [];
  window.addEventListener("beforeprint", function () {
    window.pmPrint = Array.prototype.filter.call(document.querySelectorAll("details"), function (d) { return !d.open; });
    window.pmPrint.forEach(function (d) { d.open = true; });
  });
  window.addEventListener("afterprint", function () {
    window.pmPrint.forEach(function (d) { d.open = false; });
    window.pmPrint = [];
  });
}
