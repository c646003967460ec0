#!/usr/bin/env python3
"""A deck for the set-up cost of per-particle initial velocities (issue 18 item 4): an N x N
square of 2D water particles, each with its own *SET_NODE_LIST and *INITIAL_VELOCITY (as some
pre-processors write them). `sphdeck run DECK --end-time 1e-9 --quiet` prints the set-up time.

    python3 bench/make_velocity_sets_deck.py 100 > /tmp/velocity_sets.k   # 10,000 particles
"""
import sys

n = int(sys.argv[1]) if len(sys.argv) > 1 else 100
dx = 0.01
out = ["*KEYWORD", "*CONTROL_TERMINATION", "       0.1",
       "*CONTROL_SPH", "         1         0     1e+20         2       150         0         0     1e+15",
       "*SECTION_SPH", "         1       1.2       0.2         2         0",
       "*PART", "water", "         1         1         1         1",
       "*MAT_NULL", "         1      1000         0",
       "*EOS_MURNAGHAN", "         1         7 1.121e+05         1",
       "*NODE"]
for j in range(n):
    for i in range(n):
        out.append(f"{j * n + i + 1:8d}{(i + 0.5) * dx:16.8f}{(j + 0.5) * dx:16.8f}{0.0:16.8f}")
out.append("*ELEMENT_SPH")
for k in range(1, n * n + 1):
    out.append(f"{k:8d}{1:8d}{dx * dx * 1000:16.8e}")
for k in range(1, n * n + 1):
    out += ["*SET_NODE_LIST", f"{k:10d}", f"{k:10d}",
            "*INITIAL_VELOCITY", f"{k:10d}", f"{0.001 * (k % 7):10.4f}{-0.002 * (k % 5):10.4f}"]
out.append("*END")
print("\n".join(out))
