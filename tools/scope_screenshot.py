#!/usr/bin/env python3
"""A screenshot of the radar scope: starts `squawk serve`, lets the traffic
fly, selects an aircraft, and captures the page in headless Chromium.

usage: tools/scope_screenshot.py SQUAWK OUT.png [--scenario FILE] [--serve-args "..."]
       [--settle SECONDS] [--select ACID] [--pz] [--command TEXT] [--size WxH]
       [--query "legend=0"] [--hold]
--scenario "" starts serve without a scenario (as `serve --agent` wants);
--hold stops the clock (!HOLD) just before the capture.
The README's docs/scope.png comes from:
  tools/scope_screenshot.py build/squawk docs/scope.png --scenario scenarios/scope_demo.scn \
      --serve-args "--speed 10 --navdata ../shared/bluesky/navdata" --settle 9 --select KLM1234 \
      --command "BAW8CK turn right heading 060"
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "serve"))
from cdp import Browser, find_chromium  # noqa: E402
from test_scope_browser import start_server  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("squawk")
    ap.add_argument("out")
    ap.add_argument("--scenario", default="scenarios/scope_demo.scn")
    ap.add_argument("--serve-args", default="--speed 10")
    ap.add_argument("--settle", type=float, default=8.0)
    ap.add_argument("--select")
    ap.add_argument("--pz", action="store_true")
    ap.add_argument("--command")
    ap.add_argument("--size", default="1600x900", help="window WIDTHxHEIGHT in CSS pixels")
    ap.add_argument("--query", default="", help="page query, e.g. legend=0")
    ap.add_argument("--hold", action="store_true")
    # "--serve-args --paused" would read as two options: the value always goes with the flag.
    argv = sys.argv[1:]
    for i, a in enumerate(argv[:-1]):
        if a == "--serve-args":
            argv[i:i + 2] = [f"--serve-args={argv[i + 1]}"]
            break
    args = ap.parse_args(argv)
    width, height = (int(v) for v in args.size.lower().split("x"))
    chromium = find_chromium()
    if not chromium:
        sys.exit("no chromium on PATH (apt install chromium)")
    server, addr = start_server(args.squawk, args.scenario, args.serve_args.split())
    browser = Browser(chromium, width, height)
    try:
        browser.open(f"http://{addr}/" + (f"?{args.query}" if args.query else ""))
        browser.wait_for("document.querySelectorAll('#traffic tbody tr').length > 0", what="traffic")
        if args.command:
            browser.eval("document.getElementById('cmd').focus()")
            browser.type_text(args.command)
            browser.press_enter()
        time.sleep(args.settle)
        if args.select:
            browser.eval(f"document.querySelector('#traffic tr[data-id=\"{args.select}\"]').click()")
        if args.pz:
            browser.eval("document.getElementById('toggle-pz').click()")
        if args.hold:
            browser.eval("fetch('/api/command', {method: 'POST', headers: {'Content-Type': 'application/json'}, "
                         "body: JSON.stringify({text: '!HOLD'})})")
        time.sleep(0.5)
        browser.screenshot(args.out)
        print(f"wrote {args.out}")
    finally:
        browser.close()
        server.terminate()
        server.wait(timeout=10)


if __name__ == "__main__":
    main()
