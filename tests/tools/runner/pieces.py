"""A snapshot written in pieces by P processes (a .pvtu index naming one .vtu per process:
include/rkpm/parallel/snapshot_pieces.hpp) put together and compared with one process's .vtu of
the same step. Both are read by meshio, an independent reader, and the index's XML by Python's
ElementTree. The pieces together must be the one-process snapshot exactly:
  - the index names P pieces and declares the one-process file's point arrays, then "particle";
  - every piece holds those arrays; "particle" gives each point's index in the whole model;
  - every particle is in some piece, and a particle in several pieces has the same values in each;
  - the points and every array, put in particle order, equal the one-process file's bit for bit;
  - the cells of all pieces, each written on the particles' indices, are the one-process cells
    (the same multiset of (cell type, particles));
  - the tools' vertices (<FieldData>) are piece 0's and no other piece's.
same_snapshot(vtu, pvtu, processes) returns what differs, [] when nothing does.
"""
import os
import xml.etree.ElementTree as ET

import meshio
import numpy as np


def cells_on(mesh, ids):
    return sorted((block.type, tuple(int(i) for i in ids[row])) for block in mesh.cells for row in block.data)


def same_snapshot(vtu, pvtu, processes):
    problems = []
    ref = meshio.read(vtu)
    n = len(ref.points)
    grid = ET.parse(pvtu).getroot().find("PUnstructuredGrid")
    if grid is None:
        return [f"{pvtu}: no <PUnstructuredGrid>"]
    sources = [p.get("Source") for p in grid.findall("Piece")]
    if len(sources) != processes:
        problems.append(f"{pvtu}: {len(sources)} pieces for {processes} processes")
    want = list(ref.point_data) + ["particle"]
    declared = [a.get("Name") for a in grid.findall("./PPointData/PDataArray")]
    if declared != want:
        problems.append(f"{pvtu}: declares {declared}, not {want}")
    points = np.zeros_like(ref.points)
    arrays = {name: np.zeros_like(np.asarray(v)) for name, v in ref.point_data.items()}
    seen = np.zeros(n, dtype=bool)
    cells = []
    for k, source in enumerate(sources):
        piece = meshio.read(os.path.join(os.path.dirname(pvtu), source))
        if list(piece.point_data) != want:
            problems.append(f"{source}: arrays {list(piece.point_data)}, not {want}")
            continue
        ids = np.asarray(piece.point_data["particle"])
        if not (np.array_equal(ids, np.round(ids)) and ids.min(initial=0) >= 0 and ids.max(initial=0) < n):
            problems.append(f"{source}: particle indices outside 0 .. {n - 1}")
            continue
        ids = ids.astype(int)
        again = seen[ids]  # already given by an earlier piece: must agree
        if not np.array_equal(points[ids[again]], piece.points[again]):
            problems.append(f"{source}: a particle's position differs from another piece's")
        points[ids] = piece.points
        for name in arrays:
            values = np.asarray(piece.point_data[name])
            if not np.array_equal(arrays[name][ids[again]], values[again]):
                problems.append(f"{source}: a particle's {name} differs from another piece's")
            arrays[name][ids] = values
        seen[ids] = True
        cells += cells_on(piece, ids)
        tools = {name: np.asarray(v).tobytes() for name, v in piece.field_data.items()}
        expected = {name: np.asarray(v).tobytes() for name, v in ref.field_data.items()} if k == 0 else {}
        if tools != expected:
            problems.append(f"{source}: field data {sorted(tools)}, not {sorted(expected)}")
    if not seen.all():
        problems.append(f"{pvtu}: particles {np.flatnonzero(~seen)[:5]}... are in no piece")
    if points.tobytes() != ref.points.tobytes():
        problems.append(f"{pvtu}: the points differ from one process's")
    for name, values in arrays.items():
        if values.tobytes() != np.asarray(ref.point_data[name]).tobytes():
            problems.append(f"{pvtu}: {name} differs from one process's")
    if sorted(cells) != cells_on(ref, np.arange(n)):
        problems.append(f"{pvtu}: the cells differ from one process's ({len(cells)} against {sum(len(b.data) for b in ref.cells)})")
    return problems
