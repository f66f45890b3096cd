//! Assembles the one compact vertex/triangle list both loaders produce.
//!
//! The loaders hand over *parts* (an OBJ object/material group, a glTF primitive instance)
//! with part-local indices; the builder appends them, so the rules live in one place:
//! - Normals and UVs exist for the whole scene or not at all (decided before the first part:
//!   `with_normals`, `with_uvs`). A part without normals in a scene with normals gets its flat
//!   face normal on unshared vertices (exactly what "no normals" means to a renderer); a part
//!   without UVs gets (0, 0) (it can only be untextured, or its texture is read at one texel).
//! - A triangle whose area is zero or not finite (after the transform) is dropped and
//!   counted, not an error.
//! - A transform with a negative determinant mirrors the geometry, so it swaps the winding to
//!   keep "counter-clockwise seen from the front".

use glam::{Mat3, Mat4, Vec2, Vec3, Vec4};

/// Geometry with part-local indices (all `< positions.len()`, checked by the loader).
pub(crate) struct Part<'a> {
    pub positions: &'a [Vec3],
    pub normals: Option<&'a [Vec3]>,
    pub uvs: Option<&'a [Vec2]>,
    /// Tangents (xyz, handedness w); used only when the builder keeps tangents.
    pub tangents: Option<&'a [Vec4]>,
    pub triangles: &'a [[u32; 3]],
    pub material: u32,
}

/// An instance transform: positions by `matrix`, normals by its inverse transpose.
pub(crate) struct Transform {
    matrix: Mat4,
    normal: Mat3,
    flip: bool,
}

impl Transform {
    pub fn new(matrix: Mat4) -> Self {
        let m3 = Mat3::from_mat4(matrix);
        let det = m3.determinant();
        // A singular matrix flattens the part; its triangles become degenerate and are dropped.
        let normal = if det != 0.0 { m3.inverse().transpose() } else { Mat3::ZERO };
        Transform { matrix, normal, flip: det < 0.0 }
    }
}

#[derive(Default)]
pub(crate) struct Builder {
    pub positions: Vec<Vec3>,
    pub normals: Option<Vec<Vec3>>,
    pub uvs: Option<Vec<Vec2>>,
    /// Kept only when every part has normals and tangents (`with_tangents`).
    pub tangents: Option<Vec<Vec4>>,
    pub triangles: Vec<[u32; 3]>,
    pub material_ids: Vec<u32>,
    pub dropped_degenerate: usize,
}

impl Builder {
    pub fn new(with_normals: bool, with_uvs: bool) -> Self {
        Builder { normals: with_normals.then(Vec::new), uvs: with_uvs.then(Vec::new), ..Default::default() }
    }

    /// Keeps the parts' tangents (the caller has checked that every part has them and
    /// normals): transformed by the instance matrix, handedness flipped by a mirror.
    pub fn with_tangents(mut self) -> Self {
        self.tangents = self.normals.is_some().then(Vec::new);
        self
    }

    pub fn reserve(&mut self, vertices: usize, triangles: usize) {
        self.positions.reserve(vertices);
        if let Some(n) = &mut self.normals {
            n.reserve(vertices);
        }
        if let Some(t) = &mut self.uvs {
            t.reserve(vertices);
        }
        self.triangles.reserve(triangles);
        self.material_ids.reserve(triangles);
    }

    /// Appends `part`, transformed by `xf` if given.
    pub fn push(&mut self, part: &Part, xf: Option<&Transform>) {
        if self.normals.is_some() && part.normals.is_none() {
            return self.push_flat(part, xf);
        }
        let base = self.positions.len() as u32;
        match xf {
            Some(xf) => self.positions.extend(part.positions.iter().map(|p| xf.matrix.transform_point3(*p))),
            None => self.positions.extend_from_slice(part.positions),
        }
        if let (Some(out), Some(src)) = (&mut self.normals, part.normals) {
            match xf {
                Some(xf) => out.extend(src.iter().map(|n| (xf.normal * *n).normalize_or_zero())),
                None => out.extend(src.iter().map(|n| n.normalize_or_zero())),
            }
        }
        if let Some(out) = &mut self.uvs {
            match part.uvs {
                Some(src) => out.extend_from_slice(src),
                None => out.resize(out.len() + part.positions.len(), Vec2::ZERO),
            }
        }
        let flip = xf.is_some_and(|x| x.flip);
        if let Some(out) = &mut self.tangents {
            // A tangent lies in the surface: it transforms by the matrix itself.
            let one = |t: &Vec4| {
                let d = xf.map_or(t.truncate(), |xf| Mat3::from_mat4(xf.matrix) * t.truncate()).normalize_or_zero();
                d.extend(if (t.w < 0.0) != flip { -1.0 } else { 1.0 })
            };
            match part.tangents {
                Some(src) => out.extend(src.iter().map(one)),
                None => out.resize(out.len() + part.positions.len(), Vec4::ZERO),
            }
        }
        for t in part.triangles {
            let t = if flip { [t[0], t[2], t[1]] } else { *t };
            let [a, b, c] = t.map(|i| self.positions[(base + i) as usize]);
            if is_degenerate(a, b, c) {
                self.dropped_degenerate += 1;
                continue;
            }
            self.triangles.push(t.map(|i| base + i));
            self.material_ids.push(part.material);
        }
    }

    /// A part without normals in a scene with normals: three vertices per triangle, each
    /// with the face normal.
    fn push_flat(&mut self, part: &Part, xf: Option<&Transform>) {
        let flip = xf.is_some_and(|x| x.flip);
        for t in part.triangles {
            let t = if flip { [t[0], t[2], t[1]] } else { *t };
            let p = t.map(|i| {
                let p = part.positions[i as usize];
                xf.map_or(p, |xf| xf.matrix.transform_point3(p))
            });
            if is_degenerate(p[0], p[1], p[2]) {
                self.dropped_degenerate += 1;
                continue;
            }
            let n = (p[1] - p[0]).cross(p[2] - p[0]).normalize();
            let base = self.positions.len() as u32;
            self.positions.extend_from_slice(&p);
            if let Some(out) = &mut self.normals {
                out.extend_from_slice(&[n; 3]);
            }
            if let Some(out) = &mut self.uvs {
                out.extend(t.map(|i| part.uvs.map_or(Vec2::ZERO, |uv| uv[i as usize])));
            }
            self.triangles.push([base, base + 1, base + 2]);
            self.material_ids.push(part.material);
        }
    }
}

/// Zero area, or not finite (the cross product catches NaN and Inf in any corner).
pub(crate) fn is_degenerate(a: Vec3, b: Vec3, c: Vec3) -> bool {
    let n = (b - a).cross(c - a);
    let len2 = n.length_squared();
    !(len2 > 0.0 && len2.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;

    const QUAD: [Vec3; 4] = [Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y];
    const TRIS: [[u32; 3]; 2] = [[0, 1, 2], [0, 2, 3]];

    fn part<'a>(normals: Option<&'a [Vec3]>, tris: &'a [[u32; 3]]) -> Part<'a> {
        Part { positions: &QUAD, normals, uvs: None, tangents: None, triangles: tris, material: 7 }
    }

    #[test]
    fn drops_and_counts_degenerate_triangles() {
        let tris = [[0, 1, 2], [0, 0, 1], [0, 1, 1], [0, 2, 3]];
        let mut b = Builder::new(false, false);
        b.push(&part(None, &tris), None);
        assert_eq!(b.triangles, vec![[0, 1, 2], [0, 2, 3]]);
        assert_eq!(b.material_ids, vec![7, 7]);
        assert_eq!(b.dropped_degenerate, 2);
    }

    #[test]
    fn nan_corner_is_degenerate() {
        assert!(is_degenerate(Vec3::ZERO, Vec3::X, Vec3::new(f32::NAN, 0.0, 0.0)));
        assert!(is_degenerate(Vec3::ZERO, Vec3::X, Vec3::new(0.0, f32::INFINITY, 0.0)));
        assert!(!is_degenerate(Vec3::ZERO, Vec3::X, Vec3::Y));
    }

    #[test]
    fn mirror_transform_flips_winding_and_keeps_facing() {
        let mut b = Builder::new(true, false);
        let normals = [Vec3::Z; 4];
        // Mirror in x: the front face (+z normal, CCW seen from +z) must stay CCW from +z.
        b.push(&part(Some(&normals), &TRIS), Some(&Transform::new(Mat4::from_scale(Vec3::new(-1.0, 1.0, 1.0)))));
        for t in &b.triangles {
            let [p0, p1, p2] = t.map(|i| b.positions[i as usize]);
            let geometric = (p1 - p0).cross(p2 - p0).normalize();
            assert!(geometric.dot(Vec3::Z) > 0.99, "winding not flipped: {geometric}");
        }
        assert!(b.normals.unwrap().iter().all(|n| (*n - Vec3::Z).length() < 1e-6));
    }

    #[test]
    fn normals_use_the_inverse_transpose() {
        // A 45° slope scaled by 2 in x: the normal of the plane x = y is (1,-1,0)/√2; after
        // scaling x by 2 the plane is x = 2y, whose normal is (1,-2,0)/√5 — not M·n.
        let pos = [Vec3::ZERO, Vec3::new(1.0, 1.0, 0.0), Vec3::new(0.0, 0.0, 1.0)];
        let n = Vec3::new(1.0, -1.0, 0.0).normalize();
        let mut b = Builder::new(true, false);
        let p = Part { positions: &pos, normals: Some(&[n; 3]), uvs: None, tangents: None, triangles: &[[0, 1, 2]], material: 0 };
        b.push(&p, Some(&Transform::new(Mat4::from_scale(Vec3::new(2.0, 1.0, 1.0)))));
        let got = b.normals.unwrap()[0];
        let want = Vec3::new(1.0, -2.0, 0.0).normalize();
        assert!((got - want).length() < 1e-6, "{got} != {want}");
    }

    #[test]
    fn part_without_normals_gets_flat_unshared_vertices() {
        let mut b = Builder::new(true, true);
        let normals = [Vec3::Z; 4];
        b.push(&part(Some(&normals), &TRIS), None);
        b.push(&part(None, &TRIS), Some(&Transform::new(Mat4::from_rotation_x(std::f32::consts::FRAC_PI_2))));
        assert_eq!(b.positions.len(), 4 + 6);
        let n = b.normals.as_ref().unwrap();
        assert_eq!(n.len(), b.positions.len());
        assert_eq!(b.uvs.as_ref().unwrap().len(), b.positions.len());
        // Rotating +z by 90° about x gives -y.
        for v in &n[4..10] {
            assert!((*v - Vec3::NEG_Y).length() < 1e-6, "{v}");
        }
        assert_eq!(b.triangles[2], [4, 5, 6]);
    }
}
