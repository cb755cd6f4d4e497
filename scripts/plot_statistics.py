#!/usr/bin/python3
"""Plot the energies (and the L2 error, where known) of a statistics.csv.

With `Time stepping / Step control = adaptive` (a column error_estimate) a
panel of the step size tau over time, with the error estimate of each step
and the steps that were halved marked.

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
    adaptive = "error_estimate" in rows[0]
    panels = 1 + has_error + adaptive

    fig, axes = plt.subplots(1, panels, figsize=(5.5 * panels, 4),
                             squeeze=False)
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
    if adaptive:
        plot_step_sizes(rows[1:], axes[0][panels - 1])
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    print(f"wrote {out}")


def plot_step_sizes(rows, ax):
    """tau and the error estimate per step of an adaptive run."""
    t = [float(r["time"]) for r in rows]
    tau = [float(r["tau"]) for r in rows]
    ax.semilogy(t, tau, "o-", markersize=3, label="tau")
    halved = [(ti, taui) for ti, taui, r in zip(t, tau, rows)
              if float(r["step_halvings"]) > 0]
    if halved:
        ax.semilogy(*zip(*halved), "rx", label="halved (rejected) step")
    ax.set_xlabel("time")
    ax.set_ylabel("step size tau")
    ax.set_title("adaptive step sizes")
    ax.legend(loc="lower right")
    estimates = [float(r["error_estimate"]) for r in rows]
    if any(not math.isnan(e) for e in estimates):
        ax2 = ax.twinx()
        ax2.semilogy(t, estimates, "C2.", label="error estimate")
        ax2.set_ylabel("local error estimate", color="C2")


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
