#!/usr/bin/env python3
"""Writes the fuzz harnesses' seed corpora (fuzz/corpus/<harness>/): a few small, valid inputs
of each format, from which libFuzzer mutates. Run from anywhere; the files are committed."""
import pathlib
import shutil
import struct
import zlib

HERE = pathlib.Path(__file__).resolve().parent
CORPUS = HERE / "corpus"


def put(harness, name, data):
    folder = CORPUS / harness
    folder.mkdir(parents=True, exist_ok=True)
    (folder / name).write_bytes(data)


# --- scanline: first byte 0 = RGB, 1 = RGBA; then the row ------------------------------------
# 48-bit headers as `strip_headers encode` writes them (spec §2).
COPY_3 = bytes.fromhex("600000000018")      # COPY frame, display 0 at 0,0, width 3
SKIP_2 = bytes.fromhex("800000000011")      # SKIP width 2
END = bytes.fromhex("000000000000")
COPY_4095 = bytes.fromhex("40802803fffc")   # COPY display 1 at 5,7, width 4095
EXT = bytes.fromhex("e29400f00a06")         # EXT (spec §7)


def rgb_header(h):
    return h  # two RGB pixels: R G B R G B


def rgba_header(h):
    return h[0:3] + b"\xff" + h[3:6] + b"\xff"


pixels3 = bytes(range(9))
put("scanline", "copy-skip-end-rgb",
    b"\x00" + rgb_header(COPY_3) + pixels3 + rgb_header(SKIP_2) + bytes(6) + rgb_header(END))
put("scanline", "copy-rgba",
    b"\x01" + rgba_header(COPY_3) + bytes(range(12)) + rgba_header(END))
put("scanline", "truncated-rgb", b"\x00" + rgb_header(COPY_4095) + bytes(30))
put("scanline", "ext-rgb", b"\x00" + rgb_header(EXT) + bytes(12))


# --- ready: first byte picks the piece size; then the serial bytes ---------------------------
def crc8(data):
    crc = 0
    for b in data:
        crc ^= b
        for _ in range(8):
            crc = ((crc << 1) ^ 0x07) & 0xFF if crc & 0x80 else (crc << 1) & 0xFF
    return crc


def message(verb, frame):
    body = f"{verb} {frame:06d}".encode()
    return body + f" {crc8(body):02X}\r\n".encode()


put("ready", "one-ready", b"\x10" + message("READY", 123))
put("ready", "noise-sync-ready",
    b"\x03" + b"xx\x00R" + message("SYNC?", 0) + message("READY", 999999))
put("ready", "bad-checksum", b"\x01" + message("READY", 42)[:-4] + b"00\r\n")

# --- wall_file: the example walls --------------------------------------------------------------
for wall in ("kd-2x2.toml", "projectors-2x1.toml", "wiregl-1600x1200.toml",
             "colour-matched-2x2.toml"):
    put("wall_file", wall, (HERE.parent / "walls" / wall).read_bytes())

# --- wall_import: the example configurations, first byte 0 (format told from the content) -----
for config in sorted((HERE.parent / "examples" / "walls" / "imported").iterdir()):
    put("wall_import", config.name, b"\x00" + config.read_bytes())
# A number past a double's range: nlohmann refuses it with another kind of exception.
put("wall_import", "number-overflow", b"\x00" + b'{"surfaces": [{"displayWidth": 1e999}]}')

# --- session_file: the example sessions, and a window of each fit -------------------------------
for session in ("windows.toml", "desktop.toml"):
    put("session_file", session, (HERE.parent / "examples" / "sessions" / session).read_bytes())
put("session_file", "fits.toml", b"background = 0x000000\n" + b"".join(
    b'[[window]]\nid = %d\nsource = "picture"\ncontent = "p.png"\nfit = "%s"\n'
    b"x = %d\ny = 0\nwidth = 10\nheight = 10\nz = %d\n" % (i, fit, 10 * i, -i)
    for i, fit in enumerate((b"fit", b"fill", b"stretch", b"1:1"))))


# --- colour_lut: colour-table files (docs/wall-file.md, "Colour table files") --------------------
put("colour_lut", "panel-2.txt", (HERE.parent / "walls" / "calibration" / "panel-2.txt").read_bytes())
put("colour_lut", "identity-crlf.txt", b"# identity\r\n" + b"".join(
    b"%d %d %d\r\n" % (i, i, i) for i in range(256)))
put("colour_lut", "short.txt", b"".join(b"%d\t0 255 # entry\n" % i for i in range(255)))
put("colour_lut", "bad-entry.txt", b"0 0 0\n12 300 4\n")


# --- vizserver_wire: a byte stream of messages (docs/vizserver-protocol.md) --------------------
def viz(kind, payload):
    return struct.pack("<IHHI", 0x5A56324C, 2, kind, len(payload)) + payload


hello = viz(1, struct.pack("<II", 0, 2) + bytes(16))
tile = viz(3, struct.pack("<IIiiII", 0, 1, -1, 3, 2, 1) + bytes(range(6)))
done = viz(4, struct.pack("<III", 0, 0, 1))
put("vizserver_wire", "hello-tile-done", hello + tile + done)
put("vizserver_wire", "welcome-swapped", viz(2, struct.pack("<III", 0, 2, 1)) + viz(5, b"\x07\0\0\0"))
put("vizserver_wire", "error", viz(6, b"pipeserver 1 gave up"))
# TILE_DELTA: a 2x1 COPY tile, then a stored frame delta message of its one changed row.
delta = b"L2FD" + bytes([1, 0, 0, 0]) + struct.pack("<IIII", 2, 1, 1, 7) + b"\x01" + b"\x00" + bytes(range(6))
put("vizserver_wire", "hello-tile-delta-done",
    hello + viz(8, struct.pack("<IIiiIIII", 0, 1, 0, 0, 2, 1, 0, 0) + delta) + done)


# --- png_frame: small PNG files, written chunk by chunk ------------------------------------------
def png(width, height, colour_type, bit_depth, rows, extra=b""):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(
            ">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    ihdr = struct.pack(">IIBBBBB", width, height, bit_depth, colour_type, 0, 0, 0)
    raw = b"".join(b"\x00" + r for r in rows)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + extra +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


put("png_frame", "rgb-4x2.png", png(4, 2, 2, 8, [bytes(range(12)), bytes(range(12, 24))]))
put("png_frame", "rgba-2x2.png", png(2, 2, 6, 8, [bytes(range(8)), bytes(range(8, 16))]))
put("png_frame", "rgb16-1x1.png", png(1, 1, 2, 16, [bytes(range(6))]))
palette = struct.pack(">I", 6) + b"PLTE" + bytes(range(6))
palette += struct.pack(">I", zlib.crc32(b"PLTE" + bytes(range(6))) & 0xFFFFFFFF)
put("png_frame", "palette-2x1.png", png(2, 1, 3, 8, [b"\x00\x01"], palette))
put("png_frame", "grey-2x1.png", png(2, 1, 0, 8, [b"\x10\x20"]))


# --- picture_header: 8 bytes of file size, then a file's first bytes (and the rest read as the
# numbers a reader declared: fuzz_picture_header.cpp) ---------------------------------------------
def dds(width, height, levels):
    head = struct.pack("<4sIIIIIII44s", b"DDS ", 124, 0x2100F, height, width, width * 3, 0, levels,
                       bytes(44))
    return head + struct.pack("<IIIIIIII", 32, 0x40, 0, 24, 0xFF0000, 0xFF00, 0xFF, 0) + bytes(20)


put("picture_header", "dds-8x8-4-levels", struct.pack("<Q", 512) + dds(8, 8, 4))
put("picture_header", "gif-1x1", struct.pack("<Q", 35) + b"GIF89a\x01\x00\x01\x00\x80\x00\x00")
put("picture_header", "jpeg-progressive",
    struct.pack("<Q", 1000) + b"\xff\xd8\xff\xe0\x00\x10" + bytes(14) + b"\xff\xc2\x00\x11")
put("picture_header", "ppm", struct.pack("<Q", 317) + b"P6\n1000000 1\n255\n")


def tiff(width, height, tile=0, pages=1, data=bytes(192)):
    """A little-endian TIFF of 8-bit RGB, uncompressed: one strip, or tiles of tile x tile; each of
    `pages` directories holds `data` after its entries."""
    out = b"II*\0" + struct.pack("<I", 8)
    for page in range(pages):
        tags = [(256, 4, width), (257, 4, height), (258, 3, 8), (259, 3, 1), (262, 3, 2)]
        tags += [(273, 4, None), (277, 3, 3), (278, 4, height), (279, 4, len(data))] if not tile \
            else [(277, 3, 3), (322, 4, tile), (323, 4, tile), (324, 4, None), (325, 4, len(data))]
        data_at = len(out) + 2 + 12 * len(tags) + 4
        out += struct.pack("<H", len(tags))
        for tag, kind, value in tags:
            value = data_at if value is None else value
            out += struct.pack("<HHIHH" if kind == 3 else "<HHII", tag, kind, 1,
                               *((value, 0) if kind == 3 else (value,)))
        out += struct.pack("<I", data_at + len(data) if page + 1 < pages else 0) + data
    return out


put("picture_header", "tiff-8x8-2-pages", struct.pack("<Q", 1000) + tiff(8, 8, pages=2))
put("picture_header", "tiff-16x16-tiled", struct.pack("<Q", 1000) + tiff(16, 16, tile=16, data=bytes(768)))


# --- frame_delta: width-1 and height-1 bytes, then one message (dvi_link/frame_delta.hpp) -----
def frame_delta(width, height, rows):
    """A stored (codec 0) message: rows maps a changed row to (mode, residual bytes)."""
    bitmap = bytearray((height + 7) // 8)
    block = b""
    for y in sorted(rows):
        bitmap[y // 8] |= 1 << (y % 8)
        mode, residual = rows[y]
        block += bytes([mode]) + residual
    head = b"L2FD" + bytes([1, 0, 0, 0]) + struct.pack("<IIII", width, height, len(rows), len(block))
    return bytes([width - 1, height - 1]) + head + bytes(bitmap) + block


put("frame_delta", "unchanged-4x3", frame_delta(4, 3, {}))
put("frame_delta", "xor-row-1", frame_delta(4, 3, {1: (0, bytes(range(12)))}))
put("frame_delta", "sub-rows-0-2", frame_delta(2, 3, {0: (1, bytes([9] * 6)), 2: (0, bytes(6))}))
put("frame_delta", "every-row-9x9", frame_delta(9, 9, {y: (y % 2, bytes([y] * 27)) for y in range(9)}))


# --- control_line: the balancing control channel's lines (balance/control_messages.hpp) -------
put("control_line", "times", b"TIMES 7 2 3 0.0125 0.5 0")
put("control_line", "times-batches", b"TIMES 3 1 1 0.25 BATCHES 2 10 20 30 40 640 0 0 1 1 2")
put("control_line", "layout-gone", b"LAYOUT 1 2 0 0 50 50 0 50 0 50 50 1 GONE 1 2")
put("control_line", "want", b"WANT 9 3")
put("control_line", "windows", b"WINDOWS 4 2 2 -10 20 300 200 0 5 6 7 8")
