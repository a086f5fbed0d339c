"""Render scene pages (rtfgu/browser/export.py) in headless Chromium and collect what they
report: the harness of tests/test_browser.py, standard library only.

Headless Chromium runs WebGPU on its bundled SwiftShader. ``--dump-dom`` makes it exit at
the load event, which comes before the pages' asynchronous WebGPU work ends; so a small HTTP
server on 127.0.0.1 serves an index page that loads the scene pages in iframes, one after
another (PARALLEL_PAGES at a time), each with ``?report=/result/K``, and holds the index's load event (an image it answers
last) until every page has posted its result or the time is up.

    results = render_pages({"default_lambertian": html})   # name -> the page's result
    image, canvas = result_images(results["default_lambertian"])
"""
from __future__ import annotations

import base64
import json
import os
import shutil
import signal
import subprocess
import tempfile
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

import numpy as np

# What Chromium needs for WebGPU without a GPU: compute passes need the first three; a
# WebGPU canvas (and screenshots) also Vulkan through SwiftShader and ANGLE on Vulkan.
CHROMIUM_FLAGS = ("--headless=new", "--no-sandbox", "--enable-unsafe-webgpu",
                  "--enable-features=Vulkan", "--use-vulkan=swiftshader", "--use-angle=vulkan",
                  "--no-first-run", "--disable-extensions", "--mute-audio")
# ANGLE on Vulkan loads its driver through the system's Vulkan loader, which knows no
# SwiftShader: Chromium's own ICD file (next to its binary) is named to it.
SWIFTSHADER_ICD = "vk_swiftshader_icd.json"
ICD_FOLDERS = ("/usr/lib/chromium", "/usr/lib/chromium-browser", "/opt/google/chrome")
# The Debian package that provides the browser, and the names its binary goes by.
CHROMIUM_PACKAGE = "chromium"
CHROMIUM_NAMES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
INSTALL_HINT = "install the Debian package %s (`apt-get install %s`)" % (CHROMIUM_PACKAGE, CHROMIUM_PACKAGE)
# Scene pages rendering at the same time: SwiftShader already spreads one page's work over
# the cores, so more pages at once only share them.
PARALLEL_PAGES = 1


class BrowserNotFound(RuntimeError):
    """No Chromium on this machine."""


def chromium_environment(chromium: str) -> dict:
    """The environment Chromium runs in: this one, with VK_ICD_FILENAMES naming its
    SwiftShader ICD where it has one and none is named already."""
    env = dict(os.environ)
    if "VK_ICD_FILENAMES" not in env:
        folders = (os.path.dirname(os.path.realpath(chromium)),) + ICD_FOLDERS
        icd = next((os.path.join(f, SWIFTSHADER_ICD) for f in folders
                    if os.path.isfile(os.path.join(f, SWIFTSHADER_ICD))), None)
        if icd:
            env["VK_ICD_FILENAMES"] = icd
    return env


def find_chromium() -> str:
    """The path of the Chromium binary; BrowserNotFound names the package to install."""
    for name in CHROMIUM_NAMES:
        path = shutil.which(name)
        if path:
            return path
    raise BrowserNotFound("no Chromium found (looked for %s): %s" % (", ".join(CHROMIUM_NAMES), INSTALL_HINT))


INDEX = """<!DOCTYPE html>
<html><body>
<script>
// Loads the pages PARALLEL at a time: each page posts a message when it is done.
const pages = %(pages)s;
let next = 0;
function load() {
    if (next >= pages.length) return;
    const frame = document.createElement("iframe");
    frame.src = pages[next++];
    frame.width = 600;
    frame.height = 600;
    document.body.appendChild(frame);
}
window.addEventListener("message", (event) => { if (event.data && event.data.rtfguDone !== undefined) load(); });
for (let k = 0; k < %(parallel)d; k++) load();
</script>
<img src="/hold" alt="">
</body></html>
"""


class _Server(ThreadingHTTPServer):
    daemon_threads = True

    def __init__(self, pages: dict, deadline: float, parallel: int, queries: dict):
        super().__init__(("127.0.0.1", 0), _Handler)
        self.names = list(pages)
        self.pages = {"/page/%d.html" % k: html.encode("utf-8") for k, html in enumerate(pages.values())}
        self.results = {}
        self.done = threading.Condition()
        self.deadline = deadline
        urls = ["/page/%d.html?report=/result/%d" % (k, k) + ("&" + queries[name] if name in queries else "")
                for k, name in enumerate(pages)]
        self.index = (INDEX % {"pages": json.dumps(urls),
                               "parallel": parallel}).encode("utf-8")


    def handle_error(self, request, client_address):
        """Quiet about a browser that closed its connection (it does, when it exits);
        anything else as the standard library reports it."""
        import sys

        if not isinstance(sys.exc_info()[1], ConnectionError):
            super().handle_error(request, client_address)


class _Handler(BaseHTTPRequestHandler):
    server: _Server

    def log_message(self, *args):  # quiet: the results say what happened
        pass

    def _answer(self, status: int, body: bytes = b"", kind: str = "text/html; charset=utf-8"):
        self.send_response(status)
        self.send_header("Content-Type", kind)
        self.send_header("Content-Length", str(len(body)))
        self.send_header("Cache-Control", "no-store")
        self.end_headers()
        self.wfile.write(body)

    def do_GET(self):
        path = self.path.split("?")[0]
        if path == "/":
            self._answer(200, self.server.index)
        elif path in self.server.pages:
            self._answer(200, self.server.pages[path])
        elif path == "/hold":
            with self.server.done:
                self.server.done.wait_for(lambda: len(self.server.results) == len(self.server.names),
                                          timeout=max(0.0, self.server.deadline - time.monotonic()))
            self._answer(204)
        else:
            self._answer(404)

    def do_POST(self):
        parts = self.path.split("/")
        body = self.rfile.read(int(self.headers.get("Content-Length", 0)))
        if len(parts) != 3 or parts[1] != "result" or not parts[2].isdigit() \
                or int(parts[2]) >= len(self.server.names):
            self._answer(404)
            return
        try:
            result = json.loads(body)
        except ValueError as error:
            result = {"ok": False, "message": "the page posted a result that is not JSON: %s" % error}
        with self.server.done:
            self.server.results.setdefault(self.server.names[int(parts[2])], result)
            self.server.done.notify_all()
        self._answer(204)


def render_pages(pages: dict, timeout: float = 300.0, parallel: int = PARALLEL_PAGES,
                 queries: dict | None = None) -> dict:
    """Open the pages {name: HTML} in one headless Chromium and return {name: result}, the
    JSON each page posted (rtfgu/browser/export.py); ``queries`` {name: "zoom=2&gamma=1"}
    adds to a page's query string (page.js reads its controls' values from it). A page that posted nothing within
    ``timeout`` seconds of the start gets ``{"ok": False, "message": ...}`` saying so, with
    the end of Chromium's own output."""
    chromium = find_chromium()
    server = _Server(pages, time.monotonic() + timeout, parallel, queries or {})
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    profile = tempfile.mkdtemp(prefix="rtfgu-chromium-")
    log = tempfile.TemporaryFile()
    try:
        url = "http://127.0.0.1:%d/" % server.server_address[1]
        command = [chromium, *CHROMIUM_FLAGS, "--user-data-dir=" + profile, "--dump-dom", url]
        process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=log, start_new_session=True,
                                   env=chromium_environment(chromium))
        try:
            process.wait(timeout=timeout + 30)
        except subprocess.TimeoutExpired:
            pass
        finally:
            try:
                os.killpg(process.pid, signal.SIGKILL)   # Chromium and the processes it started
            except ProcessLookupError:
                pass   # all gone already
            process.wait()
    finally:
        server.shutdown()
        server.server_close()
        shutil.rmtree(profile, ignore_errors=True)
    log.seek(0)
    # Without a desktop session Chromium complains of D-Bus at every start: not the news.
    output = [line for line in log.read().decode("utf-8", "replace").strip().splitlines()
              if "dbus" not in line.lower()]
    log.close()
    results = dict(server.results)
    if time.monotonic() < server.deadline:
        why = "Chromium exited (code %s) before the page reported a result" % process.returncode
    else:
        why = "the page reported no result within %.0f s" % timeout
    for name in pages:
        if name not in results:
            results[name] = {"ok": False, "message": "%s: %s; Chromium's output ended with:\n%s"
                             % (name, why, "\n".join(output[-15:]))}
    return results


def result_images(result: dict):
    """(the mean image, (height, width, 3) float32 as rtfgu.render returns it; the canvas,
    (height, width, 3) uint8) of a page's result; a failed page's message as a RuntimeError."""
    if not result.get("ok"):
        raise RuntimeError(result.get("message", "the page failed without a message"))
    height, width = result["height"], result["width"]
    sums = np.frombuffer(base64.b64decode(result["sums"]), dtype=np.float32).reshape(height, width, 4)
    canvas = np.frombuffer(base64.b64decode(result["canvas"]), dtype=np.uint8).reshape(height, width, 4)
    return sums[:, :, :3] / np.float32(result["samples"]), canvas[:, :, :3]
