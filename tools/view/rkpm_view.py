#!/usr/bin/python3
"""rkpm_view: a run's snapshot as a PNG, without ParaView (tools/rkpm view RUN_DIR ...).

    rkpm_view.py RUN_DIR [--field NAME] [--time T] [--out PNG]

Reads the .pvd series of RUN_DIR (rkpm_run's CASE.pvd) with meshio (Debian python3-meshio), takes
the snapshot nearest T seconds (default the last; a .vtu, or on several processes the pieces of a
.pvtu) and draws with gnuplot the deformed cells
filled by the field (each quad the mean of its four nodes' values; particles that are vertex
cells as dots), a colour bar, and the tools if the snapshot lists them (<FieldData> arrays
"tool:NAME", written by the runner). NAME is a point array of the snapshot
(equivalent_plastic_strain by default); a vector is drawn as its magnitude, "stress" as the von
Mises stress, NAME:K as component K. The gnuplot commands are those of the runner's
final_plastic_strain.png (include/rkpm/io/field_figure.hpp). Writes RUN_DIR/view_NAME_NNNNNN.png
(NNNNNN the snapshot's number) or --out, and prints its path.
"""
import argparse
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

try:
    import numpy as np
    import meshio
except ImportError as e:
    sys.exit(f"rkpm view: {e}: install python3-meshio (apt-get install python3-meshio)")

# As field_figure_preamble() in include/rkpm/io/field_figure.hpp.
PREAMBLE = """set termoption noenhanced
set title {title}
set size ratio -1
set xlabel 'r or x (mm)'
set ylabel 'z or y (mm)'
set cblabel {label}
set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21908d', 0.75 '#5dc963', 1 '#fde725')
set style fill solid 1.0 noborder
set key off
set clip two
"""


def quote(s):
    """A gnuplot single-quoted string."""
    return "'" + s.replace("'", "''") + "'"


def fail(message):
    sys.exit(f"rkpm view: error: {message}")


def snapshots(run_dir):
    """[(time, path)] of the run's .pvd, in its order."""
    pvds = sorted(f for f in os.listdir(run_dir) if f.endswith(".pvd"))
    if len(pvds) != 1:
        fail(f"{run_dir} holds {len(pvds)} .pvd files ({', '.join(pvds) or 'none'}); give a run folder of rkpm_run")
    root = ET.parse(os.path.join(run_dir, pvds[0])).getroot()
    sets = [(float(d.get("timestep")), os.path.join(run_dir, d.get("file"))) for d in root.iter("DataSet")]
    if not sets:
        fail(f"{pvds[0]} lists no snapshot yet")
    return sets


def read_snapshot(path):
    """One snapshot: a .vtu, or the pieces a .pvtu index names (a run on several processes) as one
    mesh, their points one after the other and each piece's cells on its own points; the tools'
    <FieldData> of whichever piece holds it. A particle that several pieces hold is drawn once
    per piece, with the same values."""
    if not path.endswith(".pvtu"):
        return meshio.read(path)
    grid = ET.parse(path).getroot().find("PUnstructuredGrid")
    sources = [] if grid is None else [p.get("Source") for p in grid.findall("Piece")]
    if not sources:
        fail(f"{path} names no pieces")
    pieces = [meshio.read(os.path.join(os.path.dirname(path), s)) for s in sources]
    first = [0]
    for m in pieces:
        first.append(first[-1] + len(m.points))
    cells = [(block.type, np.asarray(block.data) + at) for m, at in zip(pieces, first) for block in m.cells]
    point_data = {name: np.concatenate([np.asarray(m.point_data[name]) for m in pieces])
                  for name in pieces[0].point_data}
    field_data = {}
    for m in pieces:
        field_data.update(m.field_data)
    return meshio.Mesh(np.concatenate([m.points for m in pieces]), cells, point_data=point_data,
                       field_data=field_data)


def field_values(mesh, name):
    """The values to draw per point and the colour bar's label."""
    base, _, component = name.partition(":")
    if base not in mesh.point_data:
        fail(f"no field '{base}' in the snapshot; its fields: {', '.join(mesh.point_data)}")
    a = np.asarray(mesh.point_data[base], dtype=float)
    a = a.reshape(len(a), -1)
    if component:
        k = int(component)
        if not 0 <= k < a.shape[1]:
            fail(f"'{base}' has components 0 to {a.shape[1] - 1}, not {k}")
        return a[:, k], name
    if a.shape[1] == 1:
        return a[:, 0], base
    if a.shape[1] == 9:  # a tensor: the von Mises stress of its symmetric part
        t = a.reshape(-1, 3, 3)
        t = 0.5 * (t + t.transpose(0, 2, 1))
        dev = t - np.trace(t, axis1=1, axis2=2)[:, None, None] / 3.0 * np.eye(3)
        return np.sqrt(1.5 * np.sum(dev * dev, axis=(1, 2))), f"von Mises {base}"
    return np.linalg.norm(a, axis=1), f"|{base}|"


def data_block(name, rows_per_item, values):
    """A gnuplot inline data block: `values` (items, rows, columns), a blank line after each item."""
    row = " ".join(["%.9g"] * values.shape[2]) + "\n"
    item = row * rows_per_item + ("\n" if rows_per_item > 1 else "")
    flat = values.reshape(len(values), -1)
    return f"${name} << EOD\n" + "".join(item % tuple(r) for r in flat) + "EOD\n"


def main(argv):
    p = argparse.ArgumentParser(prog="tools/rkpm view", description=__doc__.split("\n\n")[0])
    p.add_argument("run_dir")
    p.add_argument("--field", default="equivalent_plastic_strain")
    p.add_argument("--time", type=float, help="seconds; the snapshot nearest it (default: the last)")
    p.add_argument("--out", help="the PNG (default RUN_DIR/view_FIELD_NNNNNN.png)")
    a = p.parse_args(argv)
    if not os.path.isdir(a.run_dir):
        fail(f"{a.run_dir} is not a folder")
    sets = snapshots(a.run_dir)
    index = len(sets) - 1 if a.time is None else min(range(len(sets)), key=lambda k: abs(sets[k][0] - a.time))
    t, path = sets[index]
    mesh = read_snapshot(path)
    values, label = field_values(mesh, a.field)
    xy = mesh.points[:, :2] * 1e3  # mm
    script = ""
    plots = []
    for block in mesh.cells:
        conn = np.asarray(block.data)
        if block.type == "vertex":
            script += data_block("dots", 1, np.column_stack([xy[conn[:, 0]], values[conn[:, 0]]])[:, None, :])
            plots.append("$dots using 1:2:3 with points pt 7 ps 0.4 lc palette")
        else:  # quads (or any polygon): filled with the mean of its nodes
            mean = values[conn].mean(axis=1)
            rows = np.concatenate([xy[conn], np.repeat(mean[:, None, None], conn.shape[1], axis=1)], axis=2)
            name = f"cells{len(plots)}"
            script += data_block(name, conn.shape[1], rows)
            plots.append(f"${name} using 1:2:3 with polygons fillcolor palette")
    if not plots:
        fail(f"{path} has no cells")
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    pad = 0.05 * (hi - lo).max()
    tools = sorted(k for k in mesh.field_data if k.startswith("tool:"))
    for k, tool in enumerate(tools):
        line = np.asarray(mesh.field_data[tool], dtype=float).reshape(-1, 3)[:, :2] * 1e3
        script += data_block(f"tool{k}", 1, line[:, None, :])
        plots.append(f"$tool{k} using 1:2 with lines lw 3 lc rgb 'black'")
    run = os.path.basename(os.path.normpath(a.run_dir))
    out = a.out or os.path.join(a.run_dir, f"view_{a.field.replace(':', '_')}_{index:06d}.png")
    title = f"{run}: {label} at t = {t * 1e6:.4g} us"
    script = ("if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n  set terminal pngcairo size 900,800\n"
              "} else {\n  set terminal png size 900,800\n}\n"
              f"set output {quote(out)}\n" + PREAMBLE.format(title=quote(title), label=quote(label)) + script +
              f"set xrange [{lo[0] - pad}:{hi[0] + pad}]\nset yrange [{lo[1] - pad}:{hi[1] + pad}]\n" +
              "plot " + ", ".join(plots) + "\nunset output\n")
    if os.path.exists(out):
        os.remove(out)
    r = subprocess.run(["gnuplot"], input=script, capture_output=True, text=True)
    with open(out, "rb") if os.path.exists(out) else open(os.devnull, "rb") as f:
        ok = f.read(8) == b"\x89PNG\r\n\x1a\n"
    if r.returncode != 0 or not ok or "error" in r.stderr.lower():
        fail(f"gnuplot failed on {out}: {r.stderr.strip() or 'no PNG written'}")
    print(out)


if __name__ == "__main__":
    main(sys.argv[1:])
