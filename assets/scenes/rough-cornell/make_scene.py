#!/usr/bin/env python3
"""Writes rough-cornell.obj / rough-cornell.mtl: the Cornell box (walls and light of
../../../../shared/scenes/cornell-box, the Cornell measured data, millimetres) with its two
blocks replaced by a rough metal sphere (thesis mirror, F = 1, Pr 0.4: GGX alpha 0.16) and a
rough glass sphere (thesis glass, IOR 1.5, Pr 0.3: alpha 0.09). The spheres are icospheres
(4 subdivisions, 5120 triangles each) with no `vn`: bidir and Mitsuba (mitsuba_reference.py
reads this same OBJ) both shade them with flat face normals. Deterministic:
python3 make_scene.py"""
import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ among the scenes
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from icosphere import icosphere  # noqa: E402

SUBDIVISIONS = 4


out = ["# Rough Cornell box, written by make_scene.py. Millimetres, Y up. No vn: flat normals.",
       "mtllib rough-cornell.mtl"]
vi = 1


def polygon(name, mat, *pts):
    """A quad as two triangles (0 1 2, 0 2 3), counter-clockwise seen from its lit side."""
    global vi
    out.append(f"o {name}")
    out.append(f"usemtl {mat}")
    for p in pts:
        out.append("v %g %g %g" % p)
    out.append(f"f {vi} {vi + 1} {vi + 2}")
    out.append(f"f {vi} {vi + 2} {vi + 3}")
    vi += 4


polygon("floor", "white", (552.8, 0, 0), (0, 0, 0), (0, 0, 559.2), (549.6, 0, 559.2))
polygon("ceiling", "white", (556, 548.8, 0), (556, 548.8, 559.2), (0, 548.8, 559.2), (0, 548.8, 0))
polygon("backWall", "white", (549.6, 0, 559.2), (0, 0, 559.2), (0, 548.8, 559.2), (556, 548.8, 559.2))
polygon("rightWall", "green", (0, 0, 559.2), (0, 0, 0), (0, 548.8, 0), (0, 548.8, 559.2))
polygon("leftWall", "red", (552.8, 0, 0), (549.6, 0, 559.2), (556, 548.8, 559.2), (556, 548.8, 0))
polygon("light", "light", (343, 548.3, 227), (343, 548.3, 332), (213, 548.3, 332), (213, 548.3, 227))

verts, faces = icosphere(SUBDIVISIONS)
# Where the tall and the short block stood; 1 mm above the floor.
for name, mat, centre, radius in (("metalSphere", "roughMetal", (368.0, 101.0, 351.0), 100.0),
                                  ("glassSphere", "roughGlass", (186.0, 101.0, 169.0), 100.0)):
    out.append(f"o {name}")
    out.append(f"usemtl {mat}")
    for p in verts:
        out.append("v %.6f %.6f %.6f" % tuple(centre[i] + radius * p[i] for i in range(3)))
    for a, b, c in faces:
        out.append(f"f {vi + a} {vi + b} {vi + c}")
    vi += len(verts)

with open("rough-cornell.obj", "w") as f:
    f.write("\n".join(out) + "\n")

with open("rough-cornell.mtl", "w") as f:
    f.write("""# Rough Cornell box materials (thesis keys + Pr; GGX alpha = Pr^2). Kd linear RGB.
newmtl white
Kd 0.725 0.71 0.68

newmtl red
Kd 0.63 0.065 0.05

newmtl green
Kd 0.14 0.45 0.091

newmtl light
Kd 0.78 0.78 0.78
Ke 17 12 4

# Rough conductor with F = 1 (the thesis mirror made rough).
newmtl roughMetal
Kd 0 0 0
reflectivity 1.0
Pr 0.4

# Rough dielectric, IOR 1.5, exact Fresnel, untinted.
newmtl roughGlass
Kd 0 0 0
refractivity 1.0
IOR 1.5
Pr 0.3
""")
