"""Reads the results of `hawser run scripts/vtk_check.toml` back with the tools users load them
with: the ParaView files with VTK's own XML reader (the `vtk` package), timeseries.parquet with
pyarrow and pandas, timeseries.csv with pandas. Run by scripts/vtk_check.sh; exits 1 on the
first failed check.

Usage: python scripts/vtk_check.py OUT_DIR
"""

import json
import math
import pathlib
import sys
import xml.etree.ElementTree as ET

import numpy as np
import pandas as pd
import pyarrow.parquet as pq
import vtk
from vtk.util.numpy_support import vtk_to_numpy

out = pathlib.Path(sys.argv[1])
checks = 0


def check(ok, what):
    global checks
    if not ok:
        print(f"FAILED: {what}")
        sys.exit(1)
    checks += 1


def same_bits(a, b):
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    return a.shape == b.shape and bool(np.all(a.view(np.int64) == b.view(np.int64)))


status = json.loads((out / "status.json").read_text())
units = json.loads((out / "channels.json").read_text())
check(status["complete"] and status["format_version"] == 2, "status.json: complete, format 2")

# ---- timeseries.csv with pandas: one call, plain names, numbers, times k x 0.1 exactly.
exact = pd.read_csv(out / "timeseries.csv")
check(all(exact.dtypes == np.float64), "every CSV column is read as float64")
check(set(exact.columns) == set(units["timeseries"]), "channels.json has a unit for every column")
check(units["timeseries"]["fe.end_a.tension"] == "N" and units["timeseries"]["time"] == "s", "units")
check(same_bits(exact["time"], [k / 10 for k in range(len(exact))]), "times are k x 0.1 exactly")
text_values = [
    [float(v) for v in line.split(",")]
    for line in (out / "timeseries.csv").read_text().splitlines()[1:]
]
check(same_bits(exact.to_numpy(), np.array(text_values)), "pd.read_csv reads every number exactly")

# ---- timeseries.parquet with pyarrow and pandas: the CSV's values bit for bit, units.
table = pq.read_table(out / "timeseries.parquet")
frame = pd.read_parquet(out / "timeseries.parquet")
check(list(frame.columns) == list(exact.columns), "Parquet columns are the CSV's, in order")
check(same_bits(frame.to_numpy(), exact.to_numpy()), "Parquet values equal the CSV's bit for bit")
meta = {k.decode(): v.decode() for k, v in table.schema.metadata.items()}
file_meta = pq.read_metadata(out / "timeseries.parquet").metadata
check(all(file_meta[k.encode()].decode() == v for k, v in meta.items()), "file key-value metadata")
check(meta["hawser.format_version"] == "2", "Parquet format_version")
check(meta["hawser.model_hash"] == status["model_hash"], "Parquet model hash is status.json's")
check(meta["hawser.complete"] == "true", "Parquet says complete")
check(json.loads(meta["hawser.units"]) == units["timeseries"], "Parquet units are channels.json's")
one = pq.read_table(out / "timeseries.parquet", columns=["fe.end_a.tension"])
check(one.num_columns == 1 and same_bits(one.column(0).to_numpy(), exact["fe.end_a.tension"]),
      "a column with dots in its name is selected by name")

# ---- The ParaView collection and every .vtp, read by VTK's XML reader.
errors = []


def on_error(obj, event):
    errors.append(event)


def read_vtp(path):
    r = vtk.vtkXMLPolyDataReader()
    r.AddObserver("ErrorEvent", on_error)
    r.AddObserver("WarningEvent", on_error)
    r.SetFileName(str(path))
    r.Update()
    check(not errors and r.GetErrorCode() == 0, f"VTK reads {path.name} without error")
    return r.GetOutput()


def array(data, name):
    a = data.GetArray(name)
    check(a is not None, f"array {name}")
    return vtk_to_numpy(a)


def triangles(poly):
    t = vtk.vtkTriangleFilter()
    t.SetInputData(poly)
    t.Update()
    p = t.GetOutput()
    pts = vtk_to_numpy(p.GetPoints().GetData())
    cells = vtk_to_numpy(p.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    return pts[cells]


def signed_volume(poly):
    """Volume by the divergence theorem: positive when every normal points outward."""
    tri = triangles(poly)
    return float(np.sum(np.einsum("ij,ij->i", tri[:, 0], np.cross(tri[:, 1], tri[:, 2]))) / 6)


pvd = ET.parse(out / "vtk" / "run.pvd").getroot()
datasets = pvd.find("Collection").findall("DataSet")
times = sorted({float(d.get("timestep")) for d in datasets})
check(times == [0.0, 0.5, 1.0], f"snapshot times {times}")
names = {d.get("name") for d in datasets}
check(names == {"fe", "hermite", "dgline", "tail", "barge", "buoy", "sphere", "frame", "points"},
      f"blocks {names}")
parts = {(d.get("name"), d.get("part")) for d in datasets}
check(len(parts) == len(names), "each block keeps its part number")
snapshots = {
    line: pd.read_csv(out / "snapshots" / f"{line}.csv")
    for line in ["fe", "hermite", "dgline", "tail"]
}
for d in datasets:
    t, name = float(d.get("timestep")), d.get("name")
    poly = read_vtp(out / "vtk" / d.get("file"))
    field_time = vtk_to_numpy(poly.GetFieldData().GetArray("TimeValue"))
    check(field_time[0] == t, f"{d.get('file')}: TimeValue")
    pts = vtk_to_numpy(poly.GetPoints().GetData())
    if name in snapshots:
        s = snapshots[name]
        s = s[s["time"] == t]
        check(poly.GetNumberOfLines() == 1 and poly.GetNumberOfPoints() == len(s),
              f"{name} at {t}: one polyline through every node")
        check(same_bits(pts, s[["x", "y", "z"]].to_numpy()), f"{name} at {t}: positions")
        pd_ = poly.GetPointData()
        check(same_bits(array(pd_, "tension"), s["tension"]), f"{name} at {t}: tension")
        check(same_bits(array(pd_, "arc_length"), s["arc_length"]), f"{name} at {t}: arc length")
        check(array(pd_, "velocity").shape == (len(s), 3), f"{name}: velocity vectors")
        array(pd_, "strain")
        bending = pd_.GetArray("bending_moment") is not None
        check(bending == (name in ("hermite", "dgline")), f"{name}: bending arrays where computed")
        if bending and t > 0:
            check(np.max(array(pd_, "curvature")) > 0, f"{name}: curvature is computed")
    elif name == "points":
        check(poly.GetNumberOfVerts() == 8 and poly.GetNumberOfPoints() == 8, "points: 8 vertices")
        check(same_bits(pts[4], [60.0, -30.0, -100.0]), "points: anchor_a where it is")
        array(poly.GetPointData(), "line_force")
    else:
        volume = signed_volume(poly) if name != "frame" else 0.0
        centre = {"barge": [0, 0, 0], "buoy": [40, 0, -1], "sphere": [0, 40, -30]}.get(name)
        if name == "barge":
            check(abs(volume - 640.0) < 1e-9, f"barge: box volume {volume}")
            check(abs(pts[:, 2].min() + 2) < 1e-12 and abs(pts[:, 2].max() - 2) < 1e-12, "barge: z extent")
            # Turned 30° about z: its length runs along (cos 30°, sin 30°).
            along = pts[:, :2] @ np.array([math.cos(math.pi / 6), math.sin(math.pi / 6)])
            check(abs(along.max() - 10) < 1e-9, "barge: heading")
        elif name == "buoy":
            prism = 24 / 2 * math.sin(2 * math.pi / 24) * 3.0
            check(abs(volume - prism) < 1e-9, f"buoy: cylinder volume {volume} vs {prism}")
        elif name == "sphere":
            check(0.95 * 4.18879 < volume < 4.18879, f"sphere: volume {volume}")
            r = np.linalg.norm(pts - centre, axis=1)
            check(np.allclose(r, 1.0, rtol=1e-5), "sphere: radius of the volume")
        else:
            check(poly.GetNumberOfLines() == 3 and poly.GetNumberOfPoints() == 4, "frame: axes glyph")
            array(poly.GetCellData(), "axis")
            check(same_bits(pts[0], [-40.0, 0.0, -20.0]), "frame: at its origin")
        if centre is not None:
            check(np.allclose(pts.mean(axis=0), centre, atol=1e-9), f"{name}: centred at its origin")
        array(poly.GetPointData(), "velocity")

print(f"vtk_check: {checks} checks passed ({len(datasets)} VTK files, VTK {vtk.vtkVersion.GetVTKVersion()}, "
      f"pandas {pd.__version__}, pyarrow {pq.__name__ and __import__('pyarrow').__version__})")
