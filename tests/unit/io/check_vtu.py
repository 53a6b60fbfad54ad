"""Independent check of VTK files written by tests/unit/io/vtk.cpp, read with meshio.

  /usr/bin/python3 check_vtu.py vtu FILE N [ENCODING COMPRESSOR]
                                                one snapshot with N particles (formulas below);
                                                ENCODING appended|binary|ascii and COMPRESSOR
                                                zlib|none are what the file must declare
  /usr/bin/python3 check_vtu.py pvd FILE T0,N0 T1,N1 ...
                                                a .pvd listing exactly those (time, N) snapshots
Expected values are recomputed here from the same closed formulas the C++ test uses, so a
value is only accepted if the writer put the right double at the right place. Appended raw
data is also walked here without meshio: each array's UInt64 header (byte count, or VTK's
compression header [#blocks, block size, last partial block, compressed sizes]) must match its
data, decompress with Python's zlib to the declared sizes, and the arrays, taken in order of
offset (any order is valid VTK), must tile the block.
Exit 0 if all checks pass; 2 if meshio is missing; 1 with a message otherwise.
"""
import os
import re
import struct
import sys
import xml.etree.ElementTree as ET
import zlib

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


def check_format(path, n, encoding, compressor):
    """The file declares what was asked for, and appended raw data is laid out as VTK reads it."""
    with open(path, "rb") as f:
        raw = f.read()
    start = raw.find(b"<AppendedData")
    head = raw if start < 0 else raw[:start] + b"</VTKFile>"
    root = ET.fromstring(head)
    assert root.get("header_type") == "UInt64", f"header_type {root.get('header_type')}"
    want = {"zlib": "vtkZLibDataCompressor", "none": None}[compressor]
    if encoding == "ascii":
        want = None
    assert root.get("compressor") == want, f"compressor {root.get('compressor')!r} != {want!r}"
    arrays = root.findall(".//DataArray")
    assert len(arrays) == 4 + 3 + 1, f"{len(arrays)} DataArrays"
    formats = {a.get("format") for a in arrays}
    assert formats == {encoding}, f"DataArray formats {formats} != {{{encoding!r}}}"
    if encoding != "appended":
        assert start < 0, "AppendedData present without appended arrays"
        return
    m = re.search(rb'<AppendedData encoding="raw">\s*_', raw)
    assert m, "no <AppendedData encoding=\"raw\"> followed by _"
    end = raw.rfind(b"\n  </AppendedData>")
    data = raw[m.end():end]
    order = "<" if root.get("byte_order") == "LittleEndian" else ">"
    u64 = lambda b, k: struct.unpack_from(order + "Q", b, 8 * k)[0]
    item = {"Float64": 8, "Int64": 8, "UInt8": 1}
    pos = 0
    for a in sorted(arrays, key=lambda a: int(a.get("offset"))):
        assert int(a.get("offset")) == pos, f"{a.get('Name')}: offset {a.get('offset')} != {pos}"
        size = n * int(a.get("NumberOfComponents", "1")) * item[a.get("type")]
        block = data[pos:]
        if compressor == "none":
            assert u64(block, 0) == size, f"{a.get('Name')}: byte count {u64(block, 0)} != {size}"
            pos += 8 + size
            continue
        blocks, block_size, last = u64(block, 0), u64(block, 1), u64(block, 2)
        assert block_size == 32768, f"{a.get('Name')}: block size {block_size}"
        assert blocks == -(-size // block_size), f"{a.get('Name')}: {blocks} blocks for {size} bytes"
        assert last == size % block_size, f"{a.get('Name')}: last block {last} != {size % block_size}"
        body = 8 * (3 + blocks)
        total = 0
        for k in range(blocks):
            c = u64(block, 3 + k)
            plain = zlib.decompress(block[body:body + c])
            full = block_size if k + 1 < blocks or last == 0 else last
            assert len(plain) == full, f"{a.get('Name')}: block {k} holds {len(plain)} bytes, not {full}"
            body += c
            total += len(plain)
        assert total == size, f"{a.get('Name')}: {total} bytes, expected {size}"
        pos += body
    assert pos == len(data), f"arrays end at {pos}, the appended block at {len(data)}"


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
        if len(sys.argv) > 4:
            check_format(path, int(sys.argv[3]), sys.argv[4], sys.argv[5])
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
