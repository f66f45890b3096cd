//! The forms a queue of rays takes in a ray buffer (`TraceOptions::ray_words`, SPEC_RAY_WORDS):
//! the host's twin of glsl/common/ray_words.glsl, for tests and tools that fill a queue the
//! trace kernels read in a compact form.
//!
//! ```
//! use bidir::gpu::abi::{self, GpuRay};
//! use bidir::trace::ray_forms;
//! use glam::Vec4;
//!
//! let ray = GpuRay { origin: Vec4::new(1.0, 2.0, 3.0, 0.0), dir: Vec4::new(0.0, 1.0, 0.0, 5.0) };
//! let words = ray_forms::pack(&[ray], abi::RAY_WORDS_BOUNDED).unwrap();
//! assert_eq!(words.len(), 8); // a queue of one ray takes one 32-byte place
//! assert_eq!(ray_forms::unpack(&words, 0, abi::RAY_WORDS_BOUNDED), ray);
//! ```

use crate::gpu::abi::{self, GpuRay};
use glam::{Vec3, Vec4};

/// The tmax of a compact segment (RAY_WORDS_SEGMENT): the wavefront passes' unbounded rays.
pub const SEGMENT_TMAX: f32 = 3.0e38;

/// Why a ray has no compact form.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FormError {
    #[error("ray {index}: a compact ray starts at 0, not at tmin {tmin}")]
    Tmin { index: usize, tmin: f32 },
    #[error("ray {index}: a segment (RAY_WORDS_SEGMENT) is unbounded (tmax {SEGMENT_TMAX}) or absent (tmax < 0 with a zero direction), not tmax {tmax} along {dir}")]
    Segment { index: usize, tmax: f32, dir: Vec3 },
    #[error("{0} words a ray is no form of a queue: {full}, {segment} or {bounded}", full = abi::RAY_WORDS_FULL, segment = abi::RAY_WORDS_SEGMENT, bounded = abi::RAY_WORDS_BOUNDED)]
    Words(u32),
}

/// The first of ray `i`'s two words in its 8-byte part, in a queue of `cap` rays (GLSL's
/// `ray_pair_index`, counted in words).
fn pair_at(i: usize, cap: usize) -> usize {
    2 * (2 * cap + i)
}

/// Ray `i`'s 4-byte part (RAY_WORDS_BOUNDED) in a queue of `cap` rays (GLSL's `ray_word_index`).
fn word_at(i: usize, cap: usize) -> usize {
    6 * cap + i
}

/// `rays` as a queue's 32-bit words in the form of `words` words a ray (`abi::RAY_WORDS_*`): as
/// many words as the `GpuRay`s take (a queue of n rays takes n 32-byte places in every form).
/// A segment without a ray (tmax < 0) must have a zero direction in the segment form, as
/// `wf_queue_no_segment` writes it.
pub fn pack(rays: &[GpuRay], words: u32) -> Result<Vec<u32>, FormError> {
    let cap = rays.len();
    let mut out = vec![0u32; 8 * cap];
    for (i, r) in rays.iter().enumerate() {
        if words != abi::RAY_WORDS_FULL && r.origin.w != 0.0 {
            return Err(FormError::Tmin { index: i, tmin: r.origin.w });
        }
        let (o, d, tmax) = (r.origin.truncate(), r.dir.truncate(), r.dir.w);
        let mut put = |at: usize, v: f32| out[at] = v.to_bits();
        match words {
            abi::RAY_WORDS_FULL => {
                for (k, v) in r.origin.to_array().into_iter().chain(r.dir.to_array()).enumerate() {
                    put(8 * i + k, v);
                }
            }
            abi::RAY_WORDS_SEGMENT => {
                let absent = tmax < 0.0 && d == Vec3::ZERO;
                if !(absent || tmax == SEGMENT_TMAX) {
                    return Err(FormError::Segment { index: i, tmax, dir: d });
                }
                let [ox, oy, oz] = if absent { [0.0; 3] } else { o.to_array() };
                for (k, v) in [ox, oy, oz, d.x].into_iter().enumerate() {
                    put(4 * i + k, v);
                }
                put(pair_at(i, cap), d.y);
                put(pair_at(i, cap) + 1, d.z);
            }
            abi::RAY_WORDS_BOUNDED => {
                for (k, v) in [o.x, o.y, o.z, tmax].into_iter().enumerate() {
                    put(4 * i + k, v);
                }
                put(pair_at(i, cap), d.x);
                put(pair_at(i, cap) + 1, d.y);
                put(word_at(i, cap), d.z);
            }
            w => return Err(FormError::Words(w)),
        }
    }
    Ok(out)
}

/// Ray `i` of `queue` (its 32-bit words, `pack`'s) in the form of `form` words a ray, as the
/// trace kernels read it (`load_ray` in glsl/common/trace_kernel.glsl). Panics on a form `pack`
/// refuses.
pub fn unpack(queue: &[u32], i: usize, form: u32) -> GpuRay {
    let cap = queue.len() / 8;
    let f = |at: usize| f32::from_bits(queue[at]);
    let (pair, word) = (pair_at(i, cap), word_at(i, cap));
    match form {
        abi::RAY_WORDS_FULL => GpuRay {
            origin: Vec4::new(f(8 * i), f(8 * i + 1), f(8 * i + 2), f(8 * i + 3)),
            dir: Vec4::new(f(8 * i + 4), f(8 * i + 5), f(8 * i + 6), f(8 * i + 7)),
        },
        abi::RAY_WORDS_SEGMENT => {
            let d = Vec3::new(f(4 * i + 3), f(pair), f(pair + 1));
            let tmax = if d == Vec3::ZERO { -1.0 } else { SEGMENT_TMAX };
            GpuRay { origin: Vec4::new(f(4 * i), f(4 * i + 1), f(4 * i + 2), 0.0), dir: d.extend(tmax) }
        }
        abi::RAY_WORDS_BOUNDED => GpuRay {
            origin: Vec4::new(f(4 * i), f(4 * i + 1), f(4 * i + 2), 0.0),
            dir: Vec4::new(f(pair), f(pair + 1), f(word), f(4 * i + 3)),
        },
        other => panic!("{}", FormError::Words(other)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ray(o: [f32; 3], d: [f32; 3], tmax: f32) -> GpuRay {
        GpuRay { origin: Vec3::from(o).extend(0.0), dir: Vec3::from(d).extend(tmax) }
    }

    #[test]
    fn every_form_gives_back_its_rays() {
        let rays = [
            ray([1.0, 2.0, 3.0], [0.0, 0.6, 0.8], 7.5),
            ray([-4.0, 5.0, -6.0], [1.0, 0.0, 0.0], 0.25),
            ray([0.0; 3], [0.0, 0.0, -1.0], 1.0e-3),
        ];
        let segments = rays.map(|r| GpuRay { dir: r.dir.truncate().extend(SEGMENT_TMAX), ..r });
        let absent = ray([0.0; 3], [0.0; 3], -1.0);
        for (form, rays) in [
            (abi::RAY_WORDS_FULL, rays.to_vec()),
            (abi::RAY_WORDS_BOUNDED, rays.to_vec()),
            (abi::RAY_WORDS_SEGMENT, [&segments[..], &[absent]].concat()),
        ] {
            let q = pack(&rays, form).unwrap();
            assert_eq!(q.len(), 8 * rays.len());
            for (i, r) in rays.iter().enumerate() {
                assert_eq!(unpack(&q, i, form), *r, "form {form}, ray {i}");
            }
        }
    }

    #[test]
    fn rays_without_a_compact_form_are_refused() {
        let seeded = GpuRay { origin: Vec4::new(0.0, 0.0, 0.0, 1.0), dir: Vec4::new(0.0, 0.0, 1.0, 2.0) };
        assert_eq!(pack(&[seeded], abi::RAY_WORDS_BOUNDED), Err(FormError::Tmin { index: 0, tmin: 1.0 }));
        let bounded = ray([0.0; 3], [0.0, 0.0, 1.0], 2.0);
        assert!(matches!(pack(&[bounded], abi::RAY_WORDS_SEGMENT), Err(FormError::Segment { index: 0, .. })));
        assert_eq!(pack(&[bounded], 5), Err(FormError::Words(5)));
        assert!(pack(&[seeded], abi::RAY_WORDS_FULL).is_ok());
    }
}
