#!/usr/bin/env python3
"""Writes caustic.obj / caustic.mtl: a smooth glass sphere (refractivity 1, IOR 1.5) under a
small, bright quad light, over a diffuse floor with a back wall. The light reaches the floor
under the sphere only through the glass, so that caustic is found by light paths (BDPT's
light tracing) and hardly at all by path tracing with light sampling (the shadow rays hit the
glass). Run: python3 make_scene.py (deterministic)."""
import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ among the scenes
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from icosphere import icosphere  # noqa: E402


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
