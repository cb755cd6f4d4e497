#!/usr/bin/env python3
"""Labeling error of a 3D contour run split by the target label.

Usage: labeling_error_by_label.py <output directory>

For every labeling_level_<L>.csv that shape_from_contour wrote (columns
x, y, alpha_target, alpha on the pixel grid of level L), prints per
target label k (alpha* rounded to the nearest even integer: 0, 2, 4, ...)
the area of the image plane where alpha* = k, the integral of
|alpha* - alpha[U]| there and the mean of alpha[U] there, then the total
labeling error. For the rotated torus (Fig. 6.12) the label-4 region is
where the view crosses both arms of the ring: a ring without its hole
shows alpha[U] near 2 there.
"""
import csv
import glob
import os
import re
import sys
from collections import defaultdict


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    files = glob.glob(os.path.join(sys.argv[1], "labeling_level_*.csv"))
    if not files:
        sys.exit("no labeling_level_<L>.csv in " + sys.argv[1])
    level_of = lambda f: int(re.search(r"labeling_level_(\d+)", f).group(1))
    print(f'{"level":>5} {"label":>5} {"area":>8} {"error":>9} {"mean alpha[U]":>13}')
    for filename in sorted(files, key=level_of):
        rows = list(csv.DictReader(open(filename)))
        xs = sorted({float(r["x"]) for r in rows})
        pixel_area = (xs[1] - xs[0]) ** 2
        area, error, alpha = defaultdict(float), defaultdict(float), defaultdict(float)
        for r in rows:
            target, value = float(r["alpha_target"]), float(r["alpha"])
            label = 2 * round(target / 2)
            area[label] += pixel_area
            error[label] += abs(target - value) * pixel_area
            alpha[label] += value * pixel_area
        for label in sorted(area):
            print(f"{level_of(filename):5d} {label:5d} {area[label]:8.4f} "
                  f"{error[label]:9.4g} {alpha[label] / area[label]:13.4f}")
        print(f"{level_of(filename):5d} {'all':>5} {sum(area.values()):8.4f} "
              f"{sum(error.values()):9.4g}")


if __name__ == "__main__":
    main()
