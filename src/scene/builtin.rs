//! The built-in default scene: the Cornell box (measured data, `assets/cornell-box.*`),
//! embedded in the binary and loaded through the same OBJ path as any file, with the camera
//! of its README.

use super::{load_obj_str, Camera, LoadOptions, Scene};

const OBJ: &str = include_str!("../../assets/cornell-box.obj");
const MTL: &str = include_str!("../../assets/cornell-box.mtl");

/// What [`Scene::source`] says for the built-in scene.
pub const BUILTIN_SOURCE: &str = "builtin:cornell-box";

impl Scene {
    /// The Cornell box: 32 triangles, 8 materials, a 2-triangle light of radiance (17, 12, 4),
    /// and the reference camera (256 × 256).
    pub fn builtin_cornell_box() -> Scene {
        let mtl = |name: &str| (name == "cornell-box.mtl").then(|| MTL.to_owned());
        let loaded =
            load_obj_str(BUILTIN_SOURCE, OBJ, &mtl, &LoadOptions { strict: true }).expect("the embedded Cornell box loads (tested)");
        debug_assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
        let mut scene = loaded.scene;
        scene.cameras.push(Camera::cornell_box());
        scene
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    #[test]
    fn cornell_box_counts() {
        let s = Scene::builtin_cornell_box();
        assert_eq!(s.source, BUILTIN_SOURCE);
        assert_eq!(s.triangle_count(), 32);
        assert_eq!(s.materials.len(), 8);
        assert_eq!(s.dropped_degenerate, 0);
        assert!(s.normals.is_none() && s.uvs.is_none() && s.textures.is_empty());
        let e = s.emitters();
        assert_eq!(e.len(), 2);
        for em in &e {
            assert_eq!(s.material_of(em.triangle as usize).emission, Vec3::new(17.0, 12.0, 4.0));
        }
        // The light is 130 × 105 mm.
        let area: f32 = e.iter().map(|e| e.area).sum();
        assert!((area - 130.0 * 105.0).abs() < 1e-2, "{area}");
        assert_eq!(s.cameras, vec![Camera::cornell_box()]);
    }
}
