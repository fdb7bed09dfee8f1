// The radar scope: a north-up canvas of the live state (plain JavaScript, no
// dependencies). Positions are projected flat around the view centre:
// x = (lon - lon0) * 60 cos(lat0) NM, y = (lat - lat0) * 60 NM, then scaled
// by the zoom (pixels per NM). Drag pans, the wheel zooms about the cursor.
"use strict";

const Scope = (() => {
  const canvas = document.getElementById("scope");
  const ctx = canvas.getContext("2d");
  const colors = {
    bg: "#050908", grid: "#15302a", gridText: "#3f6b5c", ac: "#7cf0b0", sel: "#5ad8ff",
    conf: "#ff4d4d", warn: "#ffb347", route: "#5ad8ff", fix: "#2f4c42", apt: "#7d9c90",
    text: "#b9d8cb", pz: "#2f6f58", fixText: "#3d5f53",
  };
  const view = { lat0: 52, lon0: 4, ppnm: 8, fitted: false };
  const opts = { pz: false, fixes: true, vectorMin: 1 };
  let state = null;
  let selected = null;
  const trails = new Map();   // id -> [[lat, lon], ...] one point per state.trail.dt_s of sim time
  const TRAIL_LEN = 24;
  const trailColors = { BLUE: "#5a8cff", RED: "#ff4d4d", YELLOW: "#ffe14d" };  // TRAIL acid colour
  let nav = { airports: [], fixes: [] }, navKey = "", navPending = false;
  let onSelect = () => {};
  let dirty = true;

  const nm = (lat, lon) => [(lon - view.lon0) * 60 * Math.cos(view.lat0 * Math.PI / 180), (lat - view.lat0) * 60];
  function px(lat, lon) {
    const [x, y] = nm(lat, lon);
    return [canvas.width / 2 + x * view.ppnm, canvas.height / 2 - y * view.ppnm];
  }
  function unpx(x, y) {
    const xn = (x - canvas.width / 2) / view.ppnm, yn = -(y - canvas.height / 2) / view.ppnm;
    return [view.lat0 + yn / 60, view.lon0 + xn / (60 * Math.cos(view.lat0 * Math.PI / 180))];
  }

  function resize() {
    const r = canvas.getBoundingClientRect();
    canvas.width = Math.max(200, Math.round(r.width));
    canvas.height = Math.max(200, Math.round(r.height));
    dirty = true;
  }

  function fit() {
    if (!state || state.aircraft.length === 0) return;
    let s = 90, n = -90, w = 180, e = -180;
    for (const a of state.aircraft) {
      s = Math.min(s, a.lat); n = Math.max(n, a.lat); w = Math.min(w, a.lon); e = Math.max(e, a.lon);
    }
    view.lat0 = (s + n) / 2; view.lon0 = (w + e) / 2;
    const [wx, hy] = [(e - w) * 60 * Math.cos(view.lat0 * Math.PI / 180), (n - s) * 60];
    const span = Math.max(wx / canvas.width, hy / canvas.height, 30 / Math.min(canvas.width, canvas.height));
    view.ppnm = 1 / (span * 1.5);
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
    const [latS, lonW] = unpx(0, canvas.height), [latN, lonE] = unpx(canvas.width, 0);
    const step = niceStep((latN - latS) / 8);
    ctx.strokeStyle = colors.grid; ctx.fillStyle = colors.gridText; ctx.lineWidth = 1;
    ctx.font = "11px monospace";
    const dec = step >= 1 ? 0 : step >= 0.1 ? 1 : 2;
    for (let lat = Math.ceil(latS / step) * step; lat <= latN; lat += step) {
      const [, y] = px(lat, view.lon0);
      ctx.beginPath(); ctx.moveTo(0, y); ctx.lineTo(canvas.width, y); ctx.stroke();
      ctx.fillText(`${Math.abs(lat).toFixed(dec)}°${lat >= 0 ? "N" : "S"}`, 4, y - 3);
    }
    for (let lon = Math.ceil(lonW / step) * step; lon <= lonE; lon += step) {
      const [x] = px(view.lat0, lon);
      ctx.beginPath(); ctx.moveTo(x, 0); ctx.lineTo(x, canvas.height); ctx.stroke();
      ctx.fillText(`${Math.abs(lon).toFixed(dec)}°${lon >= 0 ? "E" : "W"}`, x + 3, canvas.height - 6);
    }
  }

  function drawScale() {
    const nmLen = niceStep(120 / view.ppnm), len = nmLen * view.ppnm;
    const x = 16, y = canvas.height - 28;
    ctx.strokeStyle = colors.text; ctx.fillStyle = colors.text; ctx.lineWidth = 2;
    ctx.beginPath(); ctx.moveTo(x, y - 5); ctx.lineTo(x, y); ctx.lineTo(x + len, y); ctx.lineTo(x + len, y - 5); ctx.stroke();
    ctx.font = "12px monospace";
    ctx.fillText(`${nmLen} NM`, x + len / 2 - 16, y - 8);
    // North arrow, top right.
    const nx = canvas.width - 24, ny = 50;
    ctx.beginPath(); ctx.moveTo(nx, ny - 18); ctx.lineTo(nx - 6, ny); ctx.lineTo(nx + 6, ny); ctx.closePath(); ctx.fill();
    ctx.fillText("N", nx - 4, ny + 14);
  }

  function drawNav() {
    if (!opts.fixes || view.ppnm < 1.5) return;
    ctx.font = "10px monospace"; ctx.lineWidth = 1;
    for (const [id, lat, lon] of nav.fixes) {
      const [x, y] = px(lat, lon);
      if (x < -10 || y < -10 || x > canvas.width + 10 || y > canvas.height + 10) continue;
      ctx.strokeStyle = colors.fix;
      ctx.beginPath(); ctx.moveTo(x, y - 3); ctx.lineTo(x - 2.6, y + 1.8); ctx.lineTo(x + 2.6, y + 1.8); ctx.closePath(); ctx.stroke();
      if (view.ppnm > 14) { ctx.fillStyle = colors.fixText; ctx.fillText(id, x + 4, y + 3); }
    }
    for (const [id, lat, lon] of nav.airports) {
      const [x, y] = px(lat, lon);
      if (x < -10 || y < -10 || x > canvas.width + 10 || y > canvas.height + 10) continue;
      ctx.strokeStyle = colors.apt; ctx.fillStyle = colors.apt;
      ctx.beginPath(); ctx.arc(x, y, 5, 0, 2 * Math.PI); ctx.stroke();
      ctx.beginPath(); ctx.moveTo(x - 7, y); ctx.lineTo(x + 7, y); ctx.stroke();
      ctx.fillText(id, x + 7, y - 5);
    }
  }

  // Fetches the navdata of the visible box when the view moved enough.
  function refreshNav() {
    if (!opts.fixes || view.ppnm < 1.5 || navPending) return;
    const [s, w] = unpx(0, canvas.height), [n, e] = unpx(canvas.width, 0);
    const key = [s, n, w, e].map((v) => v.toFixed(1)).join(",");
    if (key === navKey) return;
    navPending = true;
    fetch(`/api/navdata?south=${s}&north=${n}&west=${w}&east=${e}`).then((r) => r.json()).then((j) => {
      nav = j; navKey = key; dirty = true;
    }).catch(() => {}).finally(() => { navPending = false; });
  }

  function inConflict() {
    const m = new Map();
    for (const c of state.conflicts) for (const id of c.ids) m.set(id, "conf");
    for (const l of state.los) for (const id of l.ids) m.set(id, "los");
    return m;
  }

  function drawRoute(a) {
    if (!a.route || a.route.length === 0) return;
    let k = a.route.findIndex((w) => w.name === a.active_wpt);
    if (k < 0) return;
    ctx.strokeStyle = colors.route; ctx.fillStyle = colors.route; ctx.lineWidth = 1; ctx.setLineDash([6, 4]);
    ctx.beginPath(); ctx.moveTo(...px(a.lat, a.lon));
    for (let i = k; i < a.route.length; i++) ctx.lineTo(...px(a.route[i].lat, a.route[i].lon));
    ctx.stroke(); ctx.setLineDash([]);
    ctx.font = "11px monospace";
    for (let i = k; i < a.route.length; i++) {
      const w = a.route[i], [x, y] = px(w.lat, w.lon);
      ctx.strokeRect(x - 3, y - 3, 6, 6);
      ctx.fillText(w.name + (w.alt_ft != null ? ` ${fl(w.alt_ft)}` : ""), x + 6, y - 6);
    }
  }

  // Text on a dark box so that it stays legible over the map.
  function label(text, x, y) {
    const w = ctx.measureText(text).width;
    const fill = ctx.fillStyle;
    ctx.fillStyle = "rgba(5, 9, 8, 0.75)";
    ctx.fillRect(x - 2, y - 11, w + 4, 14);
    ctx.fillStyle = fill;
    ctx.fillText(text, x, y);
  }

  const fl = (ft) => String(Math.round(ft / 100)).padStart(3, "0");

  function drawConflicts() {
    ctx.font = "11px monospace";
    for (const c of state.conflicts) {
      const A = state.aircraft.find((a) => a.id === c.ids[0]), B = state.aircraft.find((a) => a.id === c.ids[1]);
      if (!A || !B) continue;
      ctx.strokeStyle = colors.conf; ctx.fillStyle = colors.conf; ctx.lineWidth = 1;
      // Each aircraft's path to its closest point of approach, and the CPA points.
      [A, B].forEach((a, i) => {
        const [x0, y0] = px(a.lat, a.lon), [x1, y1] = px(c.cpa[i][0], c.cpa[i][1]);
        ctx.setLineDash([2, 3]);
        ctx.beginPath(); ctx.moveTo(x0, y0); ctx.lineTo(x1, y1); ctx.stroke();
        ctx.setLineDash([]);
        ctx.beginPath(); ctx.moveTo(x1 - 4, y1 - 4); ctx.lineTo(x1 + 4, y1 + 4); ctx.moveTo(x1 - 4, y1 + 4); ctx.lineTo(x1 + 4, y1 - 4); ctx.stroke();
      });
      const [xa, ya] = px(c.cpa[0][0], c.cpa[0][1]), [xb, yb] = px(c.cpa[1][0], c.cpa[1][1]);
      ctx.beginPath(); ctx.moveTo(xa, ya); ctx.lineTo(xb, yb); ctx.stroke();
      const tlos = c.tlos_s == null ? "" : c.tlos_s > 0 ? `LoS in ${mmss(c.tlos_s)}` : "LoS";
      ctx.font = "bold 11px monospace";
      label(`${tlos}  CPA ${c.dcpa_nm.toFixed(1)} NM in ${mmss(c.tcpa_s)}`, (xa + xb) / 2 + 8, (ya + yb) / 2 + 16);
    }
  }

  const mmss = (s) => `${Math.floor(s / 60)}:${String(Math.floor(s % 60)).padStart(2, "0")}`;

  function drawAircraft(a, status) {
    const [x, y] = px(a.lat, a.lon);
    const color = status ? colors.conf : a.id === selected ? colors.sel : colors.ac;
    ctx.strokeStyle = color; ctx.fillStyle = color; ctx.lineWidth = 1.5;
    // History trail (TRAIL ON), oldest faintest, in the colour TRAIL acid set.
    const tr = state.trail.on ? trails.get(a.id) || [] : [];
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
    // Data block with leader line: callsign / FL trend selected FL / GS type.
    const bx = x + 22, by = y - 30;
    ctx.lineWidth = 1;
    ctx.beginPath(); ctx.moveTo(x + 6, y - 6); ctx.lineTo(bx - 2, by + 10); ctx.stroke();
    const trend = a.vs_fpm > 100 ? "↑" : a.vs_fpm < -100 ? "↓" : " ";
    const selfl = Math.abs(a.sel_alt_ft - a.alt_ft) > 50 ? fl(a.sel_alt_ft) : "";
    ctx.font = "bold 12px monospace";
    label(a.id, bx, by);
    ctx.font = "12px monospace";
    label(`${fl(a.alt_ft)}${trend}${selfl}`, bx, by + 13);
    label(`${Math.round(a.gs_kt)} ${a.type}`, bx, by + 26);
  }

  function draw() {
    ctx.fillStyle = colors.bg; ctx.fillRect(0, 0, canvas.width, canvas.height);
    drawGrid();
    drawNav();
    if (state) {
      const status = inConflict();
      const sel = state.aircraft.find((a) => a.id === selected);
      if (sel) drawRoute(sel);
      drawConflicts();
      for (const a of state.aircraft) drawAircraft(a, status.get(a.id));
    }
    drawScale();
    document.getElementById("view-info").textContent =
      `${view.lat0.toFixed(3)}° ${view.lon0.toFixed(3)}°  ${(canvas.width / view.ppnm).toFixed(0)} NM across`;
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
    for (const id of [...trails.keys()]) if (!s.aircraft.some((a) => a.id === id)) trails.delete(id);
    if (!view.fitted) fit();
    dirty = true;
  }

  function frame() {
    if (dirty) { dirty = false; draw(); refreshNav(); }
    requestAnimationFrame(frame);
  }

  // Pan, zoom, click to select.
  let drag = null;
  canvas.addEventListener("mousedown", (e) => { drag = { x: e.offsetX, y: e.offsetY, moved: false }; });
  window.addEventListener("mouseup", (e) => {
    if (drag && !drag.moved && state && e.target === canvas) {
      let best = null, bestD = 15;
      for (const a of state.aircraft) {
        const [x, y] = px(a.lat, a.lon), d = Math.hypot(x - e.offsetX, y - e.offsetY);
        if (d < bestD) { best = a.id; bestD = d; }
      }
      select(best); onSelect(best);
    }
    drag = null;
  });
  canvas.addEventListener("mousemove", (e) => {
    if (!drag) return;
    const dx = e.offsetX - drag.x, dy = e.offsetY - drag.y;
    if (Math.abs(dx) + Math.abs(dy) > 2) drag.moved = true;
    if (!drag.moved) return;
    const [lat, lon] = unpx(canvas.width / 2 - dx, canvas.height / 2 - dy);
    view.lat0 = lat; view.lon0 = lon; drag.x = e.offsetX; drag.y = e.offsetY; dirty = true;
  });
  canvas.addEventListener("wheel", (e) => {
    e.preventDefault();
    const [lat, lon] = unpx(e.offsetX, e.offsetY);
    view.ppnm = Math.min(400, Math.max(0.05, view.ppnm * (e.deltaY < 0 ? 1.2 : 1 / 1.2)));
    const [lat2, lon2] = unpx(e.offsetX, e.offsetY);
    view.lat0 += lat - lat2; view.lon0 += lon - lon2; dirty = true;
  }, { passive: false });
  window.addEventListener("resize", resize);

  function select(id) { selected = id; dirty = true; }
  function toggle(name, value) { opts[name] = value; dirty = true; }

  resize();
  requestAnimationFrame(frame);
  return { update, select, fit, toggle, set onSelect(f) { onSelect = f; }, get selected() { return selected; } };
})();
