//! Writes small glTF files for loader-to-render tests: meshes of flat quads and boxes (no
//! normals; UVs 0..1 across each face), one node each, with materials given as JSON and
//! textures of one colour each.

use glam::Vec3;
use std::path::PathBuf;

/// One mesh with one primitive: triangles (CCW fronts) and the index of its material.
pub struct Mesh {
    pub positions: Vec<Vec3>,
    pub uvs: Vec<[f32; 2]>,
    pub triangles: Vec<[u32; 3]>,
    pub material: usize,
}

impl Mesh {
    fn new(material: usize) -> Mesh {
        Mesh { positions: Vec::new(), uvs: Vec::new(), triangles: Vec::new(), material }
    }

    /// Appends the parallelogram (c, c + e1, c + e1 + e2, c + e2), its front toward `front`.
    fn push_quad(&mut self, c: Vec3, e1: Vec3, e2: Vec3, front: Vec3) {
        let (e1, e2) = if e1.cross(e2).dot(front) > 0.0 { (e1, e2) } else { (e2, e1) };
        let b = self.positions.len() as u32;
        self.positions.extend([c, c + e1, c + e1 + e2, c + e2]);
        self.uvs.extend([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
        self.triangles.extend([[b, b + 1, b + 2], [b, b + 2, b + 3]]);
    }

    /// A parallelogram (two triangles), front toward `front`.
    pub fn quad(c: Vec3, e1: Vec3, e2: Vec3, front: Vec3, material: usize) -> Mesh {
        let mut m = Mesh::new(material);
        m.push_quad(c, e1, e2, front);
        m
    }

    /// The closed axis-aligned box [lo, hi]: 12 triangles, fronts outward.
    pub fn cuboid(lo: Vec3, hi: Vec3, material: usize) -> Mesh {
        let mut m = Mesh::new(material);
        let d = hi - lo;
        for axis in 0..3 {
            let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
            let (u, v) = (Vec3::AXES[a] * d[a], Vec3::AXES[b] * d[b]);
            let n = Vec3::AXES[axis];
            m.push_quad(lo, u, v, -n);
            m.push_quad(lo + n * d[axis], u, v, n);
        }
        m
    }
}

/// Writes `name.gltf` and `name.bin` into a per-process temporary folder and returns the
/// glTF's path. `materials` are glTF material objects (JSON), `extensions` the
/// `extensionsUsed` list; `textures[i]` (texture i, image `name-i.png`) is 2 x 2 texels of
/// one RGBA8 value.
pub fn write(name: &str, meshes: &[Mesh], materials: &[String], extensions: &[&str], textures: &[[u8; 4]]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("bidir-gltf-out-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (mut bin, mut views, mut accessors, mut json_meshes, mut nodes) = (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
    // Appends one buffer view of `bytes` and its accessor (the `rest` of its JSON).
    let mut push = |bytes: Vec<u8>, rest: String| {
        let start = bin.len();
        bin.extend(bytes);
        views.push(format!(r#"{{"buffer": 0, "byteOffset": {start}, "byteLength": {}}}"#, bin.len() - start));
        accessors.push(format!(r#"{{"bufferView": {}, {rest}}}"#, views.len() - 1));
        accessors.len() - 1
    };
    for (i, m) in meshes.iter().enumerate() {
        let lo = m.positions.iter().fold(Vec3::INFINITY, |a, &p| a.min(p));
        let hi = m.positions.iter().fold(Vec3::NEG_INFINITY, |a, &p| a.max(p));
        let positions = push(
            m.positions.iter().flat_map(|p| p.to_array()).flat_map(f32::to_le_bytes).collect(),
            format!(
                r#""componentType": 5126, "count": {}, "type": "VEC3", "min": [{}, {}, {}], "max": [{}, {}, {}]"#,
                m.positions.len(),
                lo.x,
                lo.y,
                lo.z,
                hi.x,
                hi.y,
                hi.z
            ),
        );
        let uvs = push(
            m.uvs.iter().flatten().flat_map(|v| v.to_le_bytes()).collect(),
            format!(r#""componentType": 5126, "count": {}, "type": "VEC2""#, m.uvs.len()),
        );
        let indices = push(
            m.triangles.iter().flatten().flat_map(|v| v.to_le_bytes()).collect(),
            format!(r#""componentType": 5125, "count": {}, "type": "SCALAR""#, 3 * m.triangles.len()),
        );
        json_meshes.push(format!(
            r#"{{"primitives": [{{"attributes": {{"POSITION": {positions}, "TEXCOORD_0": {uvs}}}, "indices": {indices}, "material": {}}}]}}"#,
            m.material
        ));
        nodes.push(format!(r#"{{"mesh": {i}}}"#));
    }
    std::fs::write(dir.join(format!("{name}.bin")), &bin).unwrap();
    let mut images = Vec::new();
    for (i, texel) in textures.iter().enumerate() {
        let file = format!("{name}-{i}.png");
        image::save_buffer(dir.join(&file), &texel.repeat(4), 2, 2, image::ExtendedColorType::Rgba8).unwrap();
        images.push(format!(r#"{{"uri": "{file}"}}"#));
    }
    let texture_list: Vec<String> = (0..textures.len()).map(|i| format!(r#"{{"source": {i}}}"#)).collect();
    let quoted: Vec<String> = extensions.iter().map(|e| format!("\"{e}\"")).collect();
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}}, "extensionsUsed": [{}], "scene": 0, "scenes": [{{"nodes": [{}]}}],
 "nodes": [{}], "meshes": [{}], "materials": [{}], "textures": [{}], "images": [{}],
 "buffers": [{{"uri": "{name}.bin", "byteLength": {}}}], "bufferViews": [{}], "accessors": [{}]}}"#,
        quoted.join(", "),
        (0..meshes.len()).map(|i| i.to_string()).collect::<Vec<_>>().join(", "),
        nodes.join(", "),
        json_meshes.join(", "),
        materials.join(", "),
        texture_list.join(", "),
        images.join(", "),
        bin.len(),
        views.join(", "),
        accessors.join(", ")
    );
    let path = dir.join(format!("{name}.gltf"));
    std::fs::write(&path, json).unwrap();
    path
}
