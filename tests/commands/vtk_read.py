#!/usr/bin/env python3
"""Reads sandflow's VTK output back with VTK's own readers (python3-vtk9) and
prints what it holds as a Tcl dict, for vtk_series.test.

    vtk_read.py --check    -> ok (VTK is there)
    vtk_read.py FILE.pvd   -> datasets {{timestep T part P name N file F} ...}
    vtk_read.py FILE.vti   -> extent origin spacing pointdata {NAME {COMPONENTS VALUES} ...}
    vtk_read.py FILE.vtp   -> points lines polys cells {{x y ...} ...}
                              celldata {NAME {COMPONENTS VALUES} ...} fielddata {NAME STRINGS ...}

A collection is parsed as XML (VTK 9.1's Python has no .pvd reader); each file
it lists must exist. Any error VTK reports makes the script fail.
"""
import os
import sys
import xml.etree.ElementTree as ET

try:
    from vtkmodules.vtkCommonCore import vtkCommand
    from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLPolyDataReader
    from vtkmodules.util.vtkConstants import VTK_DOUBLE, VTK_FLOAT
except ImportError as e:
    sys.exit(f"VTK for Python is missing ({e}): install the Debian package python3-vtk9 "
             "(scripts/install-deps)")


def tcl(value):
    """A value as a Tcl word: lists and dicts braced, floats in round-trip form."""
    if isinstance(value, dict):
        return "{" + " ".join(tcl(k) + " " + tcl(v) for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple)):
        return "{" + " ".join(tcl(v) for v in value) + "}"
    if isinstance(value, float):
        return repr(value)
    text = str(value)
    return "{" + text + "}" if not text or any(c in text for c in " {}\"\\[]$;") else text


def read(reader_class, path):
    errors = []
    reader = reader_class()
    reader.AddObserver(vtkCommand.ErrorEvent, lambda obj, event: errors.append(event))
    reader.SetFileName(path)
    reader.Update()
    if errors or reader.GetErrorCode() != 0:
        sys.exit(f"VTK could not read {path}")
    return reader.GetOutput()


def arrays(data):
    out = {}
    for k in range(data.GetNumberOfArrays()):
        a = data.GetArray(k)
        n = a.GetNumberOfComponents()
        kind = float if a.GetDataType() in (VTK_FLOAT, VTK_DOUBLE) else int
        values = [kind(a.GetComponent(t, c))
                  for t in range(a.GetNumberOfTuples()) for c in range(n)]
        out[a.GetName()] = [n, values]
    return out


def collection(path):
    root = ET.parse(path).getroot()
    if root.tag != "VTKFile" or root.get("type") != "Collection":
        sys.exit(f"{path} is not a VTK collection")
    sets = []
    for d in root.iter("DataSet"):
        entry = {"timestep": float(d.get("timestep")), "part": int(d.get("part")),
                 "name": d.get("name"), "file": d.get("file")}
        if not os.path.isfile(os.path.join(os.path.dirname(path), entry["file"])):
            sys.exit(f"{path} lists {entry['file']}, which does not exist")
        sets.append(entry)
    return {"datasets": sets}


def image(path):
    d = read(vtkXMLImageDataReader, path)
    return {"extent": list(d.GetExtent()), "origin": list(d.GetOrigin()),
            "spacing": list(d.GetSpacing()), "pointdata": arrays(d.GetPointData())}


def polydata(path):
    d = read(vtkXMLPolyDataReader, path)
    cells = []
    for c in range(d.GetNumberOfCells()):
        ids = d.GetCell(c).GetPointIds()
        xy = []
        for k in range(ids.GetNumberOfIds()):
            p = d.GetPoint(ids.GetId(k))
            xy += [p[0], p[1]]
        cells.append(xy)
    fields = {}
    fd = d.GetFieldData()
    for k in range(fd.GetNumberOfArrays()):
        a = fd.GetAbstractArray(k)
        fields[a.GetName()] = [a.GetValue(t) for t in range(a.GetNumberOfValues())]
    return {"points": d.GetNumberOfPoints(), "lines": d.GetNumberOfLines(),
            "polys": d.GetNumberOfPolys(), "cells": cells,
            "celldata": arrays(d.GetCellData()), "fielddata": fields}


path = sys.argv[1]
if path == "--check":  # VTK imports: nothing to read
    print("ok")
    sys.exit(0)
kinds = {".pvd": collection, ".vti": image, ".vtp": polydata}
print(tcl(kinds[os.path.splitext(path)[1]](path))[1:-1])
