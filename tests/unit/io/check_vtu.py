"""Independent check of VTK files written by tests/unit/io/vtk.cpp, read with meshio.

  /usr/bin/python3 check_vtu.py vtu FILE N      one snapshot with N particles (formulas below)
  /usr/bin/python3 check_vtu.py pvd FILE T0,N0 T1,N1 ...
                                                a .pvd listing exactly those (time, N) snapshots
Expected values are recomputed here from the same closed formulas the C++ test uses, so a
value is only accepted if the writer put the right double at the right place.
Exit 0 if all checks pass; 2 if meshio is missing; 1 with a message otherwise.
"""
import os
import sys
import xml.etree.ElementTree as ET

try:
    import numpy as np
    import meshio
except ImportError as e:
    print(f"meshio (or numpy) is missing for /usr/bin/python3 ({e}): install python3-meshio "
          "(apt-get install python3-meshio)")
    sys.exit(2)


def expected(n):
    i = np.arange(n, dtype=float)
    points = np.zeros((n, 3))
    points[:, 0] = i * 0.125 - 3.0 / 7.0
    points[:, 1] = -i / 3.0 + 1e-7
    data = {
        "eps_p": i / 7.0 - 2.5,
        "u": np.stack([i * 1e-6, -i / 3.0, np.zeros(n)], axis=1),
        "sigma": np.stack([1e8 * (i + 1.0) + 10.0 * r + c + 0.1 for r in range(3) for c in range(3)], axis=1),
        "det F <J>": 1.0 + i / 1024.0,
    }
    return points, data


def check_vtu(path, n):
    mesh = meshio.read(path)
    points, data = expected(n)
    assert mesh.points.shape == (n, 3), f"points shape {mesh.points.shape} != {(n, 3)}"
    assert np.array_equal(mesh.points, points), f"points differ, max |diff| {np.abs(mesh.points - points).max()}"
    assert len(mesh.cells) == 1 and mesh.cells[0].type == "vertex", f"cells {mesh.cells}"
    conn = mesh.cells[0].data
    assert conn.shape == (n, 1) and np.array_equal(conn[:, 0], np.arange(n)), f"vertex connectivity {conn}"
    assert list(mesh.point_data) == list(data), f"arrays {list(mesh.point_data)} != {list(data)}"
    for name, want in data.items():
        got = np.asarray(mesh.point_data[name])
        assert got.shape == want.shape, f"{name}: shape {got.shape} != {want.shape}"
        assert got.dtype == np.float64, f"{name}: dtype {got.dtype}"
        assert np.array_equal(got, want), f"{name}: values differ, max |diff| {np.abs(got - want).max()}"


def check_pvd(path, expect):
    root = ET.parse(path).getroot()
    assert root.tag == "VTKFile" and root.get("type") == "Collection", f"root {root.tag} {root.attrib}"
    sets = root.findall("./Collection/DataSet")
    assert len(sets) == len(expect), f"{len(sets)} DataSets, expected {len(expect)}"
    base = os.path.dirname(path)
    for ds, (t, n) in zip(sets, expect):
        assert float(ds.get("timestep")) == t, f"timestep {ds.get('timestep')} != {t!r}"
        f = os.path.join(base, ds.get("file"))
        assert os.path.isfile(f), f"listed file {f} missing"
        check_vtu(f, n)


def main():
    kind, path = sys.argv[1], sys.argv[2]
    if kind == "vtu":
        check_vtu(path, int(sys.argv[3]))
    else:
        expect = [(float(a), int(b)) for a, b in (s.split(",") for s in sys.argv[3:])]
        check_pvd(path, expect)
    print(kind, "ok")


if __name__ == "__main__":
    try:
        main()
    except Exception as e:
        print("vtk check failed:", type(e).__name__, e)
        sys.exit(1)
