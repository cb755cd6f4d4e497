#!/usr/bin/python3
"""Plot the energies (and the L2 error, where known) of a statistics.csv.

For shape_from_contour (a statistics.csv with mismatch_energy) the energy
components over the steps, with the level transitions, as thesis Fig. 6.6.

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
    if "mismatch_energy" in rows[0]:
        plot_contour(rows, out)
        return
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


def plot_contour(rows, out):
    """Energy components of shape_from_contour over the steps."""
    step = [float(r["step"]) for r in rows]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for name, label in [("total_energy", "total energy (6.3), thesis units"),
                        ("mismatch_energy", "mismatch j (with gamma)"),
                        ("willmore_energy", "Willmore energy (geometric units)"),
                        ("area_energy", "area energy (geometric units)")]:
        ax.semilogy(step, [float(r[name]) for r in rows], label=label)
    # a level starts with a row of the transferred state at the same step
    for i in range(1, len(rows)):
        if rows[i]["level"] != rows[i - 1]["level"]:
            ax.axvline(step[i], color="gray", linestyle=":")
            level = rows[i]["level"].split(".")[0]
            ax.text(step[i], ax.get_ylim()[1], f" $h = 2^{{-{level}}}$",
                    va="top", ha="left", rotation=90, fontsize=8)
    ax.set_xlabel("step")
    ax.set_ylabel("energy")
    ax.set_title("shape from contour: energy components")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
