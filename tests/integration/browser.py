#!/usr/bin/env python3
"""Drives one headless Chromium page over the DevTools protocol (--remote-debugging-pipe),
for tests that need a page kept open while things change.

Usage: browser.py URL PROFILE_DIR, then commands on standard input, one per line:
  eval EXPRESSION   prints the JSON value of the expression in the page
  shot PATH         saves a PNG screenshot of the page, prints "ok"
  quit
Prints "ready" once the page has loaded. Errors go to standard error, exit 1.
"""
import base64, fcntl, json, os, subprocess, sys

def main():
    url, profile = sys.argv[1], sys.argv[2]
    to_chrome_r, to_chrome_w = os.pipe()
    from_chrome_r, from_chrome_w = os.pipe()

    # The child's ends, first moved above 4 so that putting them at 3 and 4 clobbers
    # nothing; dup2 makes them inheritable.
    child_read = fcntl.fcntl(to_chrome_r, fcntl.F_DUPFD_CLOEXEC, 10)
    child_write = fcntl.fcntl(from_chrome_w, fcntl.F_DUPFD_CLOEXEC, 10)
    os.close(to_chrome_r)
    os.close(from_chrome_w)

    def pipes_at_3_and_4():
        os.dup2(child_read, 3)
        os.dup2(child_write, 4)

    chrome = subprocess.Popen(
        ["chromium", "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
         "--remote-debugging-pipe", f"--user-data-dir={profile}", "about:blank"],
        preexec_fn=pipes_at_3_and_4, close_fds=False,
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(child_read)
    os.close(child_write)
    out = os.fdopen(to_chrome_w, "wb")
    incoming = os.fdopen(from_chrome_r, "rb")
    state = {"id": 0, "buffer": b""}

    def receive():
        while b"\0" not in state["buffer"]:
            chunk = incoming.read1(65536)
            if not chunk:
                raise SystemExit("chromium closed the pipe")
            state["buffer"] += chunk
        message, state["buffer"] = state["buffer"].split(b"\0", 1)
        return json.loads(message)

    def call(method, params=None, session=None):
        state["id"] += 1
        message = {"id": state["id"], "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        out.write(json.dumps(message).encode() + b"\0")
        out.flush()
        while True:
            reply = receive()
            if reply.get("id") == state["id"]:
                if "error" in reply:
                    raise SystemExit(f"{method}: {reply['error']}")
                return reply.get("result", {})

    try:
        target = call("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        call("Emulation.setDeviceMetricsOverride",
             {"width": 800, "height": 500, "deviceScaleFactor": 1, "mobile": False}, session)
        call("Page.enable", {}, session)
        call("Page.navigate", {"url": url}, session)
        # Loaded: the page's script ran once the document is complete.
        while True:
            ready = call("Runtime.evaluate",
                         {"expression": "document.readyState", "returnByValue": True}, session)
            if ready["result"].get("value") == "complete":
                break
        print("ready", flush=True)
        for line in sys.stdin:
            command, _, argument = line.rstrip("\n").partition(" ")
            if command == "eval":
                value = call("Runtime.evaluate",
                             {"expression": argument, "returnByValue": True}, session)
                print(json.dumps(value["result"].get("value")), flush=True)
            elif command == "shot":
                data = call("Page.captureScreenshot", {"format": "png"}, session)["data"]
                with open(argument, "wb") as f:
                    f.write(base64.b64decode(data))
                print("ok", flush=True)
            elif command == "quit":
                break
    finally:
        chrome.kill()
        chrome.wait()

main()
