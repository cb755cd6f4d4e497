#!/usr/bin/python3
"""Plot the energies (and the L2 error, where known) of a statistics.csv.

Usage: plot_statistics.py <output directory or statistics.csv> [out.png]
Writes energies.png next to statistics.csv unless out.png is given.
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    path = sys.argv[1]
    if os.path.isdir(path):
        path = os.path.join(path, "statistics.csv")
    if not os.path.isfile(path):
        sys.exit(f"plot_statistics.py: cannot read {path}")
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(
        os.path.dirname(path), "energies.png")
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_statistics.py: {path} has no rows")
    t = [float(r["time"]) for r in rows]
    errors = [float(r["l2_error"]) for r in rows]
    has_error = any(not math.isnan(e) for e in errors)

    fig, axes = plt.subplots(1, 2 if has_error else 1, figsize=(
        11 if has_error else 6, 4), squeeze=False)
    ax = axes[0][0]
    ax.plot(t, [float(r["willmore_energy"]) for r in rows], label="Willmore energy")
    ax.set_xlabel("time")
    ax.set_ylabel("Willmore energy")
    ax2 = ax.twinx()
    ax2.plot(t, [float(r["area_energy"]) for r in rows], "C1",
             label="area (perimeter) energy")
    ax2.set_ylabel("area energy", color="C1")
    ax.set_title("energies")
    ax.legend(loc="upper center")
    if has_error:
        ax = axes[0][1]
        ax.plot(t, errors)
        ax.set_xlabel("time")
        ax.set_ylabel("L2 error")
        ax.set_title("L2 error against the exact evolution")
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
