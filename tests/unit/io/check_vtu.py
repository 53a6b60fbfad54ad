"""Independent check of VTK files written by tests/unit/io/vtk.cpp, read with meshio.

  /usr/bin/python3 check_vtu.py vtu FILE N [ENCODING COMPRESSOR]
                                                one snapshot with N particles (formulas below);
                                                ENCODING appended|binary|ascii and COMPRESSOR
                                                zlib|lz4|none are what the file must declare
  /usr/bin/python3 check_vtu.py vtus FILE N ENCODING COMPRESSOR [FILE N ...]
                                                several snapshots in one start of Python
  /usr/bin/python3 check_vtu.py refuses FILE N ENCODING COMPRESSOR [FILE N ...]
                                                files the checks must refuse: one line each,
                                                "refused FILE :: why" or "accepted FILE"
  /usr/bin/python3 check_vtu.py cells FILE NX NY EXTRA [FILE NX NY EXTRA ...]
                                                a snapshot of the NX x NY grid's nodes (the same
                                                formulas) and EXTRA points beyond them: one
                                                VTK_QUAD per grid cell, counter-clockwise, then a
                                                VTK_VERTEX per extra point, and a tool in
                                                <FieldData>; appended zlib
  /usr/bin/python3 check_vtu.py pvd FILE T0,N0 T1,N1 ...
                                                a .pvd listing exactly those (time, N) snapshots;
                                                several, separated by "/"
  /usr/bin/python3 check_vtu.py pvtu FILE N PIECES
                                                a .pvtu index of PIECES pieces (one per process)
                                                that together hold points 0 .. N-1 once each,
                                                each piece's points in any order with their
                                                index as the array "particle" and the same
                                                formulas, as vertices; the index declares
                                                exactly the pieces' arrays
Expected values are recomputed here from the same closed formulas the C++ test uses, so a
value is only accepted if the writer put the right double at the right place. Appended raw
data is also walked here without meshio: each array's UInt64 header (byte count, or VTK's
compression header [#blocks, block size, last partial block, compressed sizes]) must match its
data: each compressed block exactly one whole zlib stream of its declared compressed size
that Python's zlib inflates to the declared block size (whichever library wrote it: zlib and
libdeflate write different bytes of the same format), and the arrays, taken in order of offset
(any order is valid VTK), must tile the block. That walk comes first, so a broken header is
named as such rather than by whatever meshio makes of it.
LZ4 files (compressor="vtkLZ4DataCompressor", which meshio does not read) are walked the same
way, each block one raw LZ4 block that Python's lz4 (Debian python3-lz4) decompresses to exactly
its declared size, and their arrays (appended or inline base64) are decoded here in full and
checked against the same formulas.
Exit 0 if all checks pass; 2 if meshio is missing; 1 with a message otherwise.
"""
import base64
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
try:
    import lz4.block
except ImportError:
    lz4 = None  # needed only for LZ4 files: decompress_block then fails naming python3-lz4


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
    if compressor_of(path) == "vtkLZ4DataCompressor":
        return check_vtu_decoded(path, n)
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


def compressor_of(path):
    with open(path, "rb") as f:
        head = f.read(4096)
    m = re.search(rb'compressor="([^"]*)"', head[:head.find(b"<UnstructuredGrid")])
    return m.group(1).decode() if m else None


def decompress_block(compressor, data, size, what):
    """One compressed block of `size` bytes that must use all of `data`, by the named library."""
    if compressor == "vtkLZ4DataCompressor":
        assert lz4 is not None, "python3-lz4 is missing for /usr/bin/python3 (apt-get install python3-lz4)"
        try:
            plain = lz4.block.decompress(data, uncompressed_size=size)
        except Exception as e:  # lz4.block.LZ4BlockError
            raise AssertionError(f"{what} is not an LZ4 block of {size} bytes in its {len(data)} bytes ({e})")
        assert len(plain) == size, f"{what} holds {len(plain)} bytes, not {size}"
        return plain
    inflate = zlib.decompressobj()
    try:
        plain = inflate.decompress(data)
    except zlib.error as e:
        raise AssertionError(f"{what} is not a zlib stream ({e})")
    assert inflate.eof, f"{what}: the zlib stream does not end in its {len(data)} bytes"
    assert not inflate.unused_data, \
        f"{what}: its stream ends {len(inflate.unused_data)} bytes before its {len(data)} bytes"
    assert len(plain) == size, f"{what} holds {len(plain)} bytes, not {size}"
    return plain


def decoded_arrays(path):
    """Every DataArray of a binary (appended raw or inline base64), compressed file, decoded here
    from VTK's layout: name -> (array of values, components)."""
    with open(path, "rb") as f:
        raw = f.read()
    start = raw.find(b"<AppendedData")
    root = ET.fromstring(raw if start < 0 else raw[:start] + b"</VTKFile>")
    compressor = root.get("compressor")
    appended = b""
    if start >= 0:
        appended = raw[re.search(rb'<AppendedData encoding="raw">\s*_', raw).end():]
    dtype = {"Int64": "<i8", "UInt8": "u1", "Float64": "<f8"}
    out = {}
    for a in root.iter("DataArray"):
        if a.get("format") == "appended":
            block = appended[int(a.get("offset")):]
        else:  # the header and the blocks as two base64 streams
            text = "".join(a.text.split()).encode()
            first = base64.b64decode(text[:32])
            blocks = struct.unpack_from("<Q", first, 0)[0]
            head_chars = 4 * (-(-8 * (3 + blocks) // 3))
            block = base64.b64decode(text[:head_chars]) + base64.b64decode(text[head_chars:])
        u64 = lambda k: struct.unpack_from("<Q", block, 8 * k)[0]
        blocks, block_size, last = u64(0), u64(1), u64(2)
        body, plain = 8 * (3 + blocks), b""
        for k in range(blocks):
            c = u64(3 + k)
            full = block_size if k + 1 < blocks or last == 0 else last
            plain += decompress_block(compressor, block[body:body + c], full, f"{a.get('Name')}: block {k}")
            body += c
        out[a.get("Name")] = (np.frombuffer(plain, dtype=dtype[a.get("type")]), int(a.get("NumberOfComponents", 1)))
    return out


def check_vtu_decoded(path, n):
    """check_vtu's checks on the arrays decoded here (a format meshio cannot read)."""
    arrays = decoded_arrays(path)
    points, data = expected(n)
    got, k = arrays["Points"]
    assert k == 3 and np.array_equal(got.reshape(-1, 3), points), "points differ"
    assert np.array_equal(arrays["connectivity"][0], np.arange(n)), "vertex connectivity"
    assert np.array_equal(arrays["offsets"][0], np.arange(1, n + 1)), "vertex offsets"
    assert np.array_equal(arrays["types"][0], np.ones(n)), "vertex types"
    for name, want in data.items():
        values, k = arrays[name]
        assert np.array_equal(values.reshape(want.shape), want), f"{name}: values differ"
    names = [a for a in arrays if a not in ("Points", "connectivity", "offsets", "types")]
    assert names == list(data), f"arrays {names} != {list(data)}"


def vertex_sizes(n):
    """Values per array of a snapshot of n points as vertex cells, by name."""
    return {"eps_p": n, "u": 3 * n, "sigma": 9 * n, "det F <J>": n, "Points": 3 * n, "connectivity": n,
            "offsets": n, "types": n}


def check_format(path, sizes, encoding, compressor):
    """The file declares what was asked for, and appended raw data is laid out as VTK reads it.
    sizes: the number of values of each DataArray, by name."""
    with open(path, "rb") as f:
        raw = f.read()
    start = raw.find(b"<AppendedData")
    head = raw if start < 0 else raw[:start] + b"</VTKFile>"
    root = ET.fromstring(head)
    assert root.get("header_type") == "UInt64", f"header_type {root.get('header_type')}"
    want = {"zlib": "vtkZLibDataCompressor", "lz4": "vtkLZ4DataCompressor", "none": None}[compressor]
    if encoding == "ascii":
        want = None
    assert root.get("compressor") == want, f"compressor {root.get('compressor')!r} != {want!r}"
    arrays = root.findall(".//DataArray")
    assert sorted(a.get("Name") for a in arrays) == sorted(sizes), \
        f"DataArrays {[a.get('Name') for a in arrays]} != {list(sizes)}"
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
        size = sizes[a.get("Name")] * item[a.get("type")]
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
            assert body + c <= len(block), f"{a.get('Name')}: block {k} ({c} bytes) runs past the data"
            # One whole stream (block), exactly c bytes: not cut short, nothing of the next block in it.
            full = block_size if k + 1 < blocks or last == 0 else last
            plain = decompress_block(root.get("compressor"), block[body:body + c], full, f"{a.get('Name')}: block {k}")
            body += c
            total += len(plain)
        assert total == size, f"{a.get('Name')}: {total} bytes, expected {size}"
        pos += body
    assert pos == len(data), f"arrays end at {pos}, the appended block at {len(data)}"


def grid(nx, ny, extra):
    """The test's grid: nodes i + nx j at (x, y) of expected() (point k = i + nx j), cells (i, j) on
    nodes [k, k+1, k+1+nx, k+nx] (counter-clockwise in x right, y up), then `extra` points."""
    cells = [[i + nx * j, i + 1 + nx * j, i + 1 + nx * (j + 1), i + nx * (j + 1)]
             for j in range(ny - 1) for i in range(nx - 1)]
    return np.array(cells, dtype=np.int64), np.arange(nx * ny, nx * ny + extra)


def grid_points(nx, ny, extra):
    n = nx * ny + extra
    points = np.zeros((n, 3))
    k = np.arange(n)
    i, j = (k % nx).astype(float), (k // nx).astype(float)
    points[:, 0] = i * 0.5 + 0.01 * j * j  # the C++ test's order of operations, to the bit
    points[:, 1] = j * 0.25 - 0.002 * i * i
    return points


def shoelace(xy):
    """Signed area of each polygon, rows of (x, y) corners: positive when counter-clockwise."""
    x, y = xy[..., 0], xy[..., 1]
    return 0.5 * np.sum(x * np.roll(y, -1, axis=-1) - np.roll(x, -1, axis=-1) * y, axis=-1)


def check_cells(path, nx, ny, extra):
    """Quads on the grid's nodes, VTK's counter-clockwise order, vertices for the rest; read by
    meshio and again from the raw <Cells> arrays (types, offsets, connectivity)."""
    n = nx * ny + extra
    quads, lone = grid(nx, ny, extra)
    points = grid_points(nx, ny, extra)
    # The raw arrays as VTK reads them: types 9 (VTK_QUAD) then 1 (VTK_VERTEX), offsets 4, 8, ...
    cells = len(quads) + extra
    sizes = {"eps_p": n, "u": 3 * n, "Points": 3 * n, "connectivity": 4 * len(quads) + extra, "offsets": cells,
             "types": cells, "tool:die": 9}
    check_format(path, sizes, "appended", "zlib")
    mesh = meshio.read(path)
    assert np.array_equal(mesh.points, points), "points differ"
    kinds = [c.type for c in mesh.cells]
    want = ["quad"] + (["vertex"] if extra else [])
    assert kinds == want, f"cell blocks {kinds} != {want}"
    assert np.array_equal(mesh.cells[0].data, quads), f"quad connectivity {mesh.cells[0].data} != {quads}"
    if extra:
        assert np.array_equal(mesh.cells[1].data[:, 0], lone), f"vertex cells {mesh.cells[1].data}"
    area = shoelace(points[quads][..., :2])
    assert np.all(area > 0), f"quads not counter-clockwise: areas {area[area <= 0]}"
    # The points that are the nodes of an (x, y)-sheared grid: its cells' areas add up to the
    # polygon of the grid's outline.
    outline = ([i for i in range(nx)] + [nx - 1 + nx * j for j in range(1, ny)] +
               [i + nx * (ny - 1) for i in range(nx - 2, -1, -1)] + [nx * j for j in range(ny - 2, 0, -1)])
    assert abs(area.sum() - shoelace(points[outline][:, :2])) < 1e-12 * area.sum(), "quads do not tile the grid"
    # Every per-point array is point data (ParaView interpolates it over the quads).
    assert list(mesh.point_data) == ["eps_p", "u"], f"point arrays {list(mesh.point_data)}"
    assert np.array_equal(mesh.point_data["eps_p"], np.arange(n) / 7.0 - 2.5), "eps_p"
    tool = np.array([[-1.0, -0.5, 0.0], [3.0, -0.5, 0.0], [3.5, 2.0, 0.0]])
    got = np.asarray(mesh.field_data.get("tool:die", np.zeros(0))).reshape(-1, 3)
    assert np.array_equal(got, tool), f"field data tool:die {got}"
    types, offsets, conn = (raw_array(path, name) for name in ("types", "offsets", "connectivity"))
    assert list(types) == [9] * len(quads) + [1] * extra, f"types {types}"
    assert list(offsets) == [4 * (k + 1) for k in range(len(quads))] + [4 * len(quads) + k + 1 for k in range(extra)], \
        f"offsets {offsets}"
    assert np.array_equal(conn, np.concatenate([quads.ravel(), lone])), "connectivity"


def raw_array(path, name):
    """One appended zlib-compressed DataArray decoded here, without meshio."""
    with open(path, "rb") as f:
        raw = f.read()
    start = raw.find(b"<AppendedData")
    root = ET.fromstring(raw[:start] + b"</VTKFile>")
    a = next(a for a in root.iter("DataArray") if a.get("Name") == name)
    data = raw[re.search(rb'<AppendedData encoding="raw">\s*_', raw).end():]
    block = data[int(a.get("offset")):]
    u64 = lambda k: struct.unpack_from("<Q", block, 8 * k)[0]
    blocks, body, plain = u64(0), 8 * (3 + u64(0)), b""
    for k in range(blocks):
        plain += zlib.decompress(block[body:body + u64(3 + k)])
        body += u64(3 + k)
    return np.frombuffer(plain, dtype={"Int64": "<i8", "UInt8": "u1", "Float64": "<f8"}[a.get("type")])


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


def check_pvtu(path, n, pieces):
    root = ET.parse(path).getroot()
    assert root.tag == "VTKFile" and root.get("type") == "PUnstructuredGrid", f"root {root.tag} {root.attrib}"
    grid = root.find("PUnstructuredGrid")
    assert grid is not None, "no <PUnstructuredGrid>"
    _, data = expected(n)
    declared = [(a.get("Name"), a.get("type"), int(a.get("NumberOfComponents", 1)))
                for a in grid.findall("./PPointData/PDataArray")]
    want = [(name, "Float64", 1 if v.ndim == 1 else v.shape[1]) for name, v in data.items()] + [("particle", "Float64", 1)]
    assert declared == want, f"declared point arrays {declared} != {want}"
    points = grid.findall("./PPoints/PDataArray")
    assert len(points) == 1 and points[0].get("type") == "Float64" and points[0].get("NumberOfComponents") == "3", \
        "PPoints must declare one Float64 array of 3 components"
    sources = [p.get("Source") for p in grid.findall("Piece")]
    assert len(sources) == pieces, f"{len(sources)} pieces, expected {pieces}"
    base = os.path.dirname(path)
    seen = np.zeros(n, dtype=int)
    all_points, all_data = expected(n)
    for source in sources:
        f = os.path.join(base, source)
        assert os.path.isfile(f), f"piece {f} missing"
        mesh = meshio.read(f)
        ids = np.asarray(mesh.point_data["particle"])
        assert np.array_equal(ids, np.round(ids)) and ids.min(initial=0) >= 0 and ids.max(initial=0) < n, \
            f"{source}: particle ids not in 0 .. {n - 1}"
        idx = ids.astype(int)
        seen[idx] += 1
        assert list(mesh.point_data) == [w[0] for w in want], f"{source}: arrays {list(mesh.point_data)}"
        assert np.array_equal(mesh.points, all_points[idx]), f"{source}: points differ"
        for name, v in all_data.items():
            assert np.array_equal(np.asarray(mesh.point_data[name]), v[idx]), f"{source}: {name} differs"
        conn = mesh.cells[0].data
        assert mesh.cells[0].type == "vertex" and np.array_equal(conn[:, 0], np.arange(len(idx))), \
            f"{source}: vertex cells"
    assert (seen == 1).all(), f"points held by no piece: {np.flatnonzero(seen == 0)[:5]}, by several: " \
                              f"{np.flatnonzero(seen > 1)[:5]}"


def main():
    kind, path = sys.argv[1], sys.argv[2]
    if kind == "vtus":  # many files in one start of Python: PATH N ENCODING COMPRESSION, repeated
        args = sys.argv[2:]
        for k in range(0, len(args), 4):
            path, n, encoding, compression = args[k:k + 4]
            print("checking", path, n, encoding, compression)
            check_format(path, vertex_sizes(int(n)), encoding, compression)
            check_vtu(path, int(n))
    elif kind == "refuses":  # files the checks must refuse: PATH N ENCODING COMPRESSION, repeated
        args = sys.argv[2:]
        for k in range(0, len(args), 4):
            path, n, encoding, compression = args[k:k + 4]
            try:
                check_format(path, vertex_sizes(int(n)), encoding, compression)
                check_vtu(path, int(n))
                print("accepted", path)
            except Exception as e:
                print("refused", path, "::", type(e).__name__, e)
    elif kind == "vtu":
        if len(sys.argv) > 4:
            check_format(path, vertex_sizes(int(sys.argv[3])), sys.argv[4], sys.argv[5])
        check_vtu(path, int(sys.argv[3]))
    elif kind == "pvtu":
        check_pvtu(path, int(sys.argv[3]), int(sys.argv[4]))
    elif kind == "cells":  # PATH NX NY EXTRA, repeated
        args = sys.argv[2:]
        for k in range(0, len(args), 4):
            check_cells(args[k], int(args[k + 1]), int(args[k + 2]), int(args[k + 3]))
    else:  # pvd: PATH TIME,POINTS ..., several indexes separated by "/"
        args, at = sys.argv[2:] + ["/"], 0
        for end in (k for k, a in enumerate(args) if a == "/"):
            expect = [(float(a), int(b)) for a, b in (s.split(",") for s in args[at + 1:end])]
            check_pvd(args[at], expect)
            at = end + 1
    print(kind, "ok")


if __name__ == "__main__":
    try:
        main()
    except Exception as e:
        print("vtk check failed:", type(e).__name__, e)
        sys.exit(1)
