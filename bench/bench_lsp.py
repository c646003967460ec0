#!/usr/bin/env python3
"""Editor server benchmark: how fast `sphdeck lsp` answers an editor (issue 16 targets).

    python3 bench/bench_lsp.py BUILD_DIR          (BUILD_DIR holds sphdeck and gen_big_deck)

Measures, as an editor would see it over stdio (the times include writing the message into the
server's pipe and reading its notification back); targets of issue 29 item 5:
  (a) an edit of a 10,000-line deck: didChange -> the publishDiagnostics of that version (target 20 ms);
  (b) a 1M-particle deck: didOpen -> its first publishDiagnostics (target 1 s), a new server each run;
  (c) an edit of that deck outside its bulk *NODE / *ELEMENT_SPH blocks (the *PART title):
      didChange -> the publishDiagnostics of that version (target 100 ms);
  (d) an edit inside its bulk *NODE block (a coordinate mid-block) (target 300 ms); and, for
      information, (c2) an edit of a setting the particle rules read (CSLH of *SECTION_SPH);
  (e) issue 45: a burst of 200 one-character changes of the *PART title sent without waiting:
      the last didChange written -> the publishDiagnostics of its version (target 1 s), and the
      server's peak RSS against the deck's size (target 2x).
Edits go as incremental changes when the server offers them (textDocumentSync.change = 2), else as
the whole text. Prints every run and the medians; exit 0 when the measurements ran (targets met or
not; BENCH_STRICT=1: exit 1 on a missed target), 1 when the server failed or did not answer in time,
2 on a usage or set-up error. Python standard library only.

Environment: BENCH_NODES (particles of the big deck, default 1000000), BENCH_RUNS (runs of (b),
default 5), BENCH_EDITS (edits per measurement of (a), (c), (c2), default 9).
"""

import json
import os
import queue
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TARGETS_S = {"a": 0.020, "b": 1.0, "c": 0.100, "d": 0.300, "e": 1.0}
BURST_CHANGES = 200
SMALL_DECK_PARTICLES = 4988  # gen_big_deck writes 2 lines a particle + 24: exactly 10,000 lines
OPEN_TIMEOUT_S = 120.0
EDIT_TIMEOUT_S = 30.0


class BenchError(Exception):
    pass


def file_uri(path):
    from urllib.parse import quote
    return "file://" + quote(str(Path(path).resolve()))


class Server:
    """`sphdeck lsp` on pipes; a thread reads its messages into a queue."""

    def __init__(self, sphdeck, root_dir):
        self.stderr = tempfile.TemporaryFile()
        self.proc = subprocess.Popen([sphdeck, "lsp"], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     stderr=self.stderr, cwd=root_dir)
        self.messages = queue.Queue()
        self.next_id = 1
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        out = self.proc.stdout
        try:
            while True:
                length = None
                while True:
                    line = out.readline()
                    if not line:
                        self.messages.put(None)
                        return
                    line = line.strip()
                    if not line:
                        break
                    name, _, value = line.partition(b":")
                    if name.strip().lower() == b"content-length":
                        length = int(value.strip())
                if length is None:
                    raise BenchError("a message without Content-Length")
                body = out.read(length)
                self.messages.put((time.perf_counter(), json.loads(body)))
        except Exception as error:  # noqa: BLE001 - reported by the waiting side
            self.messages.put(error)

    @staticmethod
    def frame(message):
        body = json.dumps(message, separators=(",", ":")).encode()
        return b"Content-Length: %d\r\n\r\n" % len(body) + body

    def write(self, data):
        """Writes framed bytes; returns the time the write started."""
        start = time.perf_counter()
        self.proc.stdin.write(data)
        self.proc.stdin.flush()
        return start

    def send(self, message):
        return self.write(self.frame(message))

    def notify(self, method, params):
        return self.send({"jsonrpc": "2.0", "method": method, "params": params})

    def request(self, method, params):
        rid = self.next_id
        self.next_id += 1
        self.send({"jsonrpc": "2.0", "id": rid, "method": method, "params": params})
        return rid

    def wait(self, what, matches, timeout_s):
        """The first message for which matches(message) holds, and the time it was read. Answers
        the server's own requests (configuration, progress, registrations) with null."""
        deadline = time.perf_counter() + timeout_s
        while True:
            left = deadline - time.perf_counter()
            if left <= 0:
                raise BenchError(f"no {what} within {timeout_s:.0f} s; server's stderr: {self.tail_of_stderr()}")
            try:
                item = self.messages.get(timeout=left)
            except queue.Empty:
                continue
            if item is None:
                raise BenchError(f"the server ended while waiting for {what}: {self.tail_of_stderr()}")
            if isinstance(item, Exception):
                raise BenchError(f"unreadable message from the server: {item}")
            when, message = item
            if "method" in message and "id" in message:
                self.send({"jsonrpc": "2.0", "id": message["id"], "result": None})
                continue
            if matches(message):
                return when, message

    def tail_of_stderr(self):
        self.stderr.seek(0)
        text = self.stderr.read().decode(errors="replace").strip()
        return text[-2000:] if text else "(nothing on stderr)"

    def initialize(self):
        rid = self.request("initialize", {
            "processId": os.getpid(),
            "rootUri": file_uri(ROOT),
            "capabilities": {
                "textDocument": {
                    "synchronization": {"didSave": True},
                    "publishDiagnostics": {"relatedInformation": True, "versionSupport": True},
                },
            },
            "clientInfo": {"name": "bench_lsp.py"},
        })
        _, answer = self.wait("initialize answer", lambda m: m.get("id") == rid, 30)
        if "error" in answer:
            raise BenchError(f"initialize failed: {answer['error']}")
        self.notify("initialized", {})
        sync = answer.get("result", {}).get("capabilities", {}).get("textDocumentSync", 1)
        change = sync.get("change", 1) if isinstance(sync, dict) else sync
        return change == 2

    def stop(self):
        try:
            rid = self.request("shutdown", None)
            self.wait("shutdown answer", lambda m: m.get("id") == rid, 10)
            self.notify("exit", None)
            self.proc.stdin.close()
            self.proc.wait(timeout=10)
        except (BenchError, OSError, subprocess.TimeoutExpired):
            self.proc.kill()
            self.proc.wait()
        finally:
            self.stderr.close()


def diagnostics_of(uri, version=None):
    def matches(message):
        if message.get("method") != "textDocument/publishDiagnostics":
            return False
        params = message.get("params", {})
        if params.get("uri") != uri:
            return False
        return version is None or params.get("version") in (version, None)
    return matches


class Document:
    """An open document: its lines, version, and edits sent the way the server syncs."""

    def __init__(self, server, path, incremental):
        self.server = server
        self.uri = file_uri(path)
        self.text = Path(path).read_text()
        self.lines = self.text.split("\n")
        self.version = 1
        self.incremental = incremental

    def open_message(self):
        return Server.frame({"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {
            "textDocument": {"uri": self.uri, "languageId": "lsdyna", "version": self.version,
                             "text": self.text}}})

    def replace(self, line, start, end, new_text):
        """Replaces characters [start, end) of line `line` (0-based) and times the re-check:
        seconds from the start of the didChange to the publishDiagnostics of the new version."""
        old = self.lines[line]
        self.lines[line] = old[:start] + new_text + old[end:]
        self.version += 1
        if self.incremental:
            change = {"range": {"start": {"line": line, "character": start},
                                "end": {"line": line, "character": end}}, "text": new_text}
        else:
            change = {"text": "\n".join(self.lines)}
        data = Server.frame({"jsonrpc": "2.0", "method": "textDocument/didChange", "params": {
            "textDocument": {"uri": self.uri, "version": self.version}, "contentChanges": [change]}})
        started = self.server.write(data)
        when, _ = self.server.wait(f"diagnostics of version {self.version} of {self.uri}",
                                   diagnostics_of(self.uri, self.version), EDIT_TIMEOUT_S)
        return when - started


    def burst(self, line, column, count):
        """`count` one-character insertions at `line`, from `column` on, written one after another
        without waiting; seconds from the last write to the diagnostics of its version, and the
        publishes the server sent for the document meanwhile."""
        frames = []
        for i in range(count):
            at = column + i
            letter = chr(ord("a") + i % 26)
            self.lines[line] = self.lines[line][:at] + letter + self.lines[line][at:]
            self.version += 1
            change = {"range": {"start": {"line": line, "character": at}, "end": {"line": line, "character": at}},
                      "text": letter}
            frames.append(Server.frame({"jsonrpc": "2.0", "method": "textDocument/didChange", "params": {
                "textDocument": {"uri": self.uri, "version": self.version}, "contentChanges": [change]}}))
        for frame in frames:
            last = self.server.write(frame)
        publishes = 0

        def final(message):
            nonlocal publishes
            if diagnostics_of(self.uri)(message):
                publishes += 1
                return message["params"].get("version") == self.version
            return False
        when, _ = self.server.wait(f"diagnostics after a burst of {count} changes", final, EDIT_TIMEOUT_S * 4)
        return when - last, publishes


def peak_rss_bytes(pid):
    """The process's peak resident set (VmHWM), or None where /proc does not say."""
    try:
        for row in Path(f"/proc/{pid}/status").read_text().splitlines():
            if row.startswith("VmHWM:"):
                return int(row.split()[1]) * 1024
    except OSError:
        pass
    return None


def make_deck(gen_big_deck, path, particles):
    path.parent.mkdir(parents=True, exist_ok=True)
    header = f"gen_big_deck: {particles} SPH particles"
    if path.exists():
        with path.open() as deck:
            if header in deck.readline():
                return
    print(f"generating {path} ({particles} particles)...", flush=True)
    subprocess.run([gen_big_deck, str(path) + ".tmp", str(particles)], check=True)
    os.replace(str(path) + ".tmp", path)


def line_index(lines, text, after=0):
    for i in range(after, len(lines)):
        if lines[i].startswith(text):
            return i
    raise BenchError(f"'{text}' not found in the deck")


def open_deck(sphdeck, path):
    """A new server with `path` open: (server, document, seconds to the first diagnostics)."""
    server = Server(sphdeck, ROOT)
    try:
        incremental = server.initialize()
        document = Document(server, path, incremental)
        data = document.open_message()  # serialized before the clock starts, as an editor holds it
        started = server.write(data)
        when, _ = server.wait(f"first diagnostics of {path.name}", diagnostics_of(document.uri), OPEN_TIMEOUT_S)
        return server, document, when - started
    except BaseException:
        server.stop()
        raise


def edit_values(count, first, second):
    return [first if i % 2 else second for i in range(count)]


def fmt_ms(seconds):
    return f"{seconds * 1000:9.1f} ms"


def report(label, times, target):
    median = statistics.median(times)
    verdict = "" if target is None else ("met" if median <= target else "NOT MET")
    target_text = "(information)" if target is None else f"target {target * 1000:.0f} ms"
    print(f"{label:58s} median {fmt_ms(median)}  min {fmt_ms(min(times))}  max {fmt_ms(max(times))}"
          f"  n={len(times):<3d} {target_text} {verdict}")
    return target is None or median <= target


def main(argv):
    if len(argv) != 2 or argv[1].startswith("-"):
        print("usage: " + __doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    build = Path(argv[1]).resolve()
    sphdeck = build / "sphdeck"
    gen_big_deck = build / "gen_big_deck"
    for tool in (sphdeck, gen_big_deck):
        if not os.access(tool, os.X_OK):
            print(f"bench_lsp: {tool} is missing; build it first (cmake --build {argv[1]})", file=sys.stderr)
            return 2
    particles = int(os.environ.get("BENCH_NODES", "1000000"))
    runs = int(os.environ.get("BENCH_RUNS", "5"))
    edits = int(os.environ.get("BENCH_EDITS", "9"))

    out = ROOT / "bench" / "out"
    small = out / "lsp_10k_lines.k"
    big = out / "big.k"  # the reader benchmark's deck (run_reader_bench.sh), shared
    make_deck(gen_big_deck, small, SMALL_DECK_PARTICLES)
    make_deck(gen_big_deck, big, particles)
    try:
        version = subprocess.run([sphdeck, "--version"], capture_output=True, text=True, timeout=10,
                                 stdin=subprocess.DEVNULL).stdout.strip()
    except subprocess.TimeoutExpired:
        version = ""
    commit = subprocess.run(["git", "-C", str(ROOT), "log", "-1", "--format=%h %cd", "--date=short"],
                            capture_output=True, text=True).stdout.strip()
    print(f"server: {sphdeck} ({version or 'version unknown'}), source commit {commit or 'unknown'}")

    results = {}
    try:
        # (a) edits of the 10,000-line deck: a coordinate in the middle of its *NODE block
        server, document, opened = open_deck(sphdeck, small)
        try:
            line_count = len(document.lines) - (1 if document.lines[-1] == "" else 0)
            print(f"(a) {small.relative_to(ROOT)}: {line_count} lines, opened in {opened:.3f} s, "
                  f"{'incremental' if document.incremental else 'full-text'} didChange")
            target = line_index(document.lines, "*NODE") + 1200
            results["a"] = [document.replace(target, 8, 24, value)
                            for value in edit_values(edits, " 1.00000000e-03", "-1.00000000e-03")]
        finally:
            server.stop()

        # (b) opening the 1M-particle deck, a new server each run; (c) and (c2) edits on the first one
        size_mb = big.stat().st_size / 2**20
        results["b"] = []
        for run in range(runs):
            server, document, opened = open_deck(sphdeck, big)
            try:
                results["b"].append(opened)
                print(f"(b) run {run + 1}/{runs}: {big.relative_to(ROOT)} ({size_mb:.1f} MB) "
                      f"first diagnostics after {opened:.3f} s", flush=True)
                if run == 0:
                    title = line_index(document.lines, "*PART") + 2
                    results["c"] = [document.replace(title, 0, len(document.lines[title]), value)
                                    for value in edit_values(edits, "water block A", "water block B")]
                    node = line_index(document.lines, "*NODE") + 2 + particles // 2
                    results["d"] = [document.replace(node, 8, 24, value)
                                    for value in edit_values(edits, " 1.00000000e-03", "-1.00000000e-03")]
                    cslh = line_index(document.lines, "*SECTION_SPH") + 2
                    results["c2"] = [document.replace(cslh, 10, 20, value)
                                     for value in edit_values(edits, "       1.3", "       1.2")]
                if document.incremental:
                    seconds, publishes = document.burst(line_index(document.lines, "*PART") + 2, 0, BURST_CHANGES)
                    results.setdefault("e", []).append(seconds)
                    rss = peak_rss_bytes(server.proc.pid)
                    print(f"(e) run {run + 1}/{runs}: burst of {BURST_CHANGES} changes, {publishes} publishes, "
                          f"the last -> diagnostics {seconds:.3f} s; server peak RSS "
                          + (f"{rss / 2**20:.0f} MiB = {rss / big.stat().st_size:.2f}x the deck" if rss else "unknown"),
                          flush=True)
            finally:
                server.stop()
    except BenchError as error:
        failure = str(error)
    else:
        failure = None

    print()
    ok = True
    rows = [("a", "(a) 10,000-line deck: edit -> diagnostics", TARGETS_S["a"]),
            ("b", f"(b) {particles:,}-particle deck: open -> first diagnostics", TARGETS_S["b"]),
            ("c", "(c) same deck: *PART title edit -> diagnostics", TARGETS_S["c"]),
            ("d", "(d) same deck: *NODE coordinate edit -> diagnostics", TARGETS_S["d"]),
            ("c2", "(c2) same deck: CSLH (*SECTION_SPH) edit -> diagnostics", None),
            ("e", f"(e) same deck: burst of {BURST_CHANGES} changes, last -> diagnostics", TARGETS_S["e"])]
    for key, label, target in rows:
        if results.get(key):
            ok &= report(label, results[key], target)
        else:
            print(f"{label:58s} not measured")
    if failure:
        print(f"bench_lsp: {failure}", file=sys.stderr)
        return 1
    if os.environ.get("BENCH_STRICT") == "1" and not ok:
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
