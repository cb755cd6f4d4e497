#!/bin/sh
# Usage: damaged_png.sh <ranks> <mpiexec> <build directory> <work directory>
# PNG images whose chunks are complete with correct checksums and whose
# data has the size the header asks for, but which libpng cannot decode:
# a row with the adaptive filter value 7 (0-4 exist), a palette image
# without PLTE chunk, a PLTE chunk of 7 bytes (not a multiple of 3), bit
# depth 3 and an unknown critical chunk (type "CRIT" before IDAT). Each
# one, as the image of edge_restoration (<Geometry / Image file>) and as
# the target of shape_from_contour (<Target / Image file>), must end the
# run with exit status 2 and a message naming the file and the parameter,
# without a crash, a hang or libpng's own error line
# (doc/edge_restoration.md, "Geometry / Image file").
ranks="$1"; mpiexec="$2"; build="$3"; work="$4"
. "$(dirname "$0")/common.sh"
rm -rf "$work"; mkdir -p "$work"
/usr/bin/python3 - "$work" <<'PY'
import os, struct, sys, zlib
work = sys.argv[1]
def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))
def png(name, bit_depth, color_type, rows, extra=b"", width=4):
    header = struct.pack(">IIBBBBB", width, len(rows), bit_depth, color_type, 0, 0, 0)
    data = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + extra +
            chunk(b"IDAT", zlib.compress(b"".join(rows))) + chunk(b"IEND", b""))
    open(os.path.join(work, name + ".png"), "wb").write(data)
gray = [b"\x00" + bytes([0, 255, 0, 255])] * 2
png("bad_filter", 8, 0, [b"\x07" + bytes([0, 255, 0, 255])] * 2)
png("palette_without_plte", 8, 3, [b"\x00" + bytes([0, 0, 0, 0])] * 2)
png("plte_length_7", 8, 3, [b"\x00" + bytes([0, 0, 0, 0])] * 2,
    chunk(b"PLTE", bytes(7)))
png("bit_depth_3", 3, 0, [b"\x00" + bytes([0, 0])] * 2)
png("unknown_critical_chunk", 8, 0, gray, chunk(b"CRIT", b"data"))
PY
for image in bad_filter palette_without_plte plte_length_7 bit_depth_3 \
    unknown_critical_chunk; do
  file="$work/$image.png"
  run "$ranks" "$build/edge_restoration" --set "Geometry/Shape=image" \
    --set "Geometry/Image file=$file" --set "Mesh/Finest level=5" \
    --set "Output directory=$work/restoration_$image"
  expect "edge_restoration, $image" 2 \
    "image file <$file> given in <Geometry / Image file> is a damaged PNG image: .+ \(libpng\)"
  if printf '%s' "$output" | grep -q "libpng error"; then
    echo "FAIL: libpng's own error line is printed"; failed=1
  fi
  run "$ranks" "$build/shape_from_contour" --set "Target/Shape=image" \
    --set "Target/Image file=$file" \
    --set "Output directory=$work/contour_$image"
  expect "shape_from_contour, $image" 2 \
    "image file <$file> given in <Target / Image file> is a damaged PNG image: .+ \(libpng\)"
  if printf '%s' "$output" | grep -q "libpng error"; then
    echo "FAIL: libpng's own error line is printed"; failed=1
  fi
done
exit $failed
