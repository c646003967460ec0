#!/usr/bin/env python3
"""Checks the VS Code test's checks: stands as `sphdeck.path` between VS Code and `sphdeck lsp` and
breaks one feature in the server's answers, so that the test must fail on it (not run by CI).

    SABOTAGE=MODE REAL_SPHDECK=build/sphdeck \\
      bash tests/editor/vscode/run_vscode_test.sh tests/editor/vscode/sabotage_proxy.py

MODE: diagnostics (DK002 one column off), link (the include's link to the wrong file), symbols (no
SECTION symbol), lens ("used by 2" for "used by 1"), prepare (the prepared range widened to the whole
field), refusal (the too-wide id's reason dropped), rename (the include's edit spills past the id field).
"""
import json
import os
import subprocess
import sys
import threading

MODE = os.environ["SABOTAGE"]
server = subprocess.Popen([os.environ["REAL_SPHDECK"]] + sys.argv[1:], stdin=subprocess.PIPE, stdout=subprocess.PIPE)
methods = {}  # request id -> method, to know what a response answers


def read(stream):
    headers = {}
    while True:
        line = stream.readline()
        if not line:
            return None
        line = line.strip()
        if not line:
            break
        name, value = line.decode().split(":", 1)
        headers[name.lower()] = value.strip()
    return json.loads(stream.read(int(headers["content-length"])))


def write(stream, message):
    body = json.dumps(message).encode()
    stream.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
    stream.flush()


def client_to_server():
    while (message := read(sys.stdin.buffer)) is not None:
        if "id" in message and "method" in message:
            methods[message["id"]] = message["method"]
        write(server.stdin, message)
    server.stdin.close()


def spill(edits):  # the include's edit of the id field reaches 3 columns into the next field
    edits[0]["range"]["end"]["character"] = 13
    edits[0]["newText"] = "        42   "


def sabotage(method, message):
    result = message.get("result")
    if MODE == "diagnostics" and method == "textDocument/publishDiagnostics":
        for d in message["params"]["diagnostics"]:
            if d.get("code") == "DK002":
                d["range"]["start"]["character"] += 1
    elif MODE == "link" and method == "textDocument/documentLink" and result:
        for link in result:
            link["target"] = link["target"].replace("rename_section", "rename_main")
    elif MODE == "symbols" and method == "workspace/symbol" and result:
        message["result"] = [s for s in result if "SECTION" not in s["name"]]
    elif MODE == "lens" and method in ("textDocument/codeLens", "codeLens/resolve") and result:
        for lens in result if isinstance(result, list) else [result]:
            if lens.get("command") and lens["command"]["title"] == "used by 1":
                lens["command"]["title"] = "used by 2"
    elif MODE == "prepare" and method == "textDocument/prepareRename" and result:
        result["range"]["start"]["character"] = 10
    elif MODE == "refusal" and method == "textDocument/rename" and "error" in message:
        message["error"]["message"] = "cannot rename"
    elif MODE == "rename" and method == "textDocument/rename" and result:
        for uri, edits in (result.get("changes") or {}).items():
            if uri.endswith("rename_section.k"):
                spill(edits)
        for change in result.get("documentChanges") or []:
            if change["textDocument"]["uri"].endswith("rename_section.k"):
                spill(change["edits"])


threading.Thread(target=client_to_server, daemon=True).start()
while (message := read(server.stdout)) is not None:
    sabotage(message["method"] if "method" in message else methods.get(message.get("id")), message)
    write(sys.stdout.buffer, message)
sys.exit(server.wait())
