//! Light sampling tables: emissive triangles chosen in proportion to their *weight*,
//! luminance(Le) x area (their luminous power up to the factor pi, which cancels: "power" in
//! bidir means pi x area x Le, `scene::stats::Emitter::power`), with Walker's alias method
//! (Vose's O(n) construction), sampled in O(1) on the GPU.

use crate::gpu::abi::{GpuAlias, GpuEmitter, GpuEmitterUv};
use crate::scene::Scene;

pub use crate::scene::luminance;

/// Emitters with their alias table.
#[derive(Clone, Debug, Default)]
pub struct LightTable {
    pub emitters: Vec<GpuEmitter>,
    /// The scene triangle of each emitter.
    pub triangles: Vec<u32>,
    pub alias: Vec<GpuAlias>,
    /// Sum of the weights luminance(Le) * area: light sampling's area pdf at an emitter point
    /// is luminance(Le) / total_weight.
    pub total_weight: f32,
}

impl LightTable {
    /// Every front-emitting triangle whose material emits, weighted by luminance(Le) * area.
    pub fn build(scene: &Scene) -> LightTable {
        let mut emitters = Vec::new();
        let mut weights = Vec::new();
        let mut triangles = Vec::new();
        for (t, tri) in scene.triangles.iter().enumerate() {
            let m = &scene.materials[scene.material_ids[t] as usize];
            let lum = luminance(m.emission);
            if lum <= 0.0 {
                continue;
            }
            let [v0, v1, v2] = tri.map(|i| scene.positions[i as usize]);
            let (e1, e2) = (v1 - v0, v2 - v0);
            let area = 0.5 * e1.cross(e2).length();
            if area <= 0.0 || !area.is_finite() {
                continue;
            }
            emitters.push(GpuEmitter { v0, area, e1, e2, radiance: m.emission, pick: 0.0, pad0: 0.0, pad1: 0.0 });
            triangles.push(t as u32);
            weights.push(lum as f64 * area as f64);
        }
        let total: f64 = weights.iter().sum();
        for (e, w) in emitters.iter_mut().zip(&weights) {
            e.pick = (w / total) as f32;
        }
        LightTable { alias: alias_table(&weights), emitters, triangles, total_weight: total as f32 }
    }

    /// Per emitter, its vertices' texture coordinates and its material's emission texture.
    /// Emitters are chosen by the weight of their emission factor (the texture's scale is not
    /// known per triangle), which is unbiased: the texture only scales the radiance found.
    pub fn emitter_uvs(&self, scene: &Scene) -> Vec<GpuEmitterUv> {
        self.triangles
            .iter()
            .map(|&t| {
                let m = &scene.materials[scene.material_ids[t as usize] as usize];
                let uv = |k: usize| scene.uvs.as_ref().map_or(glam::Vec2::ZERO, |u| u[scene.triangles[t as usize][k] as usize]);
                GpuEmitterUv { uv0: uv(0), uv1: uv(1), uv2: uv(2), texture: m.emission_texture.map_or(0, |t| t + 1), pad0: 0 }
            })
            .collect()
    }
}

/// Vose's alias table for `weights` (need not be normalised): cell i keeps i with
/// probability `prob` and otherwise yields `alias`; choosing a cell uniformly then gives
/// each index its weight's share exactly.
pub fn alias_table(weights: &[f64]) -> Vec<GpuAlias> {
    let n = weights.len();
    let total: f64 = weights.iter().sum();
    if n == 0 || total <= 0.0 {
        return Vec::new();
    }
    let mut scaled: Vec<f64> = weights.iter().map(|w| w * n as f64 / total).collect();
    let mut table = vec![GpuAlias { prob: 1.0, alias: 0 }; n];
    let (mut small, mut large): (Vec<usize>, Vec<usize>) = (0..n).partition(|&i| scaled[i] < 1.0);
    while let (Some(s), Some(&l)) = (small.pop(), large.last()) {
        table[s] = GpuAlias { prob: scaled[s] as f32, alias: l as u32 };
        scaled[l] -= 1.0 - scaled[s];
        if scaled[l] < 1.0 {
            large.pop();
            small.push(l);
        }
    }
    for i in large.into_iter().chain(small) {
        table[i] = GpuAlias { prob: 1.0, alias: i as u32 };
    }
    table
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The probability the table gives each index equals its weight's share.
    #[test]
    fn alias_table_reproduces_weights_exactly() {
        let weights = [1.0, 0.0, 5.0, 2.5, 0.25, 7.0, 1.0];
        let t = alias_table(&weights);
        let n = weights.len() as f64;
        let total: f64 = weights.iter().sum();
        let mut p = vec![0.0f64; weights.len()];
        for (i, c) in t.iter().enumerate() {
            p[i] += c.prob as f64 / n;
            p[c.alias as usize] += (1.0 - c.prob as f64) / n;
        }
        for (i, w) in weights.iter().enumerate() {
            assert!((p[i] - w / total).abs() < 1e-6, "index {i}: {} vs {}", p[i], w / total);
        }
    }
}
