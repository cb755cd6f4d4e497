#!/usr/bin/env python3
"""The PNG pictures a run wrote show something: not blank, not constant.

Usage: check_png.py <file.png>... Decodes each file (8-bit gray, gray +
alpha, RGB or RGBA, not interlaced: what VTK's and matplotlib's writers
produce) with zlib only and fails (exit 1) if a file is missing or
unreadable, or if fewer than min_share of its pixels differ from its most
frequent colour (a blank or constant image, or one with a few stray
pixels). Prints one line per file: size, distinct colours, share of the
pixels that differ from the most frequent colour.

Usage: check_png.py --same <a.png> <b.png>: fails (exit 1) unless both
files decode to the same size and the same pixels (the picture of a run
on 1 and on 2 ranks).

Usage: check_png.py --self-test <directory>: writes a constant, a white,
a nearly constant and a half black picture there and checks that the
first three fail and the last passes (the check can fail), and that
--same fails for the white and the half black picture and passes for one
picture and itself.
"""
import collections
import struct
import sys
import zlib

min_share = 0.01
channels_of_type = {0: 1, 2: 3, 4: 2, 6: 4}


def chunks(data):
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG file")
    pos = 8
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        yield kind, data[pos + 8:pos + 8 + length]
        pos += 12 + length


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else (b if pb <= pc else c)


def pixels(path):
    data = open(path, "rb").read()
    header, idat = None, b""
    for kind, body in chunks(data):
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in channels_of_type or interlace:
        raise ValueError(f"unsupported PNG (depth {depth}, colour type "
                         f"{colour}, interlace {interlace})")
    bpp = channels_of_type[colour]
    stride = width * bpp
    raw = zlib.decompress(idat)
    previous = bytearray(stride)
    rows = []
    for y in range(height):
        line = raw[y * (stride + 1):(y + 1) * (stride + 1)]
        kind, row = line[0], bytearray(line[1:])
        for i in range(stride):
            a = row[i - bpp] if i >= bpp else 0
            b = previous[i]
            c = previous[i - bpp] if i >= bpp else 0
            if kind == 1:
                row[i] = (row[i] + a) & 255
            elif kind == 2:
                row[i] = (row[i] + b) & 255
            elif kind == 3:
                row[i] = (row[i] + (a + b) // 2) & 255
            elif kind == 4:
                row[i] = (row[i] + paeth(a, b, c)) & 255
        rows.append(bytes(row))
        previous = row
    return width, height, [r[i:i + bpp] for r in rows
                           for i in range(0, stride, bpp)]


def write_rgb(path, pixel, n=64):
    """An n x n RGB picture, pixel(x, y) the 3 bytes of a pixel."""
    raw = b"".join(b"\x00" + b"".join(pixel(x, y) for x in range(n))
                   for y in range(n))
    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body +
                struct.pack(">I", zlib.crc32(kind + body) & 0xffffffff))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" +
                chunk(b"IHDR", struct.pack(">IIBBBBB", n, n, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def self_test(directory):
    cases = {"constant": (lambda x, y: b"\x80\x80\x80", 1),
             "white": (lambda x, y: b"\xff\xff\xff", 1),
             "one_stray_pixel": (lambda x, y: b"\x00\x00\x00" if x == y == 3
                                 else b"\xff\xff\xff", 1),
             "half_black": (lambda x, y: b"\x00\x00\x00" if x < 32
                            else b"\xff\xff\xff", 0)}
    wrong = 0
    for name, (pixel, expected) in cases.items():
        path = f"{directory}/{name}.png"
        write_rgb(path, pixel)
        status = main([path])
        if status != expected:
            print(f"WRONG: status {status} for {name}.png, expected {expected}")
            wrong = 1
    white, half = f"{directory}/white.png", f"{directory}/half_black.png"
    for a, b, expected in [(white, half, 1), (half, half, 0)]:
        status = same([a, b])
        if status != expected:
            print(f"WRONG: --same status {status} for {a} {b}")
            wrong = 1
    print("the check fails for blank pictures" if not wrong else "FAIL")
    return wrong


def same(paths):
    if len(paths) != 2:
        print("--same needs two files")
        return 1
    try:
        a, b = (pixels(path) for path in paths)
    except (OSError, ValueError, TypeError, zlib.error, struct.error) as e:
        print(f"FAIL cannot read {paths} ({e})")
        return 1
    if a == b:
        print(f"OK   {paths[0]} and {paths[1]}: the same pixels")
        return 0
    differ = sum(x != y for x, y in zip(a[2], b[2])) if a[:2] == b[:2] \
        else "all"
    print(f"FAIL {paths[0]} and {paths[1]} differ ({a[0]} x {a[1]} and "
          f"{b[0]} x {b[1]}, {differ} pixels differ)")
    return 1


def main(paths):
    failed = 0
    for path in paths:
        try:
            width, height, values = pixels(path)
        except (OSError, ValueError, TypeError, zlib.error, struct.error) as e:
            print(f"FAIL {path}: cannot read it ({e})")
            failed = 1
            continue
        counts = collections.Counter(values)
        share = 1 - counts.most_common(1)[0][1] / len(values)
        ok = share >= min_share
        print(f"{'OK  ' if ok else 'FAIL'} {path}: {width} x {height}, "
              f"{len(counts)} colours, {share:.1%} of the pixels differ "
              f"from the most frequent colour")
        failed |= not ok
    return 1 if failed or not paths else 0


if __name__ == "__main__":
    if sys.argv[1:2] == ["--self-test"]:
        sys.exit(self_test(sys.argv[2]))
    if sys.argv[1:2] == ["--same"]:
        sys.exit(same(sys.argv[2:]))
    sys.exit(main(sys.argv[1:]))
