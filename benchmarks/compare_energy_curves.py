#!/usr/bin/env python3
"""Compare the Willmore energy W(t) of two runs at equal times.

Usage: benchmarks/compare_energy_curves.py <output dir A> <output dir B>

Two runs of the same flow (for example the augmented Lagrangian against
the nested scheme, thesis Fig. 7.6) may halve different steps, so their
step numbers belong to different times. This script interpolates run B's
W(t) linearly at run A's times and prints a table: per tenth of A's steps the relative difference |W_A - W_B| / W_B,
then the largest difference, the step where it occurs, the largest
difference from step 30 on, and both runs' last rows and total iterations.
Only A's times from B's first step on are compared: inside a first step
from rough initial data W falls by an order of magnitude (603 -> 49 for
the rectangle at 2^-9), so a linear interpolation there says nothing.
Reads only statistics.csv.
"""
import csv
import sys
from bisect import bisect_left


def read(directory):
    with open(directory + "/statistics.csv") as f:
        return list(csv.DictReader(f))


def interpolate(times, values, t):
    """Linear interpolation of values(times) at t (times increasing)."""
    i = bisect_left(times, t)
    if i < len(times) and times[i] == t:
        return values[i]
    t0, t1 = times[i - 1], times[i]
    return values[i - 1] + (values[i] - values[i - 1]) * (t - t0) / (t1 - t0)


def total(rows, column):
    return sum(float(r[column]) for r in rows[1:]) if column in rows[0] else 0


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    a, b = read(sys.argv[1]), read(sys.argv[2])
    tb = [float(r["time"]) for r in b]
    wb = [float(r["willmore_energy"]) for r in b]
    differences = []
    for r in a:
        t = float(r["time"])
        if tb[1] <= t <= tb[-1]:
            w_b = interpolate(tb, wb, t)
            w_a = float(r["willmore_energy"])
            differences.append((int(r["step"]), t, w_a, w_b, abs(w_a - w_b) / w_b))
    if not differences:
        sys.exit("the runs share no time interval")
    print(f"compared at the {len(differences)} times of A in "
          f"[{tb[1]:.4e}, {tb[-1]:.4e}] (B's step 1 to its last step)")
    print(f'{"step A":>6} {"time":>12} {"W_A":>12} {"W_B(t)":>12} {"rel. diff":>10}')
    stride = max(1, len(differences) // 10)
    for step, t, w_a, w_b, d in differences[::stride]:
        print(f"{step:6d} {t:12.5e} {w_a:12.6f} {w_b:12.6f} {d:10.2e}")
    worst = max(differences, key=lambda x: x[4])
    late = [d for d in differences if d[0] >= 30]
    print(f"largest relative difference: {worst[4]:.3e} at step {worst[0]} "
          f"(t = {worst[1]:.4e})")
    if late:
        print(f"largest from step 30 on: {max(d[4] for d in late):.3e}")
    for name, rows in (("A", a), ("B", b)):
        last = rows[-1]
        print(f'{name}: step {last["step"]}, t = {float(last["time"]):.5e}, '
              f'W = {float(last["willmore_energy"]):.6f}, '
              f'newton {total(rows, "newton_iterations"):.0f}, '
              f'al {total(rows, "al_iterations"):.0f}, '
              f'tr {total(rows, "tr_iterations"):.0f}, '
              f'linear {total(rows, "linear_iterations"):.0f}, '
              f'{float(last["wall_seconds"]):.0f} s')


if __name__ == "__main__":
    main()
