#!/usr/bin/env python3
"""Draws the app icon, assets/icons/hdprior.png (128 x 128 RGBA): a curved road of the drivable
area with its kerbs, and a trajectory along it whose keyframes are pulled onto the road, the idea of
the HD-map prior. Standard library only; run it again after changing the drawing."""
import math
import struct
import sys
import zlib

SIZE = 128
ROAD_HALF_WIDTH = 17.0
KERB = 3.0


def road_centre(y):
    """The road's centre x at row y: a gentle S-bend from bottom to top."""
    return SIZE / 2 + 22 * math.sin((y / SIZE - 0.5) * math.pi)


def distance_to_polyline(x, y, points):
    best = float("inf")
    for (ax, ay), (bx, by) in zip(points, points[1:]):
        dx, dy = bx - ax, by - ay
        t = max(0.0, min(1.0, ((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy)))
        best = min(best, math.hypot(x - ax - t * dx, y - ay - t * dy))
    return best


def pixel(x, y, trajectory, keyframes):
    cx, cy = x + 0.5, y + 0.5
    # Rounded square background (transparent outside).
    corner = 22.0
    qx, qy = max(abs(cx - SIZE / 2) - (SIZE / 2 - corner), 0), max(abs(cy - SIZE / 2) - (SIZE / 2 - corner), 0)
    if math.hypot(qx, qy) > corner:
        return (0, 0, 0, 0)
    colour = (28, 36, 48, 255)
    lateral = abs(cx - road_centre(cy))
    if lateral < ROAD_HALF_WIDTH:
        colour = (120, 128, 138, 255)
    elif lateral < ROAD_HALF_WIDTH + KERB:
        colour = (235, 235, 235, 255)
    if distance_to_polyline(cx, cy, trajectory) < 2.2:
        colour = (255, 170, 40, 255)
    for kx, ky in keyframes:
        if math.hypot(cx - kx, cy - ky) < 5.0:
            colour = (60, 200, 255, 255)
    return colour


def png(width, height, rows):
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    raw = b"".join(b"\x00" + bytes(c for px in row for c in px) for row in rows)
    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")


def main(out):
    trajectory = [(road_centre(y) + 4 * math.sin(y / 9.0), y) for y in range(SIZE + 1, -2, -4)]
    keyframes = [(road_centre(y), y) for y in (100, 64, 28)]
    rows = [[pixel(x, y, trajectory, keyframes) for x in range(SIZE)] for y in range(SIZE)]
    with open(out, "wb") as f:
        f.write(png(SIZE, SIZE, rows))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "assets/icons/hdprior.png")
