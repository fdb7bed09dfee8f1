// The scope's panels: the push stream of state, the clock and its controls,
// the traffic list, the command line, the AI teammate's advisories and the
// log. Everything goes through the HTTP API documented in README.md.
"use strict";

(() => {
  const $ = (id) => document.getElementById(id);
  let state = null;
  // This page's dialogue with the translator: a question asked here is answered only from here.
  const client = (crypto.randomUUID ? crypto.randomUUID() : String(Math.random()).slice(2)).slice(0, 36);

  async function post(path, body) {
    const r = await fetch(path, { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body) });
    return r.json();
  }
  const esc = (s) => String(s).replace(/[&<>"]/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;" })[c]);
  const hms = (t) => [t / 3600, (t % 3600) / 60, t % 60].map((v) => String(Math.floor(v)).padStart(2, "0")).join(":");
  const fl = (ft) => String(Math.round(ft / 100)).padStart(3, "0");
  const mmss = (t) => `${Math.floor(t / 60)}:${String(Math.floor(t % 60)).padStart(2, "0")}`;
  const h3 = (d) => String(Math.round(d) % 360 || 360).padStart(3, "0");

  // --- Push stream (server-sent events) ------------------------------------
  function connect() {
    const es = new EventSource("/api/stream");
    es.onopen = () => $("link").classList.add("live");
    es.onmessage = (e) => render(JSON.parse(e.data));
    es.onerror = () => $("link").classList.remove("live");  // EventSource reconnects by itself
  }

  function render(s) {
    state = s;
    Scope.update(s);
    $("simt").textContent = hms(s.simt);
    $("runstate").textContent = s.fast ? "FAST-FORWARD" : s.running ? `RUN x${s.dtmult}` : "HOLD";
    $("asas").textContent = s.asas.on ? `ASAS ON ${s.asas.rpz_nm} NM / ${s.asas.dtlook_s} s${s.asas.reso ? " MVP" : ""}` : "ASAS OFF";
    if (document.activeElement !== $("speed")) {
      const v = String(s.dtmult);
      if (![...$("speed").options].some((o) => o.value === v)) $("speed").add(new Option(`x${v}`, v));
      $("speed").value = v;
    }
    renderTraffic(s);
    renderSelected(s);
    renderConflicts(s);
    renderAdvisories(s);
    renderLog(s);
  }

  // The traffic list: every aircraft up to MAX_ROWS; beyond that the
  // selected one, those in conflict, then the others in the order of the
  // state, MAX_ROWS in all, and a last row saying how many are not listed.
  const MAX_ROWS = 200;
  function renderTraffic(s) {
    const conf = new Set();
    for (const c of s.conflicts) [c.own, c.intruder].forEach((id) => conf.add(id));
    for (const c of s.los) [c.own, c.intruder].forEach((id) => conf.add(id));
    let list = s.aircraft;
    if (list.length > MAX_ROWS) {
      const rank = (a) => (a.id === Scope.selected ? 2 : 0) + (conf.has(a.id) ? 1 : 0);
      list = list.filter((a) => rank(a) > 0).sort((p, q) => rank(q) - rank(p))
        .concat(list.filter((a) => rank(a) === 0)).slice(0, MAX_ROWS);
    }
    const rows = list.map((a) => {
      const trend = a.vs_fpm > 100 ? "↑" : a.vs_fpm < -100 ? "↓" : "";
      const spd = a.sel_cas_kt != null ? Math.round(a.sel_cas_kt) : `M${a.sel_mach.toFixed(2)}`;
      const cls = [a.id === Scope.selected ? "selected" : "", conf.has(a.id) ? "conflict" : ""].join(" ");
      return `<tr data-id="${esc(a.id)}" class="${cls}"><td>${esc(a.id)}</td><td class="type">${esc(a.type)}</td>` +
        `<td class="fl">${fl(a.alt_ft)}${trend}</td><td class="sel">${fl(a.sel_alt_ft)}</td>` +
        `<td class="hdg">${h3(a.hdg_deg)}</td><td class="sel sel-hdg">${a.lnav ? "LNAV" : h3(a.sel_hdg_deg)}</td>` +
        `<td class="cas">${Math.round(a.cas_kt)}</td><td class="sel">${spd}</td><td class="gs">${Math.round(a.gs_kt)}</td>` +
        `<td class="wpt">${esc(a.active_wpt || "")}</td></tr>`;
    });
    if (list.length < s.aircraft.length)
      rows.push(`<tr class="more"><td colspan="10">and ${s.aircraft.length - list.length} more (select one on the scope)</td></tr>`);
    $("traffic").tBodies[0].innerHTML = rows.join("");
  }

  // The selected aircraft's data and route.
  function renderSelected(s) {
    const a = s.aircraft.find((p) => p.id === Scope.selected);
    $("selected-pane").style.display = a ? "" : "none";
    if (!a) return;
    const trend = a.vs_fpm > 100 ? ` climbing ${Math.round(a.vs_fpm)} fpm` : a.vs_fpm < -100 ? ` descending ${Math.round(-a.vs_fpm)} fpm` : " level";
    const to = (now, sel, text) => (Math.abs(now - sel) > 1 ? ` → ${text}` : "");
    const spd = a.sel_cas_kt != null ? to(a.cas_kt, a.sel_cas_kt, `${Math.round(a.sel_cas_kt)} kt`) : ` → M${a.sel_mach.toFixed(2)}`;
    const hdg = a.lnav ? " → LNAV" : Math.abs(((a.sel_hdg_deg - a.hdg_deg + 540) % 360) - 180) > 1 ? ` → ${h3(a.sel_hdg_deg)}` : "";
    const k = a.route.findIndex((w) => w.name === a.active_wpt);
    const route = a.route.map((w, i) => `<span class="${i === k ? "active" : i < k ? "passed" : ""}">${esc(w.name)}` +
      `${w.alt_ft != null ? " " + fl(w.alt_ft) : ""}</span>`).join(" ");
    $("selected-data").innerHTML =
      `<div><b>${esc(a.id)}</b> ${esc(a.type)}  ${a.lat.toFixed(3)}° ${a.lon.toFixed(3)}°</div>` +
      `<div>FL ${fl(a.alt_ft)}${trend}${to(a.alt_ft, a.sel_alt_ft, "FL " + fl(a.sel_alt_ft))}</div>` +
      `<div>HDG ${h3(a.hdg_deg)}${hdg}  CAS ${Math.round(a.cas_kt)} kt${spd}  GS ${Math.round(a.gs_kt)} kt</div>` +
      `<div>route ${route || "none"}${a.route.length ? (a.lnav ? " (LNAV on)" : " (LNAV off)") : ""}</div>`;
  }

  // Standing alerts: losses of separation first, then the conflicts by time
  // to loss of separation; class urgent (LoS in 60 s or less), soon (120 s),
  // later (beyond).
  function renderConflicts(s) {
    const items = s.los.map((l) =>
      `<li class="los" data-ids="${esc(l.own + " " + l.intruder)}"><b>${esc(l.own + " – " + l.intruder)}</b> LOSS OF SEPARATION ` +
      `${l.dist_nm.toFixed(1)} NM ${Math.round(Math.abs(l.dalt_ft))} ft</li>`);
    const when = (c) => c.tlos_s != null ? c.tlos_s : c.tcpa_s, lost = new Set(s.los.map((l) => l.own + "," + l.intruder));
    for (const c of s.conflicts.slice().sort((p, q) => when(p) - when(q))) {
      if (lost.has(c.own + "," + c.intruder)) continue;
      const t = when(c);
      const cls = t <= 60 ? "urgent" : t <= 120 ? "soon" : "later";
      items.push(`<li class="${cls}" data-ids="${esc(c.own + " " + c.intruder)}"><b>${esc(c.own + " – " + c.intruder)}</b> ` +
        `LoS ${t > 0 ? "in " + mmss(t) : "now"}  CPA ${c.dcpa_nm.toFixed(1)} NM ${c.tcpa_s > 0 ? "in " + mmss(c.tcpa_s) : "passed"}</li>`);
    }
    const cap = s.conflict_cap ? `<li class="cap">${esc(s.conflict_cap)}</li>` : "";
    $("conflicts").innerHTML = cap + (items.length ? items.join("") : `<li class="none">none</li>`);
    $("conflict-count").textContent = items.length ? String(items.length) : "";
  }

  let advKey = "";
  function renderAdvisories(s) {
    $("advisory-pane").style.display = s.teammate ? "" : "none";
    $("auto").checked = s.auto;
    const key = JSON.stringify(s.advisories);
    if (key === advKey) return;  // keep the buttons stable between pushes
    advKey = key;
    const items = s.advisories.slice().reverse().map((a) => {
      const decided = a.status === "pending"
        ? `<button class="accept" data-id="${a.id}" data-decision="accept">ACCEPT</button> ` +
          `<button class="reject" data-id="${a.id}" data-decision="reject">REJECT</button>`
        : `${esc(a.status)}${a.decided_by ? " by " + esc(a.decided_by) : ""}${a.outcome ? ": " + esc(a.outcome) : ""}`;
      return `<li class="${esc(a.status)}"><div class="meta">#${a.id} at ${hms(a.simt)}</div>` +
        `<div class="text">${esc(a.text)}</div><div class="meta">${decided}</div></li>`;
    });
    $("advisories").innerHTML = items.length ? items.join("") : `<li class="none">no advisories</li>`;
  }

  let logSeq = 0;
  function renderLog(s) {
    const last = s.log.length ? s.log[s.log.length - 1].seq : 0;
    if (last === logSeq) return;
    logSeq = last;
    $("log").innerHTML = s.log.slice().reverse().map((e) =>
      `<li><span class="who who-${esc(e.who)}">${hms(e.simt)} ${esc(e.who)}</span> ${esc(e.text)}</li>`).join("");
  }

  // --- Command line ----------------------------------------------------------
  async function send(text) {
    $("reply").classList.remove("empty");
    $("reply-typed").textContent = text;
    $("reply-commands").textContent = "…";
    $("reply-result").textContent = "";
    let r;
    const body = { text, client };
    if (Scope.selected && !text.startsWith("!")) body.selected = Scope.selected;
    try {
      r = await post("/api/command", body);
    } catch (e) {
      r = { ok: false, message: String(e), commands: [] };
    }
    $("reply-commands").textContent = (r.commands || []).join(" ; ") || "—";
    $("reply-typed").textContent = r.addressed ? `${text}  (to ${r.addressed}, selected)` : text;
    const res = $("reply-result");
    if (r.ask) { res.className = "ask"; res.textContent = "? " + r.ask; }
    else { res.className = r.ok ? "ok" : "err"; res.textContent = r.ok ? (r.message || "ok") : r.message; }
    $("reply-trace").textContent = r.trace || "(TrafScript as typed: no translation)";
    return r;
  }

  $("cmdline").addEventListener("submit", (e) => {
    e.preventDefault();
    const text = $("cmd").value.trim();
    if (!text) return;
    $("cmd").value = "";
    send(text);
  });

  // --- Controls ---------------------------------------------------------------
  document.querySelectorAll("[data-cmd]").forEach((b) => b.addEventListener("click", () => send(b.dataset.cmd)));
  $("speed").addEventListener("change", () => send(`!DTMULT ${$("speed").value}`));
  $("fit").addEventListener("click", () => Scope.fit());
  const toggles = { "toggle-pz": "pz", "toggle-fixes": "fixes", "toggle-geo": "geo", "toggle-trails": "trails" };
  for (const [id, opt] of Object.entries(toggles))
    $(id).addEventListener("click", () => { const on = $(id).classList.toggle("on"); Scope.toggle(opt, on); });
  const vectors = [0, 1, 2, 5];
  $("toggle-vectors").addEventListener("click", () => {
    const b = $("toggle-vectors"), i = (vectors.indexOf(Number(b.dataset.min || 1)) + 1) % vectors.length;
    b.dataset.min = vectors[i]; b.textContent = `VEC ${vectors[i]}`; b.classList.toggle("on", vectors[i] > 0);
    Scope.toggle("vectorMin", vectors[i]);
  });
  // Selecting an aircraft (scope or list) puts its callsign at the head of
  // the command line, replacing a callsign already there.
  function selected(id) {
    Scope.select(id);
    if (id) {
      const cmd = $("cmd"), words = cmd.value.trimStart().split(/\s+/);
      const known = state && state.aircraft.some((a) => a.id === (words[0] || "").toUpperCase());
      cmd.value = `${id} ${known ? words.slice(1).join(" ") : cmd.value.trim()}`.trimEnd() + " ";
    }
    if (state) { renderTraffic(state); renderSelected(state); }
    focusCmd();
  }
  $("traffic").addEventListener("click", (e) => {
    const tr = e.target.closest("tr[data-id]");
    if (tr) selected(Scope.selected === tr.dataset.id ? null : tr.dataset.id);
  });
  $("conflicts").addEventListener("click", (e) => {
    const li = e.target.closest("li[data-ids]");
    if (li) selected(li.dataset.ids.split(" ")[0]);
  });
  Scope.onSelect = selected;

  // Keyboard focus lives in the command line: after a click anywhere but a
  // form control, and when a key is typed elsewhere. Escape clears the line,
  // then the range/bearing line and the selection.
  function focusCmd() {
    const cmd = $("cmd");
    if (document.activeElement !== cmd) { cmd.focus(); cmd.setSelectionRange(cmd.value.length, cmd.value.length); }
  }
  document.addEventListener("mouseup", (e) => {
    if (!e.target.closest("input, select, textarea, summary, #reply, #log")) setTimeout(focusCmd, 0);
  });
  document.addEventListener("keydown", (e) => {
    const t = document.activeElement;
    if (e.key === "Escape") {
      if ($("cmd").value) $("cmd").value = "";
      else { Scope.clearRbl(); selected(null); }
      focusCmd();
      return;
    }
    if (t !== $("cmd") && !(t && t.matches("input, select, textarea")) && e.key.length === 1 && !e.ctrlKey && !e.metaKey) focusCmd();
  });
  // The legend: open until closed (at first closed below 1280 px, where it
  // would hide much of the scope); the choice is remembered (?legend=0|1 overrides).
  function showLegend(on) {
    $("legend").classList.toggle("hidden", !on);
    $("toggle-legend").classList.toggle("on", on);
    Scope.toggle("legend", on);  // labels keep clear of it
    try { localStorage.setItem("squawk.legend", on ? "1" : "0"); } catch (e) { /* private mode */ }
  }
  const legendParam = new URLSearchParams(location.search).get("legend");
  let legendStored = null;
  try { legendStored = localStorage.getItem("squawk.legend"); } catch (e) { /* private mode */ }
  showLegend((legendParam ?? legendStored ?? (window.innerWidth < 1280 ? "0" : "1")) !== "0");
  $("legend-close").addEventListener("click", () => showLegend(false));
  $("toggle-legend").addEventListener("click", () => showLegend($("legend").classList.contains("hidden")));
  $("advisories").addEventListener("click", async (e) => {
    const b = e.target.closest("button[data-decision]");
    if (!b) return;
    b.disabled = true;
    const r = await post("/api/advisory", { id: Number(b.dataset.id), decision: b.dataset.decision });
    if (!r.ok) alert(r.message);
  });
  $("auto").addEventListener("change", () => post("/api/auto", { on: $("auto").checked }));

  // ?capture=1: one state from GET /api/state and no push stream, so that a
  // headless browser's --screenshot finds the page idle and returns.
  if (new URLSearchParams(location.search).get("capture") === "1") {
    fetch("/api/state").then((r) => r.json()).then((s) => { render(s); document.body.dataset.captured = "1"; });
  } else {
    connect();
  }
  focusCmd();
})();
