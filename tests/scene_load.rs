//! Scene loading: the built-in Cornell box, an OBJ+MTL room with the thesis' keys,
//! triangulation, textures, glTF flattening/materials/cameras, and Sponza when present.

use std::path::{Path, PathBuf};

use bidir::scene::{self, srgb_to_linear, AlphaMask, Camera, LoadOptions, Loaded, Scene};
use glam::{Vec2, Vec3};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data").join(name)
}

fn load(name: &str) -> Loaded {
    scene::load(&data(name), &LoadOptions { strict: true }).unwrap_or_else(|e| panic!("{e}"))
}

fn material<'a>(s: &'a Scene, name: &str) -> (u32, &'a scene::Material) {
    let i = s.materials.iter().position(|m| m.name == name).unwrap_or_else(|| panic!("no material {name}"));
    (i as u32, &s.materials[i])
}

fn triangles_of(s: &Scene, m: u32) -> Vec<usize> {
    (0..s.triangle_count()).filter(|&t| s.material_ids[t] == m).collect()
}

fn area_of(s: &Scene, m: u32) -> f32 {
    triangles_of(s, m).iter().map(|&t| s.triangle_area(t)).sum()
}

fn geometric_normal(s: &Scene, t: usize) -> Vec3 {
    let [a, b, c] = s.triangle_vertices(t);
    (b - a).cross(c - a).normalize()
}

/// Shading normals (where present) lie on the side the winding says is the front.
fn assert_winding_matches_normals(s: &Scene) {
    let normals = s.normals.as_ref().expect("normals");
    for t in 0..s.triangle_count() {
        let g = geometric_normal(s, t);
        for &v in &s.triangles[t] {
            let n = normals[v as usize];
            assert!(g.dot(n) > 0.99, "triangle {t}: winding normal {g} vs vertex normal {n}");
        }
    }
}

#[test]
fn builtin_cornell_box() {
    let s = Scene::builtin_cornell_box();
    assert_eq!(s.source, scene::BUILTIN_SOURCE);
    assert_eq!((s.triangle_count(), s.materials.len(), s.dropped_degenerate), (32, 8, 0));
    let e = s.emitters();
    assert_eq!(e.len(), 2);
    let (light, m) = material(&s, "light");
    assert_eq!(m.emission, Vec3::new(17.0, 12.0, 4.0));
    assert!(e.iter().all(|e| s.material_ids[e.triangle as usize] == light));
    // The light faces down.
    for em in &e {
        assert!((geometric_normal(&s, em.triangle as usize) - Vec3::NEG_Y).length() < 1e-6);
    }
    let (power, _) = s.total_emitted_power();
    let want = std::f32::consts::PI * 130.0 * 105.0 * Vec3::new(17.0, 12.0, 4.0);
    assert!((power - want).length() / want.length() < 1e-5, "{power} vs {want}");
    assert_eq!(material(&s, "leftWall").1.albedo, Vec3::new(0.63, 0.065, 0.05));
    let counts = s.material_counts();
    assert_eq!((counts.diffuse, counts.mirror, counts.glass, counts.emissive), (8, 0, 0, 1));
    let b = s.bounds();
    assert_eq!((b.min, b.max), (Vec3::ZERO, Vec3::new(556.0, 548.8, 559.2)));
    assert_eq!(
        s.cameras,
        vec![Camera {
            name: "cornell-box".into(),
            eye: Vec3::new(278.0, 273.0, -800.0),
            target: Vec3::new(278.0, 273.0, -799.0),
            up: Vec3::Y,
            fov_y_deg: 39.3077,
            width: 256,
            height: 256,
        }]
    );
    // The embedded copy is the shared one.
    let shared = data("../../../shared/scenes/cornell-box/cornell-box.obj");
    if shared.exists() {
        let from_disk = load("../../../shared/scenes/cornell-box/cornell-box.obj").scene;
        assert_eq!(from_disk.positions, s.positions);
        assert_eq!(from_disk.triangles, s.triangles);
        assert_eq!(from_disk.materials, s.materials);
        assert!(from_disk.cameras.is_empty());
    }
}

#[test]
fn room_with_thesis_keys() {
    let l = load("room/room.obj");
    assert!(l.warnings.is_empty(), "{:?}", l.warnings);
    let s = &l.scene;
    assert_eq!(s.triangle_count(), 29);
    assert_eq!(s.materials.len(), 9);
    assert!(s.normals.is_none(), "the room has no vn");
    assert_eq!(s.uvs.as_ref().map(Vec::len), Some(s.vertex_count()));

    let (floor_id, floor) = material(s, "Floor");
    assert_eq!(floor.albedo, Vec3::splat(0.6));
    assert_eq!((floor.emission, floor.reflectivity, floor.refractivity, floor.ior), (Vec3::ZERO, 0.0, 0.0, 1.0));
    assert!(floor.albedo_texture.is_some() && floor.alpha.is_none());

    let (_, mirror) = material(s, "Mirror");
    assert_eq!((mirror.reflectivity, mirror.refractivity), (1.0, 0.0));
    let (glass_id, glass) = material(s, "GlassBlock");
    assert_eq!((glass.reflectivity, glass.refractivity, glass.ior), (0.0, 1.0, 1.5));
    assert_eq!(triangles_of(s, glass_id).len(), 12);
    assert!((area_of(s, glass_id) - 6.0).abs() < 1e-5);

    // emissivity 5 with Ke 0: emission = 5 · Kd.
    let (lamp_id, lamp) = material(s, "Lamp");
    assert_eq!(lamp.emission, Vec3::new(5.0, 4.5, 4.0));
    let e = s.emitters();
    assert_eq!(e.len(), 2);
    assert!(e.iter().all(|e| s.material_ids[e.triangle as usize] == lamp_id));
    let (power, lum) = s.total_emitted_power();
    let want = std::f32::consts::PI * Vec3::new(5.0, 4.5, 4.0);
    assert!((power - want).length() < 1e-4, "{power}");
    assert!((lum - scene::luminance(want)).abs() < 1e-4);

    let (_, half) = material(s, "HalfMirror");
    assert_eq!((half.albedo, half.reflectivity, half.refractivity, half.ior), (Vec3::new(0.5, 0.25, 0.125), 0.3, 0.2, 1.2));
    let (_, old) = material(s, "OldGlass");
    assert_eq!((old.reflectivity, old.refractivity, old.ior), (0.0, 1.0, 1.33));
    let (_, chrome) = material(s, "Chrome");
    assert_eq!((chrome.reflectivity, chrome.refractivity), (1.0, 0.0));

    let c = s.material_counts();
    assert_eq!((c.total, c.diffuse, c.mirror, c.glass, c.emissive, c.alpha_masked, c.textured), (9, 5, 3, 3, 1, 2, 2), "{c:?}");

    // The pentagon: fan-triangulated into 3 triangles covering its area.
    let (penta, _) = material(s, "OldGlass");
    assert_eq!(triangles_of(s, penta).len(), 3);
    assert!((area_of(s, penta) - 2.5 * 0.25 * 72f32.to_radians().sin()).abs() < 1e-3);

    // OBJ's v runs up: vt (0, 0) is the bottom-left texel, uv (0, 1) in the scene.
    let uvs = s.uvs.as_ref().unwrap();
    let t = triangles_of(s, floor_id)[0];
    assert_eq!(s.positions[s.triangles[t][0] as usize], Vec3::ZERO);
    assert_eq!(uvs[s.triangles[t][0] as usize], Vec2::new(0.0, 1.0));
    assert_eq!(uvs[s.triangles[t][1] as usize], Vec2::new(0.0, 0.0));
    // Faces without vt get (0, 0).
    let (mirror_id, _) = material(s, "Mirror");
    assert_eq!(uvs[s.triangles[triangles_of(s, mirror_id)[0]][0] as usize], Vec2::ZERO);
}

#[test]
fn room_textures_srgb_and_alpha() {
    let s = load("room/room.obj").scene;
    assert_eq!(s.textures.len(), 4, "floor colour, leaf colour, leaf opacity, stencil opacity");
    let (_, floor) = material(&s, "Floor");
    let ft = &s.textures[floor.albedo_texture.unwrap() as usize];
    assert!(ft.srgb);
    assert_eq!((ft.width, ft.height), (2, 2));
    // The TGA is stored bottom-up; row 0 of the texture must be its top row: red, green.
    assert_eq!(&ft.rgba8[..8], &[255, 0, 0, 255, 0, 255, 0, 255]);
    assert_eq!(&ft.rgba8[8..], &[0, 0, 255, 255, 255, 255, 255, 255]);

    let (_, leaves) = material(&s, "Leaves");
    let colour = &s.textures[leaves.albedo_texture.unwrap() as usize];
    let AlphaMask { texture, cutoff } = leaves.alpha.unwrap();
    assert_eq!(cutoff, 0.5);
    let opacity = &s.textures[texture as usize];
    assert!(colour.srgb && !opacity.srgb);
    assert_eq!(opacity.rgba8, vec![30, 200, 40, 255, 30, 200, 40, 0]);

    let (_, stencil) = material(&s, "Stencil");
    assert!(stencil.albedo_texture.is_none());
    let mask = &s.textures[stencil.alpha.unwrap().texture as usize];
    assert!(!mask.srgb);
    // A grey image without alpha: its grey level is the alpha.
    assert_eq!((mask.rgba8[3], mask.rgba8[7]), (0, 255));
    assert_eq!(s.texture_bytes(), 16 + 8 + 8 + 8);
    assert!(s.features().textures && s.features().alpha_mask);
    assert!((srgb_to_linear(ft.rgba8[0]) - 1.0).abs() < 1e-6);
}

#[test]
fn polygons_are_fan_triangulated() {
    let l = load("polygons.obj");
    let s = &l.scene;
    assert_eq!(s.triangle_count(), 2 + 3);
    assert_eq!(s.materials.len(), 1);
    assert_eq!(s.materials[0].name, "default");
    let quad: f32 = (0..2).map(|t| s.triangle_area(t)).sum();
    let penta: f32 = (2..5).map(|t| s.triangle_area(t)).sum();
    assert!((quad - 2.0).abs() < 1e-6, "{quad}");
    assert!((penta - 2.37764).abs() < 1e-4, "{penta}");
    for t in 0..5 {
        assert!((geometric_normal(s, t) - Vec3::Z).length() < 1e-5, "triangle {t} flipped");
    }
}

#[test]
fn partial_normals_become_flat_normals() {
    let s = load("normals_partial.obj").scene;
    assert_eq!(s.triangle_count(), 3);
    let n = s.normals.as_ref().expect("normals kept");
    assert_eq!(s.vertex_count(), 3 + 6, "the flat quad's vertices are unshared");
    assert_eq!(n[0], Vec3::new(0.0, 0.6, 0.8));
    for v in &n[3..9] {
        assert!((*v - Vec3::Z).length() < 1e-6, "{v}");
    }
}

#[test]
fn degenerate_triangles_are_dropped_and_counted() {
    let s = load("degenerate.obj").scene;
    assert_eq!(s.triangle_count(), 2);
    assert_eq!(s.dropped_degenerate, 2);
    assert_eq!(s.material_ids.len(), 2);
}

fn check_instanced(l: &Loaded) {
    let s = &l.scene;
    let w = l.warnings.join("\n");
    assert!(!w.contains("BLEND"), "BLEND is supported: {w}");
    for needle in ["Points", "orthographic"] {
        assert!(w.contains(needle), "no warning about {needle}: {w}");
    }
    assert!(!w.contains("KHR_texture_transform"), "KHR_texture_transform is supported: {w}");
    // 6 quads + 1 triangle; the POINTS primitive is skipped.
    assert_eq!(s.triangle_count(), 13);
    assert_eq!(s.materials.len(), 5 + 1, "five materials and the default one");
    assert_eq!(s.materials[5].name, "default");
    assert!(s.uvs.is_some());
    assert_winding_matches_normals(s);

    // MirrorA: Root (90° about +Y) · translate (0, 0, -5): (-1,-1,0) → (-5,-1,1).
    assert!((s.positions[0] - Vec3::new(-5.0, -1.0, 1.0)).length() < 1e-5, "{}", s.positions[0]);
    let (mirror, m) = material(s, "Mirror");
    // glTF metallic-roughness: a smooth metal is a GGX lobe of its roughness, not a mirror.
    assert_eq!(m.model, bidir::scene::MaterialModel::MetalRough);
    assert_eq!((m.reflectivity, m.refractivity, m.metallic), (0.0, 0.0, 1.0));
    let mirrors = triangles_of(s, mirror);
    assert_eq!(mirrors.len(), 4, "MirrorQuad is instanced twice");
    // Both face +X after the root rotation, the mirrored one included.
    for &t in &mirrors {
        assert!((geometric_normal(s, t) - Vec3::X).length() < 1e-5, "triangle {t}");
    }
    let (_, glass) = material(s, "Glass");
    assert_eq!((glass.reflectivity, glass.refractivity, glass.ior), (0.0, 1.0, 1.33));
    let (lamp, m) = material(s, "Lamp");
    assert_eq!(m.emission, Vec3::new(10.0, 5.0, 2.5));
    for t in triangles_of(s, lamp) {
        assert!((geometric_normal(s, t) - Vec3::NEG_Y).length() < 1e-5, "the lamp faces down");
    }
    let (_, glassy) = material(s, "Glassy");
    assert_eq!(glassy.blend, Some(0.5), "BLEND: stochastic opacity of the base colour alpha");
    let (_, leaves) = material(s, "Leaves");
    let tex = leaves.albedo_texture.expect("base colour texture");
    assert_eq!(leaves.alpha, Some(AlphaMask { texture: tex, cutoff: 0.5 }));
    let t = &s.textures[tex as usize];
    assert!(t.srgb);
    assert_eq!((t.width, t.height, &t.rgba8[..8]), (2, 2, &[10u8, 20, 30, 255, 40, 50, 60, 0][..]));
    let (_, blend) = material(s, "Glassy");
    assert_eq!(blend.alpha, None);
    assert_eq!(blend.albedo, Vec3::new(0.2, 0.4, 0.6));

    assert_eq!(s.cameras.len(), 2);
    let c = &s.cameras[0];
    assert_eq!((c.name.as_str(), c.width, c.height), ("CamWide", 2160, 1080));
    assert!((c.fov_y_deg - 0.5f32.to_degrees()).abs() < 1e-4);
    assert_eq!((c.eye, c.target), (Vec3::new(0.0, 1.0, 10.0), Vec3::new(0.0, 1.0, 9.0)));
    let c = &s.cameras[1];
    assert_eq!((c.name.as_str(), c.width, c.height), ("NoAspect", 1920, 1080));
    assert!((c.target - c.eye - Vec3::NEG_X).length() < 1e-5, "-Z turned 90° about +Y is -X");
}

#[test]
fn gltf_instancing_materials_cameras() {
    check_instanced(&load("gltf/instanced.gltf"));
}

#[test]
fn glb_with_embedded_image() {
    let l = load("gltf/instanced.glb");
    check_instanced(&l);
    let g = load("gltf/instanced.gltf").scene;
    assert_eq!(l.scene.positions, g.positions);
    assert_eq!(l.scene.triangles, g.triangles);
}

/// One quantized attribute of `quantized_gltf`: glTF component type, normalised, the
/// integer components (as i64, written at the type's size).
struct Quantized {
    component_type: u32,
    normalized: bool,
    values: Vec<i64>,
}

impl Quantized {
    fn bytes(&self) -> Vec<u8> {
        let mut out = Vec::new();
        for &v in &self.values {
            match self.component_type {
                5120 | 5121 => out.push(v as u8),
                5122 | 5123 => out.extend((v as u16).to_le_bytes()),
                _ => out.extend((v as u32).to_le_bytes()),
            }
        }
        // Each bufferView starts on a multiple of 4 bytes.
        out.resize(out.len().next_multiple_of(4), 0);
        out
    }

    /// Component `k` as glTF 2.0 §3.11 dequantizes it.
    fn float(&self, k: usize) -> f32 {
        let v = self.values[k] as f32;
        if !self.normalized {
            return v;
        }
        match self.component_type {
            5120 => (v / 127.0).max(-1.0),
            5121 => v / 255.0,
            5122 => (v / 32767.0).max(-1.0),
            _ => v / 65535.0,
        }
    }
}

/// A .gltf (and .bin) of one triangle pair whose POSITION, NORMAL and TEXCOORD_0 are the
/// given integers, the node's `scale` and `translation` dequantizing the positions, requiring
/// KHR_mesh_quantization.
fn quantized_gltf(name: &str, pos: &Quantized, nrm: &Quantized, uv: &Quantized, scale: f32, translation: Vec3) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("bidir-quantized-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (mut bin, mut views, mut accessors) = (Vec::new(), Vec::new(), Vec::new());
    for (q, ty, extra) in
        [(pos, "VEC3", ", \"min\": [-32768, -32768, -32768], \"max\": [65535, 65535, 65535]"), (nrm, "VEC3", ""), (uv, "VEC2", "")]
    {
        let dims = if ty == "VEC3" { 3 } else { 2 };
        let bytes = q.bytes();
        views.push(format!(r#"{{"buffer": 0, "byteOffset": {}, "byteLength": {}}}"#, bin.len(), bytes.len()));
        bin.extend(bytes);
        accessors.push(format!(
            r#"{{"bufferView": {}, "componentType": {}, "normalized": {}, "count": {}, "type": "{ty}"{extra}}}"#,
            views.len() - 1,
            q.component_type,
            q.normalized,
            q.values.len() / dims
        ));
    }
    let indices: Vec<u8> = [0u16, 1, 2, 0, 2, 3].iter().flat_map(|i| i.to_le_bytes()).collect();
    views.push(format!(r#"{{"buffer": 0, "byteOffset": {}, "byteLength": 12}}"#, bin.len()));
    bin.extend(indices);
    accessors.push(format!(r#"{{"bufferView": {}, "componentType": 5123, "count": 6, "type": "SCALAR"}}"#, views.len() - 1));
    std::fs::write(dir.join(format!("{name}.bin")), &bin).unwrap();
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}}, "extensionsUsed": ["KHR_mesh_quantization"], "extensionsRequired": ["KHR_mesh_quantization"],
  "buffers": [{{"uri": "{name}.bin", "byteLength": {}}}], "bufferViews": [{}], "accessors": [{}],
  "materials": [{{"name": "m"}}],
  "meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}}, "indices": 3, "material": 0}}]}}],
  "nodes": [{{"mesh": 0, "scale": [{scale}, {scale}, {scale}], "translation": [{}, {}, {}]}}], "scenes": [{{"nodes": [0]}}], "scene": 0}}"#,
        bin.len(),
        views.join(", "),
        accessors.join(", "),
        translation.x,
        translation.y,
        translation.z
    );
    let path = dir.join(format!("{name}.gltf"));
    std::fs::write(&path, json).unwrap();
    path
}

/// KHR_mesh_quantization (gltfpack's output, among others): positions, normals and texture
/// coordinates stored as integers of every allowed type, normalised or not, load as the floats
/// glTF's dequantization rule and the node's transform give, with no warning; integer normals
/// that are not normalised, and 32-bit integer positions, are errors naming the accessor.
#[test]
fn quantized_attributes_load_as_their_floats() {
    let q = |component_type, normalized, values: &[i64]| Quantized { component_type, normalized, values: values.to_vec() };
    // A unit square in the z = 0 plane as integers (corners 0 and `one`), its normal +z.
    let cases = [
        (
            "i16",
            q(5122, false, &[-1000, -1000, 0, 1000, -1000, 0, 1000, 1000, 0, -1000, 1000, 0]),
            1000.0,
            q(5120, true, &[0, 0, 127, 0, 0, 127, 0, 0, 127, 0, 0, 127]),
            q(5123, true, &[0, 0, 65535, 0, 65535, 65535, 0, 65535]),
        ),
        (
            "u8",
            q(5121, true, &[0, 0, 0, 255, 0, 0, 255, 255, 0, 0, 255, 0]),
            1.0,
            q(5122, true, &[0, 0, 32767, 0, 0, 32767, 0, 0, 32767, 0, 0, 32767]),
            q(5122, false, &[0, 0, 2, 0, 2, 2, 0, 2]),
        ),
        (
            "u16",
            q(5123, false, &[0, 0, 0, 4, 0, 0, 4, 4, 0, 0, 4, 0]),
            4.0,
            q(5120, true, &[0, 0, 127, 0, 0, 127, 0, 0, 127, 0, 0, 127]),
            q(5120, true, &[0, 0, 127, 0, 127, 127, 0, 127]),
        ),
        (
            "i8",
            q(5120, true, &[-127, -127, 0, 127, -127, 0, 127, 127, 0, -127, 127, 0]),
            1.0,
            q(5120, true, &[0, 0, 127, 0, 0, 127, 0, 0, 127, 0, 0, 127]),
            q(5121, false, &[0, 0, 1, 0, 1, 1, 0, 1]),
        ),
    ];
    let translation = Vec3::new(0.5, -2.0, 3.0);
    for (name, pos, one, nrm, uv) in &cases {
        let path = quantized_gltf(name, pos, nrm, uv, 1.0 / one, translation);
        let l = scene::load(&path, &LoadOptions { strict: true }).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(l.warnings.is_empty(), "{name}: {:?}", l.warnings);
        let s = &l.scene;
        assert_eq!(s.triangle_count(), 2, "{name}");
        let (normals, uvs) = (s.normals.as_ref().expect("normals"), s.uvs.as_ref().expect("uvs"));
        for i in 0..4 {
            let want = Vec3::new(pos.float(3 * i), pos.float(3 * i + 1), pos.float(3 * i + 2)) / *one + translation;
            assert!((s.positions[i] - want).length() < 1e-5, "{name}: vertex {i} at {} not {want}", s.positions[i]);
            let n = Vec3::new(nrm.float(3 * i), nrm.float(3 * i + 1), nrm.float(3 * i + 2)).normalize();
            assert!((normals[i] - n).length() < 1e-5, "{name}: normal {i} {} not {n}", normals[i]);
            let t = Vec2::new(uv.float(2 * i), uv.float(2 * i + 1));
            assert!((uvs[i] - t).length() < 1e-6, "{name}: uv {i} {} not {t}", uvs[i]);
        }
        // The square's side is the dequantized one.
        assert!(((s.positions[1] - s.positions[0]).length() - (pos.float(3) - pos.float(0)) / one).abs() < 1e-5, "{name}");
    }
    let square = q(5122, false, &[0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]);
    let uv = q(5121, true, &[0, 0, 255, 0, 255, 255, 0, 255]);
    let raw_normals = q(5120, false, &[0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]);
    let e = scene::load(&quantized_gltf("raw-normals", &square, &raw_normals, &uv, 1.0, Vec3::ZERO), &LoadOptions::default())
        .unwrap_err()
        .to_string();
    assert!(e.contains("accessor 1 (NORMAL)") && e.contains("must be normalized"), "{e}");
    let wide = q(5125, false, &[0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]);
    let n = q(5120, true, &[0, 0, 127, 0, 0, 127, 0, 0, 127, 0, 0, 127]);
    let e =
        scene::load(&quantized_gltf("u32-positions", &wide, &n, &uv, 1.0, Vec3::ZERO), &LoadOptions::default()).unwrap_err().to_string();
    assert!(e.contains("accessor 0 (POSITION)") && e.contains("component type U32"), "{e}");
}

#[test]
fn required_material_extensions_only_warn_and_texture_transform_is_read() {
    let l = scene::load(&data("gltf/requires_texture_transform.gltf"), &LoadOptions::default()).unwrap();
    assert_eq!(l.scene.triangle_count(), 2);
    let w = l.warnings.join("\n");
    assert!(w.contains("KHR_materials_sheen") && !w.contains("KHR_texture_transform"), "{w}");
}

#[test]
fn sponza() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/scenes/sponza/Sponza.gltf");
    if !path.exists() {
        eprintln!("skipping: {} is absent", path.display());
        return;
    }
    let start = std::time::Instant::now();
    let l = scene::load(&path, &LoadOptions::default()).unwrap();
    eprintln!("Sponza loaded in {:.3} s", start.elapsed().as_secs_f64());
    let s = &l.scene;
    assert_eq!(s.triangle_count(), 262_087);
    let names: Vec<&str> = s.cameras.iter().map(|c| c.name.as_str()).collect();
    assert_eq!(names, ["CameraMain", "CameraAlternate", "CameraBalcony", "CameraAlcove"]);
    assert!(s.cameras.iter().all(|c| (c.width, c.height) == (1920, 1080) && (c.fov_y_deg - 45.0).abs() < 1e-3));
    let masked: Vec<&str> = s.materials.iter().filter(|m| m.alpha.is_some()).map(|m| m.name.as_str()).collect();
    assert_eq!(masked, ["PotPlant1", "Chain", "Plants"]);
    assert!(s.normals.is_some() && s.uvs.is_some());
    // 24 base colour (sRGB) and 11 data textures (linear: normal and metallic-roughness maps).
    assert_eq!(s.textures.len(), 35);
    assert_eq!(s.textures.iter().filter(|t| t.srgb).count(), 24);
    assert!(s.textures.iter().all(|t| t.rgba8.len() == (t.width * t.height * 4) as usize));
    assert_eq!(s.dropped_degenerate, 0);
    assert!(s.emitters().is_empty());
    assert_winding_matches_normals_loosely(s);
}

/// Sponza's normals are smooth, so only most of them agree with the winding exactly; a
/// flipped instance would make about half disagree.
fn assert_winding_matches_normals_loosely(s: &Scene) {
    let normals = s.normals.as_ref().unwrap();
    let agree = (0..s.triangle_count())
        .filter(|&t| {
            let g = geometric_normal(s, t);
            let n: Vec3 = s.triangles[t].iter().map(|&v| normals[v as usize]).sum();
            g.dot(n) > 0.0
        })
        .count();
    assert!(agree as f64 > 0.99 * s.triangle_count() as f64, "{agree} of {}", s.triangle_count());
}

/// Khronos sample models (`../shared/scenes/gltf-samples`, skipped when absent) load with no
/// warning about what the materials issue implemented: metallic-roughness (and its texture),
/// emissive and normal textures, BLEND; occlusion is ignored silently.
#[test]
fn gltf_sample_models_load_their_materials_without_warnings() {
    let dir = Path::new("../shared/scenes/gltf-samples");
    if !dir.exists() {
        eprintln!("skipping: {} is absent", dir.display());
        return;
    }
    let load = |name: &str| {
        let l = scene::load(&dir.join(name).join(format!("{name}.glb")), &LoadOptions::default()).unwrap();
        assert!(l.warnings.is_empty(), "{name}: {:?}", l.warnings);
        l.scene
    };
    let spheres = load("MetalRoughSpheresNoTextures");
    let c = spheres.material_counts();
    assert_eq!((c.glossy, c.mirror), (c.total - 1, 0), "every material but the default one is GGX: {c:?}");
    let metallic: Vec<f32> = spheres.materials.iter().filter(|m| m.is_glossy()).map(|m| m.metallic).collect();
    assert!(metallic.contains(&0.0) && metallic.contains(&1.0), "{metallic:?}");

    let helmet = load("DamagedHelmet");
    let m = &helmet.materials[0];
    assert_eq!(m.model, scene::MaterialModel::MetalRough);
    assert!(m.emission_texture.is_some() && m.normal_texture.is_some() && m.albedo_texture.is_some());
    assert!(m.roughness_texture.is_some() && m.roughness_texture == m.metallic_texture);
    let mr = &helmet.textures[m.roughness_texture.unwrap() as usize];
    assert!(!mr.srgb && !helmet.textures[m.normal_texture.unwrap() as usize].srgb, "data textures are linear");
    assert!(helmet.textures[m.emission_texture.unwrap() as usize].srgb);

    let blend = load("AlphaBlendModeTest");
    assert!(blend.material_counts().blended > 0, "BLEND materials: {:?}", blend.material_counts());
}
