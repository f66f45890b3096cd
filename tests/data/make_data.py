#!/usr/bin/env python3
"""Writes the binary test inputs (PNG, TGA, glTF + .bin, GLB) of tests/data/ with known
contents; the OBJ/MTL files are written by hand. Run from anywhere: python3 make_data.py.
Only the standard library is used, so the expected values in the tests can be read here."""

import base64
import json
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def path(*p):
    return os.path.join(HERE, *p)


def png(width, height, channels, rows):
    """rows: list of `height` lists of width*channels bytes, top row first."""
    ctype = {1: 0, 3: 2, 4: 6}[channels]
    raw = b"".join(b"\x00" + bytes(r) for r in rows)

    def chunk(tag, data):
        c = struct.pack(">I", len(data)) + tag + data
        return c + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, ctype, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def tga_bottom_up(width, height, rows_top_first):
    """Uncompressed 24-bit TGA with the default bottom-left origin: rows stored bottom first,
    pixels as BGR. rows_top_first: RGB triples per row, top row first."""
    header = struct.pack("<BBBHHBHHHHBB", 0, 0, 2, 0, 0, 0, 0, 0, width, height, 24, 0)
    body = b"".join(bytes(c for px in row for c in (px[2], px[1], px[0])) for row in reversed(rows_top_first))
    return header + body


def write(name, data):
    with open(path(*name.split("/")), "wb") as f:
        f.write(data)


# ---- room textures ---------------------------------------------------------------------
# floor_d.tga: 2x2, top row red, green; bottom row blue, white (stored bottom-up).
write("room/floor_d.tga", tga_bottom_up(2, 2, [[(255, 0, 0), (0, 255, 0)], [(0, 0, 255), (255, 255, 255)]]))
# leaf.png: 2x1 RGBA, an opaque green texel and a transparent one.
write("room/leaf.png", png(2, 1, 4, [[30, 200, 40, 255, 30, 200, 40, 0]]))
# mask_grey.png: 2x1 grey, black (hole) then white (solid).
write("room/mask_grey.png", png(2, 1, 1, [[0, 255]]))
write("bad/corrupt.png", b"\x89PNG\r\n\x1a\n this is not really a PNG")

# ---- glTF ------------------------------------------------------------------------------
LEAF_PNG = png(2, 2, 4, [[10, 20, 30, 255, 40, 50, 60, 0], [70, 80, 90, 128, 100, 110, 120, 255]])


class Buf:
    def __init__(self):
        self.data = bytearray()
        self.views = []
        self.accessors = []

    def view(self, blob, stride=None):
        while len(self.data) % 4:
            self.data += b"\x00"
        v = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(blob)}
        if stride:
            v["byteStride"] = stride
        self.data += blob
        self.views.append(v)
        return len(self.views) - 1

    def accessor(self, view, ctype, count, type_, **kw):
        a = {"bufferView": view, "componentType": ctype, "count": count, "type": type_}
        a.update(kw)
        self.accessors.append(a)
        return len(self.accessors) - 1


F32, U16, U32 = 5126, 5123, 5125


def floats(vals):
    return struct.pack("<%df" % len(vals), *vals)


def quad_buffer(buf):
    """A 2x2 quad in the XY plane facing +Z, with normals and UVs; a triangle without."""
    pos = buf.view(floats([-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0]))
    nrm = buf.view(floats([0, 0, 1] * 4))
    uv = buf.view(floats([0, 0, 1, 0, 1, 1, 0, 1]))
    idx = buf.view(struct.pack("<6H", 0, 1, 2, 0, 2, 3))
    tri = buf.view(floats([0, 0, 0, 1, 0, 0, 0, 1, 0]))
    return {
        "pos": buf.accessor(pos, F32, 4, "VEC3", min=[-1, -1, 0], max=[1, 1, 0]),
        "nrm": buf.accessor(nrm, F32, 4, "VEC3"),
        "uv": buf.accessor(uv, F32, 4, "VEC2"),
        "idx": buf.accessor(idx, U16, 6, "SCALAR"),
        "tri": buf.accessor(tri, F32, 3, "VEC3", min=[0, 0, 0], max=[1, 1, 0]),
    }


def quat_axis(axis, deg):
    s = math.sin(math.radians(deg) / 2)
    return [axis[0] * s, axis[1] * s, axis[2] * s, math.cos(math.radians(deg) / 2)]


def instanced(glb):
    buf = Buf()
    a = quad_buffer(buf)
    quad = {"attributes": {"POSITION": a["pos"], "NORMAL": a["nrm"], "TEXCOORD_0": a["uv"]}, "indices": a["idx"]}
    if glb:
        image = {"bufferView": buf.view(LEAF_PNG), "mimeType": "image/png", "name": "leaf"}
    else:
        image = {"uri": "data:image/png;base64," + base64.b64encode(LEAF_PNG).decode(), "name": "leaf"}
    doc = {
        "asset": {"version": "2.0", "generator": "bidir tests/data/make_data.py"},
        "extensionsUsed": ["KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_emissive_strength",
                           "KHR_texture_transform"],
        "scene": 0,
        "scenes": [{"nodes": [0, 3, 4, 5, 6, 7, 8, 9, 10, 11]}],
        "nodes": [
            {"name": "Root", "rotation": quat_axis((0, 1, 0), 90), "children": [1, 2]},
            {"name": "MirrorA", "mesh": 0, "translation": [0, 0, -5]},
            {"name": "MirrorB", "mesh": 0, "translation": [3, 0, 0], "scale": [-1, 1, 1]},
            {"name": "Glass", "mesh": 1, "scale": [2, 1, 1]},
            {"name": "Light", "mesh": 2, "translation": [0, 5, 0], "rotation": quat_axis((1, 0, 0), 90)},
            {"name": "Leaves", "mesh": 3, "translation": [0, 0, 3]},
            {"name": "Blend", "mesh": 4, "translation": [0, 0, 6]},
            {"name": "Tri", "mesh": 5, "translation": [5, 0, 0]},
            {"name": "Points", "mesh": 6},
            {"name": "CamWide", "camera": 0, "translation": [0, 1, 10]},
            {"camera": 1, "rotation": quat_axis((0, 1, 0), 90)},
            {"name": "Ortho", "camera": 2},
        ],
        "cameras": [
            {"name": "wide", "type": "perspective", "perspective": {"aspectRatio": 2.0, "yfov": 0.5, "znear": 0.1}},
            {"name": "NoAspect", "type": "perspective", "perspective": {"yfov": 1.0, "znear": 0.1}},
            {"type": "orthographic", "orthographic": {"xmag": 1, "ymag": 1, "znear": 0.1, "zfar": 10}},
        ],
        "meshes": [
            {"name": "MirrorQuad", "primitives": [dict(quad, material=0)]},
            {"name": "GlassQuad", "primitives": [dict(quad, material=1)]},
            {"name": "LampQuad", "primitives": [dict(quad, material=2)]},
            {"name": "LeafQuad", "primitives": [dict(quad, material=3)]},
            {"name": "BlendQuad", "primitives": [dict(quad, material=4)]},
            {"name": "Triangle", "primitives": [{"attributes": {"POSITION": a["tri"]}}]},
            {"name": "Dots", "primitives": [{"attributes": {"POSITION": a["tri"]}, "mode": 0}]},
        ],
        "materials": [
            {"name": "Mirror", "pbrMetallicRoughness": {"metallicFactor": 1.0, "roughnessFactor": 0.0}},
            {"name": "Glass", "pbrMetallicRoughness": {"metallicFactor": 0.0},
             "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                            "KHR_materials_ior": {"ior": 1.33}}},
            {"name": "Lamp", "emissiveFactor": [1.0, 0.5, 0.25],
             "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 10.0}}},
            {"name": "Leaves", "alphaMode": "MASK", "doubleSided": True,
             "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicFactor": 0.0}},
            {"name": "Glassy", "alphaMode": "BLEND",
             "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.6, 0.5], "metallicFactor": 0.0}},
        ],
        "textures": [{"source": 0}],
        "images": [image],
    }
    return doc, buf


def finish(doc, buf, name, glb=False, bin_name=None):
    buffer = {"byteLength": len(buf.data)}
    if glb:
        pass
    elif bin_name:
        buffer["uri"] = bin_name
        write("/".join(name.split("/")[:-1] + [bin_name]), bytes(buf.data))
    else:
        buffer["uri"] = "data:application/octet-stream;base64," + base64.b64encode(bytes(buf.data)).decode()
    doc.setdefault("buffers", [buffer])
    doc["bufferViews"] = buf.views
    doc["accessors"] = buf.accessors
    if not glb:
        write(name, json.dumps(doc, indent=1).encode())
        return
    js = json.dumps(doc).encode()
    js += b" " * (-len(js) % 4)
    bin_ = bytes(buf.data) + b"\x00" * (-len(buf.data) % 4)
    body = struct.pack("<I4s", len(js), b"JSON") + js + struct.pack("<I4s", len(bin_), b"BIN\x00") + bin_
    write(name, struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body)


doc, buf = instanced(False)
finish(doc, buf, "gltf/instanced.gltf", bin_name="instanced.bin")
doc, buf = instanced(True)
finish(doc, buf, "gltf/instanced.glb", glb=True)


# ---- bad glTF --------------------------------------------------------------------------
def one_quad(mutate=None, prim_extra=None):
    buf = Buf()
    a = quad_buffer(buf)
    prim = {"attributes": {"POSITION": a["pos"], "NORMAL": a["nrm"]}, "indices": a["idx"]}
    prim.update(prim_extra or {})
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
           "meshes": [{"name": "Q", "primitives": [prim]}]}
    if mutate:
        mutate(doc, buf, a)
    return doc, buf


def bad(name, mutate=None, **kw):
    doc, buf = one_quad(mutate, kw.get("prim"))
    finish(doc, buf, "bad/" + name, bin_name=kw.get("bin_name"))


def draco(doc, buf, a):
    doc["extensionsUsed"] = ["KHR_draco_mesh_compression"]
    doc["extensionsRequired"] = ["KHR_draco_mesh_compression"]


def sparse(doc, buf, a):
    v = buf.view(struct.pack("<H", 1))
    w = buf.view(floats([5, 5, 5]))
    buf.accessors[a["pos"]]["sparse"] = {"count": 1, "indices": {"bufferView": v, "componentType": U16},
                                         "values": {"bufferView": w}}


def index_range(doc, buf, a):
    v = buf.view(struct.pack("<6H", 0, 1, 2, 0, 2, 7))
    doc["meshes"][0]["primitives"][0]["indices"] = buf.accessor(v, U16, 6, "SCALAR")


def wrong_type(doc, buf, a):
    buf.accessors[a["pos"]]["type"] = "VEC2"


def overrun(doc, buf, a):
    buf.accessors[a["pos"]]["count"] = 400


def nan_position(doc, buf, a):
    v = buf.view(floats([-1, -1, 0, float("nan"), -1, 0, 1, 1, 0, -1, 1, 0]))
    doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = buf.accessor(v, F32, 4, "VEC3", min=[-1, -1, 0],
                                                                               max=[1, 1, 0])


def bad_reference(doc, buf, a):
    doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 42


def cycle(doc, buf, a):
    doc["nodes"] = [{"name": "A", "children": [1]}, {"name": "B", "mesh": 0, "children": [0]}]


def normal_count(doc, buf, a):
    buf.accessors[a["nrm"]]["count"] = 3


def short_buffer(doc, buf, a):
    doc["buffers"] = [{"byteLength": len(buf.data) + 1000,
                       "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(buf.data)).decode()}]


def points_only(doc, buf, a):
    doc["meshes"][0]["primitives"][0]["mode"] = 0


bad("gltf_draco.gltf", draco)
bad("gltf_sparse.gltf", sparse)
bad("gltf_index_out_of_range.gltf", index_range)
bad("gltf_wrong_accessor_type.gltf", wrong_type)
bad("gltf_accessor_overrun.gltf", overrun)
bad("gltf_nan_position.gltf", nan_position)
bad("gltf_bad_reference.gltf", bad_reference)
bad("gltf_node_cycle.gltf", cycle)
bad("gltf_normal_count.gltf", normal_count)
bad("gltf_short_buffer.gltf", short_buffer)
bad("gltf_points_only.gltf", points_only)
bad("gltf_missing_bin.gltf", bin_name="gltf_missing_bin.bin")
os.remove(path("bad", "gltf_missing_bin.bin"))
with open(path("bad", "gltf_invalid_json.gltf"), "w") as f:
    f.write('{\n  "asset": {"version": "2.0"},\n  "nodes": [ {"mesh": 0,\n')
doc, buf = one_quad()
finish(doc, buf, "bad/glb_truncated.glb", glb=True)


def requires_transform(doc, buf, a):
    doc["extensionsUsed"] = ["KHR_texture_transform", "KHR_materials_sheen"]
    doc["extensionsRequired"] = ["KHR_texture_transform", "KHR_materials_sheen"]


doc, buf = one_quad(requires_transform)
finish(doc, buf, "gltf/requires_texture_transform.gltf")


def requires_meshopt(doc, buf, a):
    doc["extensionsUsed"] = ["KHR_texture_transform", "EXT_meshopt_compression"]
    doc["extensionsRequired"] = ["KHR_texture_transform", "EXT_meshopt_compression"]


bad("gltf_meshopt.gltf", requires_meshopt)


def image_without_source(doc, buf, a):
    doc["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
    doc["meshes"][0]["primitives"][0]["material"] = 0
    doc["textures"] = [{"source": 0}]
    doc["images"] = [{"name": "nowhere", "mimeType": "image/png"}]


def camera_without_projection(doc, buf, a):
    doc["cameras"] = [{"type": "perspective", "orthographic": {"xmag": 1, "ymag": 1, "znear": 0.1, "zfar": 10}}]
    doc["nodes"].append({"camera": 0})
    doc["scenes"][0]["nodes"].append(1)


def missing_image(doc, buf, a):
    image_without_source(doc, buf, a)
    doc["images"] = [{"name": "gone", "uri": "nothere.png"}]


bad("gltf_image_without_source.gltf", image_without_source)
bad("gltf_missing_image.gltf", missing_image)
bad("gltf_camera_without_projection.gltf", camera_without_projection)
with open(path("bad", "glb_truncated.glb"), "rb+") as f:
    f.truncate(60)


# ---- issue 18: bad input that once crashed, hung or said too little ----------------------
def two_parents(doc, buf, a):
    # Node 1 is a child of both 0 and 2: not a forest. Chains of such nodes once expanded
    # into ~10^12 instances.
    doc["nodes"] = [{"name": "A", "children": [1]}, {"name": "Shared", "mesh": 0}, {"name": "B", "children": [1]}]
    doc["scenes"][0]["nodes"] = [0, 2]


def camera(**perspective):
    def mutate(doc, buf, a):
        doc["cameras"] = [{"name": "Cam", "type": "perspective", "perspective": dict(znear=0.1, **perspective)}]
        doc["nodes"].append({"name": "CamNode", "camera": 0, "translation": [0, 0, 5]})
        doc["scenes"][0]["nodes"].append(1)
    return mutate


bad("gltf_two_parents.gltf", two_parents)
bad("gltf_camera_aspect_zero.gltf", camera(yfov=0.8, aspectRatio=0))
bad("gltf_camera_aspect_huge.gltf", camera(yfov=0.8, aspectRatio=1e6))
bad("gltf_camera_yfov_zero.gltf", camera(yfov=0))
doc, buf = one_quad()
finish(doc, buf, "bad/glb_bad_magic.glb", glb=True)
with open(path("bad", "glb_bad_magic.glb"), "rb+") as f:
    f.write(b"GLB\x00")
# An MTL a careless or hostile user might write: an emission that overflows float32 power
# sums, and (another library) a colour of terminal escapes and NULs, and a 60,000-digit one.
write("bad/obj_huge_ke.mtl", b"newmtl lamp\nKd 0 0 0\nKe 3e38 3e38 3e38\n")
write("bad/obj_huge_ke.obj", b"mtllib obj_huge_ke.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl lamp\nf 1 2 3\n")
write("bad/obj_control_chars.mtl", b"newmtl m\nKd 1 \x1b[2J\x1b]0;pwned\x07\x00 1\n")
write("bad/obj_control_chars.obj", b"mtllib obj_control_chars.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n")
write("bad/obj_long_number.mtl", b"newmtl m\nKd 0.5 " + b"9" * 60000 + b" 0.5\n")
write("bad/obj_long_number.obj", b"mtllib obj_long_number.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n")
