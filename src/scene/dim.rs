//! Scenes whose emitters cannot light them: a glTF model whose only emission is a small
//! emissive texture (DamagedHelmet's glowing visor) has an emitter, yet renders almost black.
//! What the user expects from such a model is what a glTF viewer (and the model's reference
//! screenshot) shows, the model under an environment; glTF says nothing of the environment.
//! Where [`Scene::emitted_light_ratio`] is below [`DIM_EMISSION_RATIO`] and there is no
//! punctual light or sun, the CLI adds the default white environment to the file's own light
//! and says so (`--env none` keeps only the file's light). Until session 14 it only printed a
//! hint, and DamagedHelmet rendered as its visor on black.

use super::{luminance, srgb_to_linear, Scene};
use glam::Vec3;

/// Below this [`Scene::emitted_light_ratio`] a scene's emitters give it less than a
/// twenty-fifth of the light the default environment (radiance 1) would. Measured
/// (tests/lights.rs): the Cornell box 0.092 (a closed room lit by one small lamp),
/// EmissiveStrengthTest 0.16, the modified Sponza's sun and sky 0.53; below it DamagedHelmet
/// 0.0015 and TransmissionTest 0.019 (its white label text, the only emitter: the spheres
/// render at about a fiftieth of their screenshot's brightness by it alone). 0.04 lies about
/// halfway, on a log scale, between TransmissionTest and the Cornell box (session 63; 0.01
/// before, which left TransmissionTest dark).
pub const DIM_EMISSION_RATIO: f32 = 0.04;

impl Scene {
    /// The emitters' light relative to a uniform environment of radiance 1 around the scene:
    /// sum over emissive triangles of area x luminance of the emitted radiance (the emission
    /// factor times the emission texture's mean), over the area of the scene's bounding box.
    /// A uniform environment L deposits pi L per unit area on a convex hull, so the ratio of
    /// powers is this over L = 1 where the box approximates the hull. None without emitters.
    pub fn emitted_light_ratio(&self) -> Option<f32> {
        let emitters = self.emitters();
        if emitters.is_empty() {
            return None;
        }
        let means: Vec<Option<Vec3>> = self.materials.iter().map(|m| m.emission_texture.map(|t| self.texture_mean(t as usize))).collect();
        let light: f64 = emitters
            .iter()
            .map(|e| {
                let id = self.material_ids[e.triangle as usize] as usize;
                let le = self.materials[id].emission * means[id].unwrap_or(Vec3::ONE);
                e.area as f64 * luminance(le) as f64
            })
            .sum();
        let size = self.bounds().max - self.bounds().min;
        let box_area = 2.0 * (size.x * size.y + size.y * size.z + size.z * size.x) as f64;
        Some(if box_area > 0.0 { (light / box_area) as f32 } else { f32::INFINITY })
    }

    /// Mean linear RGB of texture `index` (sRGB decoded where it is colour); black if absent.
    fn texture_mean(&self, index: usize) -> Vec3 {
        let Some(t) = self.textures.get(index) else { return Vec3::ZERO };
        let texels = t.rgba8.chunks_exact(4);
        let n = texels.len().max(1) as f64;
        let decode = |v: u8| if t.srgb { srgb_to_linear(v) as f64 } else { v as f64 / 255.0 };
        let sum = texels.fold([0.0f64; 3], |s, p| [s[0] + decode(p[0]), s[1] + decode(p[1]), s[2] + decode(p[2])]);
        Vec3::new((sum[0] / n) as f32, (sum[1] / n) as f32, (sum[2] / n) as f32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Material, Texture};

    /// A 10 x 10 quad (both faces' box area is 200) with emission `le` times texture `tex`.
    fn quad(le: Vec3, tex: Option<Texture>) -> Scene {
        let mut s = Scene { source: "test".into(), ..Default::default() };
        let emission_texture = tex.is_some().then_some(0);
        s.textures.extend(tex);
        s.materials.push(Material { name: "m".into(), emission: le, emission_texture, ..Default::default() });
        s.positions = vec![Vec3::ZERO, Vec3::new(10.0, 0.0, 0.0), Vec3::new(10.0, 10.0, 0.0), Vec3::new(0.0, 10.0, 0.0)];
        s.triangles = vec![[0, 1, 2], [0, 2, 3]];
        s.material_ids = vec![0, 0];
        s
    }

    #[test]
    fn ratio_counts_area_radiance_and_texture() {
        assert_eq!(quad(Vec3::ZERO, None).emitted_light_ratio(), None);
        // Area 100 x radiance 2 over a flat box of area 2 x 100.
        assert!((quad(Vec3::splat(2.0), None).emitted_light_ratio().unwrap() - 1.0).abs() < 1e-6);
        // A texture black but for one texel in 100 (linear 1): a hundredth of the light.
        let mut rgba8 = vec![0u8; 100 * 4];
        rgba8[..4].copy_from_slice(&[255, 255, 255, 255]);
        let tex = Texture { name: "glow".into(), width: 10, height: 10, rgba8, srgb: true };
        let r = quad(Vec3::splat(2.0), Some(tex)).emitted_light_ratio().unwrap();
        assert!((r - 0.01).abs() < 1e-6, "{r}");
    }
}
