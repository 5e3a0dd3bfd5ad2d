"""Renders one snapshot of a run's ParaView files (vtk/run.pvd) to a PNG without a display, as
ParaView would show it: lines as tubes coloured by tension, bodies as surfaces, points as
spheres, an optional seabed. Needs the `vtk` package (PyPI wheels render offscreen; the venv of
scripts/vtk_check.sh has it).

Usage: python scripts/paraview_screenshot.py OUT_DIR PNG [--time T] [--seabed Z] [--tube R]
  --time T    snapshot time [s] (default: the last)
  --seabed Z  draw the seabed at z = Z [m]
  --tube R    tube radius [m] (default: 0.4 % of the scene's size)
"""

import pathlib
import sys
import xml.etree.ElementTree as ET

import vtk


def option(args, flag, default=None):
    if flag in args:
        i = args.index(flag)
        value = float(args[i + 1])
        del args[i : i + 2]
        return value
    return default


args = sys.argv[1:]
time = option(args, "--time")
seabed = option(args, "--seabed")
tube = option(args, "--tube")
out, png = pathlib.Path(args[0]), args[1]
root = ET.parse(out / "vtk" / "run.pvd").getroot()
datasets = root.find("Collection").findall("DataSet")
times = sorted({float(d.get("timestep")) for d in datasets})
if time is None:
    time = times[-1]
time = min(times, key=lambda t: abs(t - time))
chosen = [d for d in datasets if float(d.get("timestep")) == time]


def read(d):
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(str(out / "vtk" / d.get("file")))
    r.Update()
    return r.GetOutput()


polys = {d.get("name"): (d.get("file"), read(d)) for d in chosen}
bounds = [1e300, -1e300] * 3
for _, p in polys.values():
    b = p.GetBounds()
    for k in range(3):
        bounds[2 * k] = min(bounds[2 * k], b[2 * k])
        bounds[2 * k + 1] = max(bounds[2 * k + 1], b[2 * k + 1])
size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
tube = tube or 0.004 * size

tensions = [
    p.GetPointData().GetArray("tension").GetRange()
    for f, p in polys.values()
    if f.startswith("line_")
]
lo, hi = min(t[0] for t in tensions), max(t[1] for t in tensions)
lut = vtk.vtkLookupTable()
lut.SetHueRange(0.667, 0.0)
lut.SetTableRange(lo, hi)
lut.Build()

renderer = vtk.vtkRenderer()
renderer.SetBackground(1.0, 1.0, 1.0)
for name, (file, p) in polys.items():
    if file.startswith("line_"):
        p.GetPointData().SetActiveScalars("tension")
        f = vtk.vtkTubeFilter()
        f.SetInputData(p)
        f.SetRadius(tube)
        f.SetNumberOfSides(12)
        m = vtk.vtkPolyDataMapper()
        m.SetInputConnection(f.GetOutputPort())
        m.SetLookupTable(lut)
        m.SetScalarRange(lo, hi)
        m.SetScalarModeToUsePointData()
    elif file.startswith("points_"):
        s = vtk.vtkSphereSource()
        s.SetRadius(3 * tube)
        g = vtk.vtkGlyph3D()
        g.SetInputData(p)
        g.SetSourceConnection(s.GetOutputPort())
        g.SetScaleModeToDataScalingOff()
        m = vtk.vtkPolyDataMapper()
        m.SetInputConnection(g.GetOutputPort())
        m.ScalarVisibilityOff()
    else:
        m = vtk.vtkPolyDataMapper()
        m.SetInputData(p)
        m.ScalarVisibilityOff()
    a = vtk.vtkActor()
    a.SetMapper(m)
    if file.startswith("points_"):
        a.GetProperty().SetColor(0.2, 0.2, 0.2)
    elif not file.startswith("line_"):
        a.GetProperty().SetColor(0.85, 0.55, 0.2)
    renderer.AddActor(a)

if seabed is not None:
    plane = vtk.vtkPlaneSource()
    margin = 0.1 * size
    # A little below the seabed, so that lines lying on it stay in view.
    z = seabed - 0.5 * tube
    plane.SetOrigin(bounds[0] - margin, bounds[2] - margin, z)
    plane.SetPoint1(bounds[1] + margin, bounds[2] - margin, z)
    plane.SetPoint2(bounds[0] - margin, bounds[3] + margin, z)
    m = vtk.vtkPolyDataMapper()
    m.SetInputConnection(plane.GetOutputPort())
    a = vtk.vtkActor()
    a.SetMapper(m)
    a.GetProperty().SetColor(0.82, 0.78, 0.68)
    a.GetProperty().SetOpacity(0.5)
    renderer.AddActor(a)

bar = vtk.vtkScalarBarActor()
bar.SetLookupTable(lut)
bar.SetTitle("tension [N]")
bar.SetNumberOfLabels(5)
bar.SetLabelFormat("%.3g")
bar.SetWidth(0.1)
bar.SetHeight(0.55)
bar.SetPosition(0.88, 0.15)
for prop in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
    prop.SetColor(0.1, 0.1, 0.1)
    prop.ItalicOff()
    prop.ShadowOff()
renderer.AddViewProp(bar)
label = vtk.vtkTextActor()
label.SetInput(f"{out.name}: t = {time:g} s")
label.GetTextProperty().SetColor(0.1, 0.1, 0.1)
label.GetTextProperty().SetFontSize(18)
label.SetPosition(12, 12)
renderer.AddViewProp(label)

camera = renderer.GetActiveCamera()
camera.SetViewUp(0, 0, 1)
camera.SetPosition(-0.25, -1.0, 0.55)
camera.SetFocalPoint(0, 0, 0)
renderer.ResetCamera()
camera.Zoom(1.3)

window = vtk.vtkRenderWindow()
window.SetOffScreenRendering(1)
window.AddRenderer(renderer)
window.SetSize(1200, 700)
window.Render()
grab = vtk.vtkWindowToImageFilter()
grab.SetInput(window)
grab.Update()
writer = vtk.vtkPNGWriter()
writer.SetFileName(png)
writer.SetInputConnection(grab.GetOutputPort())
writer.Write()
print(f"{png}: t = {time:g} s, tension {lo:.4g} to {hi:.4g} N")
