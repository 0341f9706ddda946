#!/usr/bin/env python3
"""Writes the fuzz harnesses' seed corpora (fuzz/corpus/<harness>/): a few small, valid inputs
of each format, from which libFuzzer mutates. Run from anywhere; the files are committed."""
import base64
import pathlib
import shutil
import struct
import zipfile
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
put("wall_file", "stereo-passive-2x1.toml",
    (HERE.parent / "examples" / "walls" / "stereo-passive-2x1.toml").read_bytes())
put("wall_file", "stereo-active-2x1.toml",
    (HERE.parent / "examples" / "walls" / "stereo-active-2x1.toml").read_bytes())
put("wall_file", "stereo-side-by-side-2x1.toml",
    (HERE.parent / "examples" / "walls" / "stereo-side-by-side-2x1.toml").read_bytes())
put("wall_file", "stereo-top-bottom-2x1.toml",
    (HERE.parent / "examples" / "walls" / "stereo-top-bottom-2x1.toml").read_bytes())

# --- wall_import: the example configurations, first byte 0 (format told from the content) -----
for config in sorted((HERE.parent / "examples" / "walls" / "imported").iterdir()):
    if config.suffix in (".json", ".ndisplay"):
        put("wall_import", config.name, b"\x00" + config.read_bytes())
# A number past a double's range: nlohmann refuses it with another kind of exception.
put("wall_import", "number-overflow", b"\x00" + b'{"surfaces": [{"displayWidth": 1e999}]}')

# --- mpcdi_import: the example calibration's mpcdi.xml, and one of version 1.0 with notes ------
with zipfile.ZipFile(HERE.parent / "examples" / "walls" / "imported" /
                     "projectors-2x1-warped.mpcdi") as archive:
    put("mpcdi_import", "projectors-2x1-warped.xml", archive.read("mpcdi.xml"))
put("mpcdi_import", "version-1-notes.xml", b"""<?xml version="1.0"?>
<MPCDI profile="2d" geometry="1" version="1.0"><display>
<buffer id="a" xResolution="100" yResolution="50">
<region id="r" x="0" y="0" xsize="0.6" ysize="1" xResolution="64" yResolution="48"><frame/></region>
</buffer><buffer id="b" xResolution="64" yResolution="48">
<region id="s" x="0" y="0" xsize="1" ysize="1" Xresolution="64" Yresolution="48"/></buffer></display>
<files><fileset region="r"><geometryWarpFile><path>w.pfm</path><interpolation>cubic</interpolation>
</geometryWarpFile><alphaMap><path>./a.png</path><bitDepth>16</bitDepth></alphaMap></fileset>
<fileset region="s"><betaMap><path>right/beta.png</path></betaMap><distortionMap/></fileset></files>
</MPCDI>""")

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


# --- warp_pfm: two bytes picking the display's size (width - 1, height - 1), then a PFM warp ----
def warp(w, h, scale, at):
    rows = [b"".join(struct.pack("<fff" if scale < 0 else ">fff", *at(x, y), 0.0) for x in range(w))
            for y in reversed(range(h))]  # PFM rows run bottom to top
    return bytes([w - 1, h - 1]) + b"PF\n%d %d\n%g\n" % (w, h, scale) + b"".join(rows)


put("warp_pfm", "identity-4x3.pfm", warp(4, 3, -1.0, lambda x, y: ((x + .5) / 4, (y + .5) / 3)))
put("warp_pfm", "mirror-big-endian-3x2.pfm",
    warp(3, 2, 1.0, lambda x, y: ((2 - x + .5) / 3, (y + .5) / 2)))
put("warp_pfm", "off-frame-2x2.pfm", warp(2, 2, -1.0, lambda x, y: (x * 1.5 - .25, float("nan"))))
put("warp_pfm", "short-2x1.pfm", warp(2, 1, -1.0, lambda x, y: (.5, .5))[:-5])


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


# --- jpeg_frame: a byte of limits (the largest side less 1), then a shared screen's JPEG ----------
# A 16x16 red and blue checker board, as `oiiotool --pattern checker:width=8:height=8:color1=1,0,0:
# color2=0,0,1 16x16 3 -o seed.jpg` writes it.
CHECKER_JPEG = bytes.fromhex(
    "ffd8ffe000104a46494600010100000100010000ffe1013845786966000049492a00dc0000006f69696f746f"
    "6f6c202d2d7061747465726e20636865636b65723a77696474683d383a6865696768743d383a636f6c6f7231"
    "3d312c302c303a636f6c6f72323d302c302c312031367831362033202d6f202f746d702f736565642e6a7067"
    "004f70656e496d616765494f20322e342e372e31203a206f69696f746f6f6c202d2d7061747465726e206368"
    "65636b65723a77696474683d383a6865696768743d383a636f6c6f72313d312c302c303a636f6c6f72323d30"
    "2c302c312031367831362033202d6f202f746d702f736565642e6a7067000200310102007500000067000000"
    "6987040001000000fa0000000000000004000090070004000000303233300191070004000000010203001392"
    "02005f0000000800000000a00700040000003031303000000000ffed009550686f746f73686f7020332e3000"
    "3842494d04040000000000791c024100744f70656e496d616765494f20322e342e372e31203a206f69696f74"
    "6f6f6c202d2d7061747465726e20636865636b65723a77696474683d383a6865696768743d383a636f6c6f72"
    "313d312c302c303a636f6c6f72323d302c302c312031367831362033202d6f202f746d702f736565642e6a70"
    "67ffdb0043000101010101010101010101010101010201010101010201010102020202020202020203030403"
    "0303030302020304030304040404040203050504040504040404ffdb00430101010101010102010102040302"
    "0304040404040404040404040404040404040404040404040404040404040404040404040404040404040404"
    "04040404040404ffc00011080010001003012200021101031101ffc4001f0000010501010101010100000000"
    "000000000102030405060708090a0bffc400b5100002010303020403050504040000017d0102030004110512"
    "2131410613516107227114328191a1082342b1c11552d1f02433627282090a161718191a25262728292a3435"
    "363738393a434445464748494a535455565758595a636465666768696a737475767778797a83848586878889"
    "8a92939495969798999aa2a3a4a5a6a7a8a9aab2b3b4b5b6b7b8b9bac2c3c4c5c6c7c8c9cad2d3d4d5d6d7d8"
    "d9dae1e2e3e4e5e6e7e8e9eaf1f2f3f4f5f6f7f8f9faffc4001f010003010101010101010101000000000000"
    "0102030405060708090a0bffc400b51100020102040403040705040400010277000102031104052131061241"
    "510761711322328108144291a1b1c109233352f0156272d10a162434e125f11718191a262728292a35363738"
    "393a434445464748494a535455565758595a636465666768696a737475767778797a82838485868788898a92"
    "939495969798999aa2a3a4a5a6a7a8a9aab2b3b4b5b6b7b8b9bac2c3c4c5c6c7c8c9cad2d3d4d5d6d7d8d9da"
    "e2e3e4e5e6e7e8e9eaf2f3f4f5f6f7f8f9faffda000c03010002110311003f00fc5fafc87a2bf5e2bfd50ff9"
    "6747feae0ffc441ffbb7bfb3bfd5effc3e7d73eb9fdb9ff50bf57faaff00cbff006ffb9ff6a3fe57cdff0054"
    "37fa8dff0075dfafff006eff00e19feabf55fec7ff00a88f6ff59ff973ec7f7bffd9")
put("jpeg_frame", "checker-16x16", b"\x0f" + CHECKER_JPEG)
put("jpeg_frame", "checker-16x16-over-limit", b"\x07" + CHECKER_JPEG)


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


# --- picture_file: a byte choosing the extension (fuzz_picture_file.cpp's kExtensions), then a
# small valid file of that format ----------------------------------------------------------------
EXTENSIONS = ["png", "jpg", "tif", "bmp", "ppm", "pfm", "hdr", "fits", "ico", "gif", "tga", "dds",
              "exr", "sgi", "psd", "rla"]


def picture(name, data):
    put("picture_file", name, bytes([EXTENSIONS.index(name.rsplit(".", 1)[1])]) + data)


rgb_4x4 = bytes((x * 60, y * 60, 128) [c] for y in range(4) for x in range(4) for c in range(3))
picture("rgb-4x4.png", png(4, 4, 2, 8, [rgb_4x4[12 * y:12 * y + 12] for y in range(4)]))
# An 8x8 grey baseline JPEG (FFmpeg's, as pipeserver/hostile_files.hpp's jpeg_frame).
picture("grey-8x8.jpg", bytes.fromhex(
    "ffd8ffe000104a46494600010200000100010000ffdb004300083e3e493e49555555555555645d6468686864"
    "646464686868707070838383707070686870707c7c83838f938f8787838793939b9b9bbabab2b2d9d9e0ffff"
    "ffffc4004a000100000000000000000000000000000000010100000000000000000000000000000000100100"
    "000000000000000000000000000000110100000000000000000000000000000000ffc0001108000800080301"
    "2200021100031100ffda000c03010002110311003f00000fffd9"))
picture("rgb-8x8.tif", tiff(8, 8, data=bytes(range(192))))
picture("tiled-16x16.tif", tiff(16, 16, tile=16, data=bytes(768)))
picture("pages-8x8.tif", tiff(8, 8, pages=3))
# Findings kept as seeds: compression scheme 768 (no reader knows it) with RowsPerStrip 1885995016,
# which its reader sized a 45 GB buffer by; a PNG whose signature's CR was lost in transfer,
# named .dds, which let another reader print libpng's own line.
picture("unknown-scheme-8x8.tif", tiff(8, 8, data=bytes(range(192)))
        .replace(struct.pack("<HHIHH", 259, 3, 1, 1, 0), struct.pack("<HHIHH", 259, 3, 1, 768, 0))
        .replace(struct.pack("<HHII", 278, 4, 1, 8), struct.pack("<HHII", 278, 4, 1, 1885995016)))
picture("line-ends-4x4.dds",
        png(4, 4, 2, 8, [rgb_4x4[12 * y:12 * y + 12] for y in range(4)]).replace(b"\r\n", b"\n", 1))
bmp_rows = b"".join(rgb_4x4[12 * y:12 * y + 12] for y in range(4))  # 12 bytes: no padding
picture("rgb-4x4.bmp", b"BM" + struct.pack("<IHHI", 54 + len(bmp_rows), 0, 0, 54) +
        struct.pack("<IiiHHIIiiII", 40, 4, 4, 1, 24, 0, len(bmp_rows), 2835, 2835, 0, 0) + bmp_rows)
picture("rgb-4x4.ppm", b"P6\n4 4\n255\n" + rgb_4x4)
picture("grey-4x4.ppm", b"P5\n4 4\n255\n" + bytes(range(0, 160, 10)))
picture("rgb-2x2.pfm", b"PF\n2 2\n-1.0\n" + struct.pack("<12f", *[i / 12 for i in range(12)]))
# Radiance: flat RGBE scanlines (a side under 8 is never run-length encoded).
picture("rgbe-4x4.hdr", b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 4\n" +
        bytes([128, 64, 32, 129]) * 16)


def fits_card(key, value):
    return (key.ljust(8) + "= " + value.rjust(20)).ljust(80).encode()


fits_header = (fits_card("SIMPLE", "T") + fits_card("BITPIX", "8") + fits_card("NAXIS", "2") +
               fits_card("NAXIS1", "4") + fits_card("NAXIS2", "4") + b"END".ljust(80))
picture("grey-4x4.fits", fits_header.ljust(2880, b" ") + bytes(range(16)).ljust(2880, b"\0"))
icon_png = png(4, 4, 6, 8, [bytes(range(16 * y, 16 * y + 16)) for y in range(4)])
picture("png-4x4.ico", struct.pack("<HHH", 0, 1, 1) +
        struct.pack("<BBBBHHII", 4, 4, 0, 0, 1, 32, len(icon_png), 22) + icon_png)
picture("1x1.gif", b"GIF89a\x01\x00\x01\x00\x80\x00\x00\x00\x00\x00\xff\xff\xff"
        b"\x2c\x00\x00\x00\x00\x01\x00\x01\x00\x00\x02\x02\x44\x01\x00\x3b")
picture("bgr-4x4.tga", struct.pack("<BBBHHBHHHHBB", 0, 0, 2, 0, 0, 0, 0, 0, 4, 4, 24, 0x20) +
        rgb_4x4)
# The header as dds() writes it, its capabilities saying "a texture" (DDSCAPS_TEXTURE).
picture("rgb-8x8.dds", dds(8, 8, 1)[:108] + struct.pack("<I", 0x1000) + bytes(16) +
        bytes(range(192)))
# OpenEXR: as `oiiotool --pattern constant:color=0.5,0.25,1 2x2 3 -d half --compression none`
# writes it.
picture("rgb-2x2.exr", bytes.fromhex(
    "762f310102000000457869663a496d616765486973746f727900737472696e6700560000006f69696f746f6f6c202d2d"
    "7061747465726e20636f6e7374616e743a636f6c6f723d302e352c302e32352c31203278322033202d642068616c6620"
    "2d2d636f6d7072657373696f6e206e6f6e65202d6f20742e657872536f66747761726500737472696e67006c0000004f"
    "70656e496d616765494f20322e342e372e31203a206f69696f746f6f6c202d2d7061747465726e20636f6e7374616e74"
    "3a636f6c6f723d302e352c302e32352c31203278322033202d642068616c66202d2d636f6d7072657373696f6e206e6f"
    "6e65202d6f20742e6578726361704461746500737472696e670013000000323032363a31323a30362030383a33363a34"
    "386368616e6e656c730063686c6973740037000000420001000000000000000100000001000000470001000000000000"
    "00010000000100000052000100000000000000010000000100000000636f6d7072657373696f6e00636f6d7072657373"
    "696f6e0001000000006461746157696e646f7700626f7832690010000000000000000000000001000000010000006469"
    "73706c617957696e646f7700626f7832690010000000000000000000000001000000010000006c696e654f7264657200"
    "6c696e654f72646572000100000000706978656c417370656374526174696f00666c6f617400040000000000803f7363"
    "7265656e57696e646f7743656e746572007632660008000000000000000000000073637265656e57696e646f77576964"
    "746800666c6f617400040000000000803f0062020000000000007602000000000000000000000c000000003c003c0034"
    "003400380038010000000c000000003c003c0034003400380038"))
# SGI: a 512-byte header (magic 474, verbatim, a byte a channel, three channels), then planes.
picture("rgb-4x4.sgi", struct.pack(">HBBHHHHIII", 474, 0, 1, 3, 4, 4, 3, 0, 255, 0).ljust(512, b"\0")
        + bytes(range(48)))
# Findings kept as seeds: an SGI of storage 64 and 0 bytes a channel, which crashed its reader as
# it read a row; an OpenEXR of 26 half channels a million pixels wide in PIZ's chunks of 32
# lines, whose chunk buffer (1.6 GB) OpenEXR allocated as it opened the file.
picture("zero-bytes-4x4.sgi", struct.pack(">HBBHHHHIII", 474, 64, 0, 3, 4, 4, 3, 0, 255, 0)
        .ljust(512, b"\0") + bytes(range(48)))
# Findings kept as seeds: a FITS of three axes that names two (depth 0: the image cache aborted
# on it), and a DDS flagged alpha alone (0xFFFDFFC2, RGB among the flags) whose alpha mask is
# zero (its reader spread the alpha bits over a byte in steps of zero, for good).
picture("depth-0.fits", (fits_card("SIMPLE", "T") + fits_card("BITPIX", "8") + fits_card("NAXIS", "3")
                         + fits_card("NAXIS1", "9") + fits_card("NAXIS2", "4") + b"END".ljust(80))
        .ljust(2880, b" ") + bytes(range(36)).ljust(122, b"\0"))
picture("alpha-alone.dds", dds(8, 8, 1)[:80] + struct.pack("<I", 0xFFFDFFC2) + dds(8, 8, 1)[84:108]
        + struct.pack("<I", 0x1000) + bytes(16) + bytes(range(84)))
# A finding kept as found (zlib-compressed here): an uncompressed 20x24 DDS flagged ALPHAPIXELS
# alone whose bit count is 4227792896, for which OpenImageIO's reader asked 2 GB for a row (it
# checks the count only with other flags). The hostile-process tests read it from here.
picture("bits-a-pixel.dds", zlib.decompress(base64.b64decode(
    "eNpzcQlWqGFgYOAXYNKTANIiQCyxjAEMmBiwgUsMuIACEDPCtf7/zcDyn4GBBZsFGppa2jq6XMFA+f8g5YpgqqRSvSA1Na+M"
    "gUEAyFOHKQIALHQRrg==")))
# A finding kept as a seed: a TIFF of 24x2049 pixels whose RowsPerStrip says 855,640,105 rows;
# OpenImageIO sized its read buffer by it (20 GB).
picture("tall-strips.tif", bytes.fromhex(
    "49492a000800000009000001040001000000180000000101040001000000010800000200030001000000080000000301"
    "03000100000003000000060103000100000002000000110104000100000079fffffa155f030001000000030000001601"
    "040001000000290800330000000000000000000000000000000000002222222222222222222222222222222200000000"
    "0000000000006a7065670000"))
# And its variant: a second width entry of type 0 pointing past the file, which hid the first
# from the checks.
picture("tall-strips-width-0.tif", bytes.fromhex(
    "49492a000800000009000001040001000000180000000101040001000000010800000200030001000000080000000301"
    "03000100000003000000060103000100000002000000110104000100000079fffffa0001000000010800000200001601"
    "0400010000002908003300000000000000000000000000000000001b0022222222222222222222222222222222000000"
    "020000000000006a7065670000"))
# And one as found (zlib-compressed here): its directory's next offset cut off by the file's end,
# which hid the directory from the checks while libtiff read it: strips of 50,331,689 rows asked
# for 1.2 GB in the picture scene. The hostile-process tests read it from here.
picture("strips-no-next-offset.tif", zlib.decompress(base64.b64decode(
    "eNrz9NRi4GBgYOBkYGBkYWAEsiSAmBHKZgRKMTEwg9kgVcyMEDYzELNB2UxALAhVX/n//y/ReIQaMai4JogrBmQwZBWkpjMw"
    "AAAgLAcp")))
# RLE storage: tables of each row's offset and length (4x4, three channels: 12 rows), then each
# row as one run of 4 samples copied and an end. And a finding: one row of one channel whose
# tables (43283 x 0 entries) are empty, on which the reader crashed at the first row.
rle_rows = [bytes([0x84, 16 * r, 16 * r + 1, 16 * r + 2, 16 * r + 3, 0]) for r in range(12)]
picture("rle-4x4.sgi", struct.pack(">HBBHHHHIII", 474, 1, 1, 3, 4, 4, 3, 0, 255, 0).ljust(512, b"\0")
        + b"".join(struct.pack(">I", 512 + 96 + 6 * r) for r in range(12))
        + b"".join(struct.pack(">I", 6) for _ in range(12)) + b"".join(rle_rows))
picture("rle-empty-tables.sgi", struct.pack(">HBBHHHH", 474, 1, 1, 1, 256, 43283, 0)
        + bytes.fromhex("96" * 120 + "3ea91300003e86666974eaff00"))


# An icon of one 4x4 bitmap (32 bits a pixel, its colour rows then its mask rows), and a finding
# (zlib-compressed here): 105 directory entries, the first a bitmap whose header claims 2304
# bytes, 1 bit a pixel, a width of 16,778,241 and 2048 planes, on which OpenImageIO's ICO reader
# corrupted the heap (`strip_headers dump`: "double free or corruption").
dib_4x4 = struct.pack("<IiiHHIIiiII", 40, 4, 8, 1, 32, 0, 0, 0, 0, 0, 0) + bytes(64 + 16)
picture("bitmap-4x4.ico", struct.pack("<HHHBBBBHHII", 0, 1, 1, 4, 4, 0, 0, 1, 32, len(dib_4x4), 22)
        + dib_4x4)
picture("heap-1bit.ico", zlib.decompress(base64.b64decode(
    "eNrtVEtLw0AQnrQ9tOhBEDx52Iu3Jibp04AXUWtOBQW9eHBN0nYh3Q27i00v4sXf50+qm4TU2hQfRQSxQ2azmZ2ZfDPfsAAa"
    "EKhUQL0RPAPAnlKoqe+KMiVPVWm6h+odwPbDoaWVJONTEJITOoRrdTLC4S3SdY+NIx4IQRhFlNEA6Zm78jiLycBxx3gYXBCx"
    "HM4IYZKxUKWIsJQBp8hjVEhMpeOxkPFj02jVTcNu1bfWkv2PJHeCtNxUe+kKC5bLggUWqn23Tw99LPENoT6bwD2LbQI7kMvB"
    "PIVPRBTiaeb3yy1ZFgvZsY0aSPeRYnOA1gxbNQQMSSOI+RX7N3w3NnwnfA/kBPMgLzNUZfajgKa3gNtHttE0OoaFHPSN4rP/"
    "13ruefcIa6qrT2mPZ7MlSDxaBcnD0SmWc0S7KtI27bZj2Y7ZRmbXabSdZtcbYUqDUIA3CtVlBR3ldlKYhy/MzCP8EDlvXS5p"
    "5SSzEACuK8QnbRdFKTKxYekvsLQeEy85xiRpOUMFKV54BSG3oBQ=")))



def rla(colour_type, colour_bits, aux, aux_bits):
    """A 4x4 Wavefront RLA (big-endian; read as RLA by its name alone): 3 colour channels of
    colour_type (0 bytes, 1 words) and aux auxiliary byte channels, each row of each channel one
    run of 4 samples of a byte per byte of a sample (other types than 1 as bytes)."""
    head = struct.pack(">14h", 0, 3, 0, 3, 0, 3, 0, 3, 1, colour_type, 3, 0, aux, -2).ljust(740, b"\0")
    head = head[:658] + struct.pack(">5h", colour_bits, 0, 0, 0, aux_bits) + head[668:]
    row = b"".join(struct.pack(">H", 2 * n) + b"\x03\x40" * n
                   for n in [2 if colour_type == 1 else 1] * 3 + [1] * aux)
    return head + b"".join(struct.pack(">I", 740 + 16 + y * len(row)) for y in range(4)) + row * 4


# And three findings: an auxiliary channel of 0 bits, which the reader rescaled in a loop that
# never ends, words of 20 bits, which it rescaled as 32-bit samples past the end of its row, and
# colour of type 3 (the format's are 0, 1, 2 and 4), on which it aborted (an assertion).
picture("rgb-4x4.rla", rla(0, 8, 0, 0))
picture("aux-bits-0.rla", rla(0, 8, 1, 0))
picture("words-20-bits.rla", rla(1, 20, 0, 0))
picture("type-3.rla", rla(3, 8, 0, 0))
# And one as found (zlib-compressed here): a next image at byte -1, where the reader's failed
# seek left it reading a header from wherever the file stood; the picture scene hung. The
# hostile-process tests read it from here.
picture("next-offset-garbage.rla", zlib.decompress(base64.b64decode(
    "eNpjYGBgZkDGjEAIYjH8/8dAH8DIoMDQyqCMDh7e+f9/x6evT7mQ1ZakMhSXqGTmpTMIA3lGBkZmVoZGVgZmXFxwZYy3IPT/"
    "AQQMAw7EhqjZ2IAyCWpl5WAp5fv/mfD4YMphYGAqAuIKIK4D4hYg7gLiCUA8DYjnADHDIgYGNgZcmA1sKpwPNJTRBBTRRUw4"
    "jJ0ENXYRAz5jseAWBkYmZoYWAUEh4YFMQbYQioXZgdkBQgIADeKtLw==")))


def ico_bitmap(side, bits, colours):
    """An icon of one side x side bitmap of `bits` a pixel, its directory entry `colours`."""
    palette = bytes(4 << bits) if bits <= 8 else b""
    dib = (struct.pack("<IiiHHIIiiII", 40, side, 2 * side, 1, bits, 0, 0, 0, 0, 0, 0) + palette
           + bytes(((side * bits + 31) // 32 + (side + 31) // 32) * 4 * side))
    return struct.pack("<HHHBBBBHHII", 0, 1, 1, side, side, colours, 0, 1, 32, len(dib), 22) + dib


# Findings kept as seeds: a well-formed 12x12 icon of 4 bits a pixel, whose mask OpenImageIO's
# ICO reader writes past its buffer (it found a 4x4 one of 1 bit), and an 8-bit icon whose entry
# says 2 colours (the reader looks colours up by any value in a palette of 2).
picture("mask-12x12-4bit.ico", ico_bitmap(12, 4, 16))
picture("palette-8bit-2.ico", ico_bitmap(8, 8, 2))

def exr_attribute(name, type_, value):
    return name.encode() + b"\0" + type_.encode() + b"\0" + struct.pack("<I", len(value)) + value


picture("wide-chunk.exr", b"\x76\x2f\x31\x01" + struct.pack("<I", 2) +
        exr_attribute("channels", "chlist", b"".join(bytes([65 + c]) + b"\0" +
                      struct.pack("<IIII", 1, 0, 1, 1) for c in range(26)) + b"\0") +
        exr_attribute("compression", "compression", b"\x04") +
        exr_attribute("dataWindow", "box2i", struct.pack("<4i", 0, 0, 999999, 63)) +
        exr_attribute("displayWindow", "box2i", bytes(16)) +
        exr_attribute("lineOrder", "lineOrder", b"\0") +
        exr_attribute("pixelAspectRatio", "float", struct.pack("<f", 1)) +
        exr_attribute("screenWindowCenter", "v2f", bytes(8)) +
        exr_attribute("screenWindowWidth", "float", struct.pack("<f", 1)) + b"\0" + bytes(512))


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


# --- tuio: TUIO 1.1 bundles (/tuio/2Dcur), datagrams joined by "|~|" (fuzz_tuio.cpp) -----------
def osc_string(s):
    b = s.encode() + b"\0"
    return b + b"\0" * (-len(b) % 4)


def osc_message(address, *args):
    tags, data = ",", b""
    for a in args:
        if isinstance(a, str):
            tags, data = tags + "s", data + osc_string(a)
        elif isinstance(a, int):
            tags, data = tags + "i", data + struct.pack(">i", a)
        else:
            tags, data = tags + "f", data + struct.pack(">f", a)
    return osc_string(address) + osc_string(tags) + data


def tuio_frame(fseq, fingers):
    elements = [osc_message("/tuio/2Dcur", "source", "seed@127.0.0.1"),
                osc_message("/tuio/2Dcur", "alive", *[f[0] for f in fingers])]
    elements += [osc_message("/tuio/2Dcur", "set", i, x, y, 0.0, 0.0, 0.0) for i, x, y in fingers]
    elements.append(osc_message("/tuio/2Dcur", "fseq", fseq))
    return b"#bundle\0" + struct.pack(">II", 0, 1) + b"".join(
        struct.pack(">I", len(e)) + e for e in elements)


put("tuio", "drag", b"|~|".join(tuio_frame(n, [(3, 0.2 + 0.05 * n, 0.3)]) for n in range(4))
    + b"|~|" + tuio_frame(4, []))
put("tuio", "pinch", b"|~|".join(
    tuio_frame(n, [(1, 0.3 - 0.02 * n, 0.4), (2, 0.35 + 0.02 * n, 0.4)]) for n in range(3)))
put("tuio", "tap", tuio_frame(1, [(9, 0.25, 0.25)]) + b"|~|" + tuio_frame(2, []))
