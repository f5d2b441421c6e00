#!/usr/bin/env python3
"""Makes the environment images raylab ships (issue 24), from formulas: nothing
is downloaded. Writes scenes/environments/{sky.hdr, studio.hdr, white.pfm, small-sun.pfm}.

    python3 scripts/make-environments.py [OUTPUT_FOLDER]

Equirectangular, as docs/model.md "Environment light" maps them: pixel (x, y)
covers u in [x/W, (x+1)/W), v in [y/H, (y+1)/H), row 0 at the top; the
direction of (u, v) is
    phi = 2 pi (u - 1/2), theta = pi v
    d = (sin theta sin phi, cos theta, -sin theta cos phi)
so the middle column looks along -z (where raylab's default camera looks)
and u = 3/4 along +x. Each pixel is the mean of 4x4 points inside it, so the
sun's edge is antialiased. Plain python3, no numpy: the output is the same
bytes on every machine (IEEE double arithmetic, then RGBE or float32).
"""
import math
import os
import struct
import sys

SUPERSAMPLE = 4


def direction(u, v):
    phi = 2.0 * math.pi * (u - 0.5)
    theta = math.pi * v
    s = math.sin(theta)
    return (s * math.sin(phi), math.cos(theta), -s * math.cos(phi))


def from_angles(elevation_deg, azimuth_deg):
    """Unit vector at an elevation above the horizon and an azimuth from -z towards +x."""
    e = math.radians(elevation_deg)
    a = math.radians(azimuth_deg)
    return (math.cos(e) * math.sin(a), math.sin(e), -math.cos(e) * math.cos(a))


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def mix(a, b, t):
    return tuple(x + (y - x) * t for x, y in zip(a, b))


# ---- the sky: blue gradient, a sun disc, grey-brown ground ------------------
SUN = from_angles(35.0, -40.0)  # 35 degrees up, to the camera's front left
SUN_RADIUS = math.radians(2.5)  # five times the real sun, so that 256x128 pixels resolve it
SUN_RADIANCE = (500.0, 470.0, 420.0)  # irradiance about 5 at normal incidence, the sky's about 2.5


def sky(d):
    if dot(d, SUN) >= math.cos(SUN_RADIUS):
        return SUN_RADIANCE
    if d[1] >= 0.0:
        horizon = (0.95, 1.0, 1.05)
        zenith = (0.20, 0.38, 0.85)
        t = math.sqrt(d[1])
        base = mix(horizon, zenith, t)
        glow = 0.6 * max(dot(d, SUN), 0.0) ** 8  # brighter around the sun
        return tuple(c + glow for c in base)
    ground = (0.30, 0.26, 0.21)
    fade = 1.0 - 0.5 * min(-d[1] * 3.0, 1.0)  # darker straight down
    return tuple(c * fade for c in ground)


# ---- a small bright sun: one pixel of a 128x64 map, on a dim sky ---------------
# (issue 34: the case where a heavy-tailed estimate and SH9's ringing show)
SMALL_SUN = from_angles(40.0, 25.0)
SMALL_SUN_RADIUS = math.radians(1.0)
SMALL_SUN_RADIANCE = (20000.0, 19000.0, 17000.0)  # irradiance about 6 at normal incidence


def small_sun(d):
    if dot(d, SMALL_SUN) >= math.cos(SMALL_SUN_RADIUS):
        return SMALL_SUN_RADIANCE
    if d[1] >= 0.0:
        return mix((0.25, 0.28, 0.32), (0.05, 0.09, 0.2), math.sqrt(d[1]))
    return (0.08, 0.07, 0.06)


# ---- the studio: a dark room with three soft boxes ---------------------------
def panel(d, centre_elevation, centre_azimuth, half_width_deg, half_height_deg):
    """True inside a rectangle of angles around a direction (a soft box seen from the middle)."""
    elevation = math.degrees(math.asin(max(-1.0, min(1.0, d[1]))))
    azimuth = math.degrees(math.atan2(d[0], -d[2]))
    da = (azimuth - centre_azimuth + 180.0) % 360.0 - 180.0
    return abs(elevation - centre_elevation) <= half_height_deg and abs(da) <= half_width_deg


def studio(d):
    if panel(d, 70.0, 0.0, 40.0, 12.0):  # key: a wide box overhead, towards the camera's view
        return (12.0, 12.0, 11.5)
    if panel(d, 15.0, -100.0, 8.0, 30.0):  # a tall strip on the left
        return (6.0, 6.5, 7.0)
    if panel(d, 20.0, 110.0, 12.0, 15.0):  # a warm box on the right, behind
        return (8.0, 6.0, 4.0)
    if d[1] < 0.0:
        return (0.08, 0.08, 0.08)  # the floor
    return (0.03, 0.03, 0.035)  # the walls


def white(d):
    return (1.0, 1.0, 1.0)


def render(function, width, height):
    rows = []
    for y in range(height):
        row = []
        for x in range(width):
            total = [0.0, 0.0, 0.0]
            for sy in range(SUPERSAMPLE):
                for sx in range(SUPERSAMPLE):
                    u = (x + (sx + 0.5) / SUPERSAMPLE) / width
                    v = (y + (sy + 0.5) / SUPERSAMPLE) / height
                    c = function(direction(u, v))
                    for k in range(3):
                        total[k] += c[k]
            n = SUPERSAMPLE * SUPERSAMPLE
            row.append(tuple(t / n for t in total))
        rows.append(row)
    return rows  # rows[0] is the top


# ---- writers -----------------------------------------------------------------
def rgbe(c):
    m = max(c)
    if m < 1e-32:
        return bytes((0, 0, 0, 0))
    mantissa, exponent = math.frexp(m)  # m = mantissa 2^exponent, mantissa in [0.5, 1)
    scale = mantissa * 256.0 / m
    return bytes((int(c[0] * scale), int(c[1] * scale), int(c[2] * scale), exponent + 128))


def write_hdr(path, rows):
    height, width = len(rows), len(rows[0])
    out = bytearray(b"#?RADIANCE\n# made by scripts/make-environments.py\nFORMAT=32-bit_rle_rgbe\n\n")
    out += b"-Y %d +X %d\n" % (height, width)
    for row in rows:
        # New-style run-length scanline: 2 2 W/256 W%256, then each of the 4
        # components in literal runs of at most 128 (no repeat runs: simple,
        # and unambiguous whatever the first pixel holds).
        out += bytes((2, 2, width >> 8, width & 255))
        pixels = [rgbe(c) for c in row]
        for component in range(4):
            values = [p[component] for p in pixels]
            for start in range(0, width, 128):
                chunk = values[start:start + 128]
                out.append(len(chunk))
                out += bytes(chunk)
    with open(path, "wb") as f:
        f.write(out)


def write_pfm(path, rows):
    height, width = len(rows), len(rows[0])
    out = bytearray(b"PF\n%d %d\n-1.0\n" % (width, height))
    for row in reversed(rows):  # PFM stores the bottom row first
        for c in row:
            out += struct.pack("<3f", *c)
    with open(path, "wb") as f:
        f.write(out)


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "scenes", "environments")
    os.makedirs(folder, exist_ok=True)
    write_hdr(os.path.join(folder, "sky.hdr"), render(sky, 256, 128))
    write_hdr(os.path.join(folder, "studio.hdr"), render(studio, 256, 128))
    write_pfm(os.path.join(folder, "white.pfm"), render(white, 64, 32))
    write_pfm(os.path.join(folder, "small-sun.pfm"), render(small_sun, 128, 64))


if __name__ == "__main__":
    main()
