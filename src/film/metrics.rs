//! Error metrics between images (both linear RGB, same size).

use super::RgbImage;

fn check(a: &RgbImage, b: &RgbImage) {
    assert!(a.width == b.width && a.height == b.height, "image sizes differ: {}x{} vs {}x{}", a.width, a.height, b.width, b.height);
}

/// sqrt(mean((a - b)^2)) over every pixel and channel (the reference README's definition).
pub fn rmse(a: &RgbImage, b: &RgbImage) -> f64 {
    check(a, b);
    let s: f64 = a.data.iter().zip(&b.data).map(|(x, y)| ((x - y) as f64).powi(2)).sum();
    (s / a.data.len().max(1) as f64).sqrt()
}

/// Mean of (a - b)^2 / (b^2 + eps) with eps = 1e-2 (relative MSE, robust near black).
pub fn rel_mse(a: &RgbImage, b: &RgbImage) -> f64 {
    check(a, b);
    let s: f64 = a.data.iter().zip(&b.data).map(|(x, y)| ((x - y) as f64).powi(2) / ((*y as f64).powi(2) + 1e-2)).sum();
    s / a.data.len().max(1) as f64
}

/// Per-channel ratio of means, a / b.
pub fn mean_ratio(a: &RgbImage, b: &RgbImage) -> [f64; 3] {
    check(a, b);
    let (ma, mb) = (a.mean(), b.mean());
    [ma[0] / mb[0], ma[1] / mb[1], ma[2] / mb[2]]
}

/// Means of `block` x `block` tiles: (tile x, tile y, mean rgb).
pub fn block_means(img: &RgbImage, block: u32) -> Vec<(u32, u32, [f64; 3])> {
    let mut out = Vec::new();
    for by in 0..img.height.div_ceil(block) {
        for bx in 0..img.width.div_ceil(block) {
            let mut m = [0.0f64; 3];
            let mut n = 0.0;
            for y in by * block..((by + 1) * block).min(img.height) {
                for x in bx * block..((bx + 1) * block).min(img.width) {
                    let p = img.pixel(x, y);
                    for c in 0..3 {
                        m[c] += p[c] as f64;
                    }
                    n += 1.0;
                }
            }
            out.push((bx, by, m.map(|v| v / n)));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn rmse_of_known_difference() {
        let a = RgbImage { width: 2, height: 1, data: vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0] };
        let b = RgbImage { width: 2, height: 1, data: vec![0.0; 6] };
        assert!((rmse(&a, &b) - (0.5f64).sqrt()).abs() < 1e-12);
        assert_eq!(block_means(&a, 1).len(), 2);
    }
}
