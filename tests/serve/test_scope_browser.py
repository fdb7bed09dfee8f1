"""The radar scope in a real browser: headless Chromium loads the page served
by `squawk serve`, sees the aircraft in the traffic list, types an English
command into the command line and sees the heading change (list and API);
in a dense converging scene started paused the predicted conflicts are
listed at t = 0 by time to loss of separation and coloured by urgency, and
once it runs no two labels of the page's label model
intersect and none lies on a symbol, and a dragged data block keeps its
offset; a click on an aircraft selects it, fills the command line and a
line without a callsign goes to it, right-drag measures range and bearing;
two pages at once keep their own dialogues; 5 000 aircraft over the globe:
at world zoom the labels are thinned to the scope's budget and the traffic
list is capped, zoomed in every aircraft has its data block again.

usage: test_scope_browser.py SQUAWK_BINARY [--screenshot FILE.png] [--scenario FILE]
Exit 77 (skipped) only when no Chromium is installed.
"""
import argparse
import json
import math
import shutil
import os
import random
import subprocess
import sys
import tempfile
import time
import urllib.request

sys.path.insert(0, os.path.dirname(__file__))
from cdp import Browser, find_chromium  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def start_server(squawk, scenario, extra=()):
    proc = subprocess.Popen([squawk, "serve", *([scenario] if scenario else []), "--port", "0", *extra],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    line = proc.stdout.readline()
    if "http://" not in line:
        proc.kill()
        raise AssertionError(f"squawk serve did not start: {line!r} {proc.stdout.read()}")
    return proc, line.split("http://", 1)[1].split("/", 1)[0]


def get_state(addr):
    with urllib.request.urlopen(f"http://{addr}/api/state", timeout=5) as r:
        return json.load(r)


def post(addr, path, body):
    req = urllib.request.Request(f"http://{addr}{path}", data=json.dumps(body).encode(),
                                 headers={"Content-Type": "application/json"})
    with urllib.request.urlopen(req, timeout=30) as r:
        return json.load(r)


def intersect(a, b):
    return a["x"] < b["x"] + b["w"] and b["x"] < a["x"] + a["w"] and a["y"] < b["y"] + b["h"] and b["y"] < a["y"] + a["h"]


def overprints(labels, symbols):
    """Every pair (label, label) or (label, symbol) of the label model that intersects."""
    bad = []
    for i, a in enumerate(labels):
        bad += [(a["key"], b["key"]) for b in labels[i + 1:] if intersect(a, b)]
        bad += [(a["key"], "symbol " + s["key"]) for s in symbols if intersect(a, s)]
    return bad


def check_labels(browser, squawk):
    """A dense converging scene: labels never overprint; conflict labels name their pair; drag keeps an offset."""
    scn = os.path.join(HERE, "converging.scn")
    server, addr = start_server(squawk, scn, ["--speed", "10", "--paused"])
    try:
        browser.open(f"http://{addr}/")
        # Alerts at t = 0 with the clock held: the predicted conflicts, sorted
        # by time to loss of separation, each coloured by urgency.
        rows = browser.wait_for("[...document.querySelectorAll('#conflicts li[data-ids]')]"
                                ".map(li => [li.dataset.ids, li.className, li.textContent])", what="conflict alerts at t = 0")
        state = get_state(addr)
        assert state["simt"] == 0 and not state["running"], state["simt"]
        assert len(rows) == len(state["conflicts"]) >= 10, (len(rows), len(state["conflicts"]))
        los = [l["own"] + " " + l["intruder"] for l in state["los"]]
        assert los == ["KLM88A KLM88B"], los  # in trail 2 NM apart: a loss of separation from the start
        assert [ids for ids, cls, _ in rows[:len(los)]] == los and rows[0][1] == "los", rows[0]
        rows = rows[len(los):]
        tlos = {c["own"] + " " + c["intruder"]: c["tlos_s"] for c in state["conflicts"]}
        shown = [tlos[ids] for ids, _, _ in rows]
        assert shown == sorted(shown), shown
        for ids, cls, text in rows:
            t = tlos[ids]
            assert cls == ("urgent" if t <= 60 else "soon" if t <= 120 else "later"), (ids, t, cls)
            assert text.startswith(ids.replace(" ", " – ")), text
        print(f"ok   t = 0, clock held: {len(rows)} predicted conflicts listed, sorted by tLOS "
              f"({shown[0]:.0f} s .. {shown[-1]:.0f} s), coloured by urgency")
        post(addr, "/api/command", {"text": "!OP"})  # real time (DTMULT 1, as BlueSky's OP); then x10
        post(addr, "/api/command", {"text": "!DTMULT 10"})
        browser.wait_for("Scope.labels().filter(l => l.kind === 'conflict').length >= 6", what="six conflict labels")
        for _ in range(5):  # several frames of a moving scene
            labels, symbols = browser.eval("[Scope.labels(), Scope.symbols()]")
            bad = overprints(labels, symbols)
            assert not bad, f"overprinted labels: {bad}"
            time.sleep(0.2)
        blocks = [l for l in labels if l["kind"] == "block"]
        conflicts = [l for l in labels if l["kind"] == "conflict"]
        assert len(blocks) == 12, [l["key"] for l in blocks]
        for c in conflicts:
            a, b = c["key"].split("-")
            assert c["text"][0].startswith(f"{a}–{b} "), c["text"]
        print(f"ok   {len(blocks)} data blocks, {len(conflicts)} conflict labels (each naming its pair), "
              f"{len(symbols)} symbols: no overlap in 5 frames")
        # The clock is held for the drag (a push while dragging would move the aircraft under the
        # mouse: on a loaded machine the drag spans pushes), then runs on.
        post(addr, "/api/command", {"text": "!HOLD"})
        time.sleep(0.5)
        r = browser.eval("(() => { const c = document.getElementById('scope').getBoundingClientRect(); "
                         "const b = Scope.labels().find(l => l.key === 'KLM88A'); "
                         "const k = Scope.scale; return [c.left + (b.x + b.w / 2) * k, c.top + (b.y + b.h / 2) * k, b.x - b.ax, b.y - b.ay]; })()")
        x, y, dx0, dy0 = r
        browser.drag(x, y, x + 60, y + 45)  # at 1600 px the scale is 1: page px = canvas px
        off = browser.wait_for("Scope.offset('KLM88A')", what="a dragged offset")
        assert abs(off[0] - (dx0 + 60)) < 2 and abs(off[1] - (dy0 + 45)) < 2, (off, dx0, dy0)
        post(addr, "/api/command", {"text": "!OP"})
        post(addr, "/api/command", {"text": "!DTMULT 10"})
        time.sleep(0.5)  # the aircraft moves on; the block keeps its offset from it
        b = browser.eval("Scope.labels().find(l => l.key === 'KLM88A')")
        assert abs(b["x"] - b["ax"] - off[0]) < 0.01 and abs(b["y"] - b["ay"] - off[1]) < 0.01, (b, off)
        labels = browser.eval("Scope.labels()")
        others = [l["key"] for l in labels if l["key"] != "KLM88A" and intersect(l, b)]
        assert not others, f"labels over the dragged block: {others}"
        print(f"ok   dragged KLM88A's data block keeps its offset ({off[0]:.0f}, {off[1]:.0f}) px; no label over it")
    finally:
        server.terminate()
        server.wait(timeout=10)


def canvas_point(browser, lat, lon):
    """Page pixel of (lat, lon) on the scope."""
    return browser.eval(f"(() => {{ const c = document.getElementById('scope').getBoundingClientRect(); "
                        f"const [x, y] = Scope.px({lat}, {lon}); return [c.left + x * Scope.scale, c.top + y * Scope.scale]; }})()")


def great_circle(a, b):
    """(bearing [deg], distance [NM]) from a to b, (lat, lon) in degrees."""
    p1, l1, p2, l2 = map(math.radians, (*a, *b))
    brg = math.degrees(math.atan2(math.sin(l2 - l1) * math.cos(p2),
                                  math.cos(p1) * math.sin(p2) - math.sin(p1) * math.cos(p2) * math.cos(l2 - l1)))
    h = math.sin((p2 - p1) / 2) ** 2 + math.cos(p1) * math.cos(p2) * math.sin((l2 - l1) / 2) ** 2
    return brg % 360, 2 * math.asin(math.sqrt(h)) * 6371000 / 1852


def check_workflow(browser, squawk, scenario):
    """Click an aircraft: selected, callsign in the command line, focus kept there; a line without a
    callsign goes to it; its data are shown; right-drag measures range and bearing."""
    server, addr = start_server(squawk, scenario, ["--paused"])
    try:
        browser.open(f"http://{addr}/")
        browser.wait_for("document.querySelectorAll('#traffic tbody tr').length === 3", what="three aircraft")
        ac = {a["id"]: a for a in get_state(addr)["aircraft"]}
        x, y = canvas_point(browser, ac["KL204"]["lat"], ac["KL204"]["lon"])
        browser.click(x, y)
        browser.wait_for("Scope.selected === 'KL204'", what="KL204 selected by a click on its symbol")
        assert browser.eval("document.getElementById('cmd').value") == "KL204 "
        browser.wait_for("document.activeElement.id === 'cmd'", what="focus in the command line")
        shown = browser.wait_for("document.getElementById('selected-pane').style.display !== 'none' && "
                                 "document.getElementById('selected-data').textContent", what="the selected aircraft's data")
        assert "KL204" in shown and "B744" in shown and "FL 200" in shown, shown
        print(f"ok   a click on KL204 selects it, puts 'KL204 ' in the command line (focused) and shows {shown[:40]!r}...")
        browser.type_text("turn right heading 120")
        browser.press_enter()
        said = browser.wait_for("document.getElementById('reply-commands').textContent.includes('HDG') && "
                                "document.getElementById('reply-commands').textContent", what="HDG KL204 120")
        assert said == "HDG KL204 120 RIGHT", said
        browser.type_text("climb to flight level 250")
        browser.press_enter()
        said = browser.wait_for("document.getElementById('reply-commands').textContent.includes('ALT') && "
                                "document.getElementById('reply-commands').textContent", what="ALT KL204 FL250")
        assert said == "ALT KL204 FL250", said
        typed = browser.eval("document.getElementById('reply-typed').textContent")
        assert "(to KL204, selected)" in typed, typed
        print(f"ok   a line without a callsign goes to the selected aircraft: {said!r}, shown as {typed!r}")
        a, b = ac["KL204"], ac["BAW31"]
        (x0, y0), (x1, y1) = canvas_point(browser, a["lat"], a["lon"]), canvas_point(browser, b["lat"], b["lon"])
        browser.drag(x0, y0, x1, y1, button="right")
        r = browser.wait_for("Scope.rbl()", what="a range/bearing line")
        brg, nm = great_circle((a["lat"], a["lon"]), (b["lat"], b["lon"]))
        assert abs(r["nm"] - nm) < 0.02 * nm + 0.2 and abs((r["brg"] - brg + 180) % 360 - 180) < 1.5, (r, brg, nm)
        browser.wait_for("document.activeElement.id === 'cmd'", timeout=2, what="focus back in the command line")
        print(f"ok   right-drag KL204 -> BAW31: {r['brg']:03.0f}° {r['nm']:.1f} NM (expected {brg:03.0f}° {nm:.1f} NM); "
              "focus stays in the command line")
    finally:
        server.terminate()
        server.wait(timeout=10)


def say(browser, text, what):
    """Types `text` + Enter into the page's command line; waits for the reply; returns (result class, text)."""
    browser.eval("document.getElementById('reply-result').textContent = ''; document.getElementById('cmd').value = ''")
    browser.eval("document.getElementById('cmd').focus()")
    browser.type_text(text)
    browser.press_enter()
    browser.wait_for("document.getElementById('reply-result').textContent", what=what)
    return browser.eval("[document.getElementById('reply-result').className, "
                        "document.getElementById('reply-result').textContent, "
                        "document.getElementById('reply-commands').textContent]")


def check_two_clients(browser, squawk, scenario):
    """Two pages at once: a question raised on one is answered only by that page's next line."""
    server, addr = start_server(squawk, scenario, ["--paused"])
    try:
        pages = [browser.open(f"http://{addr}/"), browser.open(f"http://{addr}/")]
        for p in pages:
            browser.use(p)
            browser.wait_for("document.querySelectorAll('#traffic tbody tr').length === 3", what="three aircraft")
        browser.use(pages[0])
        cls, text, _ = say(browser, "KL204 descend", "page 1's question")
        assert cls == "ask" and "KL204" in text, (cls, text)
        browser.use(pages[1])
        cls, text, cmds = say(browser, "flight level 100", "page 2's reply")
        assert cls != "ok" and "KL204" not in text and "ALT" not in cmds, (cls, text, cmds)
        sel = next(a for a in get_state(addr)["aircraft"] if a["id"] == "KL204")["sel_alt_ft"]
        assert abs(sel - 20000) < 1, sel
        browser.use(pages[0])
        cls, text, cmds = say(browser, "flight level 100", "page 1's answer")
        assert cls == "ok" and cmds == "ALT KL204 FL100", (cls, text, cmds)
        sel = next(a for a in get_state(addr)["aircraft"] if a["id"] == "KL204")["sel_alt_ft"]
        assert abs(sel - 10000) < 1, sel
        print("ok   two pages: page 1 asks about 'KL204 descend', page 2's 'flight level 100' is not its answer, "
              "page 1's is: ALT KL204 FL100")
    finally:
        server.terminate()
        server.wait(timeout=10)


def world_scenario(path, n, seed=1):
    """n aircraft at FL300-390 (ASAS ON): nine tenths in three boxes (Europe, the eastern US, eastern
    China), the rest uniform over the sphere up to 78 degrees of latitude."""
    rng = random.Random(seed)
    boxes = [(44, 56, -5, 20), (30, 45, -95, -70), (22, 40, 105, 122)]
    with open(path, "w") as f:
        f.write("00:00:00.00>ASAS ON\n")
        for i in range(n):
            if i % 10:
                s, no, w, e = boxes[i % 3]
                lat, lon = rng.uniform(s, no), rng.uniform(w, e)
            else:
                lat, lon = math.degrees(math.asin(rng.uniform(-0.98, 0.98))), rng.uniform(-180, 180)
            f.write(f"00:00:00.00>CRE W{i:05d} A320 {lat:.4f} {lon:.4f} {rng.uniform(0, 360):.0f} "
                    f"FL{rng.randrange(300, 400, 10)} 280\n")


def check_dense(browser, squawk):
    """5 000 aircraft: at world zoom at most the budget of labels, none overprinting, small symbols, the traffic
    list capped at 200 rows; zoomed in on a lone aircraft every aircraft in view has its data block."""
    tmp = tempfile.mkdtemp(prefix="squawk-dense-")
    scn = os.path.join(tmp, "world.scn")
    world_scenario(scn, 5000)
    server, addr = start_server(squawk, scn, ["--paused"])
    try:
        browser.open(f"http://{addr}/")
        browser.wait_for("Scope.symbols().filter(s => s.kind === 'aircraft').length > 4000", timeout=60,
                         what="the aircraft of the whole world")
        d = browser.eval("Scope.density()")
        labels, symbols = browser.eval("[Scope.labels(), Scope.symbols()]")
        blocks = [l for l in labels if l["kind"] == "block"]
        shown = [s for s in symbols if s["kind"] == "aircraft"]
        assert d["dense"] and 0 < len(blocks) and len(labels) <= d["budget"], (d, len(blocks), len(labels))
        assert all(s["w"] <= 8 for s in shown), "dense symbols are small"
        bad = overprints(labels, symbols)
        assert not bad, f"overprinted labels at world zoom: {bad[:5]}"
        rows = browser.eval("document.querySelectorAll('#traffic tbody tr[data-id]').length")
        more = browser.eval("document.querySelector('#traffic tr.more').textContent")
        assert rows == 200 and "4800 more" in more, (rows, more)
        print(f"ok   5000 aircraft at world zoom: {len(shown)} symbols, {len(labels)} labels (budget {d['budget']}), "
              f"no overprint; traffic list 200 rows + {more!r}; draw {d['frameMs']:.0f} ms")
        lone = next(a for a in get_state(addr)["aircraft"] if a["id"] == "W00010")  # one of the uniform tenth
        browser.eval(f"Scope.center({lone['lat']}, {lone['lon']}); Scope.zoom(1)")
        browser.wait_for("!Scope.density().dense", what="a view that is not dense")
        labels, symbols = browser.eval("[Scope.labels(), Scope.symbols()]")
        inview = sorted(s["key"] for s in symbols if s["kind"] == "aircraft")
        blocks = sorted(l["key"] for l in labels if l["kind"] == "block")
        assert "W00010" in inview and blocks == inview, (inview, blocks)
        bad = overprints(labels, symbols)
        assert not bad, bad
        print(f"ok   zoomed in on W00010 (1 px/NM): {len(inview)} aircraft in view, each with its data block")
    finally:
        server.terminate()
        server.wait(timeout=10)
        shutil.rmtree(tmp, ignore_errors=True)


NAVDATA = os.path.join(HERE, "..", "..", "..", "shared", "bluesky", "navdata")


def check_geography(browser, squawk):
    """With navdata: coastlines and FIR borders drawn, navdata by zoom, a legend that closes and reopens."""
    if not os.path.exists(os.path.join(NAVDATA, "coastlines.dat")):
        print(f"skip geography: {NAVDATA} absent")
        return
    scn = os.path.join(HERE, "..", "..", "scenarios", "scope_demo.scn")
    server, addr = start_server(squawk, scn, ["--paused", "--navdata", NAVDATA])
    try:
        browser.open(f"http://{addr}/")
        geo = browser.wait_for("Scope.geo().coast > 0 && Scope.geo()", what="coastlines")
        assert "EHAA" in geo["fir"], geo["fir"]
        nav = browser.wait_for("Scope.nav().navaids > 0 && Scope.nav()", what="navaids at the fitted zoom")
        assert nav["kinds"] == ["airports", "navaids"] and nav["airports"] > 0, nav
        # Labels are placed a bounded number per frame: wait for the frame that has the names.
        labels, symbols = browser.wait_for(
            "Scope.labels().some(l => l.kind === 'nav') && [Scope.labels(), Scope.symbols()]",
            what="navdata names placed")
        names = [l for l in labels if l["kind"] == "nav"]
        assert not overprints(labels, symbols), overprints(labels, symbols)
        print(f"ok   navdata: {geo['coast']} coastlines, FIR {', '.join(geo['fir'])}; {nav['airports']} airports, "
              f"{nav['navaids']} navaids; {len(names)} names placed without overlap")
        browser.eval("Scope.zoom(0.5)")
        nav = browser.wait_for("Scope.nav().navaids === 0 && Scope.nav().airports > 0 && Scope.nav()", what="airports only")
        assert nav["kinds"] == ["airports"], nav
        browser.eval("Scope.zoom(20)")
        nav = browser.wait_for("Scope.nav().fixes > 0 && Scope.nav()", what="fixes zoomed in")
        print(f"ok   by zoom: 0.5 px/NM airports only; 20 px/NM {nav['fixes']} fixes too")
        assert browser.eval("!document.getElementById('legend').classList.contains('hidden')")
        rows = browser.eval("document.querySelectorAll('#legend dd').length")
        assert rows >= 15, rows
        browser.eval("document.getElementById('legend-close').click()")
        assert browser.eval("document.getElementById('legend').classList.contains('hidden')")
        browser.eval("document.getElementById('toggle-legend').click()")
        assert browser.eval("!document.getElementById('legend').classList.contains('hidden')")
        print(f"ok   legend of {rows} entries open, closed with ×, reopened with LEGEND")
    finally:
        server.terminate()
        server.wait(timeout=10)


def check_layout_and_capture(browser, squawk, chromium, scenario):
    """1024 px to 4K and 420 px keep scope, clock and panels apart; trails on by default; ?capture=1
    lets a plain `chromium --headless --screenshot` (with --virtual-time-budget) return."""
    server, addr = start_server(squawk, scenario, ["--speed", "10"])
    try:
        browser.open(f"http://{addr}/")
        browser.wait_for("document.querySelectorAll('#traffic tbody tr').length === 3", what="three aircraft")
        boxes = """(() => { const r = (e) => { const b = e.getBoundingClientRect(); return {x: b.left, y: b.top, w: b.width, h: b.height}; };
            return {canvas: r(document.getElementById('scope')), side: r(document.getElementById('side')),
                    simt: r(document.getElementById('simt')), cmd: r(document.getElementById('cmd')),
                    buttons: [...document.querySelectorAll('#clock button, #clock select, #scope-tools button')].map(r)}; })()"""
        for w, h in ((1024, 700), (3840, 2160), (420, 800)):
            browser.resize(w, h)
            time.sleep(0.3)
            b = browser.eval(boxes)
            assert b["canvas"]["w"] >= min(380, w - 40) and b["canvas"]["h"] >= 300, (w, b["canvas"])
            assert all(not intersect(b["simt"], x) for x in b["buttons"]), (w, "a button over the clock")
            assert b["cmd"]["w"] >= 200 and b["side"]["w"] >= min(360, w - 40), (w, b["cmd"], b["side"])
            if w >= 1024:
                assert not intersect(b["canvas"], b["side"]), (w, "scope and side panel overlap")
            print(f"ok   {w}x{h}: scope {b['canvas']['w']:.0f}x{b['canvas']['h']:.0f}, side panel "
                  f"{b['side']['w']:.0f} px wide, clock clear of the buttons")
        browser.resize(1600, 900)
        trail = browser.wait_for("document.getElementById('toggle-trails').classList.contains('on')", what="TRAIL on")
        assert trail
        print("ok   trails on by default (TRAIL button lit)")
    finally:
        server.terminate()
        server.wait(timeout=10)
    server, addr = start_server(squawk, scenario, ["--speed", "10"])
    out = os.path.join(tempfile.mkdtemp(prefix="squawk-capture-"), "scope.png")
    try:
        t0 = time.time()
        r = subprocess.run([chromium, "--headless", "--no-sandbox", "--disable-gpu", "--window-size=1600,900",
                            "--virtual-time-budget=3000", f"--screenshot={out}", f"http://{addr}/?capture=1"],
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=90)
        size = os.path.getsize(out) if os.path.exists(out) else 0
        assert r.returncode == 0 and size > 20000, (r.returncode, size)
        print(f"ok   chromium --headless --screenshot of ?capture=1 returned in {time.time() - t0:.1f} s ({size} bytes)")
    finally:
        shutil.rmtree(os.path.dirname(out), ignore_errors=True)
        server.terminate()
        server.wait(timeout=10)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("squawk")
    ap.add_argument("--scenario", default=os.path.join(HERE, "..", "data", "serve", "crossing.scn"))
    ap.add_argument("--screenshot")
    ap.add_argument("--settle", type=float, default=0.0, help="seconds to let the scene run before the screenshot")
    ap.add_argument("--serve-args", default="--speed 10")
    args = ap.parse_args()
    chromium = find_chromium()
    if not chromium:
        print("SKIP: no chromium on PATH (tools/setup installs Debian's chromium)")
        return 77

    server, addr = start_server(args.squawk, args.scenario, args.serve_args.split())
    browser = Browser(chromium)
    try:
        browser.open(f"http://{addr}/")
        rows = browser.wait_for("[...document.querySelectorAll('#traffic tbody tr')].map(r => r.dataset.id)",
                                what="aircraft rows in the traffic list")
        assert {"KL204", "AF123"} <= set(rows), rows
        print(f"ok   traffic list shows {rows}")
        hdg_cell = "document.querySelector('#traffic tr[data-id=\"KL204\"] td.hdg').textContent"
        before = int(browser.eval(hdg_cell))
        assert 80 <= before <= 100, before
        browser.wait_for("document.querySelector('#link').classList.contains('live')", what="the push stream")
        print(f"ok   push stream live; KL204 heading {before:03d}")

        browser.eval("document.getElementById('cmd').focus()")
        browser.type_text("KL204 turn left heading 270")
        browser.press_enter()
        said = browser.wait_for("document.getElementById('reply-commands').textContent.includes('HDG') && "
                                "document.getElementById('reply-commands').textContent", what="the TrafScript shown")
        assert said == "HDG KL204 270 LEFT", said  # the turn direction said is kept (HDG ... LEFT)
        assert browser.eval("document.getElementById('reply-typed').textContent") == "KL204 turn left heading 270"
        assert browser.eval("document.getElementById('reply-result').className") == "ok"
        print(f"ok   typed English became {said!r}")

        sel = browser.wait_for(f"document.querySelector('#traffic tr[data-id=\"KL204\"] td.sel-hdg').textContent === '270'",
                               what="selected heading 270 in the list")
        api = next(a for a in get_state(addr)["aircraft"] if a["id"] == "KL204")
        assert abs(api["sel_hdg_deg"] - 270) < 1e-6, api
        # The aircraft turns left through north (x10 real time: about 6 s of
        # wall clock) and settles on 270, in the list and in the API.
        browser.wait_for(f"{hdg_cell} === '270'", timeout=40, what="KL204 flying heading 270 in the list")
        end = time.time() + 10
        while abs(next(a for a in get_state(addr)["aircraft"] if a["id"] == "KL204")["hdg_deg"] - 270) > 0.5:
            assert time.time() < end, "GET /api/state: KL204 not on heading 270"
            time.sleep(0.1)
        print(f"ok   KL204 heading {before:03d} -> 270 in the list and in GET /api/state")

        browser.eval("document.querySelector('#traffic tr[data-id=\"BAW31\"]').click()")
        browser.wait_for("document.querySelector('#traffic tr.selected')?.dataset.id === 'BAW31'", what="row selection")
        print("ok   clicking a row selects the aircraft")
        if args.screenshot:
            time.sleep(args.settle)
            browser.screenshot(args.screenshot)
            print(f"screenshot {args.screenshot}")
        check_labels(browser, args.squawk)
        check_workflow(browser, args.squawk, args.scenario)
        check_two_clients(browser, args.squawk, args.scenario)
        check_dense(browser, args.squawk)
        check_geography(browser, args.squawk)
        check_layout_and_capture(browser, args.squawk, chromium, args.scenario)
    finally:
        browser.close()
        server.terminate()
        rc = server.wait(timeout=10)
    assert rc == 0, f"squawk serve exited {rc} on SIGTERM"
    print("ok   squawk serve stops cleanly on SIGTERM")
    return 0


if __name__ == "__main__":
    sys.exit(main())
