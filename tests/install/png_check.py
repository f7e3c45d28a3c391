"""Checks the backend scene's PNGs (examples/scene.cpp, c/scene.c, python/scene.py): sampled pixels
against values worked out from the scene's geometry, and every file pixel for pixel against the
golden. Pure Python (zlib), independent of casteljau. Usage: png_check.py GOLDEN.png OUT.png..."""
import struct
import sys
import zlib


def decode(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path + ": not a PNG"
    pos, idat, hdr = 8, b"", None
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            hdr = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    w, h, depth, ctype, _, _, interlace = hdr
    assert depth == 8 and interlace == 0, path + ": only 8-bit non-interlaced files are checked"
    channels = {0: 1, 2: 3, 4: 2, 6: 4}[ctype]
    raw, bpp, stride = zlib.decompress(idat), channels, w * channels
    rows, prev, i = [], bytearray(stride), 0
    for _ in range(h):
        f, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b, c = prev[x], prev[x - bpp] if x >= bpp else 0
            if f == 1: line[x] = (line[x] + a) & 255
            elif f == 2: line[x] = (line[x] + b) & 255
            elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    def px(x, y):
        v = rows[y][x * channels:(x + 1) * channels]
        return {1: lambda: (v[0], v[0], v[0], 255), 2: lambda: (v[0], v[0], v[0], v[1]),
                3: lambda: (v[0], v[1], v[2], 255), 4: lambda: tuple(v)}[channels]()
    return w, h, px


def near(got, want, tol=1):
    return all(abs(g - w) <= tol for g, w in zip(got, want))


def check_scene(path):
    w, h, px = decode(path)
    errors = []
    def expect(x, y, want, tol=1, what=""):
        if not near(px(x, y), want, tol):
            errors.append("%s: pixel (%d, %d) %s is %s, expected %s" % (path, x, y, what, px(x, y), want))
    if (w, h) != (200, 120):
        return ["%s: size %dx%d, expected 200x120" % (path, w, h)]
    expect(5, 5, (255, 255, 255, 255), 0, "background")
    expect(35, 30, (255, 0, 0, 255), 0, "red rectangle")
    for x in (85, 120, 135, 180):  # linear gradient blue -> green from x = 80 to 190
        t = (x + 0.5 - 80) / 110
        expect(x, 30, (0, round(255 * t), round(255 * (1 - t)), 255), 1, "gradient")
    expect(50, 90, (255, 165, 0, 255), 0, "inside the clip circle")
    expect(10, 115, (255, 255, 255, 255), 0, "outside the clip circle")
    expect(140, 70, (0, 0, 0, 255), 0, "stroke")
    expect(140, 66, (255, 255, 255, 255), 0, "beside the stroke")
    expect(175, 85, (255, 0, 0, 255), 0, "image")
    expect(185, 85, (0, 255, 0, 255), 0, "image")
    expect(175, 95, (0, 0, 255, 255), 0, "image")
    expect(185, 95, (255, 255, 255, 255), 0, "image")
    ink = sum(1 for y in range(90, 110) for x in range(90, 165) if px(x, y)[0] < 128)
    if ink < 40:
        errors.append("%s: only %d dark text pixels" % (path, ink))
    return errors


def main(golden, outputs):
    errors = check_scene(golden)
    gw, gh, gpx = decode(golden)
    for out in outputs:
        errors += check_scene(out)
        w, h, px = decode(out)
        diff = sum(1 for y in range(gh) for x in range(gw) if (w, h) != (gw, gh) or px(x, y) != gpx(x, y))
        if diff:
            errors.append("%s: %d pixels differ from %s" % (out, diff, golden))
    for e in errors:
        print(e)
    print("png_check: %d files, %d problems" % (1 + len(outputs), len(errors)))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2:]))
