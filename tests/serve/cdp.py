"""A headless Chromium driven over the DevTools protocol on a pipe.

Chromium started with --remote-debugging-pipe reads protocol messages on fd 3
and writes replies on fd 4, each a JSON object ended by a NUL byte. Only the
Python standard library is used.
"""
import json
import os
import shutil
import subprocess
import tempfile
import time


def find_chromium():
    """The Chromium binary ($SQUAWK_CHROMIUM, chromium, chromium-browser), or None."""
    for name in (os.environ.get("SQUAWK_CHROMIUM"), "chromium", "chromium-browser"):
        if name and shutil.which(name):
            return shutil.which(name)
    return None


class Browser:
    def __init__(self, binary, width=1600, height=900):
        self.profile = tempfile.mkdtemp(prefix="squawk-chromium-")
        to_chrome_r, to_chrome_w = os.pipe()
        from_chrome_r, from_chrome_w = os.pipe()
        # Child fds 3 and 4 must be exactly these pipe ends; move them above 10 first
        # so that the dup2 calls cannot overwrite one another.
        hi_r = os.dup2(to_chrome_r, 20, inheritable=True)
        hi_w = os.dup2(from_chrome_w, 21, inheritable=True)

        def wire():
            os.dup2(hi_r, 3)
            os.dup2(hi_w, 4)

        args = [binary, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                "--disable-component-update", "--disable-sync", "--no-first-run", "--disable-dev-shm-usage",
                "--remote-debugging-pipe", f"--user-data-dir={self.profile}", f"--window-size={width},{height}",
                "about:blank"]
        self.proc = subprocess.Popen(args, preexec_fn=wire, close_fds=False,
                                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        for fd in (to_chrome_r, from_chrome_w, hi_r, hi_w):
            os.close(fd)
        self.out = os.fdopen(to_chrome_w, "wb", buffering=0)
        self.inp = os.fdopen(from_chrome_r, "rb", buffering=0)
        self.buf = b""
        self.next_id = 0
        self.session = None
        self.width, self.height = width, height

    def _read_message(self):
        while b"\0" not in self.buf:
            chunk = self.inp.read(65536)
            if not chunk:
                raise RuntimeError("chromium closed the DevTools pipe")
            self.buf += chunk
        msg, self.buf = self.buf.split(b"\0", 1)
        return json.loads(msg)

    def send(self, method, params=None, session=True):
        self.next_id += 1
        msg = {"id": self.next_id, "method": method, "params": params or {}}
        if session and self.session:
            msg["sessionId"] = self.session
        self.out.write(json.dumps(msg).encode() + b"\0")
        while True:
            reply = self._read_message()
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply.get("result", {})

    def open(self, url):
        """Opens `url` in a new page, which later calls drive; returns its session (see use)."""
        target = self.send("Target.createTarget", {"url": "about:blank"}, session=False)["targetId"]
        self.session = self.send("Target.attachToTarget", {"targetId": target, "flatten": True},
                                 session=False)["sessionId"]
        self.send("Emulation.setDeviceMetricsOverride",
                  {"width": self.width, "height": self.height, "deviceScaleFactor": 1, "mobile": False})
        self.send("Page.enable")
        self.send("Page.navigate", {"url": url})
        return self.session

    def use(self, session):
        """Drives the page of `session` (from open) from now on."""
        self.session = session
        self.send("Page.bringToFront")

    def resize(self, width, height):
        """Sets the page's viewport to width x height CSS pixels."""
        self.width, self.height = width, height
        self.send("Emulation.setDeviceMetricsOverride",
                  {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})

    def eval(self, expression):
        r = self.send("Runtime.evaluate", {"expression": expression, "returnByValue": True, "awaitPromise": True})
        if "exceptionDetails" in r:
            raise RuntimeError(f"{expression}: {r['exceptionDetails']}")
        return r["result"].get("value")

    def wait_for(self, expression, timeout=20.0, what=None):
        """Polls `expression` until it is truthy; returns its value."""
        end = time.time() + timeout
        while time.time() < end:
            try:
                v = self.eval(expression)
            except RuntimeError:
                v = None
            if v:
                return v
            time.sleep(0.1)
        raise AssertionError(f"timed out after {timeout} s waiting for {what or expression}")

    def type_text(self, text):
        self.send("Input.insertText", {"text": text})

    def press_enter(self):
        for kind in ("keyDown", "keyUp"):
            self.send("Input.dispatchKeyEvent", {"type": kind, "key": "Enter", "code": "Enter",
                                                 "windowsVirtualKeyCode": 13, "text": "\r" if kind == "keyDown" else ""})

    def mouse(self, kind, x, y, button="left", modifiers=0):
        """One mouse event at page pixel (x, y): kind mousePressed, mouseMoved or mouseReleased."""
        self.send("Input.dispatchMouseEvent", {"type": kind, "x": x, "y": y, "button": button,
                                               "buttons": 0 if kind == "mouseReleased" else 1,
                                               "clickCount": 1, "modifiers": modifiers})

    def drag(self, x0, y0, x1, y1, steps=5, button="left", modifiers=0):
        """Presses at (x0, y0), moves to (x1, y1) in `steps` moves and releases."""
        self.mouse("mousePressed", x0, y0, button, modifiers)
        for i in range(1, steps + 1):
            self.mouse("mouseMoved", x0 + (x1 - x0) * i / steps, y0 + (y1 - y0) * i / steps, button, modifiers)
        self.mouse("mouseReleased", x1, y1, button, modifiers)

    def click(self, x, y, modifiers=0):
        self.mouse("mousePressed", x, y, modifiers=modifiers)
        self.mouse("mouseReleased", x, y, modifiers=modifiers)

    def screenshot(self, path):
        import base64
        data = self.send("Page.captureScreenshot", {"format": "png"})["data"]
        with open(path, "wb") as f:
            f.write(base64.b64decode(data))

    def close(self):
        try:
            self.send("Browser.close", session=False)
        except (RuntimeError, OSError):
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        shutil.rmtree(self.profile, ignore_errors=True)
