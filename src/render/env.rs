//! The environment light on the GPU (`glsl/common/env.glsl`): per texel its radiance and the
//! solid-angle pdf of sampling it, and Walker's alias table over texels weighted by
//! luminance x texel solid angle (a 2D piecewise-constant distribution, exact per texel).

use super::lights::{alias_table, luminance};
use crate::gpu::abi::{GpuAlias, GpuEnv, GpuEnvTexel};
use crate::scene::{Aabb, Environment};
use glam::Vec4;

/// The disk from which light paths of lights at infinity (environment, directional) start:
/// the scene's bounding sphere, 1 % larger so disk origins lie outside every surface, as
/// (centre, radius) and its area.
pub fn light_disk(bounds: &Aabb) -> (Vec4, f32) {
    let (centre, radius) =
        if bounds.is_empty() { (glam::Vec3::ZERO, 1.0) } else { (bounds.center(), (0.5 * bounds.diagonal().length()).max(1e-3)) };
    let radius = radius * 1.01;
    (centre.extend(radius), std::f32::consts::PI * radius * radius)
}

/// What the kernels read of an environment.
#[derive(Clone, Debug)]
pub struct EnvTable {
    pub env: GpuEnv,
    pub texels: Vec<GpuEnvTexel>,
    pub alias: Vec<GpuAlias>,
}

impl EnvTable {
    /// Tables for `env` in a scene with `bounds`, picked by light sampling with probability
    /// `pick`; `None` if the environment is black (nothing to sample).
    pub fn build(env: &Environment, bounds: &Aabb, pick: f32) -> Option<EnvTable> {
        let mut weights: Vec<f64> = env
            .texels
            .iter()
            .enumerate()
            .map(|(i, t)| luminance(*t * env.scale) as f64 * env.texel_solid_angle(i as u32 / env.width) as f64)
            .collect();
        // The sun is one more cell: a direction uniform in its disk.
        let sun = env.sun.filter(|s| s.irradiance.max_element() > 0.0);
        if let Some(s) = sun {
            weights.push(luminance(s.radiance()) as f64 * s.solid_angle() as f64);
        }
        let total: f64 = weights.iter().sum();
        if total <= 0.0 || !total.is_finite() {
            return None;
        }
        let texels = env
            .texels
            .iter()
            .zip(&weights)
            .enumerate()
            .map(|(i, (t, w))| {
                let le = *t * env.scale;
                let omega = env.texel_solid_angle(i as u32 / env.width) as f64;
                GpuEnvTexel { r: le.x, g: le.y, b: le.z, pdf_w: (w / total / omega) as f32 }
            })
            .collect();
        let (bounds, disk_area) = light_disk(bounds);
        let gpu = GpuEnv {
            bounds,
            width: env.width,
            height: env.height,
            rotate: env.rotate_deg.to_radians(),
            pick,
            disk_area,
            punctual_count: 0,
            punctual_pick: 0.0,
            sun_cos_max: sun.map_or(2.0, |s| s.cos_max()),
            sun_direction: sun.map_or(Vec4::ZERO, |s| s.direction.extend(0.0)),
            sun_radiance: sun.map_or(Vec4::ZERO, |s| s.radiance().extend(0.0)),
            sun_pdf_w: sun.map_or(0.0, |s| (weights[weights.len() - 1] / total / s.solid_angle() as f64) as f32),
            cells: weights.len() as u32,
            pad0: 0,
            pad1: 0,
        };
        Some(EnvTable { env: gpu, texels, alias: alias_table(&weights) })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    /// The per-texel pdfs integrate to one over the sphere, and are proportional to
    /// luminance where the map is not black.
    #[test]
    fn texel_pdfs_integrate_to_one() {
        let texels = (0..32).map(|i| if i % 5 == 0 { Vec3::ZERO } else { Vec3::new(i as f32, 1.0, 0.5) }).collect();
        let env = Environment::from_texels("t", 8, 4, texels);
        let b = Aabb { min: Vec3::splat(-1.0), max: Vec3::ONE };
        let t = EnvTable::build(&env, &b, 1.0).unwrap();
        let sum: f64 = t.texels.iter().enumerate().map(|(i, x)| x.pdf_w as f64 * env.texel_solid_angle(i as u32 / 8) as f64).sum();
        assert!((sum - 1.0).abs() < 1e-5, "{sum}");
        let ratio = |i: usize| t.texels[i].pdf_w / luminance(env.texels[i]);
        assert!((ratio(3) / ratio(31) - 1.0).abs() < 1e-5);
        assert_eq!(t.texels[5].pdf_w, 0.0);
        assert!(EnvTable::build(&Environment::uniform(Vec3::ZERO), &b, 1.0).is_none());
    }
}
