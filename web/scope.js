// The radar scope: a north-up canvas of the live state (plain JavaScript, no
// dependencies). Positions are projected flat around the view centre:
// x = (lon - lon0) * 60 cos(lat0) NM, y = (lat - lat0) * 60 NM, then scaled
// by the zoom (pixels per NM). Drag pans, the wheel zooms about the cursor,
// a click selects, right- or Shift-drag measures range and bearing. Behind
// the traffic: the grid, and with navdata coastlines, FIR borders, airports,
// navaids and fixes by zoom (GET /api/geo, /api/navdata). The legend is in
// index.html; docs/scope_guide.md explains every symbol.
//
// Labels never overprint: each frame the symbols (aircraft, CPA crosses,
// route waypoints) are laid down first, then the data blocks, the conflict
// labels and the route labels are placed one after another, each at the
// first position around its anchor that overlaps no symbol and no label
// placed before it, with a leader line back to the anchor. A data block that
// was dragged keeps its offset from its aircraft. The placement of the last
// frame is the label model: Scope.labels() [{kind, key, text, x, y, w, h}]
// and Scope.symbols() [{kind, key, x, y, w, h}] in canvas pixels.
"use strict";

const Scope = (() => {
  const canvas = document.getElementById("scope");
  const ctx = canvas.getContext("2d");
  const colors = {
    bg: "#050908", grid: "#15302a", gridText: "#3f6b5c", ac: "#7cf0b0", sel: "#5ad8ff",
    conf: "#ff4d4d", warn: "#ffb347", later: "#e0d36a", route: "#5ad8ff", fix: "#2f4c42", apt: "#7d9c90",
    text: "#b9d8cb", pz: "#2f6f58", fixText: "#4d7567", leader: "#4f7a6a", navaid: "#6f8fb0",
    coast: "#2f5d7a", fir: "#6a4f86", rbl: "#ffb347",
  };
  const view = { lat0: 52, lon0: 4, ppnm: 8, fitted: false };
  const opts = { pz: false, fixes: true, geo: true, trails: true, vectorMin: 1 };
  let state = null;
  let selected = null;
  const trails = new Map();   // id -> [[lat, lon], ...] one point per state.trail.dt_s of sim time
  const TRAIL_LEN = 24;
  const trailColors = { BLUE: "#5a8cff", RED: "#ff4d4d", YELLOW: "#ffe14d" };  // TRAIL acid colour
  let nav = { airports: [], navaids: [], fixes: [] }, navKey = "", navPending = false;
  let geo = { coast: [], fir: [] }, geoKey = "", geoPending = false;
  let onSelect = () => {};
  let dirty = true;
  const offsets = new Map();  // id -> [dx, dy] [px] a dragged data block's top-left from its aircraft
  let labels = [], symbols = [];
  let rbl = null;  // range/bearing line: {from: [lat, lon], to: [lat, lon]} (right- or Shift-drag)

  const nm = (lat, lon) => [(lon - view.lon0) * 60 * Math.cos(view.lat0 * Math.PI / 180), (lat - view.lat0) * 60];
  function px(lat, lon) {
    const [x, y] = nm(lat, lon);
    return [W / 2 + x * view.ppnm, H / 2 - y * view.ppnm];
  }
  function unpx(x, y) {
    const xn = (x - W / 2) / view.ppnm, yn = -(y - H / 2) / view.ppnm;
    return [view.lat0 + yn / 60, view.lon0 + xn / (60 * Math.cos(view.lat0 * Math.PI / 180))];
  }

  // The canvas is drawn in logical pixels: CSS pixels / K, K = 1 up to a
  // 2400 px wide scope and more beyond (4K: symbols and text grow with the
  // screen), times the device pixel ratio for sharp lines.
  let W = 200, H = 200, K = 1;
  function resize() {
    const r = canvas.getBoundingClientRect(), dpr = window.devicePixelRatio || 1;
    K = r.width >= 2400 ? Math.min(2, r.width / 1600) : 1;
    canvas.width = Math.max(200, Math.round(r.width * dpr));
    canvas.height = Math.max(200, Math.round(r.height * dpr));
    W = canvas.width / (dpr * K); H = canvas.height / (dpr * K);
    ctx.setTransform(dpr * K, 0, 0, dpr * K, 0, 0);
    dirty = true;
  }
  const mx = (e) => e.offsetX / K, my = (e) => e.offsetY / K;

  // Fits the traffic into the part of the canvas left of the legend (when open).
  function fit() {
    if (!state || state.aircraft.length === 0) return;
    let s = 90, n = -90, w = 180, e = -180;
    for (const a of state.aircraft) {
      s = Math.min(s, a.lat); n = Math.max(n, a.lat); w = Math.min(w, a.lon); e = Math.max(e, a.lon);
    }
    const legend = document.getElementById("legend");
    const lw = legend && !legend.classList.contains("hidden") ? (legend.getBoundingClientRect().width + 20) / K : 0;
    const free = Math.max(W / 2, W - lw), cos = Math.cos((s + n) / 2 * Math.PI / 180);
    const [wx, hy] = [(e - w) * 60 * cos, (n - s) * 60];
    const span = Math.max(wx / free, hy / H, 30 / Math.min(free, H));
    view.ppnm = 1 / (span * 1.5);
    view.lat0 = (s + n) / 2;
    view.lon0 = (w + e) / 2 + (W - free) / 2 / view.ppnm / (60 * cos);  // the box's centre at x = free / 2
    view.fitted = true;
    dirty = true;
  }

  // A "nice" step (1, 2, 2.5, 5 x 10^k) at least `raw`.
  function niceStep(raw) {
    const p = Math.pow(10, Math.floor(Math.log10(raw)));
    for (const m of [1, 2, 2.5, 5, 10]) if (m * p >= raw) return m * p;
    return 10 * p;
  }

  function drawGrid() {
    const [latS, lonW] = unpx(0, H), [latN, lonE] = unpx(W, 0);
    const step = niceStep((latN - latS) / 8);
    ctx.strokeStyle = colors.grid; ctx.fillStyle = colors.gridText; ctx.lineWidth = 1;
    ctx.font = "11px monospace";
    const dec = step >= 1 ? 0 : step >= 0.1 ? 1 : 2;
    // Parallels exist only within ±90°; meridians repeat past ±180° and are
    // labelled with their longitude in [-180°, 180°).
    for (let lat = Math.ceil(Math.max(latS, -90) / step) * step; lat <= Math.min(latN, 90); lat += step) {
      const [, y] = px(lat, view.lon0);
      ctx.beginPath(); ctx.moveTo(0, y); ctx.lineTo(W, y); ctx.stroke();
      ctx.fillText(`${Math.abs(lat).toFixed(dec)}°${lat >= 0 ? "N" : "S"}`, 4, y - 3);
    }
    for (let lon = Math.ceil(lonW / step) * step; lon <= lonE; lon += step) {
      const [x] = px(view.lat0, lon);
      ctx.beginPath(); ctx.moveTo(x, 0); ctx.lineTo(x, H); ctx.stroke();
      const l = ((lon + 180) % 360 + 360) % 360 - 180;
      ctx.fillText(`${Math.abs(l).toFixed(dec)}°${l >= 0 ? "E" : "W"}`, x + 3, H - 6);
    }
  }

  function drawScale() {
    const nmLen = niceStep(120 / view.ppnm), len = nmLen * view.ppnm;
    const x = 16, y = H - 28;
    ctx.strokeStyle = colors.text; ctx.fillStyle = colors.text; ctx.lineWidth = 2;
    ctx.beginPath(); ctx.moveTo(x, y - 5); ctx.lineTo(x, y); ctx.lineTo(x + len, y); ctx.lineTo(x + len, y - 5); ctx.stroke();
    ctx.font = "12px monospace";
    ctx.fillText(`${nmLen} NM`, x + len / 2 - 16, y - 8);
    // North arrow, top right.
    const nx = W - 24, ny = 50;
    ctx.beginPath(); ctx.moveTo(nx, ny - 18); ctx.lineTo(nx - 6, ny); ctx.lineTo(nx + 6, ny); ctx.closePath(); ctx.fill();
    ctx.fillText("N", nx - 4, ny + 14);
  }

  // What the zoom shows of the navdata: airports from 0.4 px/NM (about
  // 2500 NM across a 1000 px scope), navaids from 1.5, fixes from 12; their
  // names where a free place is found around them. A navaid listed several
  // times at one place (VOR, DME and NDB of one station) is drawn once.
  const navKinds = () => opts.fixes ? ["airports", "navaids", "fixes"].filter((k, i) => view.ppnm >= [0.4, 1.5, 12][i]) : [];
  const onCanvas = (x, y) => x > -10 && y > -10 && x < W + 10 && y < H + 10;

  function navPoints() {
    const out = [], kinds = navKinds();
    const seen = new Map();  // id -> [x, y] drawn
    for (const k of kinds) for (const [id, lat, lon, type] of nav[k] || []) {
      const [x, y] = px(lat, lon), prev = seen.get(id);
      if (!onCanvas(x, y) || (prev && Math.hypot(prev[0] - x, prev[1] - y) < 4)) continue;
      seen.set(id, [x, y]);
      out.push({ kind: k, id, type, x, y });
    }
    return out;
  }

  function drawNav(points) {
    ctx.lineWidth = 1;
    for (const p of points) {
      const { x, y } = p;
      if (p.kind === "fixes") {
        ctx.strokeStyle = colors.fix;
        ctx.beginPath(); ctx.moveTo(x, y - 3); ctx.lineTo(x - 2.6, y + 1.8); ctx.lineTo(x + 2.6, y + 1.8); ctx.closePath(); ctx.stroke();
      } else if (p.kind === "navaids") {
        ctx.strokeStyle = colors.navaid;
        ctx.beginPath();
        for (let i = 0; i <= 6; i++) ctx[i ? "lineTo" : "moveTo"](x + 4 * Math.cos(i * Math.PI / 3), y + 4 * Math.sin(i * Math.PI / 3));
        ctx.stroke();
        if (p.type === "NDB" || p.type === "DME" || p.type === "TACAN") ctx.strokeRect(x - 1, y - 1, 2, 2);
      } else {
        ctx.strokeStyle = colors.apt;
        ctx.beginPath(); ctx.arc(x, y, 5, 0, 2 * Math.PI); ctx.stroke();
        ctx.beginPath(); ctx.moveTo(x - 7, y); ctx.lineTo(x + 7, y); ctx.stroke();
      }
    }
  }

  // Coastlines and FIR borders (navdata's coastlines.dat and fir/*.txt).
  function drawGeo() {
    if (!opts.geo) return;
    ctx.lineWidth = 1; ctx.strokeStyle = colors.coast;
    for (const line of geo.coast) {
      ctx.beginPath();
      for (let i = 0; i < line.length; i += 2) ctx[i ? "lineTo" : "moveTo"](...px(line[i], line[i + 1]));
      ctx.stroke();
    }
    ctx.strokeStyle = colors.fir; ctx.setLineDash([8, 4, 2, 4]);
    for (const f of geo.fir) {
      ctx.beginPath();
      for (let i = 0; i < f.pts.length; i += 2) ctx[i ? "lineTo" : "moveTo"](...px(f.pts[i], f.pts[i + 1]));
      ctx.stroke();
    }
    ctx.setLineDash([]);
  }

  // Fetches the navdata and the geography of the visible box when the view moved enough.
  function refreshNav() {
    const [s, w] = unpx(0, H), [n, e] = unpx(W, 0);
    const box = `south=${s}&north=${n}&west=${w}&east=${e}`;
    const kinds = navKinds(), key = [s, n, w, e].map((v) => v.toFixed(2)).join(",") + kinds.join();
    if (key !== navKey && !navPending) {
      if (kinds.length === 0) { nav = { airports: [], navaids: [], fixes: [] }; navKey = key; dirty = true; }
      else {
        navPending = true;
        fetch(`/api/navdata?${box}&kinds=${kinds.join(",")}`).then((r) => r.json()).then((j) => {
          nav = j; navKey = key; dirty = true;
        }).catch(() => {}).finally(() => { navPending = false; });
      }
    }
    const step = 1.5 / (view.ppnm * 60);  // [deg] 1.5 px
    const gkey = [s, n, w, e].map((v) => v.toFixed(2)).join(",") + step.toPrecision(2);
    if (opts.geo && gkey !== geoKey && !geoPending) {
      geoPending = true;
      fetch(`/api/geo?${box}&step=${step}`).then((r) => r.json()).then((j) => {
        geo = j; geoKey = gkey; dirty = true;
      }).catch(() => {}).finally(() => { geoPending = false; });
    }
  }

  function inConflict() {
    const m = new Map();
    for (const c of state.conflicts) for (const id of [c.own, c.intruder]) m.set(id, "conf");
    for (const l of state.los) for (const id of [l.own, l.intruder]) m.set(id, "los");
    return m;
  }

  const fl = (ft) => String(Math.round(ft / 100)).padStart(3, "0");
  const mmss = (s) => `${Math.floor(s / 60)}:${String(Math.floor(s % 60)).padStart(2, "0")}`;

  // --- Label placement ------------------------------------------------------
  const PAD = 2;  // [px] free margin kept around every label
  const hits = (a, b) => a.x < b.x + b.w + PAD && b.x < a.x + a.w + PAD && a.y < b.y + b.h + PAD && b.y < a.y + a.h + PAD;
  function overlapArea(a, b) {
    const w = Math.min(a.x + a.w, b.x + b.w) - Math.max(a.x, b.x) + PAD, h = Math.min(a.y + a.h, b.y + b.h) - Math.max(a.y, b.y) + PAD;
    return w > 0 && h > 0 ? w * h : 0;
  }
  // Directions tried around an anchor, preferred first (up-right as blocks usually sit).
  const DIRS = [[1, -1], [1, 1], [-1, -1], [-1, 1], [1, 0], [-1, 0], [0, -1], [0, 1]];
  const RINGS = [14, 26, 42, 62, 88, 120, 160];  // [px] distances from the anchor
  // The boxes laid down so far (symbols, labels, the tool bar), bucketed by
  // a CELL px grid so that a candidate box is compared only with its neighbours.
  const CELL = 64;
  class Taken {
    constructor() { this.cells = new Map(); this.stamp = 0; }
    keys(b, f) {
      const x0 = Math.floor((b.x - PAD) / CELL), x1 = Math.floor((b.x + b.w + PAD) / CELL);
      const y0 = Math.floor((b.y - PAD) / CELL), y1 = Math.floor((b.y + b.h + PAD) / CELL);
      for (let cx = x0; cx <= x1; cx++) for (let cy = y0; cy <= y1; cy++) f(cx * 65536 + cy);
    }
    add(b) {
      const e = { b, seen: 0 };
      this.keys(b, (k) => { const c = this.cells.get(k); if (c) c.push(e); else this.cells.set(k, [e]); });
    }
    // Overlap area of `box` with the boxes laid down, counted up to `limit`.
    overlap(box, limit) {
      const stamp = ++this.stamp;
      let sc = 0;
      this.keys(box, (k) => {
        const c = this.cells.get(k);
        if (!c || sc >= limit) return;
        for (const e of c) {
          if (e.seen === stamp) continue;
          e.seen = stamp;
          sc += overlapArea(box, e.b);
          if (sc >= limit) return;
        }
      });
      return sc;
    }
  }

  // The top-left of a w x h box at the first free candidate around (ax, ay);
  // when the rings are full, the free spot of a 10 px grid over the canvas
  // nearest the anchor (a longer leader line); when none is free, the ring
  // candidate with the least overlap (off-canvas counts as overlap).
  // strict: a free ring candidate or null (in dense traffic only the three
  // inner rings: a label stays next to its aircraft or is left out).
  function place(ax, ay, w, h, taken, strict = false) {
    let best = null, bestScore = strict ? 1e-9 : Infinity;  // strict: any overlap rules a candidate out
    const score = (box, limit) => {
      const sc = box.x < 0 || box.y < 0 || box.x + box.w > W || box.y + box.h > H ? box.w * box.h : 0;
      return sc >= limit ? sc : sc + taken.overlap(box, limit - sc);
    };
    for (const r of strict && dense ? RINGS.slice(0, 3) : RINGS) for (const [ux, uy] of DIRS) {
      const d = ux && uy ? r * 0.75 : r;
      const x = ux > 0 ? ax + d : ux < 0 ? ax - d - w : ax - w / 2;
      const y = uy > 0 ? ay + d * 0.6 : uy < 0 ? ay - d * 0.6 - h : ay - h / 2;
      const box = { x, y, w, h }, sc = score(box, bestScore);
      if (sc === 0) return box;
      if (sc < bestScore) { best = box; bestScore = sc; }
    }
    if (strict) return null;
    const grid = [];
    for (let x = 0; x + w <= W; x += 10) for (let y = 0; y + h <= H; y += 10)
      grid.push([Math.hypot(x + w / 2 - ax, y + h / 2 - ay), x, y]);
    grid.sort((p, q) => p[0] - q[0]);
    for (const [, x, y] of grid) { const box = { x, y, w, h }; if (score(box, 1) === 0) return box; }
    return best;
  }

  // The point of `box` nearest (x, y): where a leader line ends.
  const nearest = (box, x, y) => [Math.max(box.x, Math.min(x, box.x + box.w)), Math.max(box.y, Math.min(y, box.y + box.h))];

  const LINE_H = 13;  // [px] text line height in labels
  function textBox(lines, fonts) {
    let w = 0;
    lines.forEach((t, i) => { ctx.font = fonts[i] || fonts[0]; w = Math.max(w, ctx.measureText(t).width); });
    return [Math.ceil(w) + 6, lines.length * LINE_H + 4];
  }

  // Zoomed out over dense traffic the scope thins its labels: while more
  // aircraft and conflicts (CPA midpoints) are on the canvas than
  // labelBudget() (one per 8000 px², at least 24), data blocks and conflict labels are placed only where a ring
  // place next to their anchor is free, at most labelBudget() of them
  // (dragged and selected blocks always); the symbols go small
  // (DENSE_SIZE px) and trails are not drawn. Aircraft off the canvas get
  // no symbol and no data block (unless dragged or selected), conflicts
  // whose CPA midpoint is off the canvas no label.
  const labelBudget = () => Math.max(24, Math.floor(W * H / 8000));
  const DENSE_SIZE = 5, TILE = 100, TRIES = 3;
  let dense = false;

  // Lays out every symbol and label of the frame (no drawing); the names of
  // navdata points come last and only where a ring place is free.
  function layout(status, navPts) {
    symbols = []; labels = [];
    const sel = state.aircraft.find((a) => a.id === selected);
    const shown = [];  // [aircraft, x, y]: on the canvas, dragged or selected
    for (const a of state.aircraft) {
      const [x, y] = px(a.lat, a.lon);
      if (onCanvas(x, y) || offsets.has(a.id) || a.id === selected) shown.push([a, x, y]);
    }
    // Conflicts whose CPA midpoint is on the canvas: [conflict, x, y].
    const conflicts = [];
    for (const c of state.conflicts) {
      const [xa, ya] = px(...c.cpa[0]), [xb, yb] = px(...c.cpa[1]);
      if (onCanvas((xa + xb) / 2, (ya + yb) / 2)) conflicts.push([c, (xa + xb) / 2, (ya + yb) / 2]);
    }
    const budget = labelBudget(), crowded = shown.length + conflicts.length > budget;
    dense = crowded;
    const half = crowded ? DENSE_SIZE / 2 + 1 : 6;
    for (const [a, x, y] of shown)
      symbols.push({ kind: "aircraft", key: a.id, x: x - half, y: y - half, w: 2 * half, h: 2 * half, cx: x, cy: y });
    for (const c of state.conflicts) c.cpa.forEach(([lat, lon], i) => {
      const [x, y] = px(lat, lon);
      if (onCanvas(x, y)) symbols.push({ kind: "cpa", key: `${c.own}-${c.intruder}:${i}`, x: x - 5, y: y - 5, w: 10, h: 10, cx: x, cy: y });
    });
    const route = sel ? routeAhead(sel) : [];
    for (const w of route) {
      const [x, y] = px(w.lat, w.lon);
      symbols.push({ kind: "waypoint", key: w.name, x: x - 4, y: y - 4, w: 8, h: 8, cx: x, cy: y });
    }
    // Labels also keep clear of the tool bar and of the legend when it is open.
    const cr = canvas.getBoundingClientRect(), taken = new Taken();
    for (const b of symbols) taken.add(b);
    for (const id of ["scope-tools", "legend"]) {
      const el = document.getElementById(id), r = el && !el.classList.contains("hidden") ? el.getBoundingClientRect() : null;
      if (r && r.width) taken.add({ kind: id, x: (r.left - cr.left) / K, y: (r.top - cr.top) / K, w: r.width / K, h: r.height / K });
    }
    const add = (l) => { labels.push(l); taken.add(l); };
    let left = budget;  // labels still allowed when crowded
    // Data blocks: dragged ones first (they stay where they were put), then
    // the selected aircraft, those in conflict, the rest. Crowded, the
    // others are tried TILE px tile by tile, at most TRIES per tile, so that
    // the labels spread over the canvas and the work stays bounded.
    const rank = (a) => (offsets.has(a.id) ? 4 : 0) + (a.id === selected ? 2 : 0) + (status.has(a.id) ? 1 : 0);
    let order = shown.slice().sort((p, q) => rank(q[0]) - rank(p[0]));
    if (crowded) {
      const tiles = new Map(), must = [];
      for (const e of order) {
        if (offsets.has(e[0].id) || e[0].id === selected) { must.push(e); continue; }
        const k = Math.floor(e[1] / TILE) * 4096 + Math.floor(e[2] / TILE), t = tiles.get(k);
        if (!t) tiles.set(k, [e]); else if (t.length < TRIES) t.push(e);
      }
      order = must.concat(...tiles.values());
    }
    for (const [a, x, y] of order) {
      const off = offsets.get(a.id), must = off || a.id === selected;
      if (crowded && !must && left <= 0) break;
      const text = blockLines(a), [w, h] = textBox(text, ["bold 12px monospace", "12px monospace"]);
      const box = off ? { x: x + off[0], y: y + off[1], w, h } : place(x, y, w, h, taken, crowded && !must);
      if (!box) continue;
      add({ kind: "block", key: a.id, text, ...box, ax: x, ay: y });
      if (!must) left--;
    }
    let tries = budget;  // conflict labels tried when crowded
    for (const [c, ax, ay] of conflicts) {
      if (crowded && (left <= 0 || tries-- <= 0)) break;
      const text = [conflictText(c)], [w, h] = textBox(text, ["bold 11px monospace"]);
      const box = place(ax, ay, w, h, taken, crowded);
      if (!box) continue;
      add({ kind: "conflict", key: `${c.own}-${c.intruder}`, text, ...box, ax, ay, color: urgency(c) });
      left--;
    }
    for (const wp of route) {
      const [x, y] = px(wp.lat, wp.lon);
      const text = [wp.name + (wp.alt_ft != null ? ` ${fl(wp.alt_ft)}` : "")], [w, h] = textBox(text, ["11px monospace"]);
      add({ kind: "route", key: wp.name, text, ...place(x, y, w, h, taken), ax: x, ay: y });
    }
    const named = { airports: 0.4, navaids: 3, fixes: 25 };  // [px/NM] zoom from which names show
    for (const p of navPts) {
      if (view.ppnm < named[p.kind]) continue;
      const text = [p.id], [w, h] = textBox(text, ["10px monospace"]);
      const box = place(p.x, p.y, w, h, taken, true);
      if (box) add({ kind: "nav", key: `${p.kind}:${p.id}`, text, ...box, ax: p.x, ay: p.y, color: colors[{ airports: "apt", navaids: "navaid", fixes: "fixText" }[p.kind]] });
    }
  }

  function blockLines(a) {
    const trend = a.vs_fpm > 100 ? "↑" : a.vs_fpm < -100 ? "↓" : " ";
    const selfl = Math.abs(a.sel_alt_ft - a.alt_ft) > 50 ? fl(a.sel_alt_ft) : "";
    return [a.id, `${fl(a.alt_ft)}${trend}${selfl}`, `${Math.round(a.gs_kt)} ${a.type}`];
  }

  // "KLM1234–DLH4AX LoS 1:23 CPA 0.4 NM 2:10": the pair first, so that each countdown names whom it is for.
  function conflictText(c) {
    const tlos = c.tlos_s == null ? "" : c.tlos_s > 0 ? ` LoS ${mmss(c.tlos_s)}` : " LoS NOW";
    return `${c.own}–${c.intruder}${tlos} CPA ${c.dcpa_nm.toFixed(1)} NM ${c.tcpa_s > 0 ? mmss(c.tcpa_s) : "passed"}`;
  }

  // The colour of a conflict by time to loss of separation: 60 s or less, 120 s or less, beyond.
  function urgency(c) {
    const t = c.tlos_s != null ? c.tlos_s : c.tcpa_s;
    return t <= 60 ? colors.conf : t <= 120 ? colors.warn : colors.later;
  }

  function routeAhead(a) {
    if (!a.route || a.route.length === 0) return [];
    const k = a.route.findIndex((w) => w.name === a.active_wpt);
    return k < 0 ? [] : a.route.slice(k);
  }

  // Bearing [deg true] and distance [NM] from a to b ([lat, lon]), great circle.
  function rangeBearing(a, b) {
    const r = Math.PI / 180, [p1, l1] = [a[0] * r, a[1] * r], [p2, l2] = [b[0] * r, b[1] * r];
    const y = Math.sin(l2 - l1) * Math.cos(p2), x = Math.cos(p1) * Math.sin(p2) - Math.sin(p1) * Math.cos(p2) * Math.cos(l2 - l1);
    const h = Math.sin((p2 - p1) / 2) ** 2 + Math.cos(p1) * Math.cos(p2) * Math.sin((l2 - l1) / 2) ** 2;
    return { brg: (Math.atan2(y, x) / r + 360) % 360, nm: 2 * Math.asin(Math.sqrt(h)) * 6371000 / 1852 };
  }

  function drawRbl() {
    if (!rbl) return;
    const [x0, y0] = px(...rbl.from), [x1, y1] = px(...rbl.to), { brg, nm: d } = rangeBearing(rbl.from, rbl.to);
    ctx.strokeStyle = colors.rbl; ctx.fillStyle = colors.rbl; ctx.lineWidth = 1.5;
    ctx.beginPath(); ctx.moveTo(x0, y0); ctx.lineTo(x1, y1); ctx.stroke();
    ctx.beginPath(); ctx.arc(x0, y0, 3, 0, 2 * Math.PI); ctx.fill();
    ctx.font = "bold 12px monospace";
    const text = `${String(Math.round(brg) % 360 || 360).padStart(3, "0")}° ${d.toFixed(1)} NM`;
    const w = ctx.measureText(text).width + 6;
    ctx.fillStyle = "rgba(5, 9, 8, 0.85)"; ctx.fillRect(x1 + 8, y1 - 8, w, 16);
    ctx.fillStyle = colors.rbl; ctx.fillText(text, x1 + 11, y1 + 4);
  }

  // --- Drawing ----------------------------------------------------------------
  function drawRoute(a) {
    const route = routeAhead(a);
    if (route.length === 0) return;
    ctx.strokeStyle = colors.route; ctx.lineWidth = 1; ctx.setLineDash([6, 4]);
    ctx.beginPath(); ctx.moveTo(...px(a.lat, a.lon));
    for (const w of route) ctx.lineTo(...px(w.lat, w.lon));
    ctx.stroke(); ctx.setLineDash([]);
    for (const w of route) { const [x, y] = px(w.lat, w.lon); ctx.strokeRect(x - 3, y - 3, 6, 6); }
  }

  // Each pair's paths to their closest points of approach (dotted), the CPA
  // crosses and the line between them: one dotted and one solid path for all.
  function drawConflicts() {
    const byId = new Map(state.aircraft.map((a) => [a.id, a])), dotted = new Path2D(), solid = new Path2D();
    for (const c of state.conflicts) {
      const A = byId.get(c.own), B = byId.get(c.intruder);
      if (!A || !B) continue;
      [A, B].forEach((a, i) => {
        const [x0, y0] = px(a.lat, a.lon), [x1, y1] = px(c.cpa[i][0], c.cpa[i][1]);
        dotted.moveTo(x0, y0); dotted.lineTo(x1, y1);
        solid.moveTo(x1 - 4, y1 - 4); solid.lineTo(x1 + 4, y1 + 4); solid.moveTo(x1 - 4, y1 + 4); solid.lineTo(x1 + 4, y1 - 4);
      });
      const [xa, ya] = px(c.cpa[0][0], c.cpa[0][1]), [xb, yb] = px(c.cpa[1][0], c.cpa[1][1]);
      solid.moveTo(xa, ya); solid.lineTo(xb, yb);
    }
    ctx.strokeStyle = colors.conf; ctx.lineWidth = 1;
    ctx.setLineDash([2, 3]); ctx.stroke(dotted);
    ctx.setLineDash([]); ctx.stroke(solid);
  }

  function drawAircraft(a, status, withTrail = opts.trails) {
    const [x, y] = px(a.lat, a.lon);
    const color = status ? colors.conf : a.id === selected ? colors.sel : colors.ac;
    ctx.strokeStyle = color; ctx.fillStyle = color; ctx.lineWidth = 1.5;
    // History trail (the TRAIL button; on by default), oldest faintest, in the colour TRAIL acid set.
    const tr = withTrail ? trails.get(a.id) || [] : [];
    ctx.fillStyle = trailColors[state.trail.colour[a.id]] || color;
    tr.forEach(([lat, lon], i) => {
      const [tx, ty] = px(lat, lon);
      ctx.globalAlpha = 0.15 + 0.6 * (i / tr.length);
      ctx.fillRect(tx - 1.5, ty - 1.5, 3, 3);
    });
    ctx.globalAlpha = 1; ctx.fillStyle = color;
    // Speed vector: where the aircraft will be in vectorMin minutes on its track.
    const d = a.gs_kt * opts.vectorMin / 60 * view.ppnm, t = a.trk_deg * Math.PI / 180;
    ctx.beginPath(); ctx.moveTo(x, y); ctx.lineTo(x + d * Math.sin(t), y - d * Math.cos(t)); ctx.stroke();
    // Protected zone on demand.
    if (opts.pz && state.asas) {
      ctx.strokeStyle = status ? colors.conf : colors.pz; ctx.setLineDash([4, 4]);
      ctx.beginPath(); ctx.arc(x, y, state.asas.rpz_nm * view.ppnm, 0, 2 * Math.PI); ctx.stroke();
      ctx.setLineDash([]); ctx.strokeStyle = color;
    }
    // Symbol: a square, filled when in loss of separation.
    if (status === "los") ctx.fillRect(x - 5, y - 5, 10, 10); else ctx.strokeRect(x - 4.5, y - 4.5, 9, 9);
    if (a.id === selected) { ctx.beginPath(); ctx.arc(x, y, 10, 0, 2 * Math.PI); ctx.stroke(); }
  }

  // Dense traffic: every aircraft on the canvas a small square with its
  // speed vector, one path per colour (those in conflict or loss of
  // separation red, the latter filled), no trails; the selected one as usual.
  function drawDense(status) {
    const h = DENSE_SIZE / 2, paths = { ac: new Path2D(), conf: new Path2D(), los: new Path2D() };
    for (const a of state.aircraft) {
      if (a.id === selected) continue;
      const [x, y] = px(a.lat, a.lon);
      if (!onCanvas(x, y)) continue;
      const st = status.get(a.id), p = paths[st || "ac"];
      const d = a.gs_kt * opts.vectorMin / 60 * view.ppnm, t = a.trk_deg * Math.PI / 180;
      p.rect(x - h, y - h, DENSE_SIZE, DENSE_SIZE);
      if (d > h) { p.moveTo(x, y); p.lineTo(x + d * Math.sin(t), y - d * Math.cos(t)); }
    }
    ctx.lineWidth = 1;
    ctx.strokeStyle = colors.ac; ctx.stroke(paths.ac);
    ctx.strokeStyle = colors.conf; ctx.stroke(paths.conf); ctx.stroke(paths.los);
    ctx.fillStyle = colors.conf; ctx.fill(paths.los);
    const sel = state.aircraft.find((a) => a.id === selected);
    if (sel) drawAircraft(sel, status.get(sel.id), false);
  }

  // A placed label: dark box, text lines, and a leader line from its anchor when it sits away from it.
  // Plain labels (navdata names) have neither box nor leader line.
  function drawLabel(l, color, fonts, plain = false) {
    const [ex, ey] = nearest(l, l.ax, l.ay);
    if (!plain && Math.hypot(ex - l.ax, ey - l.ay) > 7) {
      // Conflict labels lead in their urgency colour, so the eye finds their CPA pair.
      ctx.strokeStyle = l.kind === "conflict" ? color : colors.leader; ctx.lineWidth = 1;
      ctx.globalAlpha = l.kind === "conflict" ? 0.7 : 1;
      const d = Math.hypot(ex - l.ax, ey - l.ay), sx = l.ax + (ex - l.ax) * 6 / d, sy = l.ay + (ey - l.ay) * 6 / d;
      ctx.beginPath(); ctx.moveTo(sx, sy); ctx.lineTo(ex, ey); ctx.stroke();
      ctx.globalAlpha = 1;
    }
    if (!plain) { ctx.fillStyle = "rgba(5, 9, 8, 0.8)"; ctx.fillRect(l.x, l.y, l.w, l.h); }
    ctx.fillStyle = color;
    l.text.forEach((t, i) => { ctx.font = fonts[i] || fonts[0]; ctx.fillText(t, l.x + 3, l.y + 2 + (i + 1) * LINE_H - 3); });
  }

  function draw() {
    ctx.fillStyle = colors.bg; ctx.fillRect(0, 0, W, H);
    drawGrid();
    drawGeo();
    const navPts = navPoints();
    drawNav(navPts);
    if (state) {
      const status = inConflict();
      layout(status, navPts);
      const sel = state.aircraft.find((a) => a.id === selected);
      if (sel) drawRoute(sel);
      drawConflicts();
      if (dense) drawDense(status);
      else for (const a of state.aircraft) drawAircraft(a, status.get(a.id));
      for (const l of labels) {
        if (l.kind === "block") {
          const st = status.get(l.key);
          drawLabel(l, st ? colors.conf : l.key === selected ? colors.sel : colors.ac, ["bold 12px monospace", "12px monospace"]);
        } else if (l.kind === "conflict") {
          drawLabel(l, l.color, ["bold 11px monospace"]);
        } else if (l.kind === "nav") {
          drawLabel(l, l.color, ["10px monospace"], true);
        } else {
          drawLabel(l, colors.route, ["11px monospace"]);
        }
      }
    }
    drawRbl();
    drawScale();
    document.getElementById("view-info").textContent =
      `${view.lat0.toFixed(3)}° ${view.lon0.toFixed(3)}°  ${(W / view.ppnm).toFixed(0)} NM across`;
  }

  function update(s) {
    state = s;
    for (const a of s.aircraft) {
      const tr = trails.get(a.id) || [];
      if (!tr.lastT || s.simt - tr.lastT >= s.trail.dt_s || s.simt < tr.lastT) {
        tr.push([a.lat, a.lon]); tr.lastT = s.simt;
        if (tr.length > TRAIL_LEN) tr.shift();
        trails.set(a.id, tr);
      }
    }
    const alive = new Set(s.aircraft.map((a) => a.id));
    for (const id of [...trails.keys()]) if (!alive.has(id)) { trails.delete(id); offsets.delete(id); }
    if (!view.fitted) fit();
    dirty = true;
  }

  let frameMs = 0;  // [ms] the last draw (layout included)
  function frame() {
    if (dirty) {
      dirty = false;
      const t0 = performance.now();
      draw();
      frameMs = performance.now() - t0;
      refreshNav();
    }
    requestAnimationFrame(frame);
  }

  // Pan (drag), zoom (wheel), select (click), move a data block (drag it),
  // range and bearing (right- or Shift-drag; Escape clears it).
  let drag = null;
  const blockAt = (x, y) => labels.find((l) => l.kind === "block" && x >= l.x && x <= l.x + l.w && y >= l.y && y <= l.y + l.h);
  canvas.addEventListener("contextmenu", (e) => e.preventDefault());
  canvas.addEventListener("mousedown", (e) => {
    if (e.button === 2 || e.shiftKey) {
      const p = unpx(mx(e), my(e));
      rbl = { from: p, to: p }; drag = { rbl: true, moved: false, x: mx(e), y: my(e) }; dirty = true;
      return;
    }
    const b = blockAt(mx(e), my(e));
    drag = { x: mx(e), y: my(e), moved: false, block: b ? b.key : null, dx: b ? b.x - mx(e) : 0, dy: b ? b.y - my(e) : 0 };
  });
  window.addEventListener("mouseup", (e) => {
    if (drag && drag.rbl) {
      if (!drag.moved) rbl = null;
      drag = null; dirty = true;
      return;
    }
    if (drag && !drag.moved && state && e.target === canvas) {
      let best = drag.block, bestD = 15;
      if (!best) for (const a of state.aircraft) {
        const [x, y] = px(a.lat, a.lon), d = Math.hypot(x - mx(e), y - my(e));
        if (d < bestD) { best = a.id; bestD = d; }
      }
      select(best); onSelect(best);
    }
    drag = null;
  });
  canvas.addEventListener("mousemove", (e) => {
    if (!drag) return;
    const dx = mx(e) - drag.x, dy = my(e) - drag.y;
    if (Math.abs(dx) + Math.abs(dy) > 2) drag.moved = true;
    if (!drag.moved) return;
    if (drag.rbl) { rbl.to = unpx(mx(e), my(e)); dirty = true; return; }
    if (drag.block) {
      const a = state && state.aircraft.find((p) => p.id === drag.block);
      if (a) {
        const [x, y] = px(a.lat, a.lon);
        offsets.set(a.id, [mx(e) + drag.dx - x, my(e) + drag.dy - y]);
      }
      dirty = true;
      return;
    }
    const [lat, lon] = unpx(W / 2 - dx, H / 2 - dy);
    view.lat0 = lat; view.lon0 = lon; drag.x = mx(e); drag.y = my(e); dirty = true;
  });
  canvas.addEventListener("wheel", (e) => {
    e.preventDefault();
    const [lat, lon] = unpx(mx(e), my(e));
    view.ppnm = Math.min(400, Math.max(0.05, view.ppnm * (e.deltaY < 0 ? 1.2 : 1 / 1.2)));
    const [lat2, lon2] = unpx(mx(e), my(e));
    view.lat0 += lat - lat2; view.lon0 += lon - lon2; dirty = true;
  }, { passive: false });
  window.addEventListener("resize", resize);

  function select(id) { selected = id; dirty = true; }
  function clearRbl() { rbl = null; dirty = true; }
  function toggle(name, value) { opts[name] = value; dirty = true; }
  const copy = (list) => list.map((l) => ({ ...l }));

  resize();
  requestAnimationFrame(frame);
  return {
    update, select, fit, toggle, px, clearRbl, get scale() { return K; },
    rbl: () => rbl && { ...rbl, ...rangeBearing(rbl.from, rbl.to) },
    labels: () => copy(labels), geo: () => ({ coast: geo.coast.length, fir: geo.fir.map((f) => f.name) }),
    nav: () => ({ kinds: navKinds(), airports: nav.airports.length, navaids: nav.navaids.length, fixes: nav.fixes.length }),
    zoom: (ppnm) => { view.ppnm = ppnm; dirty = true; }, symbols: () => copy(symbols), offset: (id) => offsets.get(id) || null,
    center: (lat, lon) => { view.lat0 = lat; view.lon0 = lon; dirty = true; },
    // The label budget, whether the last frame thinned labels, its draw time [ms].
    density: () => ({ budget: labelBudget(), dense, frameMs }),
    set onSelect(f) { onSelect = f; }, get selected() { return selected; },
  };
})();
