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

/// The masks of [`superset_xor`]'s five steps: the bit positions whose bit `h` is clear.
const SUPERSET_MASKS: [(u32, u32); 5] = [(1, 0x5555_5555), (2, 0x3333_3333), (4, 0x0f0f_0f0f), (8, 0x00ff_00ff), (16, 0x0000_ffff)];

/// Bit i of the result is the xor of the bits k of `x` whose positions k contain i (k & i
/// == i): five shift-and-xor steps, one per bit of a position (the binary "superset" or zeta
/// transform).
pub fn superset_xor(mut x: u32) -> u32 {
    for (h, m) in SUPERSET_MASKS {
        x ^= (x >> h) & m;
    }
    x
}

/// Point `index` of the second dimension without its 32 direction numbers: that dimension's
/// generator matrix is Pascal's triangle mod 2 (m_k = (1 + 2)^(k - 1), carry-less), so bit
/// 31 - i of the point is the xor of the index bits k with C(k, i) odd, i.e. (Lucas) with k
/// containing i: the reversed [`superset_xor`] of the index. Eleven operations where the
/// matrix product took ~110 instructions (the H200's machine code, session 13).
pub fn sobol_dim1(index: u32) -> u32 {
    superset_xor(index).reverse_bits()
}

/// `uint sobol_point(uint index, uint dim)` for the kernels, equal bit for bit to [`sobol`]
/// (tests/sampling.rs checks the kernels' numbers against a CPU twin): dimension 0 as a bit
/// reversal, 1 as [`sobol_dim1`], 2 and 3 as the xor of the direction numbers of the index's
/// set bits, each a literal under a test of its bit (a constant array indexed at run time is
/// copied into every invocation by some drivers). The matrix product written as a multiply
/// by each bit took ~3.5 instructions a bit on the H200 and was inlined at every call for
/// all three dimensions; in this form pt-nee on the Cornell box runs at 1104 against 878
/// Msamples/s, and 1077 with the bit tests written as selects (session 13, docs/results.md).
pub fn glsl() -> String {
    let v = sobol_directions();
    let mut s = String::from("uint sobol_point(uint index, uint dim) {\n    if (dim == 0u) {\n        return bitfieldReverse(index);\n    }\n    uint x = index;\n    if (dim == 1u) {\n");
    for (h, m) in SUPERSET_MASKS {
        s += &format!("        x ^= (x >> {h}u) & {m:#010x}u;\n");
    }
    s += "        return bitfieldReverse(x);\n    }\n    x = 0u;\n";
    for (d, dirs) in v.iter().enumerate().skip(2) {
        s += &format!("    if (dim == {d}u) {{\n");
        for (k, c) in dirs.iter().enumerate() {
            s += &format!("        if ((index & {:#010x}u) != 0u) {{\n            x ^= {c:#010x}u;\n        }}\n", 1u32 << k);
        }
        s += "    }\n";
    }
    s + "    return x;\n}\n"
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

    /// The second dimension's shortcut is its matrix product, for every bit alone and for
    /// random indices.
    #[test]
    fn dimension_1_is_the_reversed_superset_transform() {
        for k in 0..32 {
            assert_eq!(sobol_dim1(1 << k), sobol(1 << k, 1), "index bit {k}");
        }
        let mut x = 0x1234_5678u32;
        for _ in 0..100_000 {
            x = x.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
            assert_eq!(sobol_dim1(x), sobol(x, 1), "index {x:#x}");
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
