//! Sobol' direction numbers for the first four dimensions (Joe & Kuo's primitive
//! polynomials and initial values) and the kernels' `sobol_point` made from them ([`glsl`],
//! written by build.rs into `bidir_sobol.glsl`). Kernels use it for Owen-scrambled Sobol'
//! sampling (Burley 2020,
//! "Practical Hash-based Owen Scrambling"): each group of four dimensions gets its own
//! shuffled index and scrambled values, so any number of dimensions stays uniformly
//! distributed (unbiased) while each 4D group keeps Sobol's stratification.

/// Dimensions with their own direction numbers (later dimensions reuse them, re-seeded).
pub const SOBOL_DIMS: usize = 4;

/// (degree s, coefficient bits a, initial m values) of dimensions 2..4 (dimension 1 is the
/// van der Corput sequence).
const POLYS: [(u32, u32, [u32; 3]); 3] = [(1, 0, [1, 0, 0]), (2, 1, [1, 3, 0]), (3, 1, [1, 3, 1])];

/// `v[d][k]`: the direction number of bit k (k = 0 is the lowest bit of the index).
pub fn sobol_directions() -> [[u32; 32]; SOBOL_DIMS] {
    let mut v = [[0u32; 32]; SOBOL_DIMS];
    for (k, x) in v[0].iter_mut().enumerate() {
        *x = 1u32 << (31 - k);
    }
    for (d, &(s, a, init)) in POLYS.iter().enumerate() {
        let s = s as usize;
        let mut m = [0u32; 33]; // m[1..=32]
        m[1..=s].copy_from_slice(&init[..s]);
        for k in s + 1..=32 {
            // m_k = 2 a_1 m_{k-1} ^ 4 a_2 m_{k-2} ^ ... ^ 2^{s-1} a_{s-1} m_{k-s+1} ^ 2^s m_{k-s} ^ m_{k-s}
            let mut x = m[k - s] ^ (m[k - s] << s);
            for j in 1..s {
                if (a >> (s - 1 - j)) & 1 == 1 {
                    x ^= m[k - j] << j;
                }
            }
            m[k] = x;
        }
        for k in 1..=32 {
            v[d + 1][k - 1] = m[k] << (32 - k);
        }
    }
    v
}

/// Point `index` of dimension `dim` (< 4) as a 32-bit fraction.
pub fn sobol(index: u32, dim: usize) -> u32 {
    let v = sobol_directions();
    (0..32).filter(|k| (index >> k) & 1 == 1).fold(0, |x, k| x ^ v[dim][k])
}

/// Steps `x ^= (x >> h) & m` that, followed by a bit reversal, compute dimensions 1, 2 and 3
/// from the index ([`shift_xor`]): each generator matrix factors into these few steps.
///
/// Dimension 1's matrix is Pascal's triangle mod 2 (m_k = (1 + 2)^(k - 1), carry-less), so bit
/// 31 - i of its point is the xor of the index bits k with C(k, i) odd, i.e. (Lucas) with k
/// containing i: five steps, one per bit of a position, the binary "superset" (zeta)
/// transform. In general (session 14) the matrix of a dimension with primitive polynomial p
/// of degree s rewrites the index as a polynomial in base q, q the reciprocal of p (1 + z for
/// dimension 1, 1 + z + z^2 for 2, 1 + z + z^3 for 3), followed by one fix-up step within each
/// s-bit digit; as q^(2^b) = q(z^(2^b)) over GF(2), the base change splits level by level into
/// block steps on h = 2^b-bit parts: two per level for dimension 2 (8 steps with the fix-up
/// merged), three for dimension 3 (12, shortened to 9 by an SMT search over the masks with the
/// shifts fixed). Every step is linear, so agreeing with the matrix product on the 32 one-bit
/// indices (the tests below) proves them equal on all 2^32.
pub const STEPS: [&[(u32, u32)]; SOBOL_DIMS] = [
    &[],
    &[(1, 0x5555_5555), (2, 0x3333_3333), (4, 0x0f0f_0f0f), (8, 0x00ff_00ff), (16, 0x0000_ffff)],
    &[
        (8, 0x00ff_ff00),
        (16, 0x0000_00ff),
        (4, 0x0ff0_0ff0),
        (8, 0x000f_000f),
        (2, 0x3c3c_3c3c),
        (4, 0x0303_0303),
        (1, 0x3333_3333),
        (3, 0x1111_1111),
    ],
    &[
        (24, 0x0000_00ff),
        (16, 0x0000_fffe),
        (8, 0x0000_1ffe),
        (12, 0x0000_0fff),
        (4, 0x0e07_e07e),
        (6, 0x0303_f03f),
        (2, 0x0e38_e38e),
        (3, 0x071c_71c7),
        (1, 0x4924_9249),
    ],
];

/// `x` through `steps` (`x ^= (x >> h) & m` each, in order).
pub fn shift_xor(mut x: u32, steps: &[(u32, u32)]) -> u32 {
    for &(h, m) in steps {
        x ^= (x >> h) & m;
    }
    x
}

/// Point `index` of dimension `dim` (< 4) as the kernels compute it: a bit reversal after
/// [`STEPS`]`[dim]`. Equal to [`sobol`] (the matrix product) bit for bit.
pub fn sobol_fast(index: u32, dim: usize) -> u32 {
    shift_xor(index, STEPS[dim]).reverse_bits()
}

/// `uint sobol_point(uint index, uint dim)` for the kernels, equal bit for bit to [`sobol`]
/// (tests/sampling.rs checks the kernels' numbers against a CPU twin): [`sobol_fast`], 5, 8
/// and 9 steps of two instructions (a shift, and a LOP3 for the mask and the xor) and a bit
/// reversal for dimensions 1, 2 and 3, straight-line code. History (docs/results.md): the
/// matrix product as a multiply by each index bit, ~3.5 instructions a bit on the H200, pt-nee
/// on the Cornell box 878 Msamples/s (before session 13); dimension 1 by its five steps and 2 and 3
/// as a literal under a test of each bit, ~2 instructions a bit, 1104 (session 13), but 64
/// branches inlined at each of a megakernel's ~100 calls (pt_cwbvh: 354,265 words of SPIR-V,
/// whose validation at pipeline creation cost lavapipe ~2 s); tables of the xors of 4 or 8
/// index bits in a buffer: faster on the Cornell box, slower on Sponza and lavapipe.
pub fn glsl() -> String {
    let mut s = String::from("uint sobol_point(uint index, uint dim) {\n    uint x = index;\n");
    for (d, steps) in STEPS.iter().enumerate() {
        let last = d + 1 == SOBOL_DIMS;
        let indent = if last { "    " } else { "        " };
        if !last {
            s += &format!("    if (dim == {d}u) {{\n");
        }
        for &(h, m) in steps.iter() {
            s += &format!("{indent}x ^= (x >> {h}u) & {m:#010x}u;\n");
        }
        s += &format!("{indent}return bitfieldReverse(x);\n");
        if !last {
            s += "    }\n";
        }
    }
    s + "}\n"
}

#[cfg(test)]
mod tests {
    use super::*;

    fn f(x: u32) -> f64 {
        x as f64 / 4294967296.0
    }

    /// By hand, direct (not Gray-code) order: dimension 2 has m = 1, 3, 5 so v = .1, .11,
    /// .101 (binary); dimension 3 has m = 1, 3, 3 so v = .1, .11, .011; point i is the xor
    /// of the v of i's set bits.
    #[test]
    fn first_points_follow_the_recurrence() {
        let d1: Vec<f64> = (0..8).map(|i| f(sobol(i, 1))).collect();
        assert_eq!(d1, vec![0.0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875]);
        let d2: Vec<f64> = (0..8).map(|i| f(sobol(i, 2))).collect();
        assert_eq!(d2, vec![0.0, 0.5, 0.75, 0.25, 0.375, 0.875, 0.625, 0.125]);
    }

    /// The kernels' steps are the matrix product for every bit alone (which, the steps being
    /// linear over GF(2), proves them equal everywhere) and, as a check of that argument, for
    /// random indices.
    #[test]
    fn steps_are_the_matrix_product() {
        for d in 0..SOBOL_DIMS {
            assert_eq!(sobol_fast(0, d), 0, "dimension {d}, index 0");
            for k in 0..32 {
                assert_eq!(sobol_fast(1 << k, d), sobol(1 << k, d), "dimension {d}, index bit {k}");
            }
            let mut x = 0x1234_5678u32;
            for _ in 0..20_000 {
                x = x.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
                assert_eq!(sobol_fast(x, d), sobol(x, d), "dimension {d}, index {x:#x}");
            }
        }
    }

    /// Each dimension alone puts one of the first 256 points in every 1/256 interval, and
    /// each pair of dimensions is a (t, 8, 2)-net: every 16 x (16 >> t) cell holds 2^t of the
    /// first 256 points (t = 0 for these pairs, t = 1 for dimensions 3 and 4).
    #[test]
    fn points_stratify() {
        for d in 0..SOBOL_DIMS {
            let mut seen = [false; 256];
            for i in 0..256u32 {
                seen[(sobol(i, d) >> 24) as usize] = true;
            }
            assert!(seen.iter().all(|&x| x), "dimension {d} leaves a 1/256 interval empty");
        }
        for (a, b, t) in [(0usize, 1usize, 0u32), (1, 2, 0), (0, 3, 0), (2, 3, 1)] {
            let mut grid = [0u32; 256];
            for i in 0..256u32 {
                let (x, y) = (sobol(i, a) >> 28, sobol(i, b) >> (28 + t));
                grid[(y * 16 + x) as usize] += 1;
            }
            let cells = 256 >> t;
            assert!(grid[..cells].iter().all(|&c| c == 1 << t), "dims {a},{b}: not a ({t}, 8, 2)-net: {:?}", &grid[..cells]);
        }
    }
}
