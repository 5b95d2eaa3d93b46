"""Run by pvpython for test_paraview.py: loads the plugin, opens one file with one of its readers
and prints, as JSON, what ParaView holds: per dataset its sizes, bounds, arrays' sums and
extremes and field data, and the VTK libraries the process loaded.

pvpython paraview_probe.py PLUGIN READER FILE [PROPERTY=VALUE ...]   (READER "open": OpenDataFile)
"""

import json
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import LoadPlugin, OpenDataFile
from vtkmodules.util import numpy_support


def describe(data):
    if data.IsA("vtkMultiBlockDataSet"):
        blocks = {}
        for i in range(data.GetNumberOfBlocks()):
            name = data.GetMetaData(i).Get(data.NAME()) if data.HasMetaData(i) else str(i)
            blocks[name] = describe(data.GetBlock(i))
        return {"type": data.GetClassName(), "blocks": blocks}
    out = {"type": data.GetClassName(), "points": data.GetNumberOfPoints(),
           "cells": data.GetNumberOfCells(), "bounds": list(data.GetBounds())}
    if data.IsA("vtkImageData"):
        out["dims"] = list(data.GetDimensions())
        out["origin"] = list(data.GetOrigin())
        out["spacing"] = list(data.GetSpacing())
    if data.GetNumberOfPoints() and hasattr(data, "GetPoints"):  # not vtkImageData
        xyz = numpy_support.vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64)
        if xyz is not None:
            radius = np.linalg.norm(xyz, axis=1)
            out["max_radius"] = float(radius.max())
            out["point_at_max_radius"] = xyz[int(radius.argmax())].tolist()
            out["min_z_point"] = xyz[int(xyz[:, 2].argmin())].tolist()
    arrays = {}
    pd = data.GetPointData()
    for i in range(pd.GetNumberOfArrays()):
        a = pd.GetArray(i)
        v = numpy_support.vtk_to_numpy(a).astype(np.float64)
        v = v.reshape(len(v), -1)
        finite = v[np.isfinite(v).all(axis=1)]
        entry = {"components": v.shape[1], "tuples": len(v), "dtype": a.GetDataTypeAsString(),
                 "sum": finite.sum(axis=0).tolist(), "nonzero": int((v != 0).any(axis=1).sum())}
        if len(finite):
            entry["min"] = finite.min(axis=0).tolist()
            entry["max"] = finite.max(axis=0).tolist()
        if v.shape[1] == 3 and len(v):
            norms = np.linalg.norm(v, axis=1)
            entry["norm_range"] = [float(norms.min()), float(norms.max())]
        if a.GetName() == "intensity" and data.IsA("vtkPolyData") and data.GetNumberOfPolys():
            entry["integral"] = surface_integral(data, v[:, 0])
        arrays[a.GetName()] = entry
    out["arrays"] = arrays
    fields = {}
    fd = data.GetFieldData()
    for i in range(fd.GetNumberOfArrays()):
        a = fd.GetAbstractArray(i)
        if a.IsA("vtkStringArray"):
            fields[a.GetName()] = a.GetValue(0)
        else:
            fields[a.GetName()] = [a.GetTuple1(k) for k in range(a.GetNumberOfTuples())]
    out["fields"] = fields
    return out


def surface_integral(surface, intensity):
    """Integral of the intensity over the sphere of directions, from a polar surface: each
    polygon's directions span a solid angle; the mean intensity of its corners times it."""
    xyz = numpy_support.vtk_to_numpy(surface.GetPoints().GetData()).astype(np.float64)
    polys = numpy_support.vtk_to_numpy(surface.GetPolys().GetConnectivityArray())
    offsets = numpy_support.vtk_to_numpy(surface.GetPolys().GetOffsetsArray())
    centre = np.asarray(centre_of(surface))
    total = 0.0
    for k in range(len(offsets) - 1):
        ids = polys[offsets[k]:offsets[k + 1]]
        d = xyz[ids] - centre
        n = np.linalg.norm(d, axis=1)
        if (n == 0).any():
            continue  # a corner at the centre: no direction, and no light toward it
        u = d / n[:, None]
        # The spherical polygon's solid angle as a fan of spherical triangles.
        omega = 0.0
        for j in range(1, len(ids) - 1):
            a, b, c = u[0], u[j], u[j + 1]
            num = abs(np.dot(a, np.cross(b, c)))
            den = 1 + np.dot(a, b) + np.dot(b, c) + np.dot(c, a)
            omega += 2 * np.arctan2(num, den)
        total += omega * intensity[ids].mean()
    return total


def centre_of(surface):
    a = surface.GetFieldData().GetArray("surface_centre_mm")
    return [0.0, 0.0, 0.0] if a is None else [a.GetTuple1(k) for k in range(3)]


def vtk_libraries():
    with open("/proc/self/maps") as maps:
        return sorted({line.split()[-1] for line in maps if "libvtk" in line})


def main():
    plugin, reader, path = sys.argv[1:4]
    properties = dict(arg.split("=", 1) for arg in sys.argv[4:])
    namespace = globals()
    LoadPlugin(plugin, ns=namespace)
    if reader == "open":
        proxy = OpenDataFile(path)
    else:
        proxy = namespace[reader](FileName=path)
    for key, value in properties.items():
        setattr(proxy, key, json.loads(value))
    proxy.UpdatePipeline()
    data = servermanager.Fetch(proxy)
    result = describe(data)
    result["proxy"] = proxy.GetXMLName()
    result["vtk_libraries"] = vtk_libraries()
    print("PROBE " + json.dumps(result))


main()
