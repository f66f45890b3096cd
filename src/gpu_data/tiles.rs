//! The order in which kernels visit pixels: whole `TILE_SIZE` x `TILE_SIZE` tiles, so that
//! neighbouring invocations trace neighbouring rays (`tiled_pixel` in glsl/common/ray.glsl).

use crate::gpu::abi::TILE_SIZE;

/// Invocations that cover a `width` x `height` image in whole tiles of `TILE_SIZE` x
/// `TILE_SIZE` pixels (the order of `tiled_pixel` in glsl/common/ray.glsl).
pub fn tiled_invocations(width: u32, height: u32) -> u32 {
    width.div_ceil(TILE_SIZE) * TILE_SIZE * height.div_ceil(TILE_SIZE) * TILE_SIZE
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn whole_tiles_cover_the_image() {
        assert_eq!(tiled_invocations(TILE_SIZE, TILE_SIZE), TILE_SIZE * TILE_SIZE);
        assert_eq!(tiled_invocations(1, 1), TILE_SIZE * TILE_SIZE);
        assert_eq!(tiled_invocations(TILE_SIZE + 1, 1), 2 * TILE_SIZE * TILE_SIZE);
    }
}
