#!/usr/bin/env python3
"""The scene of part s31b of pending-h200.sh: a white plane (albedo 0.8) under a smooth sky
map of 8192 x 4096 texels (2^25 cells, past the 2^24 values of a float in [0, 1)), radiance
0.05 + 0.05 cos(theta) about +Y, and a 128 x 128 image of the plane's exact radiance,
0.8 / pi x E with E = 0.05 pi + 0.05 x 2 pi / 3 (the irradiance of the upper hemisphere).

    pip install numpy OpenEXR
    python3 scripts/device/make_env8k.py .device/scenes/env8k
"""
import math
import pathlib
import sys

import numpy as np
import OpenEXR

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".device/scenes/env8k")
out.mkdir(parents=True, exist_ok=True)


def header():
    """A fresh header for each file (OpenEXR.File fills in the one it is given)."""
    return {"compression": OpenEXR.ZIP_COMPRESSION, "type": OpenEXR.scanlineimage}


W, H = 8192, 4096
theta = np.pi * (np.arange(H) + 0.5) / H
row = (0.05 + 0.05 * np.cos(theta)).astype(np.float32)
sky = np.broadcast_to(row[:, None, None], (H, W, 3)).astype(np.float32)
OpenEXR.File(header(), {"RGB": sky}).write(str(out / "sky8k-smooth.exr"))

irradiance = 0.05 * math.pi + 0.05 * 2.0 * math.pi / 3.0
const = np.full((128, 128, 3), 0.8 / math.pi * irradiance, dtype=np.float32)
OpenEXR.File(header(), {"RGB": const}).write(str(out / "const.exr"))

(out / "p.mtl").write_text("newmtl w\nKd 0.8 0.8 0.8\n")
(out / "plane.obj").write_text("mtllib p.mtl\nv -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nusemtl w\nf 1 4 3\nf 1 3 2\n")
print(f"wrote {out}: plane radiance {0.8 / math.pi * irradiance:.6f}")
