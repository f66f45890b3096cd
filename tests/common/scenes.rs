//! Test scenes shared by several test files.

use super::geometry;
use bidir::scene::{Camera, Material, Scene};
use glam::Vec3;

/// The analytic furnace: a sphere of diffuse albedo `rho` emitting `le` on its inside, where
/// the radiance is le / (1 - rho) everywhere. The sphere's triangles are wound to face
/// inward (front faces toward the centre).
pub fn furnace_scene(rho: f32, le: f32) -> Scene {
    let (positions, tris) = geometry::icosphere(3, Vec3::ZERO, 1.0);
    let triangles: Vec<[u32; 3]> = tris.into_iter().map(|[a, b, c]| [a, c, b]).collect();
    let n = triangles.len();
    Scene {
        source: "test:furnace".into(),
        positions,
        triangles,
        material_ids: vec![0; n],
        materials: vec![Material { name: "furnace".into(), albedo: Vec3::splat(rho), emission: Vec3::splat(le), ..Default::default() }],
        cameras: vec![Camera {
            name: "inside".into(),
            eye: Vec3::new(0.1, -0.05, 0.02),
            target: Vec3::new(1.0, 0.3, 0.2),
            up: Vec3::Y,
            fov_y_deg: 90.0,
            width: 64,
            height: 64,
        }],
        ..Default::default()
    }
}
