#!/usr/bin/env python3
"""Writes caustic.obj / caustic.mtl: a smooth glass sphere (refractivity 1, IOR 1.5) under a
small, bright quad light, over a diffuse floor with a back wall. The light reaches the floor
under the sphere only through the glass, so that caustic is found by light paths (BDPT's
light tracing) and hardly at all by path tracing with light sampling (the shadow rays hit the
glass). Run: python3 make_scene.py (deterministic)."""
import math

def icosphere(n):
    t = (1 + 5 ** 0.5) / 2
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
         (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    v = [tuple(c / math.sqrt(sum(x * x for x in p)) for c in p) for p in v]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6),
         (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10),
         (8, 6, 7), (9, 8, 1)]
    for _ in range(n):
        mid = {}
        def m(a, b):
            k = (min(a, b), max(a, b))
            if k not in mid:
                p = [(v[a][i] + v[b][i]) / 2 for i in range(3)]
                l = math.sqrt(sum(x * x for x in p))
                v.append(tuple(x / l for x in p))
                mid[k] = len(v) - 1
            return mid[k]
        nf = []
        for a, b, c in f:
            ab, bc, ca = m(a, b), m(b, c), m(c, a)
            nf += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = nf
    return v, f

out = ["# Caustic test scene, written by make_scene.py. Metres, Y up.", "mtllib caustic.mtl"]
vi = 1
def quad(name, mat, a, b, c, d):
    global vi
    out.append(f"o {name}")
    out.append(f"usemtl {mat}")
    for p in (a, b, c, d):
        out.append("v %.6f %.6f %.6f" % p)
    out.append(f"f {vi} {vi + 1} {vi + 2}")
    out.append(f"f {vi} {vi + 2} {vi + 3}")
    vi += 4

# Floor facing +y, back wall at z = 2 facing -z (counter-clockwise seen from the lit side).
quad("floor", "floor", (-2, 0, -2), (-2, 0, 2), (2, 0, 2), (2, 0, -2))
quad("back", "wall", (-2, 0, 2), (-2, 3, 2), (2, 3, 2), (2, 0, 2))
# A 0.2 x 0.2 light at y = 2.5 facing down.
quad("light", "light", (0.1, 2.5, 0.4), (0.3, 2.5, 0.4), (0.3, 2.5, 0.6), (0.1, 2.5, 0.6))

verts, faces = icosphere(3)
c, r = (0.0, 0.6, 0.0), 0.5
out.append("o sphere")
out.append("usemtl glass")
for p in verts:
    out.append("v %.6f %.6f %.6f" % tuple(c[i] + r * p[i] for i in range(3)))
for p in verts:
    out.append("vn %.6f %.6f %.6f" % p)
vn0 = 1
for a, b, cc in faces:
    out.append(f"f {vi + a}//{vn0 + a} {vi + b}//{vn0 + b} {vi + cc}//{vn0 + cc}")
open("caustic.obj", "w").write("\n".join(out) + "\n")

open("caustic.mtl", "w").write("""# Caustic test scene materials (thesis keys: emissivity, reflectivity, refractivity, IOR).
newmtl floor
Kd 0.7 0.7 0.7

newmtl wall
Kd 0.5 0.5 0.6

newmtl glass
Kd 0 0 0
reflectivity 0.0
refractivity 1.0
IOR 1.5

newmtl light
Kd 1 1 1
emissivity 300.0
""")
