#!/usr/bin/env python3
"""Renders rough-cornell.obj with Mitsuba 3 in bidir's conventions: the reference of
tests/render_mitsuba.rs. See README.md for the command, the version and what was run.

The same triangles as bidir: this script reads rough-cornell.obj and .mtl itself, writes each
material's faces (the vertex lines copied verbatim) into its own OBJ in a temporary folder and
loads those with Mitsuba's `obj` plugin and `face_normals` (bidir has no `vn` here, so it
shades with flat face normals too). Materials (only what this scene uses; anything else is an
error): Kd -> `diffuse`; Ke -> an `area` emitter of that radiance (the emitter also reflects
with its Kd, as in bidir); thesis `reflectivity 1` + `Pr` -> `roughconductor` with
`material none` (F = 1); `refractivity 1` + `Pr` + `IOR` -> `roughdielectric` (int_ior IOR,
ext_ior 1); both GGX with alpha = Pr^2 and visible-normal sampling.

One convention differs and is converted here, not in bidir: Mitsuba's microfacet models use the
separable Smith shadowing-masking G1(wi) G1(wo) (mitsuba/render/microfacet.h, `G`), bidir the
height-correlated G2 = 1 / (1 + Lambda(wi) + Lambda(wo)) (Heitz 2014, eq. 99;
glsl/common/microfacet.glsl). `HeightCorrelated` wraps Mitsuba's own BSDF and multiplies its
value and its sample weight by G2 / (G1(wi) G1(wo)) = (1 + Li)(1 + Lo) / (1 + Li + Lo), which
depends on the two directions only; D, Fresnel, the Jacobians and the sampling stay Mitsuba's.

Camera: pinhole at (278, 273, -800) looking along +z, up +y, vertical fov 39.3077 degrees, a
1-pixel box filter (a sample is uniform inside its pixel), row 0 at the top: the shared Cornell
box's camera (Mitsuba's look_at shows world +x on the left, as bidir's right = forward x up).
Integrator `path`, max_depth -1 (unbounded) and Russian roulette from depth 5, as bidir's
pt-nee (both unbiased for the same infinite sum). `independent` sampler: every pass has its own
seed, so the passes are independent and their spread gives each pixel's standard error.
"""
import argparse
import os
import sys
import tempfile
import time

import drjit as dr
import mitsuba as mi
import numpy as np


def read_mtl(path):
    mats, cur = {}, None
    with open(path) as f:
        for n, line in enumerate(f, 1):
            tok = line.split()
            if not tok or tok[0].startswith("#"):
                continue
            if tok[0] == "newmtl":
                cur = mats.setdefault(tok[1], {})
            elif cur is None:
                sys.exit(f"{path}:{n}: '{tok[0]}' before newmtl")
            else:
                cur[tok[0]] = [float(x) for x in tok[1:]]
    return mats


def split_obj(path, outdir):
    """Per material: an OBJ of its faces (triangles only) with the vertex lines as written."""
    verts, groups, mtl, cur = [], {}, None, None
    with open(path) as f:
        for n, line in enumerate(f, 1):
            tok = line.split()
            if not tok or tok[0].startswith("#"):
                continue
            if tok[0] == "mtllib":
                mtl = os.path.join(os.path.dirname(path), tok[1])
            elif tok[0] == "v":
                verts.append(line.strip())
            elif tok[0] == "usemtl":
                cur = tok[1]
            elif tok[0] == "f":
                if len(tok) != 4 or any("/" in t for t in tok[1:]):
                    sys.exit(f"{path}:{n}: only plain triangles 'f a b c' are supported")
                groups.setdefault(cur, []).append([int(t) - 1 for t in tok[1:]])
            elif tok[0] in ("vn", "vt"):
                sys.exit(f"{path}:{n}: this script assumes flat shading (no vn/vt)")
    files = {}
    for name, faces in groups.items():
        used = sorted({i for fc in faces for i in fc})
        index = {v: k + 1 for k, v in enumerate(used)}
        out = [verts[i] for i in used] + ["f %d %d %d" % tuple(index[i] for i in fc) for fc in faces]
        files[name] = os.path.join(outdir, f"{name}.obj")
        with open(files[name], "w") as f:
            f.write("\n".join(out) + "\n")
    return files, mtl


def lam(w, alpha):
    """Smith's Lambda for GGX (Heitz 2014, eq. 72) of a local direction, with |cos|."""
    c2 = dr.square(mi.Frame3f.cos_theta(w))
    s2 = dr.maximum(0.0, 1.0 - c2)
    return 0.5 * (dr.sqrt(c2 + alpha * alpha * s2) / dr.maximum(dr.sqrt(c2), 1e-12) - 1.0)


def register_height_correlated():
    """Registers `height_correlated` (needs a variant set: mi.BSDF exists only then)."""

    class HeightCorrelated(mi.BSDF):
        """Mitsuba's GGX BSDF `inner` with its separable G1 G1 turned into the height-correlated G2."""

        def __init__(self, props):
            mi.BSDF.__init__(self, props)
            self.alpha = props["alpha"]
            inner = {"type": props["inner"], "distribution": "ggx", "alpha": self.alpha, "sample_visible": True}
            if props["inner"] == "roughconductor":
                inner["material"] = "none"
            else:
                inner["int_ior"] = props["int_ior"]
                inner["ext_ior"] = 1.0
            self.inner = mi.load_dict(inner)
            self.m_flags = self.inner.flags()
            self.m_components = [self.inner.flags(i) for i in range(self.inner.component_count())]

        def ratio(self, wi, wo):
            li, lo = lam(wi, self.alpha), lam(wo, self.alpha)
            return (1.0 + li) * (1.0 + lo) / (1.0 + li + lo)

        def sample(self, ctx, si, sample1, sample2, active=True):
            bs, weight = self.inner.sample(ctx, si, sample1, sample2, active)
            return bs, weight * self.ratio(si.wi, bs.wo)

        def eval(self, ctx, si, wo, active=True):
            return self.inner.eval(ctx, si, wo, active) * self.ratio(si.wi, wo)

        def pdf(self, ctx, si, wo, active=True):
            return self.inner.pdf(ctx, si, wo, active)

        def eval_pdf(self, ctx, si, wo, active=True):
            value, pdf = self.inner.eval_pdf(ctx, si, wo, active)
            return value * self.ratio(si.wi, wo), pdf

        def eval_pdf_sample(self, ctx, si, wo, sample1, sample2, active=True):
            value, pdf, bs, weight = self.inner.eval_pdf_sample(ctx, si, wo, sample1, sample2, active)
            return value * self.ratio(si.wi, wo), pdf, bs, weight * self.ratio(si.wi, bs.wo)

        def traverse(self, callback):
            pass

        def to_string(self):
            return f"HeightCorrelated[{self.inner}]"

    mi.register_bsdf("height_correlated", lambda props: HeightCorrelated(props))


def bsdf_of(name, m, corrected):
    rgb = lambda v: {"type": "rgb", "value": v}
    refl, refr, pr = m.get("reflectivity", [0.0])[0], m.get("refractivity", [0.0])[0], m.get("Pr", [0.0])[0]
    kd = m.get("Kd", [0.0, 0.0, 0.0])
    if refl == 0.0 and refr == 0.0:
        return {"type": "diffuse", "reflectance": rgb(kd)}
    if pr <= 0.0 or max(kd) > 0.0 or (refl, refr) not in ((1.0, 0.0), (0.0, 1.0)):
        sys.exit(f"material {name}: only pure diffuse, rough mirror or rough glass (Kd 0, Pr > 0) are supported")
    inner = "roughconductor" if refl == 1.0 else "roughdielectric"
    ior = {} if inner == "roughconductor" else {"int_ior": m.get("IOR", [1.5])[0]}
    if corrected:
        return {"type": "height_correlated", "inner": inner, "alpha": pr * pr, **ior}
    out = {"type": inner, "distribution": "ggx", "alpha": pr * pr, "sample_visible": True, **ior}
    out.update({"material": "none"} if inner == "roughconductor" else {"ext_ior": 1.0})
    return out


def scene_dict(obj, tmp, width, height, corrected):
    files, mtl = split_obj(obj, tmp)
    mats = read_mtl(mtl)
    d = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": -1, "rr_depth": 5},
        "sensor": {
            "type": "perspective",
            "fov": 39.3077,
            "fov_axis": "y",
            "to_world": mi.ScalarTransform4f().look_at(origin=[278, 273, -800], target=[278, 273, -799], up=[0, 1, 0]),
            "sampler": {"type": "independent"},
            "film": {"type": "hdrfilm", "width": width, "height": height, "rfilter": {"type": "box"}, "pixel_format": "rgb"},
        },
    }
    for name, path in files.items():
        m = mats[name]
        shape = {"type": "obj", "filename": path, "face_normals": True, "bsdf": bsdf_of(name, m, corrected)}
        ke = m.get("Ke", [0.0, 0.0, 0.0])
        if max(ke) > 0.0:
            shape["emitter"] = {"type": "area", "radiance": {"type": "rgb", "value": ke}}
        d[name] = shape
    return d


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--obj", default=os.path.join(here, "rough-cornell.obj"))
    ap.add_argument("--variant", default="llvm_ad_rgb")
    ap.add_argument("--size", type=int, default=64)
    ap.add_argument("--spp", type=int, default=256, help="samples per pixel of one pass")
    ap.add_argument("--passes", type=int, default=64)
    ap.add_argument("--seed0", type=int, default=1000)
    ap.add_argument("--separable", action="store_true", help="Mitsuba's own separable G (no conversion)")
    ap.add_argument("-o", "--out", default=os.path.join(here, "reference.exr"))
    a = ap.parse_args()
    mi.set_variant(a.variant)
    register_height_correlated()
    with tempfile.TemporaryDirectory() as tmp:
        scene = mi.load_dict(scene_dict(a.obj, tmp, a.size, a.size, not a.separable))
        s1 = s2 = None
        t0 = time.time()
        for k in range(a.passes):
            img = np.array(mi.render(scene, spp=a.spp, seed=a.seed0 + k), dtype=np.float64)[:, :, :3]
            s1 = img if s1 is None else s1 + img
            s2 = img * img if s2 is None else s2 + img * img
            n = k + 1
            print(f"pass {n}/{a.passes}: {time.time() - t0:.0f} s, mean {np.mean(s1 / n, axis=(0, 1))}", flush=True)
    mean = s1 / n
    se = np.sqrt(np.maximum(s2 / n - mean * mean, 0.0) * n / (n - 1) / n)
    mi.Bitmap(mean.astype(np.float32), pixel_format=mi.Bitmap.PixelFormat.RGB).write(a.out)
    base, ext = os.path.splitext(a.out)
    mi.Bitmap(se.astype(np.float32), pixel_format=mi.Bitmap.PixelFormat.RGB).write(base + "-se" + ext)
    print(f"{a.out}: {a.passes} x {a.spp} spp in {time.time() - t0:.0f} s, mean RGB {mean.mean(axis=(0, 1))}, "
          f"per-pixel se RMS {np.sqrt(np.mean(se * se)):.3e}")


if __name__ == "__main__":
    main()
