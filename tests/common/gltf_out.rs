//! Writes small glTF files for loader-to-render tests: meshes of flat quads and boxes (no
//! normals, no UVs), one node each, with materials given as JSON.

use glam::Vec3;
use std::path::PathBuf;

/// One mesh with one primitive: triangles (CCW fronts) and the index of its material.
pub struct Mesh {
    pub positions: Vec<Vec3>,
    pub triangles: Vec<[u32; 3]>,
    pub material: usize,
}

impl Mesh {
    fn new(material: usize) -> Mesh {
        Mesh { positions: Vec::new(), triangles: Vec::new(), material }
    }

    /// Appends the parallelogram (c, c + e1, c + e1 + e2, c + e2), its front toward `front`.
    fn push_quad(&mut self, c: Vec3, e1: Vec3, e2: Vec3, front: Vec3) {
        let (e1, e2) = if e1.cross(e2).dot(front) > 0.0 { (e1, e2) } else { (e2, e1) };
        let b = self.positions.len() as u32;
        self.positions.extend([c, c + e1, c + e1 + e2, c + e2]);
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
/// `extensionsUsed` list.
pub fn write(name: &str, meshes: &[Mesh], materials: &[String], extensions: &[&str]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("bidir-gltf-out-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (mut bin, mut views, mut accessors, mut json_meshes, mut nodes) = (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for (i, m) in meshes.iter().enumerate() {
        let start = bin.len();
        bin.extend(m.positions.iter().flat_map(|p| p.to_array()).flat_map(f32::to_le_bytes));
        views.push(format!(r#"{{"buffer": 0, "byteOffset": {start}, "byteLength": {}}}"#, bin.len() - start));
        let lo = m.positions.iter().fold(Vec3::INFINITY, |a, &p| a.min(p));
        let hi = m.positions.iter().fold(Vec3::NEG_INFINITY, |a, &p| a.max(p));
        accessors.push(format!(
            r#"{{"bufferView": {}, "componentType": 5126, "count": {}, "type": "VEC3", "min": [{}, {}, {}], "max": [{}, {}, {}]}}"#,
            2 * i,
            m.positions.len(),
            lo.x,
            lo.y,
            lo.z,
            hi.x,
            hi.y,
            hi.z
        ));
        let start = bin.len();
        bin.extend(m.triangles.iter().flatten().flat_map(|v| v.to_le_bytes()));
        views.push(format!(r#"{{"buffer": 0, "byteOffset": {start}, "byteLength": {}}}"#, bin.len() - start));
        accessors.push(format!(
            r#"{{"bufferView": {}, "componentType": 5125, "count": {}, "type": "SCALAR"}}"#,
            2 * i + 1,
            3 * m.triangles.len()
        ));
        json_meshes.push(format!(
            r#"{{"primitives": [{{"attributes": {{"POSITION": {}}}, "indices": {}, "material": {}}}]}}"#,
            2 * i,
            2 * i + 1,
            m.material
        ));
        nodes.push(format!(r#"{{"mesh": {i}}}"#));
    }
    std::fs::write(dir.join(format!("{name}.bin")), &bin).unwrap();
    let quoted: Vec<String> = extensions.iter().map(|e| format!("\"{e}\"")).collect();
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}}, "extensionsUsed": [{}], "scene": 0, "scenes": [{{"nodes": [{}]}}],
 "nodes": [{}], "meshes": [{}], "materials": [{}],
 "buffers": [{{"uri": "{name}.bin", "byteLength": {}}}], "bufferViews": [{}], "accessors": [{}]}}"#,
        quoted.join(", "),
        (0..meshes.len()).map(|i| i.to_string()).collect::<Vec<_>>().join(", "),
        nodes.join(", "),
        json_meshes.join(", "),
        materials.join(", "),
        bin.len(),
        views.join(", "),
        accessors.join(", ")
    );
    let path = dir.join(format!("{name}.gltf"));
    std::fs::write(&path, json).unwrap();
    path
}
