"""A small OpenEXR reader for the float images our mapper writes (WriteLastImageEXR): scanline
files, FLOAT channels, compression NONE, ZIPS or ZIP (OpenEXR's default). No dependency beyond
numpy and zlib, so float scoring needs no extra package.

    rgba = read_exr(path)   # (height, width, channels) float32, row 0 at the BOTTOM (VTK order),
                            # channels in the order R, G, B, A where present
"""
import struct
import zlib

import numpy as np

_LINES = {0: 1, 2: 1, 3: 16}  # NONE, ZIPS, ZIP: scanlines a chunk


def _undo_zip(data, size):
    d = np.frombuffer(zlib.decompress(data), np.uint8).astype(np.int64)
    # Predictor: t[i] = t[i-1] + d[i] - 128 (mod 256), t[0] = d[0].
    t = ((np.cumsum(d) - 128 * np.arange(len(d))) & 0xFF).astype(np.uint8)
    half = (len(t) + 1) // 2
    out = np.empty(len(t), np.uint8)
    out[0::2], out[1::2] = t[:half], t[half:]
    if len(out) != size:
        raise ValueError("EXR ZIP chunk: %d bytes after decompression, expected %d" % (len(out), size))
    return out.tobytes()


def read_exr(path):
    with open(path, "rb") as f:
        buf = f.read()
    if buf[:4] != b"\x76\x2f\x31\x01":
        raise ValueError("%s: not an OpenEXR file (magic %r)" % (path, buf[:4]))
    pos, attrs = 8, {}
    while buf[pos] != 0:
        end = buf.index(b"\0", pos)
        name = buf[pos:end].decode()
        tend = buf.index(b"\0", end + 1)
        (size,) = struct.unpack_from("<i", buf, tend + 1)
        attrs[name] = buf[tend + 5:tend + 5 + size]
        pos = tend + 5 + size
    pos += 1
    channels, c = [], attrs["channels"]
    p = 0
    while c[p] != 0:
        end = c.index(b"\0", p)
        ptype = struct.unpack_from("<i", c, end + 1)[0]
        if ptype != 2:
            raise ValueError("%s: channel %s is not FLOAT (type %d)" % (path, c[p:end], ptype))
        channels.append(c[p:end].decode())
        p = end + 1 + 16
    compression = attrs["compression"][0]
    if compression not in _LINES:
        raise ValueError("%s: compression %d, expected NONE (0), ZIPS (2) or ZIP (3)" % (path, compression))
    x0, y0, x1, y1 = struct.unpack("<4i", attrs["dataWindow"])
    w, h = x1 - x0 + 1, y1 - y0 + 1
    lines = _LINES[compression]
    nchunks = (h + lines - 1) // lines
    offsets = struct.unpack_from("<%dQ" % nchunks, buf, pos)
    img = np.zeros((h, len(channels), w), np.float32)  # top-down rows, channels sorted by name
    for off in offsets:
        y, size = struct.unpack_from("<2i", buf, off)
        data = buf[off + 8:off + 8 + size]
        n = min(lines, y1 - y + 1)
        raw = n * len(channels) * w * 4
        if compression != 0 and size < raw:
            data = _undo_zip(data, raw)
        img[y - y0:y - y0 + n] = np.frombuffer(data, "<f4").reshape(n, len(channels), w)
    order = [channels.index(k) for k in "RGBA" if k in channels]
    return np.ascontiguousarray(img[::-1].transpose(0, 2, 1)[..., order])
