#!/usr/bin/env python3
"""Labeling error inside the hole of a torus, per level (thesis 6.4.2).

Usage: hole_labeling_error.py <output directory> [center_x center_y radius]

Reads every labeling_level_<L>.csv that shape_from_contour wrote in the
output directory (columns x, y, alpha_target, alpha on the pixel grid of
level L) and prints, per level, the integral of |alpha* - alpha[U]| over
the disc of the image plane around (center_x, center_y) with the given
radius (default: the hole of fig6_11_torus.prm, centre (0.5, 0.5), radius
R - r = 0.25 - 0.1 = 0.15), the mean of alpha[U] there (alpha* = 0 in
the hole: a hole that is too small shows alpha[U] near 2) and the
labeling error over the whole image plane.
"""
import csv
import glob
import math
import os
import re
import sys


# the hole's 1-level line is looked for within this multiple of the radius
SEARCH_FACTOR = 1.5


def level_errors(filename, center, radius):
    hole_below_one = {"alpha": 0.0, "alpha_target": 0.0}
    hole_error = 0.0
    total_error = 0.0
    hole_alpha = 0.0
    hole_area = 0.0
    rows = list(csv.DictReader(open(filename)))
    # pixel size from the first two distinct x values
    xs = sorted({float(r["x"]) for r in rows})
    pixel = xs[1] - xs[0]
    area = pixel * pixel
    for r in rows:
        x, y = float(r["x"]), float(r["y"])
        error = abs(float(r["alpha_target"]) - float(r["alpha"])) * area
        total_error += error
        distance = math.hypot(x - center[0], y - center[1])
        if distance < SEARCH_FACTOR * radius:
            for key in hole_below_one:
                if float(r[key]) < 1:
                    hole_below_one[key] += area
        if distance < radius:
            hole_error += error
            hole_alpha += float(r["alpha"]) * area
            hole_area += area
    radii = {k: math.sqrt(a / math.pi) for k, a in hole_below_one.items()}
    return (hole_error, hole_alpha / hole_area, radii["alpha"],
            radii["alpha_target"], total_error)


def main():
    if len(sys.argv) not in (2, 5):
        sys.exit(__doc__)
    directory = sys.argv[1]
    center = (0.5, 0.5)
    radius = 0.15
    if len(sys.argv) == 5:
        center = (float(sys.argv[2]), float(sys.argv[3]))
        radius = float(sys.argv[4])
    files = glob.glob(os.path.join(directory, "labeling_level_*.csv"))
    if not files:
        sys.exit("no labeling_level_<L>.csv in " + directory)
    level = lambda f: int(re.search(r"labeling_level_(\d+)\.csv", f).group(1))
    print("| level | error in the hole | mean alpha[U] in the hole | "
          "hole radius of alpha[U] / alpha* | labeling error |")
    print("|---|---|---|---|---|")
    for f in sorted(files, key=level):
        hole, mean_alpha, r_alpha, r_target, total = level_errors(
            f, center, radius)
        print(f"| {level(f)} | {hole:.4g} | {mean_alpha:.4g} | "
              f"{r_alpha:.3f} / {r_target:.3f} | {total:.4g} |")


if __name__ == "__main__":
    main()
