"""Minimal reader for the VTU files that deal.II writes (zlib-compressed,
base64-encoded appended-inline binary): points, cells and cell/point data
as numpy arrays. Only what the plotting scripts need."""
import base64, re, struct, zlib

import numpy as np

_TYPES = {"Float32": np.float32, "Float64": np.float64, "Int32": np.int32,
          "Int64": np.int64, "UInt8": np.uint8, "UInt32": np.uint32,
          "UInt64": np.uint64}


def _decode(text, dtype, compressed):
    text = "".join(text.split())
    if not text:
        return np.zeros(0, dtype=dtype)
    if not compressed:
        raw = base64.b64decode(text)
        return np.frombuffer(raw[4:], dtype=dtype)
    # header: n_blocks, block size, last block size, compressed sizes
    first = base64.b64decode(text[:8])
    n_blocks = struct.unpack("<I", first[:4])[0]
    header_bytes = 4 * (3 + n_blocks)
    header_chars = 4 * ((header_bytes + 2) // 3)
    header = struct.unpack(f"<{3 + n_blocks}I",
                           base64.b64decode(text[:header_chars])[:header_bytes])
    data = base64.b64decode(text[header_chars:])
    out, offset = [], 0
    for size in header[3:]:
        out.append(zlib.decompress(data[offset:offset + size]))
        offset += size
    return np.frombuffer(b"".join(out), dtype=dtype)


def read(path):
    """Returns dict(points=(n,3), connectivity, offsets, types,
    cell_data={name: array}, point_data={name: array})."""
    with open(path) as f:
        xml = f.read()
    compressed = "vtkZLibDataCompressor" in xml
    result = dict(cell_data={}, point_data={})
    section = None
    pattern = re.compile(r"<(/?)(PointData|CellData|Points|Cells)\b[^>]*>|"
                         r"<DataArray([^>]*)>(.*?)</DataArray>", re.S)
    for m in pattern.finditer(xml):
        if m.group(2):
            section = None if m.group(1) else m.group(2)
            continue
        attributes, body = m.group(3), m.group(4)
        dtype = _TYPES[re.search(r'type="(\w+)"', attributes).group(1)]
        name = re.search(r'Name="([^"]*)"', attributes)
        components = re.search(r'NumberOfComponents="(\d+)"', attributes)
        if 'format="ascii"' in attributes:
            values = np.array(body.split(), dtype=dtype)
        else:
            values = _decode(body, dtype, compressed)
        if components and int(components.group(1)) > 1:
            values = values.reshape(-1, int(components.group(1)))
        if section == "Points":
            result["points"] = values.reshape(-1, 3).astype(float)
        elif section == "Cells":
            result[name.group(1)] = values
        elif section == "CellData":
            result["cell_data"][name.group(1)] = values
        elif section == "PointData":
            result["point_data"][name.group(1)] = values
    return result


def cells(mesh):
    """The cells as a list of vertex-index arrays."""
    offsets = mesh.get("offsets", np.zeros(0, dtype=int))
    connectivity = mesh.get("connectivity", np.zeros(0, dtype=int))
    starts = np.concatenate([[0], offsets[:-1]])
    return [connectivity[s:e] for s, e in zip(starts, offsets)]


def cell_values(mesh, name):
    """Cell data named @p name; deal.II writes cell data as point data on
    the vertices of each cell, so this falls back to the first vertex."""
    if name in mesh["cell_data"]:
        return mesh["cell_data"][name]
    values = mesh["point_data"][name]
    return np.array([values[c[0]] for c in cells(mesh)])
