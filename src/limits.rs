//! Size limits, checked before anything large is allocated, so an absurd or hostile input
//! (a glTF that instances a mesh a trillion times, an EXR header claiming 100000x100000) is a
//! clear error naming the file or flag and the limit, not an abort for lack of memory.
//! Each is far above what the renderer's target scenes need (Sponza: 262,267 triangles, 2 K
//! textures, 1080p) and below what would exhaust a large GPU.

/// Triangles in a scene after instancing (each needs ~100 bytes of GPU memory with its BVH).
pub const MAX_TRIANGLES: u64 = 1 << 28;
/// Mesh instances (glTF nodes with a mesh) in a scene.
pub const MAX_INSTANCES: u64 = 1 << 24;
/// Pixels of one texture (16384 x 16384, 1 GiB as RGBA8).
pub const MAX_TEXTURE_PIXELS: u64 = 1 << 28;
/// Pixels of the film (16 bytes each on the GPU, 2 GiB: 16384 x 8192).
pub const MAX_FILM_PIXELS: u64 = 1 << 27;
/// Pixels of an image read from disk (`diff`, `--reference`; 12 bytes each in memory).
pub const MAX_IMAGE_PIXELS: u64 = 1 << 28;
/// Emitted radiance of a material or added light, per channel: far above any physical light
/// (the sun's disc is ~1.6e9 W/(sr m^2)), low enough that power = pi * area * radiance
/// summed over a large scene stays finite in float32.
pub const MAX_RADIANCE: f32 = 1e12;

/// `n` with thousands separators, for the limits in messages.
pub fn thousands(n: u64) -> String {
    let s = n.to_string();
    let mut out = String::new();
    for (i, c) in s.chars().enumerate() {
        if i > 0 && (s.len() - i) % 3 == 0 {
            out.push(',');
        }
        out.push(c);
    }
    out
}
