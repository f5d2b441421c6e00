#!/usr/bin/env python3
"""Scenes of issue #23's kinds (the camera just above a huge sphere, tiny
spheres on a huge one, a light on a surface, a sphere far from the origin, a
huge sphere around the camera), written apart from the metamorphic suite's,
at 96x72. Each is rendered by `raylab render` (the program for the picture),
`raylab render --generic` and `raylab render --cpu`, judged against the
true picture (build/bin/judge), and its PFM searched for NaN and Inf.
Run from the repository root after building raylab and judge:
    python3 scripts/judge-hard-kinds.py [--raylab BINARY] [--root DIR] [--out DIR]
--root runs the binary with RAYLAB_ROOT=DIR (the shaders and solutions of
another tree: the "before" column of docs/numerics.md). docs/numerics.md
quotes its figures."""
import array, json, math, os, subprocess, sys

args = sys.argv[1:]
def option(name, default):
    if name in args:
        i = args.index(name); value = args[i + 1]; del args[i:i + 2]; return value
    return default
raylab = option('--raylab', 'build/bin/raylab')
root = option('--root', None)
out = option('--out', 'build/judge-hard-kinds')
os.makedirs(out, exist_ok=True)
env = dict(os.environ)
if root: env['RAYLAB_ROOT'] = root

def scene(cam, target, spheres, lights, fov=40, bounces=2):
    return {"camera": {"position": cam, "target": target, "up": [0, 1, 0], "fov_y": fov},
            "render": {"width": 96, "height": 72, "max_bounces": bounces, "background": [0.2, 0.25, 0.35]},
            "lights": lights, "spheres": spheres}
def ball(c, r, albedo=(0.8, 0.8, 0.8), rough=0.5, metal=0.0):
    return {"center": list(c), "radius": r, "material": {"albedo": list(albedo), "roughness": rough, "metallic": metal}}
def light(p, i, colour=(1, 1, 1)):
    return {"position": list(p), "intensity": i, "color": list(colour)}

def camera_above(R, h, rough=0.0):
    return scene([0, h, 0], [0, 0.6 * h, -10 * h],
                 [ball((0, -R, 0), R, rough=rough), ball((-1.5 * h, 2 * h, -12 * h), 2 * h, (0.9, 0.3, 0.1), 0.3),
                  ball((3 * h, 2 * h, -20 * h), 2 * h, (0.9, 0.9, 0.9), 0.045, 1.0)],
                 [light((2 * h, 6 * h, -6 * h), 40 * h * h), light((-8 * h, 3 * h, -30 * h), 60 * h * h, (0.6, 0.7, 1))])
def tiny_on_huge(R, r, height):
    s = [ball((0, -R, 0), R, (0.7, 0.7, 0.7), 0.5)]
    for k in range(5):
        s.append(ball(((k - 2) * 2.5 * r, r, -(8 + 3 * (k % 3)) * r), r, (0.3 + 0.1 * k, 0.5, 0.9 - 0.1 * k), 0.2 + 0.15 * k, 1.0 if k == 4 else 0.0))
    return scene([0, height, 0], [0, 0.3 * height, -10 * r], s, [light((3 * r, 10 * r, -2 * r), 200 * r * r), light((-20 * r, 4 * r, -10 * r), 300 * r * r)])
def light_on_surface():
    return scene([0.5, 2.5, 6], [0, 0.7, 0],
                 [ball((0, -100, 0), 100, rough=0.6), ball((0, 1, 0), 1, (0.9, 0.3, 0.1), 0.3), ball((1.8, 0.5, 0.6), 0.5, (0.3, 0.9, 0.4), 0.4)],
                 [light((0, 2, 0), 3), light((1.8, 1, 0.6), 2, (0.6, 0.7, 1)), light((-2, math.sqrt(1e4 - 5) - 100, 1), 2, (1, 0.8, 0.6)), light((0.6, 1, 0.8), 2)])
far = 1e10
S = {
    "ground-1e5-camera-1e-3": camera_above(1e5, 1e-3),
    "tiny-1e-4-on-1e4-camera-4e-4": tiny_on_huge(1e4, 1e-4, 4e-4),
    "tiny-1e-3-on-1e5-camera-3e-3": tiny_on_huge(1e5, 1e-3, 3e-3),
    "ground-1e6-camera-1e-1": camera_above(1e6, 1e-1),
    "light-on-surface": light_on_surface(),
    "sphere-at-1e10": scene([far, -far, -far + 6], [far, -far, -far], [ball((far, -far, -far), 1, (0.9, 0.3, 0.1), 0.3)],
                            [light((far + 2, -far + 3, -far + 4), 20)]),
    "sphere-at-1e10-camera-at-origin": scene([0, 0, 0], [far, -far, -far], [ball((far, -far, -far), 1e9, (0.9, 0.3, 0.1), 0.3)],
                                             [light((0, 1, 0), 20)]),
    "inside-radius-1e18": scene([0, 0.2, 0], [0, 0, -5], [ball((0, 0, 0), 1e18), ball((0, 0, -5), 1, (0.9, 0.3, 0.1), 0.3)], [light((0, 2, -3), 20)]),
    "inside-radius-2e64": scene([0, 0.2, 0], [0, 0, -5], [ball((0, 0, 0), 2.0 ** 64), ball((0, 0, -5), 1, (0.9, 0.3, 0.1), 0.3)], [light((0, 2, -3), 20)]),
}
def nonfinite(path):
    data = open(path, 'rb').read().split(b'\n', 3)
    a = array.array('f'); a.frombytes(data[3])
    return sum(1 for v in a if not math.isfinite(v)), len(a)
names = args or list(S)
for name in names:
    f = f"{out}/{name}.json"; json.dump(S[name], open(f, "w"))
    cells = []
    pictures = []
    for how, extra in (("gl", []), ("generic", ["--generic"]), ("cpu", ["--cpu"])):
        png, pfm = f"{out}/{name}-{how}.png", f"{out}/{name}-{how}.pfm"
        for p in (png, pfm):
            if os.path.exists(p): os.remove(p)
        r = subprocess.run([raylab, "render", f, "-o", png, "--hdr", pfm] + extra, capture_output=True, text=True, env=env)
        if r.returncode != 0:
            cells.append(f"{how}: exit {r.returncode}: {r.stderr.strip().splitlines()[-1] if r.stderr.strip() else ''}")
            continue
        bad, total = nonfinite(pfm)
        cells.append(f"{how}: {bad} of {total} PFM values NaN/Inf")
        pictures.append(png)
    if pictures:
        r = subprocess.run(["build/bin/judge", f, f"{out}/{name}-truth.png"] + pictures, capture_output=True, text=True)
        cells += [l.replace(out + "/", "") for l in r.stdout.strip().splitlines()] + ([r.stderr.strip()] if r.stderr.strip() else [])
    print(name, "|", " | ".join(cells), flush=True)
