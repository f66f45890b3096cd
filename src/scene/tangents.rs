//! Per-vertex tangent frames for tangent-space normal maps, generated from the texture
//! coordinates (Lengyel 2001, "Computing Tangent Space Basis Vectors for an Arbitrary Mesh"):
//! per triangle the directions in which u and image-up (decreasing v: bidir's UVs have (0, 0)
//! at the top-left, so "up" in a normal map, +Y, is -v) increase, summed per vertex
//! (weighted by the triangle's size, as the unnormalised derivatives are), then made
//! orthogonal to the vertex normal (Gram–Schmidt). `w` is the handedness: the bitangent is
//! `cross(n, t) * w`, as glTF defines it. Not MikkTSpace: maps baked against MikkTSpace
//! tangents differ slightly where UV charts are sheared.

use glam::{Vec3, Vec4};

use super::Scene;

/// Tangents (xyz unit, w = ±1) for every vertex; `None` without normals or UVs.
pub fn generate(scene: &Scene) -> Option<Vec<Vec4>> {
    let (normals, uvs) = (scene.normals.as_ref()?, scene.uvs.as_ref()?);
    let n = scene.positions.len();
    // The file's tangents (glTF TANGENT), where the loader kept them for every vertex.
    if let Some(t) = scene.tangents.as_ref().filter(|t| t.len() == n) {
        return Some(t.clone());
    }
    let (mut tan, mut up) = (vec![Vec3::ZERO; n], vec![Vec3::ZERO; n]);
    for tri in &scene.triangles {
        let [a, b, c] = tri.map(|i| i as usize);
        let (e1, e2) = (scene.positions[b] - scene.positions[a], scene.positions[c] - scene.positions[a]);
        let (d1, d2) = (uvs[b] - uvs[a], uvs[c] - uvs[a]);
        let det = d1.x * d2.y - d2.x * d1.y;
        if det == 0.0 || !det.is_finite() {
            continue;
        }
        // dp/du and dp/dv, times det's sign so that the sums weigh triangles by area.
        let s = det.signum();
        let dpdu = (e1 * d2.y - e2 * d1.y) * s;
        let dpdv = (e2 * d1.x - e1 * d2.x) * s;
        for v in [a, b, c] {
            tan[v] += dpdu;
            up[v] -= dpdv;
        }
    }
    Some(
        (0..n)
            .map(|i| {
                let nrm = normals[i];
                let mut t = tan[i] - nrm * nrm.dot(tan[i]);
                if t.length_squared() <= 1e-20 || !t.is_finite() {
                    t = nrm.any_orthonormal_vector();
                }
                let t = t.normalize_or_zero();
                let w = if nrm.cross(t).dot(up[i]) < 0.0 { -1.0 } else { 1.0 };
                t.extend(w)
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec2;

    /// A quad in the z = 0 plane facing +z, u along +x and v along -y (image up is +y): the
    /// tangent is +x and the bitangent cross(n, t) * w = +y; mirroring u flips w.
    #[test]
    fn tangents_follow_u_and_image_up() {
        let mut s = Scene {
            positions: vec![Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y],
            normals: Some(vec![Vec3::Z; 4]),
            uvs: Some(vec![Vec2::new(0.0, 1.0), Vec2::new(1.0, 1.0), Vec2::new(1.0, 0.0), Vec2::new(0.0, 0.0)]),
            triangles: vec![[0, 1, 2], [0, 2, 3]],
            ..Default::default()
        };
        for t in generate(&s).unwrap() {
            assert!((t.truncate() - Vec3::X).length() < 1e-6 && t.w == 1.0, "{t}");
            assert!((Vec3::Z.cross(t.truncate()) * t.w - Vec3::Y).length() < 1e-6);
        }
        s.uvs = Some(s.uvs.unwrap().iter().map(|uv| Vec2::new(1.0 - uv.x, uv.y)).collect());
        for t in generate(&s).unwrap() {
            assert!((t.truncate() + Vec3::X).length() < 1e-6 && t.w == -1.0, "{t}");
            assert!((Vec3::Z.cross(t.truncate()) * t.w - Vec3::Y).length() < 1e-6);
        }
        s.uvs = None;
        assert!(generate(&s).is_none());
    }
}
