#!/usr/bin/env bash
# A procedural gigapixel picture as a tiled TIFF with MIP levels, made without holding it whole:
# squares of 1024 pixels, each its own colour, crossed by lines one pixel wide every 256 pixels
# (the lines a zoomed-out view keeps from the MIP levels, and nearest sampling of the picture
# itself would mostly miss). Its rows are written as a PNG a row at a time (python's zlib, a
# row a join of repeated bytes; a PNG because OpenImageIO reads its rows in turn, where it
# reads a PPM whole), then copied tiled, level by level, a band of rows at a time, by the
# pipeserver's own tiled copy (image/tiled_copy.hpp, L2_TILED_COPY_MB=0), and the PNG removed.
#
#   scripts/make-gigapixel.sh [--side N] [--build DIR] OUT.tif   (default side 32768, a multiple of 1024)
#
# Then, for instance: l2wall run --scene picture --content OUT.tif --frames 600
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
side=32768
build=$root/build/default
usage() { sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'; }
out=
while (($#)); do
  case $1 in
    --side) side=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --help|-h) usage; exit 0 ;;
    -*) echo "make-gigapixel.sh: unknown argument $1" >&2; usage >&2; exit 2 ;;
    *) out=$1; shift ;;
  esac
done
[[ -n $out ]] || { echo "make-gigapixel.sh: no OUT.tif given" >&2; usage >&2; exit 2; }
[[ $side =~ ^[0-9]+$ && $side -ge 1024 && $((side % 1024)) -eq 0 ]] ||
  { echo "make-gigapixel.sh: --side: $side is not a multiple of 1024" >&2; exit 2; }
pipeserver=$build/pipeserver/pipeserver
[[ -x $pipeserver ]] || { echo "make-gigapixel.sh: no $pipeserver: build it first" >&2; exit 1; }

work=$(mktemp -d "$(dirname "$out")/.gigapixel.XXXXXX")
trap 'rm -rf "$work"' EXIT
png=$work/gigapixel.png

echo "writing the rows of a ${side}x${side} picture into $png"
python3 - "$side" "$png" <<'PYTHON'
import struct, sys, zlib
side, path = int(sys.argv[1]), sys.argv[2]
squares = side // 1024
line = bytes((255, 255, 0))
def colour(sx, sy):
    return bytes(((sx * 67 + sy * 29) % 200 + 30, (sx * 13 + sy * 71) % 200 + 30,
                  (sx * 41 + sy * 7) % 200 + 30))
def chunk(f, kind, data):
    f.write(struct.pack(">I", len(data)) + kind + data)
    f.write(struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))
with open(path, "wb") as f:
    f.write(b"\x89PNG\r\n\x1a\n")
    chunk(f, b"IHDR", struct.pack(">IIBBBBB", side, side, 8, 2, 0, 0, 0))
    z = zlib.compressobj(1)
    full = b"\0" + line * side  # each row after its filter byte (none)
    for sy in range(squares):
        # A square's run: a line pixel, then 255 of its colour, four times over.
        rows = b"\0" + b"".join((line + colour(sx, sy) * 255) * 4 for sx in range(squares))
        for y in range(1024):
            data = z.compress(full if y % 256 == 0 else rows)
            if data:
                chunk(f, b"IDAT", data)
    chunk(f, b"IDAT", z.flush())
    chunk(f, b"IEND", b"")
PYTHON

echo "copying it tiled with MIP levels"
XDG_CACHE_HOME=$work/cache L2_TILED_COPY_MB=0 "$pipeserver" --scene picture --content "$png" \
  --picture-cache-mb 64 --frame 0 --out "$work/scanout" 2>&1 | grep -v '^pipeserver\|^wrote' || true
copy=$(ls "$work"/cache/lightning2/pictures/*.tif)
mv "$copy" "$out"
echo "wrote $out"
