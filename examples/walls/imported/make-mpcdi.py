#!/usr/bin/env python3
"""Writes projectors-2x1-warped.mpcdi: the calibration of walls/projectors-2x1-warped.toml as a
VESA MPCDI file (version 2.0, the 2D media profile), for tilelayout import (docs/wall-import.md,
"MPCDI").

A zip of mpcdi.xml and, per projector (region), the files its fileset names:
  - the geometry warp: walls/calibration/keystone-N.pfm as they are (17x13 points);
  - an alpha map, 1024x768 8-bit grey PNG, the edge blend the wall file generates with
    blend = { gamma = 2.2 }: across the 64 overlap columns each projector's weight falls
    linearly, w = (1024 - u - 0.5) / 64 for the left one at canvas column u and
    (u + 0.5 - 960) / 64 for the right one, stored as round(w * 255) in linear light
    (gammaEmbedded 1.0: on projectors of gamma 2.2 the import gives alpha_gamma 2.2);
  - for the right projector also a beta map, all 0 (black levels left as they are), so that
    the example carries every kind of map while showing what the wall file shows.

The region places: one 1984x768 buffer, the left projector at x 0, the right at x 960/1984,
each 1024/1984 wide. Run from anywhere; the file is committed. Deterministic: fixed entry times.
"""
import pathlib
import struct
import zipfile
import zlib

HERE = pathlib.Path(__file__).resolve().parent
CALIBRATION = HERE.parents[2] / "walls" / "calibration"
WIDTH, HEIGHT = 1024, 768
CANVAS = 1984
LEFT_OF = {0: 0, 1: 960}  # each projector's canvas column
OVERLAP = (960, 1024)
WHEN = (2026, 1, 1, 0, 0, 0)


def grey_png(width, height, row_of):
    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
    raw = b"".join(b"\x00" + row_of(y) for y in range(height))
    header = struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0)  # 8-bit grey
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def alpha_row(display):
    lo, hi = OVERLAP
    row = bytearray()
    for x in range(WIDTH):
        u = LEFT_OF[display] + x
        w = 1.0
        if lo <= u < hi:
            w = (hi - u - 0.5) / (hi - lo) if display == 0 else (u + 0.5 - lo) / (hi - lo)
        row.append(int(w * 255 + 0.5))
    return bytes(row)


def region(display, name):
    x = LEFT_OF[display] / CANVAS
    return (f'      <region id="{name}" x="{x:.9f}" y="0.0" xsize="{WIDTH / CANVAS:.9f}" '
            f'ysize="1.0" xResolution="{WIDTH}" yResolution="{HEIGHT}"/>\n')


def fileset(name, beta):
    text = (f'    <fileset region="{name}">\n'
            f'      <geometryWarpFile>\n        <path>{name}/warp.pfm</path>\n'
            f'        <interpolation>linear</interpolation>\n      </geometryWarpFile>\n'
            f'      <alphaMap>\n        <path>{name}/alpha.png</path>\n'
            f'        <componentDepth>1</componentDepth>\n        <bitDepth>8</bitDepth>\n'
            f'        <gammaEmbedded>1.0</gammaEmbedded>\n      </alphaMap>\n')
    if beta:
        text += (f'      <betaMap>\n        <path>{name}/beta.png</path>\n'
                 f'        <componentDepth>1</componentDepth>\n        <bitDepth>8</bitDepth>\n'
                 f'      </betaMap>\n')
    return text + '    </fileset>\n'


NAMES = {0: "left", 1: "right"}
xml = ('<?xml version="1.0" encoding="utf-8"?>\n'
       '<MPCDI profile="2d" geometry="1" version="2.0">\n  <display>\n'
       f'    <buffer id="wall" xResolution="{CANVAS}" yResolution="{HEIGHT}">\n' +
       "".join(region(d, n) for d, n in NAMES.items()) +
       '    </buffer>\n  </display>\n  <files>\n' +
       "".join(fileset(n, d == 1) for d, n in NAMES.items()) +
       '  </files>\n</MPCDI>\n')

with zipfile.ZipFile(HERE / "projectors-2x1-warped.mpcdi", "w") as z:
    def add(name, data):
        z.writestr(zipfile.ZipInfo(name, WHEN), data, compress_type=zipfile.ZIP_DEFLATED)
    add("mpcdi.xml", xml)
    for d, n in NAMES.items():
        add(f"{n}/warp.pfm", (CALIBRATION / f"keystone-{d}.pfm").read_bytes())
        row = alpha_row(d)
        add(f"{n}/alpha.png", grey_png(WIDTH, HEIGHT, lambda y: row))
        if d == 1:
            add(f"{n}/beta.png", grey_png(WIDTH, HEIGHT, lambda y: bytes(WIDTH)))
