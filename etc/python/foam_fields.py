"""Reading what OpenFOAM writes, for the project's post-processing scripts and tests: one reader of
a field's internalField and of a particle cloud's positions, in both of OpenFOAM's formats.

    read_internal_field(path, n_cells=None)   numpy array, (n,) for a volScalarField, (n, 3) for a
                                              volVectorField; ascii or binary (writeFormat), plain or
                                              gzipped (writeCompression: path or path.gz)
    read_cloud_positions(path)                numpy array (n, 3) of a cloud's `positions` file
                                              (entries "(x y z) cell")
    read_label_list(path)                     numpy int array of a labelList file (e.g. a processor's
                                              constant/polyMesh/cellProcAddressing), ascii or binary
    read_decomposed_field(run, time, name, n_cells)
                                              a field of a decomposed run assembled from its
                                              processor*/<time>/ parts by cellProcAddressing

A uniform field is returned as n_cells copies of its value and needs n_cells (the reader does not
read the mesh). What cannot be read raises FieldFormatError, whose message names the file; a
script turns it into its own error (`sys.exit(f"myscript.py: {e}")`).

Scripts find this folder through COARSEDEM_DIR (etc/bashrc sets it) or their place in the tree.
"""
import gzip
import os
import re

import numpy as np

__all__ = ["FieldFormatError", "read_internal_field", "read_cloud_positions", "read_label_list",
           "read_decomposed_field"]


class FieldFormatError(ValueError):
    """A file that is not the field or list it was read as; the message names the file."""


def _read_bytes(path):
    """The file's bytes; OpenFOAM's compressed form path.gz when only that exists."""
    if not os.path.exists(path) and os.path.exists(path + ".gz"):
        path += ".gz"
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise FieldFormatError(f"{path}: cannot be read ({e.strerror})") from None
    return gzip.decompress(data) if path.endswith(".gz") else data


def _header(data):
    """(binary?, bytes per scalar, bytes per label, offset after the header) from the FoamFile
    header's format and arch; a file without a header reads as ascii of doubles and 32-bit labels."""
    end = data.find(b"}") + 1 if b"FoamFile" in data[:2048] else 0
    head = data[:end]
    binary = re.search(rb"format\s+binary\s*;", head) is not None
    arch = re.search(rb'arch\s+"([^"]*)"', head)
    scalar, label = 8, 4
    if arch:
        s = re.search(rb"scalar=(\d+)", arch.group(1))
        lb = re.search(rb"label=(\d+)", arch.group(1))
        scalar = int(s.group(1)) // 8 if s else scalar
        label = int(lb.group(1)) // 8 if lb else label
    return binary, scalar, label, end


def _numbers(text, count):
    """The first `count` numbers of ascii text, parentheses ignored."""
    tokens = text.replace(b"(", b" ").replace(b")", b" ").split(None, count)[:count]
    try:
        return np.array(tokens, dtype=float)
    except ValueError:
        return np.array([], dtype=float)


def read_internal_field(path, n_cells=None):
    data = _read_bytes(path)
    binary, scalar, _, _ = _header(data)
    at = data.find(b"internalField")
    if at < 0:
        raise FieldFormatError(f"{path}: no internalField")
    body = data[at:]
    m = re.match(rb"internalField\s+uniform\s+(\([^)]*\)|[^\s;]+)\s*;", body)
    if m:
        value = _numbers(m.group(1), 3)
        if n_cells is None:
            raise FieldFormatError(f"{path}: a uniform internalField (the reader needs the number of cells)")
        return np.tile(value, (n_cells, 1)) if len(value) == 3 else np.full(n_cells, value[0])
    m = re.match(rb"internalField\s+nonuniform\s+List<(scalar|vector)>\s*(\d+)\s*\(", body)
    if not m:
        raise FieldFormatError(f"{path}: internalField is neither uniform nor a List<scalar> or List<vector>")
    width = 1 if m.group(1) == b"scalar" else 3
    n = int(m.group(2))
    if binary:
        size = n * width * scalar
        raw = body[m.end():m.end() + size]
        if len(raw) != size or body[m.end() + size:m.end() + size + 1] != b")":
            raise FieldFormatError(f"{path}: a binary list of {n} entries that does not end where it should")
        values = np.frombuffer(raw, dtype=np.float64 if scalar == 8 else np.float32).astype(float)
    else:
        values = _numbers(body[m.end():], n * width)
        if len(values) != n * width:
            raise FieldFormatError(f"{path}: {len(values) // width} values read for a list of {n}")
    return values.reshape(n, 3) if width == 3 else values


def _read_list(path, what):
    """(bytes, binary?, bytes per scalar, bytes per label, N, offset after its '(') of a file holding
    one list 'N (' after its header; FieldFormatError naming the file and `what` when there is none."""
    data = _read_bytes(path)
    binary, scalar, label, end_of_header = _header(data)
    m = re.compile(rb"\s(\d+)\s*\(").search(data, end_of_header)
    if not m:
        raise FieldFormatError(f"{path}: no list of {what}")
    return data, binary, scalar, label, int(m.group(1)), m.end()


def read_cloud_positions(path):
    """The (x, y, z) of every particle of a cloud's positions file (entries "(x y z) cell")."""
    data, binary, scalar, label, n, start = _read_list(path, "positions")
    if not binary:
        values = _numbers(data[start:], 4 * n)
        if len(values) != 4 * n:
            raise FieldFormatError(f"{path}: {len(values) // 4} positions read for a list of {n}")
        return values.reshape(n, 4)[:, :3]
    # binary: every entry on its own line, "\n(" + 3 scalars + a label + ")"
    record = 2 + 3 * scalar + label + 1
    if len(data) < start + n * record:
        raise FieldFormatError(f"{path}: a binary list of {n} positions that is cut short")
    dtype = np.dtype([("newline", "S1"), ("open", "S1"), ("xyz", "<f8" if scalar == 8 else "<f4", 3),
                      ("cell", f"<i{label}"), ("close", "S1")])
    rows = np.frombuffer(data, dtype=dtype, count=n, offset=start)
    if n and not (np.all(rows["open"] == b"(") and np.all(rows["close"] == b")")):
        raise FieldFormatError(f"{path}: binary positions not in the (x y z) cell layout")
    return rows["xyz"].astype(float)


def read_label_list(path):
    data, binary, _, label, n, start = _read_list(path, "labels")
    if binary:
        raw = data[start:start + n * label]
        if len(raw) != n * label or data[start + n * label:start + n * label + 1] != b")":
            raise FieldFormatError(f"{path}: a binary list of {n} labels that does not end where it should")
        return np.frombuffer(raw, dtype=np.int32 if label == 4 else np.int64).astype(int)
    values = _numbers(data[start:], n)
    if len(values) != n:
        raise FieldFormatError(f"{path}: {len(values)} labels read for a list of {n}")
    return values.astype(int)


def read_decomposed_field(run, time, name, n_cells):
    """The field `name` at `time` (the folder's name) of a run decomposed into run/processor*/, on the
    whole mesh of n_cells: each part placed by its processor's cellProcAddressing. None when a part
    lacks the field; FieldFormatError, naming the file, when a part's cellProcAddressing is missing or
    unreadable, or the parts do not fill the mesh once."""
    parts = sorted(d for d in os.listdir(run) if re.fullmatch(r"processor\d+", d)) if os.path.isdir(run) else []
    if not parts or not all(os.path.exists(os.path.join(run, d, time, name)) or
                            os.path.exists(os.path.join(run, d, time, name + ".gz")) for d in parts):
        return None
    out, seen = None, np.zeros(n_cells, dtype=int)
    for d in parts:
        where = read_label_list(os.path.join(run, d, "constant", "polyMesh", "cellProcAddressing"))
        if len(where) and (where.min() < 0 or where.max() >= n_cells):
            raise FieldFormatError(f"{run}/{d}: cellProcAddressing has cells outside 0..{n_cells - 1}")
        values = read_internal_field(os.path.join(run, d, time, name), len(where))
        if out is None:
            out = np.zeros((n_cells,) + values.shape[1:])
        out[where] = values
        seen[where] += 1
    if not (seen == 1).all():
        raise FieldFormatError(f"{run}: the processors' cellProcAddressing do not cover the {n_cells} cells once")
    return out
