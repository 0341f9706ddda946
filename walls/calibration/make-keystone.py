#!/usr/bin/env python3
"""Writes the geometry warps of walls/projectors-2x1-warped.toml: keystone-0.pfm and
keystone-1.pfm, a gentle keystone correction for each 1024x768 projector as a 17x13 mesh of
points (docs/wall-file.md, "Warping projected pictures").

A projector set below its screen and tilted up throws a picture wider at the top than at the
bottom. The correction draws the content narrower toward the top, by KEYSTONE of the width at the
top row and not at all at the bottom, so that on the screen it stands square: output pixel at
normalised (u, v) shows the frame at x = 1/2 + (u - 1/2) / s(v), y = v, where s(v) = 1 -
KEYSTONE * (1 - v). Near the top corners x falls off the frame, and those pixels are black.

Run from anywhere; the files are committed. PFM: "PF", width, height, -1 (little-endian), then
rows of (x, y, 0) floats from the bottom row up."""
import pathlib
import struct

HERE = pathlib.Path(__file__).resolve().parent
WIDTH, HEIGHT = 1024, 768  # each projector's raster
POINTS_X, POINTS_Y = 17, 13  # the mesh, its points spread over the pixel centres
KEYSTONE = {0: 0.08, 1: 0.05}  # of the width at the top row: the two projectors tilt differently


def mesh(keystone):
    rows = []
    for j in range(POINTS_Y):
        py = j * (HEIGHT - 1) / (POINTS_Y - 1)  # the pixel row of this point
        v = (py + 0.5) / HEIGHT
        s = 1 - keystone * (1 - v)
        row = b""
        for i in range(POINTS_X):
            px = i * (WIDTH - 1) / (POINTS_X - 1)
            u = (px + 0.5) / WIDTH
            row += struct.pack("<fff", 0.5 + (u - 0.5) / s, v, 0.0)
        rows.append(row)
    return b"PF\n%d %d\n-1\n" % (POINTS_X, POINTS_Y) + b"".join(reversed(rows))


for display, keystone in KEYSTONE.items():
    (HERE / f"keystone-{display}.pfm").write_bytes(mesh(keystone))
