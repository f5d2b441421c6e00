#!/usr/bin/env python3
"""Scenes of issue #10's kinds (touching spheres with 6 lights, spp 4, no
bounces; 1e-3 and 1e3 scales; a distant camera; a 1e5 ground with grazing
light; the camera inside a sphere; facing mirrors), written apart from the
metamorphic suite's generator, at 320x240. Each is rendered by `raylab render`
(GLSL) and `raylab render --cpu`, and judged against the true picture
(build/bin/judge). Run from the repository root after scripts/build.sh:
    python3 scripts/judge-kinds.py [SEED [NAME...]] [--out DIR]
docs/numerics.md quotes its figures."""
import json, math, random, subprocess, sys, os

W, H = 320, 240
R = None  # set below, from the seed
args = [a for a in sys.argv[1:]]
out = args[args.index('--out') + 1] if '--out' in args else 'build/judge-kinds'
if '--out' in args: del args[args.index('--out'):args.index('--out') + 2]
os.makedirs(out, exist_ok=True)
def mat(metal=None):
    m = {"albedo": [round(R.uniform(0.1, 0.95), 3) for _ in range(3)], "roughness": round(R.uniform(0.03, 0.95), 3)}
    if metal or (metal is None and R.random() < 0.3): m["metallic"] = 1.0
    return m
def lights(n, spread=4, height=(1, 5)):
    return [{"position": [R.uniform(-spread, spread), R.uniform(*height), R.uniform(-spread, spread)],
             "color": [round(R.uniform(0.5, 1), 2) for _ in range(3)], "intensity": round(R.uniform(5, 40), 1)} for _ in range(n)]
def touching(n):
    sph = [{"center": [0, -1000, 0], "radius": 1000, "material": mat(False)}]
    x = -2.5; z = 0
    for i in range(n):
        r = R.uniform(0.15, 0.4)
        if i and R.random() < 0.7:
            p = sph[-1]; pr = p["radius"]; ang = R.uniform(-0.8, 0.8)
            cx = p["center"][0] + (pr + r) * math.cos(ang); cz = p["center"][2] + (pr + r) * math.sin(ang)
            # on the ground: centre height r; horizontal distance must make them touch: adjust
            dy = pr - r; d = pr + r; hd = math.sqrt(max(d * d - dy * dy, 1e-9))
            cx = p["center"][0] + hd * math.cos(ang); cz = p["center"][2] + hd * math.sin(ang)
        else:
            cx = R.uniform(-2.5, 2.5); cz = R.uniform(-2, 1)
        sph.append({"center": [cx, r, cz], "radius": r, "material": mat()})
    return sph
def scene(cam, sph, lig, spp=4, bounces=0, fov=45):
    return {"camera": {"position": cam, "target": [0, 0.3, -0.5], "up": [0, 1, 0], "fov_y": fov},
            "render": {"width": W, "height": H, "spp": spp, "max_bounces": bounces, "background": [0.2, 0.25, 0.35]},
            "lights": lig, "spheres": sph}
def scaled(s, k):
    s = json.loads(json.dumps(s))
    s["camera"]["position"] = [k * v for v in s["camera"]["position"]]; s["camera"]["target"] = [k * v for v in s["camera"]["target"]]
    for l in s["lights"]: l["position"] = [k * v for v in l["position"]]; l["intensity"] *= k * k
    for x in s["spheres"]: x["center"] = [k * v for v in x["center"]]; x["radius"] *= k
    return s
R = random.Random(int(args[0]) if args else 7)
S = {}
for k in range(3): S[f"touching{k}"] = scene([R.uniform(-1, 1), 2.2, 5.5], touching(R.randint(12, 32)), lights(6), spp=4, bounces=0)
S["touching-bounces"] = scene([0.5, 2.0, 5.0], touching(20), lights(6), spp=1, bounces=2)
S["scaled-1e-3"] = scaled(S["touching0"], 1e-3); S["scaled-1e3"] = scaled(S["touching1"], 1e3)
S["distant1"] = {"camera": {"position": [0, 0, 3000], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y": 0.06},
                 "render": {"width": W, "height": H, "spp": 1, "max_bounces": 2}, "lights": lights(2, 5, (2, 6)),
                 "spheres": [{"center": [0, 0, 0], "radius": 1, "material": mat(False)}]}
t = touching(14); S["distant-touching"] = scene([1200, 900, 2700], t, lights(6), spp=4, bounces=1, fov=0.1)
S["distant-touching"]["camera"]["target"] = [0, 0.3, -0.5]
g = [{"center": [0, -1e5, 0], "radius": 1e5, "material": mat(False)}] + [{"center": [x, 0.5, z], "radius": 0.5, "material": mat()} for x, z in [(-1.2, 0), (0, -0.4), (1.2, 0.2)]]
S["ground-grazing"] = scene([0, 1.5, 5], g, [{"position": [-40, 0.8, -3], "intensity": 4000}, {"position": [30, 1.2, 10], "intensity": 2500}], spp=1, bounces=2)
S["camera-inside"] = scene([0.2, 0.3, 1.5], [{"center": [0, 0, 0], "radius": 5, "material": mat(False)}, {"center": [-1, -0.5, -1], "radius": 0.6, "material": mat()}, {"center": [1, 0.2, -1.5], "radius": 0.7, "material": mat(True)}], [{"position": [1, 2, 0.5], "intensity": 20}, {"position": [-2, -1, 1], "intensity": 10}], spp=4, bounces=3)
S["facing-mirrors"] = scene([0, 0.5, 0.5], [{"center": [0, 0, -102], "radius": 100, "material": {"albedo": [0.95, 0.93, 0.9], "roughness": 0.05, "metallic": 1}}, {"center": [0, 0, 102], "radius": 100, "material": {"albedo": [0.9, 0.92, 0.95], "roughness": 0.05, "metallic": 1}}, {"center": [0.3, 0, 0], "radius": 0.4, "material": mat(False)}], [{"position": [0.5, 1.5, 0.5], "intensity": 15}], spp=1, bounces=8, fov=60)
S["facing-mirrors"]["camera"]["target"] = [0, 0, -1]
names = args[1:] or list(S)
for name in names:
    f = f"{out}/{name}.json"; json.dump(S[name], open(f, "w"))
    subprocess.run(["./raylab", "render", f, "-o", f"{out}/{name}-gl.png"], check=True, capture_output=True)
    subprocess.run(["./raylab", "render", f, "--cpu", "-o", f"{out}/{name}-cpu.png"], check=True, capture_output=True)
    r = subprocess.run(["build/bin/judge", f, f"{out}/{name}-truth.png", f"{out}/{name}-gl.png", f"{out}/{name}-cpu.png"], capture_output=True, text=True)
    print(name, "|", " | ".join(l.split(": ", 1)[1] for l in r.stdout.strip().splitlines()), r.stderr.strip(), flush=True)
