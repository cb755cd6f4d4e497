#!/usr/bin/python3
"""Draw the zero lines U = 0 of 2D runs: the first record of the first run
dashed in gray, the last record of every run in colour.

Reads <output directory>/solution.pvd of each run with VTK's Python bindings
(Debian's python3-vtk9, which libvtk9-dev installs). Used for the pictures
of doc/vesicles.md, "Results in 2D".

Usage: plot_zero_lines.py <out.png> <title> <run directory>:<label> ...
"""
import os
import sys
import xml.etree.ElementTree as ElementTree

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    sys.exit("plot_zero_lines.py: needs VTK's Python bindings (apt-get "
             "install python3-vtk9; run it with /usr/bin/python3)")


def records(directory):
    """The VTU files of a run's solution.pvd, in time order."""
    pvd = os.path.join(directory, "solution.pvd")
    if not os.path.isfile(pvd):
        sys.exit(f"plot_zero_lines.py: no {pvd}")
    datasets = ElementTree.parse(pvd).getroot().iter("DataSet")
    return [os.path.join(directory, d.get("file")) for d in datasets]


def zero_lines(path):
    """The segments of the zero line of U in one (parallel) VTU file."""
    reader = (vtk.vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu")
              else vtk.vtkXMLUnstructuredGridReader())
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    grid.GetPointData().SetActiveScalars("U")
    contour = vtk.vtkContourFilter()
    contour.SetInputData(grid)
    contour.SetValue(0, 0.0)
    contour.Update()
    poly = contour.GetOutput()
    points = vtk_to_numpy(poly.GetPoints().GetData())
    lines = poly.GetLines()
    lines.InitTraversal()
    ids = vtk.vtkIdList()
    while lines.GetNextCell(ids):
        yield [points[ids.GetId(k)][:2] for k in range(ids.GetNumberOfIds())]


def draw(axes, path, colour, style, label):
    for k, segment in enumerate(zero_lines(path)):
        axes.plot([p[0] for p in segment], [p[1] for p in segment],
                  color=colour, linestyle=style, lw=1.2,
                  label=label if k == 0 else None)


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    out, title, runs = sys.argv[1], sys.argv[2], sys.argv[3:]
    figure, axes = plt.subplots(figsize=(6, 3.4))
    first = records(runs[0].rsplit(":", 1)[0])[0]
    draw(axes, first, "0.6", "--", "initial")
    colours = ["tab:blue", "tab:red", "tab:green", "tab:purple"]
    for k, run in enumerate(runs):
        directory, label = run.rsplit(":", 1)
        draw(axes, records(directory)[-1], colours[k % len(colours)], "-",
             label)
    axes.set_aspect("equal")
    axes.legend(loc="upper center", bbox_to_anchor=(0.5, -0.08), fontsize=7,
                ncol=len(runs) + 1, frameon=False)
    axes.set_title(title, fontsize=9)
    figure.tight_layout()
    figure.savefig(out, dpi=130)


if __name__ == "__main__":
    main()
