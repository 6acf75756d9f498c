#!/usr/bin/env python3
"""Time `durer lsp` from an edit to its diagnostics, on a scene of your choice.

usage: scripts/lsp-latency.py SCENE [--durer PATH] [--runs N]

Starts `durer lsp` on standard input/output, opens SCENE (its text as an unsaved buffer),
then N times: changes the text (alternately breaking its last line with an undefined name
and restoring it) and measures the time until the matching textDocument/publishDiagnostics
arrives. The time includes the server's 150 ms debounce. Prints each time and the median.
Standard library only.
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def send(proc, message):
    body = json.dumps(message).encode()
    proc.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
    proc.stdin.flush()


def receive(proc):
    length = 0
    while True:
        line = proc.stdout.readline()
        if not line:
            raise SystemExit("durer lsp closed its output")
        line = line.strip()
        if not line:
            break
        if line.lower().startswith(b"content-length:"):
            length = int(line.split(b":")[1])
    return json.loads(proc.stdout.read(length))


def wait_diagnostics(proc, uri, want_error):
    while True:
        message = receive(proc)
        if message.get("method") != "textDocument/publishDiagnostics":
            continue
        params = message["params"]
        if params["uri"] != uri:
            continue
        has_error = any(d.get("severity") == 1 for d in params["diagnostics"])
        if has_error == want_error:
            return params["diagnostics"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("scene")
    parser.add_argument("--durer", default=os.path.join(REPO, "target", "release", "durer"))
    parser.add_argument("--runs", type=int, default=6)
    args = parser.parse_args()
    path = os.path.abspath(args.scene)
    text = open(path, encoding="utf-8", errors="replace").read()
    uri = "file://" + path
    proc = subprocess.Popen([args.durer, "lsp"], stdin=subprocess.PIPE, stdout=subprocess.PIPE)
    send(proc, {"jsonrpc": "2.0", "id": 1, "method": "initialize",
                "params": {"processId": None, "rootUri": None, "capabilities": {},
                           "initializationOptions": {"timeBudgetMs": 60000}}})
    while receive(proc).get("id") != 1:
        pass
    send(proc, {"jsonrpc": "2.0", "method": "initialized", "params": {}})
    start = time.monotonic()
    send(proc, {"jsonrpc": "2.0", "method": "textDocument/didOpen",
                "params": {"textDocument": {"uri": uri, "languageId": "povray",
                                            "version": 1, "text": text}}})
    first = wait_diagnostics(proc, uri, False)
    print(f"open: {time.monotonic() - start:.3f} s, {len(first)} diagnostics, "
          f"{len(text):,} bytes")
    times = []
    for run in range(args.runs):
        broken = run % 2 == 0
        changed = text + ("\nobject { Undefined_Name_For_Latency }\n" if broken else "")
        start = time.monotonic()
        send(proc, {"jsonrpc": "2.0", "method": "textDocument/didChange",
                    "params": {"textDocument": {"uri": uri, "version": run + 2},
                               "contentChanges": [{"text": changed}]}})
        wait_diagnostics(proc, uri, broken)
        took = time.monotonic() - start
        times.append(took)
        print(f"change {run + 1} ({'error added' if broken else 'error removed'}): {took:.3f} s")
    print(f"median change to diagnostics: {statistics.median(times):.3f} s")
    send(proc, {"jsonrpc": "2.0", "id": 2, "method": "shutdown"})
    send(proc, {"jsonrpc": "2.0", "method": "exit"})
    proc.wait(timeout=10)
    return 0


if __name__ == "__main__":
    sys.exit(main())
