#!/usr/bin/env python3
# 8-bit RMSE between two PNG pictures (usage: picture_rmse.py A.png B.png) of the same size (RGB or RGBA, 8 bits), no libraries.
import struct, sys, zlib
def read(path):
    data = open(path, 'rb').read()
    pos, chunks, w = 8, b'', 0
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b'IHDR': w, h, depth, colour = struct.unpack('>IIBB', body[:10])
        if kind == b'IDAT': chunks += body
        pos += 12 + n
    bpp = {2: 3, 6: 4}[colour]
    raw, stride, rows, prev = zlib.decompress(chunks), w * bpp, [], bytearray(w * bpp)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line); prev = line
    return [px for row in rows for k, px in enumerate(row) if k % bpp < 3]
a, b = read(sys.argv[1]), read(sys.argv[2])
print(f"{(sum((x - y) ** 2 for x, y in zip(a, b)) / len(a)) ** 0.5:.2f}")
