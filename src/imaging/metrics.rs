//! Error metrics between images (both linear RGB, same size), over the pixels that are finite
//! in both (a NaN or infinite pixel in either image is left out; callers warn with
//! [`RgbImage::non_finite_pixels`]).

use super::RgbImage;

fn check(a: &RgbImage, b: &RgbImage) {
    assert!(a.width == b.width && a.height == b.height, "image sizes differ: {}x{} vs {}x{}", a.width, a.height, b.width, b.height);
}

/// Mean of `f(a, b)` over the channels of the pixels finite in both images (and kept by
/// `keep`, one flag a pixel, where given), and the number of pixels it is over.
fn mean_over_finite_where(a: &RgbImage, b: &RgbImage, keep: Option<&[bool]>, f: impl Fn(f64, f64) -> f64) -> (f64, usize) {
    check(a, b);
    let finite = |p: &[f32]| p.iter().all(|v| v.is_finite());
    let (mut sum, mut n) = (0.0, 0usize);
    for (i, (pa, pb)) in a.data.chunks_exact(3).zip(b.data.chunks_exact(3)).enumerate() {
        if finite(pa) && finite(pb) && keep.is_none_or(|k| k[i]) {
            sum += pa.iter().zip(pb).map(|(&x, &y)| f(x as f64, y as f64)).sum::<f64>();
            n += 1;
        }
    }
    (sum / (3 * n).max(1) as f64, n)
}

fn mean_over_finite(a: &RgbImage, b: &RgbImage, f: impl Fn(f64, f64) -> f64) -> f64 {
    mean_over_finite_where(a, b, None, f).0
}

/// One flag a pixel: false where the pixel's mean over its channels exceeds `level` in `a` or
/// in `b`, and within `margin` pixels (a square) of such a pixel; true elsewhere. Used to
/// judge an image away from a light seen directly, whose edge converges at its own rate (the
/// pixel's stratified samples resolve it: its error falls faster than 1/N).
pub fn away_from_bright(a: &RgbImage, b: &RgbImage, level: f32, margin: u32) -> Vec<bool> {
    check(a, b);
    let (w, h) = (a.width as usize, a.height as usize);
    let bright = |img: &RgbImage, i: usize| img.data[3 * i..3 * i + 3].iter().sum::<f32>() / 3.0 > level;
    let mut keep = vec![true; w * h];
    let m = margin as usize;
    for y in 0..h {
        for x in 0..w {
            if bright(a, y * w + x) || bright(b, y * w + x) {
                for yy in y.saturating_sub(m)..(y + m + 1).min(h) {
                    keep[yy * w + x.saturating_sub(m)..yy * w + (x + m + 1).min(w)].fill(false);
                }
            }
        }
    }
    keep
}

/// [`rmse`] over the pixels `keep` marks (one flag a pixel), and how many pixels that is.
pub fn rmse_where(a: &RgbImage, b: &RgbImage, keep: &[bool]) -> (f64, usize) {
    assert_eq!(keep.len(), a.width as usize * a.height as usize, "one flag a pixel");
    let (mse, n) = mean_over_finite_where(a, b, Some(keep), |x, y| (x - y).powi(2));
    (mse.sqrt(), n)
}

/// sqrt(mean((a - b)^2)) over every channel of the finite pixels (the reference README's
/// definition).
pub fn rmse(a: &RgbImage, b: &RgbImage) -> f64 {
    mean_over_finite(a, b, |x, y| (x - y).powi(2)).sqrt()
}

/// Mean of (a - b)^2 / (b^2 + eps) with eps = 1e-2 (relative MSE, robust near black).
pub fn rel_mse(a: &RgbImage, b: &RgbImage) -> f64 {
    mean_over_finite(a, b, |x, y| (x - y).powi(2) / (y.powi(2) + 1e-2))
}

/// Per-channel ratio of means, a / b, over the pixels finite in both.
pub fn mean_ratio(a: &RgbImage, b: &RgbImage) -> [f64; 3] {
    check(a, b);
    let finite = |p: &[f32]| p.iter().all(|v| v.is_finite());
    let (mut ma, mut mb) = ([0.0f64; 3], [0.0f64; 3]);
    for (pa, pb) in a.data.chunks_exact(3).zip(b.data.chunks_exact(3)).filter(|(pa, pb)| finite(pa) && finite(pb)) {
        for c in 0..3 {
            ma[c] += pa[c] as f64;
            mb[c] += pb[c] as f64;
        }
    }
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

    #[test]
    fn pixels_near_bright_ones_are_left_out_of_rmse_where() {
        // 5 x 5, one bright pixel at (1, 1) in b only (a is 0 there); a differs from b by 1 at
        // (4, 4) and at (0, 0), which is within the margin of the bright pixel.
        let mut a = RgbImage::new(5, 5);
        let mut b = RgbImage::new(5, 5);
        b.data[3 * 6..3 * 6 + 3].fill(10.0);
        a.data[3 * 24..3 * 24 + 3].fill(1.0);
        a.data[0..3].fill(1.0);
        let keep = away_from_bright(&a, &b, 5.0, 1);
        assert_eq!(keep.iter().filter(|k| !**k).count(), 9, "the bright pixel and its 8 neighbours");
        assert!(!keep[0] && keep[24] && !keep[12] && keep[13]);
        let (r, n) = rmse_where(&a, &b, &keep);
        assert_eq!(n, 16);
        assert!((r - (1.0f64 / 16.0).sqrt()).abs() < 1e-12);
        // With no margin only the bright pixel goes; (0, 0)'s difference counts too.
        let (r0, n0) = rmse_where(&a, &b, &away_from_bright(&a, &b, 5.0, 0));
        assert_eq!(n0, 24);
        assert!((r0 - (2.0f64 / 24.0).sqrt()).abs() < 1e-12);
    }

    #[test]
    fn non_finite_pixels_are_left_out() {
        let a = RgbImage { width: 3, height: 1, data: vec![1.0, 1.0, 1.0, f32::NAN, 0.0, 0.0, 2.0, 2.0, 2.0] };
        let b = RgbImage { width: 3, height: 1, data: vec![0.0, 0.0, 0.0, 5.0, 5.0, 5.0, f32::INFINITY, 0.0, 0.0] };
        assert_eq!((a.non_finite_pixels(), b.non_finite_pixels()), (1, 1));
        // Only pixel 0 is finite in both.
        assert!((rmse(&a, &b) - 1.0).abs() < 1e-12);
        assert_eq!(a.mean(), [1.5; 3]);
        assert!(mean_ratio(&b, &a).iter().all(|r| *r == 0.0));
    }
}
