#!/usr/bin/python3
"""Draw the 3D shape of a run: the level set U = 0 of its last VTU output.

Reads the last record of <output directory>/solution.pvd with VTK's Python
bindings (Debian's python3-vtk9, which libvtk9-dev installs), extracts the
surface U = 0 and draws it with matplotlib, lit from the upper left, seen
from the direction (azimuth, elevation) in degrees, default (-60, 30), with
the view axis x_3 of shape_from_contour pointing up. No OpenGL needed.

Usage: plot_shape.py <output directory> [out.png] [azimuth elevation]
Writes shape.png in the output directory unless out.png is given.
"""
import os
import sys
import xml.etree.ElementTree as ElementTree

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import LightSource  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    sys.exit("plot_shape.py: needs VTK's Python bindings (apt-get install "
             "python3-vtk9; run it with /usr/bin/python3)")

# at most this many triangles are drawn (the surface is decimated)
MAX_TRIANGLES = 40000


def last_record(directory):
    pvd = os.path.join(directory, "solution.pvd")
    if not os.path.isfile(pvd):
        sys.exit(f"plot_shape.py: no {pvd} (set Output / VTU interval > 0)")
    datasets = ElementTree.parse(pvd).getroot().iter("DataSet")
    files = [d.get("file") for d in datasets]
    if not files:
        sys.exit(f"plot_shape.py: {pvd} lists no output")
    return os.path.join(directory, files[-1])


def surface(record):
    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(record)
    reader.Update()
    grid = reader.GetOutput()
    if grid.GetPointData().GetArray("U") is None:
        sys.exit(f"plot_shape.py: {record} has no point data U")
    grid.GetPointData().SetActiveScalars("U")
    contour = vtk.vtkContourFilter()
    contour.SetInputData(grid)
    contour.SetValue(0, 0.0)
    merged = vtk.vtkCleanPolyData()
    merged.SetInputConnection(contour.GetOutputPort())
    triangles = vtk.vtkTriangleFilter()
    triangles.SetInputConnection(merged.GetOutputPort())
    triangles.Update()
    mesh = triangles.GetOutput()
    if mesh.GetNumberOfCells() > MAX_TRIANGLES:
        decimate = vtk.vtkQuadricDecimation()
        decimate.SetInputData(mesh)
        decimate.SetTargetReduction(1 - MAX_TRIANGLES / mesh.GetNumberOfCells())
        decimate.Update()
        mesh = decimate.GetOutput()
    if mesh.GetNumberOfCells() == 0:
        sys.exit(f"plot_shape.py: U has no zero level set in {record}")
    points = vtk_to_numpy(mesh.GetPoints().GetData())
    cells = vtk_to_numpy(mesh.GetPolys().GetData()).reshape(-1, 4)[:, 1:]
    return points[cells]


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    directory = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(
        directory, "shape.png")
    azimuth, elevation = (float(a) for a in sys.argv[3:5]) \
        if len(sys.argv) > 4 else (-60.0, 30.0)
    record = last_record(directory)
    faces = surface(record)
    normals = np.cross(faces[:, 1] - faces[:, 0], faces[:, 2] - faces[:, 0])
    normals /= np.linalg.norm(normals, axis=1, keepdims=True) + 1e-300
    light = LightSource(azdeg=315, altdeg=45).direction
    shade = 0.25 + 0.75 * np.abs(normals @ light)
    figure = plt.figure(figsize=(6, 6))
    axes = figure.add_subplot(projection="3d")
    axes.add_collection3d(Poly3DCollection(
        faces, facecolors=plt.cm.gray(shade), edgecolors="none"))
    low, high = faces.reshape(-1, 3).min(0), faces.reshape(-1, 3).max(0)
    centre, radius = (low + high) / 2, (high - low).max() / 2
    for set_limits, c in zip(
            (axes.set_xlim, axes.set_ylim, axes.set_zlim), centre):
        set_limits(c - radius, c + radius)
    axes.set_box_aspect((1, 1, 1))
    axes.view_init(elev=elevation, azim=azimuth)
    axes.set_xlabel("x")
    axes.set_ylabel("y")
    axes.set_zlabel("z (view axis)")
    axes.set_title(os.path.basename(record) + ": U = 0")
    figure.savefig(out, dpi=100, bbox_inches="tight")
    print(f"plot_shape.py: wrote {out} ({len(faces)} triangles)")


if __name__ == "__main__":
    main()
