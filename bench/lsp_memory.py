#!/usr/bin/env python3
"""What the editor server holds (issue 45: RSS <= 2x the deck), old and new binaries taking turns.

    python3 bench/lsp_memory.py DECK SPHDECK [SPHDECK ...]     (RUNS rounds, default 5)

For each round and each binary: a new `SPHDECK lsp` on pipes, the deck opened, then its *PART title
retyped, a coordinate mid *NODE retyped and the title again, each waited for until its
publishDiagnostics. After the open
and after each edit it reads the server's VmRSS and VmHWM (peak) from /proc and its CPU time (user +
system, of the process itself). Prints one row a run and the medians a binary. Uses bench_lsp.py's
client; Python standard library only. Set OMP_WAIT_POLICY=passive for comparable CPU times on a busy
machine (the server sets it for itself when unset).
"""

import os
import statistics
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import bench_lsp  # noqa: E402

STAGES = ("open", "title", "node", "title2")


def process_state(pid):
    """(VmRSS MiB, VmHWM MiB, CPU ms of the process)."""
    rows = dict(row.split(":", 1) for row in Path(f"/proc/{pid}/status").read_text().splitlines() if ":" in row)
    mib = lambda key: int(rows[key].split()[0]) / 1024  # noqa: E731
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    ticks = int(fields[11]) + int(fields[12])  # utime, stime
    return mib("VmRSS"), mib("VmHWM"), ticks * 1000 / os.sysconf("SC_CLK_TCK")


def one_run(sphdeck, deck, particles):
    server, document, opened = bench_lsp.open_deck(sphdeck, deck)
    try:
        pid = server.proc.pid
        rss, peak, cpu = process_state(pid)
        out = {"open": (rss, peak, cpu, opened * 1000)}
        title = bench_lsp.line_index(document.lines, "*PART") + 2
        seconds = document.replace(title, 0, len(document.lines[title]), "water block B")
        rss, peak, cpu_after = process_state(pid)
        out["title"] = (rss, peak, cpu_after - cpu, seconds * 1000)
        node = bench_lsp.line_index(document.lines, "*NODE") + 2 + particles // 2
        seconds = document.replace(node, 8, 24, " 1.00000000e-03")
        rss, peak, cpu_last = process_state(pid)
        out["node"] = (rss, peak, cpu_last - cpu_after, seconds * 1000)
        seconds = document.replace(title, 0, len(document.lines[title]), "water block A")
        rss, peak, cpu_end = process_state(pid)
        out["title2"] = (rss, peak, cpu_end - cpu_last, seconds * 1000)
        return out
    finally:
        server.stop()


def main(argv):
    if len(argv) < 3:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    deck = Path(argv[1]).resolve()
    binaries = argv[2:]
    runs = int(os.environ.get("RUNS", "5"))
    with deck.open() as f:
        head = f.readline()
    particles = int(head.split("gen_big_deck:")[1].split()[0]) if "gen_big_deck:" in head else 1000000
    results = {b: [] for b in binaries}
    for run in range(runs):
        for binary in binaries:
            r = one_run(binary, deck, particles)
            results[binary].append(r)
            print(f"run {run + 1} {binary}: " + "; ".join(
                f"{s} RSS {r[s][0]:.0f} peak {r[s][1]:.0f} MiB, {r[s][2]:.0f} ms CPU, {r[s][3]:.0f} ms wall"
                for s in STAGES) + f"; load {os.getloadavg()[0]:.1f}", flush=True)
    size = deck.stat().st_size / 2**20
    print(f"\nmedians of {runs} runs, deck {size:.1f} MiB")
    for binary in binaries:
        rs = results[binary]
        med = lambda s, k: statistics.median(r[s][k] for r in rs)  # noqa: E731
        print(f"{binary}: " + "; ".join(
            f"{s} RSS {med(s, 0):.0f} peak {med(s, 1):.0f} MiB, {med(s, 2):.0f} ms CPU" for s in STAGES)
              + f"; RSS after the edits / deck {med('title2', 0) / size:.2f}x")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
