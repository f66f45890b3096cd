#!/usr/bin/env python3
"""Writes sds.obj / sds.mtl: a specular-diffuse-specular test scene (thesis MTL keys). A
Cornell-like box, open at the front, with a small light in the ceiling; a smooth glass sphere
(IOR 1.5) under the light focuses it into a caustic on the floor; the left wall is a mirror,
and the camera sees the caustic both directly and in the mirror. Seen in the mirror, the
caustic is lit along eye - mirror - floor - glass - glass - light: no connection strategy of
BDPT samples it (the floor point is seen only through the mirror, and the light only through
the glass), so only unidirectional paths that happen to hit the small light find it; vertex
merging finds it with photons. Run: python3 make_scene.py (deterministic)."""
import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ among the scenes
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from icosphere import icosphere  # noqa: E402


out = ["# SDS test scene, written by make_scene.py. Metres, Y up; the box spans x -1..1, y 0..2, z -1.5..1.",
       "mtllib sds.mtl"]
vi = 1
def quad(name, mat, a, b, c, d):
    """Two triangles a b c, a c d: counter-clockwise seen from the side they face."""
    global vi
    out.append(f"o {name}")
    out.append(f"usemtl {mat}")
    for p in (a, b, c, d):
        out.append("v %.6f %.6f %.6f" % p)
    out.append(f"f {vi} {vi + 1} {vi + 2}")
    out.append(f"f {vi} {vi + 2} {vi + 3}")
    vi += 4

X0, X1, Y1, Z0, Z1 = -1.0, 1.0, 2.0, -1.5, 1.0
quad("floor", "white", (X0, 0, Z0), (X0, 0, Z1), (X1, 0, Z1), (X1, 0, Z0))          # faces +y
quad("ceiling", "white", (X0, Y1, Z0), (X1, Y1, Z0), (X1, Y1, Z1), (X0, Y1, Z1))    # faces -y
quad("back", "white", (X0, 0, Z1), (X0, Y1, Z1), (X1, Y1, Z1), (X1, 0, Z1))         # faces -z
quad("mirror", "mirror", (X0, 0, Z0), (X0, Y1, Z0), (X0, Y1, Z1), (X0, 0, Z1))      # faces +x
quad("right", "green", (X1, 0, Z0), (X1, 0, Z1), (X1, Y1, Z1), (X1, Y1, Z0))        # faces -x
# A 0.2 x 0.2 light just under the ceiling, facing down, over the sphere.
L, LX, LZ, LY = 0.1, 0.2, 0.0, Y1 - 0.001
quad("light", "light", (LX - L, LY, LZ - L), (LX + L, LY, LZ - L), (LX + L, LY, LZ + L), (LX - L, LY, LZ + L))

verts, faces = icosphere(2)
c, r = (0.2, 0.9, 0.0), 0.35
out.append("o sphere")
out.append("usemtl glass")
for p in verts:
    out.append("v %.6f %.6f %.6f" % tuple(c[i] + r * p[i] for i in range(3)))
for p in verts:
    out.append("vn %.6f %.6f %.6f" % p)
for a, b, cc in faces:
    out.append(f"f {vi + a}//{1 + a} {vi + b}//{1 + b} {vi + cc}//{1 + cc}")
open("sds.obj", "w").write("\n".join(out) + "\n")

open("sds.mtl", "w").write("""# SDS test scene materials (thesis keys: emissivity, reflectivity, refractivity, IOR).
newmtl white
Kd 0.7 0.7 0.7

newmtl green
Kd 0.2 0.6 0.2

newmtl mirror
Kd 0 0 0
reflectivity 1.0

newmtl glass
Kd 0 0 0
reflectivity 0.0
refractivity 1.0
IOR 1.5

newmtl light
Kd 0.7 0.7 0.7
emissivity 100.0
""")
