#!/usr/bin/python3
"""An SI run's ParaView files against its dimensionless twin's.

usage: check_si_vtu.py SI_DIR TWIN_DIR --length R --stress E --time T [--tol 1e-6]

For each .pvd both runs wrote (impact.pvd, impact_3d.pvd): the same number
of states, the SI times equal the twin's times T (T = R/c in s), and in every
.vtu piece the SI points and displacement equal the twin's times R [m] and
every other field (the stresses) the twin's times E [Pa]. The .vtu files
hold 32-bit floats, so each array is compared to TOL of its largest value.
deal.II writes each DataArray as base64: a zlib block header (four uint32:
blocks, block size, last block size, compressed size), then the compressed
data.
"""
import argparse
import base64
import os
import re
import struct
import sys
import xml.etree.ElementTree as ElementTree
import zlib


def decode(text, kind):
    """The values of one binary, zlib-compressed DataArray."""
    text = "".join(text.split())
    header = base64.b64decode(text[:24])
    blocks, _, _, compressed = struct.unpack("<4I", header)
    if blocks != 1:
        sys.exit(f"check_si_vtu: {blocks} compressed blocks are not supported")
    data = zlib.decompress(base64.b64decode(text[24:])[:compressed])
    code = {"Float32": "f", "Float64": "d", "Int32": "i", "UInt8": "B"}[kind]
    return struct.unpack(f"<{len(data) // struct.calcsize(code)}{code}", data)


def read_vtu(path):
    """{array name: values} of a .vtu file, the coordinates as 'points'."""
    arrays = {}
    root = ElementTree.parse(path).getroot()
    piece = root.find("UnstructuredGrid/Piece")
    points = piece.find("Points/DataArray")
    arrays["points"] = decode(points.text, points.get("type"))
    for array in piece.findall("PointData/DataArray"):
        arrays[array.get("Name")] = decode(array.text, array.get("type"))
    return arrays


def read_pvd(path):
    """(time, .pvtu file) of each state of a .pvd."""
    root = ElementTree.parse(path).getroot()
    return [(float(d.get("timestep")), d.get("file"))
            for d in root.iter("DataSet")]


def pieces(directory, pvtu):
    root = ElementTree.parse(os.path.join(directory, pvtu)).getroot()
    return [p.get("Source") for p in root.iter("Piece")]


def compare(name, si, twin, factor, tol, failures):
    if len(si) != len(twin):
        failures.append(f"{name}: {len(si)} values against {len(twin)}")
        return 0.0
    largest = max((abs(x) * factor for x in twin), default=0.0)
    worst = max((abs(a - b * factor) for a, b in zip(si, twin)), default=0.0)
    relative = worst / largest if largest > 0 else worst
    if relative > tol:
        failures.append(f"{name}: largest difference {relative:.2e} of the "
                        f"largest value > {tol:g}")
    return relative


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("si_dir")
    parser.add_argument("twin_dir")
    parser.add_argument("--length", type=float, required=True)
    parser.add_argument("--stress", type=float, required=True)
    parser.add_argument("--time", type=float, required=True)
    parser.add_argument("--tol", type=float, default=1e-6)
    args = parser.parse_args()
    failures, compared, worst = [], 0, 0.0
    for pvd in ("impact.pvd", "impact_3d.pvd"):
        si_path, twin_path = (os.path.join(d, pvd) for d in (args.si_dir, args.twin_dir))
        if not os.path.exists(twin_path):
            continue
        si_states, twin_states = read_pvd(si_path), read_pvd(twin_path)
        if len(si_states) != len(twin_states):
            failures.append(f"{pvd}: {len(si_states)} states against {len(twin_states)}")
            continue
        for (t_si, f_si), (t_twin, f_twin) in zip(si_states, twin_states):
            # The .pvd holds 12 significant digits.
            if abs(t_si - t_twin * args.time) > 1e-10 * max(abs(t_si), 1e-300):
                failures.append(f"{pvd}: time {t_si:.15g} s against "
                                f"{t_twin:.15g} x {args.time:.15g} s")
            for a, b in zip(pieces(args.si_dir, f_si), pieces(args.twin_dir, f_twin)):
                si = read_vtu(os.path.join(args.si_dir, a))
                twin = read_vtu(os.path.join(args.twin_dir, b))
                if sorted(si) != sorted(twin):
                    failures.append(f"{a}: arrays {sorted(si)} against {sorted(twin)}")
                    continue
                for name in twin:
                    factor = args.length if name in ("points", "displacement") \
                        else args.stress
                    worst = max(worst, compare(f"{a} {name}", si[name], twin[name],
                                               factor, args.tol, failures))
                    compared += 1
    if compared == 0:
        failures.append("no .vtu arrays compared (no impact.pvd in " + args.twin_dir + ")")
    for failure in failures:
        print("FAIL:", failure)
    if failures:
        sys.exit(1)
    print(f"check_si_vtu: {compared} arrays agree (largest relative difference "
          f"{worst:.2e} <= {args.tol:g})")


if __name__ == "__main__":
    main()
