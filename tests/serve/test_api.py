"""`squawk serve`'s HTTP API without a browser: state shape, commands
(English, !TrafScript, errors), clock control, request limits, several push
streams at once with one client that never reads, and the AI teammate's
advisories with accept / reject and automatic execution.

usage: test_api.py SQUAWK_BINARY
"""
import json
import re
import os
import socket
import sys
import time
import urllib.error
import urllib.request

sys.path.insert(0, os.path.dirname(__file__))
from test_scope_browser import start_server  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
CROSSING = os.path.join(HERE, "..", "data", "serve", "crossing.scn")
failures = 0


def check(cond, what):
    global failures
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures += 1


def request(addr, path, body=None, content_type="application/json", raw=None):
    data = raw if raw is not None else (json.dumps(body).encode() if body is not None else None)
    req = urllib.request.Request(f"http://{addr}{path}", data=data, method="POST" if data is not None else "GET")
    if data is not None:
        req.add_header("Content-Type", content_type)
    try:
        with urllib.request.urlopen(req, timeout=30) as r:
            return r.status, json.load(r)
    except urllib.error.HTTPError as e:
        text = e.read()
        return e.code, json.loads(text) if text.startswith(b"{") else {}


def command(addr, text):
    return request(addr, "/api/command", {"text": text})[1]


def state(addr):
    return request(addr, "/api/state")[1]


def aircraft(addr, acid):
    return next(a for a in state(addr)["aircraft"] if a["id"] == acid)


def stream_events(addr, seconds):
    """Counts `data:` events on /api/stream for `seconds`."""
    s = socket.create_connection(tuple(addr.rsplit(":", 1)), timeout=5)
    s.sendall(b"GET /api/stream HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n")
    buf, end = b"", time.time() + seconds
    while time.time() < end:
        buf += s.recv(1 << 20)
    s.close()
    return buf.count(b"data: {")


def test_plain(squawk):
    server, addr = start_server(squawk, CROSSING, ["--speed", "1"])
    try:
        s = state(addr)
        check({"simt", "aircraft", "conflicts", "los", "log", "advisories"} <= set(s), "state has simt, aircraft, conflicts")
        a = aircraft(addr, "KL204")
        keys = {"id", "type", "lat", "lon", "alt_ft", "hdg_deg", "cas_kt", "gs_kt", "vs_fpm", "sel_hdg_deg",
                "sel_alt_ft", "sel_cas_kt", "route", "active_wpt"}
        check(keys <= set(a), f"aircraft fields {sorted(keys - set(a)) or 'complete'}")
        time.sleep(1.5)
        check(state(addr)["simt"] >= 1.0, "the clock runs in real time from the start")
        c = state(addr)["conflicts"]
        check(len(c) == 1 and [c[0]["own"], c[0]["intruder"]] == ["AF123", "KL204"] and c[0]["tlos_s"] > 0 and c[0]["dcpa_nm"] < 0.5
              and len(c[0]["cpa"]) == 2, f"one conflict AF123-KL204 with tlos, dcpa, cpa: {c}")

        r = command(addr, "KL204 climb to flight level 300")
        check(r["ok"] and r["commands"] == ["ALT KL204 FL300"], f"English -> {r.get('commands')}")
        check(aircraft(addr, "KL204")["sel_alt_ft"] == 30000, "selected altitude in the state after the command")
        r = command(addr, "!SPD KL204 250")
        check(r["ok"] and r["commands"] == ["SPD KL204 250"], "!TrafScript runs as typed")
        check(abs(aircraft(addr, "KL204")["sel_cas_kt"] - 250) < 1e-6, "selected speed 250 kt")
        r = command(addr, "!ALT KL204 FL9X")
        check(not r["ok"] and "FL9X" in r["message"], f"bad TrafScript names the culprit: {r['message']!r}")
        r = command(addr, "climb to flight level 300")
        check(r.get("ask") and not r["ok"], f"missing callsign -> a question: {r.get('ask')!r}")
        r = command(addr, "cancel")
        check(r.get("cancelled") is True, "cancel drops the question")

        check(command(addr, "!HOLD")["ok"], "HOLD")
        t1 = state(addr)["simt"]
        time.sleep(0.6)
        check(state(addr)["simt"] == t1 and not state(addr)["running"], f"clock stops on HOLD (t={t1})")
        command(addr, "!FF 120")
        time.sleep(1.0)
        t2 = state(addr)["simt"]
        check(t2 >= t1 + 119.9, f"FF 120 ran two minutes at once ({t1} -> {t2})")
        # FF 10^9 s must not hold the simulation's thread: it runs in slices,
        # the server keeps answering, and HOLD stops it where it is.
        r = command(addr, "!FF 1e9")
        check(r["ok"] and "fast-forwarding" in r["message"] and "HOLD stops it" in r["message"],
              f"FF 1e9 runs in slices: {r['message']!r}")
        time.sleep(0.5)
        check(state(addr)["simt"] > t2 + 120, "the long FF goes on between requests")
        check(command(addr, "!HOLD")["ok"], "HOLD during a long FF")
        t2 = state(addr)["simt"]
        time.sleep(0.6)
        check(state(addr)["simt"] == t2 and not state(addr)["running"], f"HOLD ended the long FF at t={t2}")
        command(addr, "!OP")
        command(addr, "!DTMULT 4")
        t3 = state(addr)["simt"]
        time.sleep(1.0)
        t4 = state(addr)["simt"]
        check(2.0 <= t4 - t3 <= 8.0, f"OP x4: {t4 - t3:.2f} s of sim time in 1 s of wall clock")

        code, r = request(addr, "/api/command", raw=b"x" * 100_000)
        check(code == 413, f"a 100 kB body is refused (HTTP {code})")
        code, r = request(addr, "/api/command", {"text": "KL204 climb"}, content_type="text/plain")
        check(code == 400 and "application/json" in r["message"], f"non-JSON content type refused (HTTP {code})")
        code, r = request(addr, "/api/command", raw=b"{not json")
        check(code == 400, f"malformed JSON refused (HTTP {code})")
        code, r = request(addr, "/api/command", {"text": "a" * 5000})
        check(code == 413, f"5000-character command refused (HTTP {code})")
        code, r = request(addr, "/api/advisory", {"id": 1, "decision": "accept"})
        check(code == 409 and "no advisory" in r["message"], f"unknown advisory (HTTP {code})")
        code, r = request(addr, "/api/command", {"text": "KL204 climb", "client": 5})
        check(code == 400 and '"client"' in r["message"], f"a client that is not a string is refused (HTTP {code})")
        code, r = request(addr, "/api/command", {"text": "KL204 climb", "selected": "x" * 65})
        check(code == 400 and '"selected"' in r["message"], f"a 65-character selection is refused (HTTP {code})")
        with urllib.request.urlopen(f"http://{addr}/api/geo?south=50&north=55&west=0&east=8&step=0.01", timeout=5) as g:
            geo = json.load(g)
        check(geo == {"coast": [], "fir": [], "truncated": False}, f"no navdata: GET /api/geo is empty: {geo}")
        try:
            urllib.request.urlopen(f"http://{addr}/api/geo?step=abc", timeout=5)
            check(False, "GET /api/geo?step=abc refused")
        except urllib.error.HTTPError as e:
            check(e.code == 400, f"GET /api/geo?step=abc refused (HTTP {e.code})")

        s_ = socket.create_connection(tuple(addr.rsplit(":", 1)), timeout=5)
        s_.sendall(b"GET /api/state HTTP/1.1\r\nHost: evil.example:80\r\nConnection: close\r\n\r\n")
        head = s_.recv(4096).split(b"\r\n", 1)[0]
        s_.close()
        check(b" 403 " in head, f"a request for another host name is refused: {head!r}")

        # Request bytes that are not UTF-8, quoted in the error message, must
        # not kill the server (they are written as U+FFFD).
        for raw, want in [(b"GET /api/%FF HTTP/1.1\r\nHost: 127.0.0.1\r\n", b" 404 "),
                          (b"GET /api/navdata?south=%FF HTTP/1.1\r\nHost: 127.0.0.1\r\n", b" 400 "),
                          (b"GET /api/state HTTP/1.1\r\nHost: \xff\xfe\r\n", b" 403 ")]:
            s_ = socket.create_connection(tuple(addr.rsplit(":", 1)), timeout=5)
            s_.sendall(raw + b"Connection: close\r\n\r\n")
            reply = b""
            while chunk := s_.recv(4096):  # Connection: close -> read to the end
                reply += chunk
            s_.close()
            status = reply.split(b"\r\n", 1)[0]
            check(want in status and b"\xef\xbf\xbd" in reply,
                  f"non-UTF-8 request {raw[:30]!r} -> {status!r}, culprit as U+FFFD")
        check(state(addr)["simt"] > 0, "the server still answers after non-UTF-8 requests")

        import subprocess
        p = subprocess.run([squawk, "serve", "--port", addr.rsplit(":", 1)[1]], capture_output=True, text=True,
                           timeout=30)
        check(p.returncode == 1 and "in use" in p.stderr, f"a second server on the same port is refused: {p.stderr!r}")

        # A client that opens a stream and never reads must not stall the
        # simulation or the other streams.
        stalled = socket.create_connection(tuple(addr.rsplit(":", 1)))
        stalled.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
        stalled.sendall(b"GET /api/stream HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n")
        t5 = state(addr)["simt"]
        n = stream_events(addr, 2.0)
        t6 = state(addr)["simt"]
        check(n >= 10, f"a second stream gets {n} events in 2 s (>= 5 Hz)")
        check(t6 - t5 >= 4.0, f"the clock kept running beside a stalled client ({t6 - t5:.1f} s sim in 2 s)")
        stalled.close()
    finally:
        server.terminate()
        check(server.wait(timeout=10) == 0, "squawk serve exits 0 on SIGTERM")


def test_teammate(squawk):
    server, addr = start_server(squawk, "", ["--agent", "--speed", "50"])
    try:
        deadline = time.time() + 20
        adv = []
        while time.time() < deadline and not any(a["status"] == "pending" for a in adv):
            adv = state(addr)["advisories"]
            time.sleep(0.05)
        pending = [a for a in adv if a["status"] == "pending"]
        check(len(pending) == 1 and pending[0]["text"].startswith("KL001, "), f"an advisory for KL001: {pending}")
        command(addr, "!HOLD")  # decide at leisure
        fleet = state(addr)["aircraft"]
        check(all(re.fullmatch(r"[A-Z]{2,3}[0-9][0-9A-Z]{1,3}", a["id"]) for a in fleet) and len({a["type"] for a in fleet}) > 2
              and all(abs(a["alt_ft"] - 24000) < 50 for a in fleet),
              "the teammate's traffic has airline callsigns, several types, FL240: "
              + ", ".join(f"{a['id']} {a['type']} {a['alt_ft']:.0f} ft" for a in fleet))
        a = next(a for a in state(addr)["advisories"] if a["status"] == "pending")
        code, r = request(addr, "/api/advisory", {"id": a["id"], "decision": "reject"})
        check(code == 200 and r["status"] == "rejected", f"reject -> {r}")
        s = state(addr)
        check(any(e["who"] == "controller" and e["text"] == f"rejected advisory {a['id']}" for e in s["log"]),
              "the log records the controller's rejection")
        code, r = request(addr, "/api/advisory", {"id": a["id"], "decision": "accept"})
        check(code == 409, "a decided advisory cannot be decided again")

        # Catch the next advisory while it is pending (HOLD stops the clock, so
        # it cannot expire while being decided); a few tries on a loaded machine.
        b, last = None, a["id"]
        for _ in range(5):
            command(addr, "!OP")  # real time (DTMULT 1, as BlueSky's OP): the speed again after it
            command(addr, "!DTMULT 50")
            deadline = time.time() + 20
            cand = None
            while time.time() < deadline and not cand:
                cand = next((x for x in state(addr)["advisories"] if x["status"] == "pending" and x["id"] > last), None)
                time.sleep(0.02)
            command(addr, "!HOLD")
            if not cand:
                break
            last = cand["id"]
            cand = next((x for x in state(addr)["advisories"] if x["id"] == cand["id"]), None)
            if cand and cand["status"] == "pending":
                b = cand
                break
        if b:
            code, r = request(addr, "/api/advisory", {"id": b["id"], "decision": "accept"})
            hdg = int(b["text"].split("heading ")[1][:3])
            sel = aircraft(addr, "KL001")["sel_hdg_deg"]
            check(code == 200 and r["outcome"].startswith("HDG KL001") and abs(sel - hdg) < 1e-6,
                  f"accept runs the advisory through the translator: {r['outcome']}, selected {sel}")
        else:
            check(False, "a second advisory to accept")

        request(addr, "/api/auto", {"on": True})
        command(addr, "!OP")
        command(addr, "!DTMULT 50")
        deadline = time.time() + 20
        auto = []
        while time.time() < deadline and not auto:
            auto = [x for x in state(addr)["advisories"] if x["decided_by"] == "auto"]
            time.sleep(0.05)
        check(bool(auto) and auto[0]["status"] == "accepted", f"automatic mode executes advisories: {auto[:1]}")
        s = state(addr)
        texts = [x["text"] for x in s["advisories"]]
        advice = [re.sub(r", \d+ miles", "", t) for t in texts]  # the distance changes as time goes by
        check(all(p != q for p, q in zip(advice, advice[1:])), f"no advisory offered twice in a row unchanged: {texts}")
        miles = [int(m) for m in re.findall(r"o'clock, (\d+) miles", " ".join(texts))]
        check(all(m <= 15 for m in miles), f"traffic information within 15 miles: {miles}")
        who = {e["who"] for e in s["log"]}
        check({"controller", "auto", "teammate"} <= who and
              any(e["text"].startswith("accepted advisory") for e in s["log"]) and
              any(e["text"] == "automatic execution of advisories on" for e in s["log"]),
              f"accept, reject and automatic mode stay in the log: {sorted(who)}")
    finally:
        server.terminate()
        check(server.wait(timeout=10) == 0, "squawk serve --agent exits 0 on SIGTERM")


def test_usage(squawk):
    import subprocess
    for args, rc, text in [(["--port", "70000"], 2, "expected a port number"),
                           (["--speed", "0"], 2, "expected a multiple of real time"),
                           (["--auto"], 2, "go with --agent"),
                           (["no-such.scn"], 1, "no scenario file 'no-such.scn'"),
                           (["--host", "999.1.1.1", "--port", "0"], 1, "cannot listen on 999.1.1.1"),
                           (["--web", "/no/such/dir", "--port", "0"], 1, "web folder '/no/such/dir' does not exist")]:
        p = subprocess.run([squawk, "serve", *args], capture_output=True, text=True, timeout=30)
        check(p.returncode == rc and text in p.stderr, f"serve {' '.join(args)} -> exit {p.returncode}, {p.stderr.strip()!r}")


def raw_status(port, host_header, body=None):
    s_ = socket.create_connection(("127.0.0.1", port), timeout=5)
    if body is None:
        req = b"GET /api/state HTTP/1.1\r\nHost: " + host_header + b"\r\nConnection: close\r\n\r\n"
    else:
        req = (b"POST /api/advisory HTTP/1.1\r\nHost: " + host_header + b"\r\nContent-Type: application/json\r\n"
               b"Content-Length: " + str(len(body)).encode() + b"\r\nConnection: close\r\n\r\n" + body)
    s_.sendall(req)
    head = s_.recv(4096).split(b"\r\n", 1)[0]
    s_.close()
    return head


def test_host_any_address(squawk):
    """Issue 52: the Host check holds whatever --host is (0.0.0.0 included);
    --allow-host adds names; advisory ids outside int range are refused."""
    server, addr = start_server(squawk, CROSSING, ["--host", "0.0.0.0", "--allow-host", "squawk.lan,10.0.0.7"])
    try:
        port = int(addr.rsplit(":", 1)[1])
        for host, want in [(b"evil.example", b" 403 "), (b"evil.example:%d" % port, b" 403 "),
                           (b"127.0.0.1:%d" % port, b" 200 "), (b"localhost", b" 200 "),
                           (b"Squawk.LAN:%d" % port, b" 200 "), (b"10.0.0.7", b" 200 "), (b"10.0.0.8", b" 403 ")]:
            head = raw_status(port, host)
            check(want in head, f"--host 0.0.0.0, Host {host!r}: {head!r}")
        for bad in [b'{"id": 4294967297, "decision": "accept"}', b'{"id": -1, "decision": "accept"}',
                    b'{"id": 18446744073709551615, "decision": "accept"}']:
            head = raw_status(port, b"127.0.0.1", bad)
            check(b" 400 " in head, f"advisory {bad!r} refused: {head!r}")
    finally:
        server.terminate()
        server.wait(timeout=10)


def test_conflict_cap(squawk):
    """Issue 52: conflict detection at its pair cap says so in the state (the
    scope lists it above the conflicts), naming the cap and the flag; the
    event log says it too once time runs."""
    converging = os.path.join(HERE, "converging.scn")
    server, addr = start_server(squawk, converging, ["--paused", "--max-conflict-pairs", "5"])
    try:
        s = state(addr)
        check(len(s["conflicts"]) == 5 and "cap of 5 stored pairs" in s["conflict_cap"]
              and "--max-conflict-pairs" in s["conflict_cap"], f"capped state: {s['conflict_cap']!r}")
        command(addr, "!OP")
        time.sleep(2.5)
        log = [e["text"] for e in state(addr)["log"]]
        check(any("cap of 5 stored pairs" in t for t in log), f"capped, the log says so: {log[-3:]}")
    finally:
        server.terminate()
        server.wait(timeout=10)
    server, addr = start_server(squawk, converging, ["--paused"])
    try:
        s = state(addr)
        check(len(s["conflicts"]) == 19 and s["conflict_cap"] == "", f"under the cap: {s['conflict_cap']!r}")
    finally:
        server.terminate()
        server.wait(timeout=10)


def main():
    squawk = sys.argv[1]
    test_usage(squawk)
    test_host_any_address(squawk)
    test_conflict_cap(squawk)
    test_plain(squawk)
    test_teammate(squawk)
    print(f"{failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
