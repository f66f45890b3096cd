//! What makes a render one part of a bigger one (`--sample-range`, `--crop`), and the
//! metadata every render writes into its EXR so that parts can be checked and merged.

use super::scene_args::LoadedScene;
use bidir::imaging::part::{keys, RenderInfo};
use bidir::imaging::{Crop, SampleRange};
use bidir::render::RenderSettings;
use bidir::scene::Scene;

#[derive(clap::Args, Debug)]
pub struct PartArgs {
    /// Render sample indices START..END-1 of every pixel, with the random numbers a whole
    /// render uses for them: disjoint ranges merge (`bidir merge`) into the render of their
    /// union.
    #[arg(long, value_name = "START..END", conflicts_with_all = ["spp", "time"])]
    pub sample_range: Option<SampleRange>,
    /// Render only the window X0..X1 x Y0..Y1 of the image (the camera and the full size are
    /// unchanged); windows merge with `bidir merge`.
    #[arg(long, value_name = "X0,Y0,X1,Y1")]
    pub crop: Option<Crop>,
}

impl PartArgs {
    /// Sets the sample start and crop of `settings`; a crop outside `camera`'s image is an
    /// error before any GPU work.
    pub fn apply(&self, settings: &mut RenderSettings, camera: &bidir::scene::Camera) -> anyhow::Result<()> {
        if let Some(c) = self.crop {
            c.check(camera.width, camera.height).map_err(|e| anyhow::anyhow!("--crop: {e}"))?;
        }
        settings.sample_start = self.sample_range.map_or(0, |r| r.start);
        settings.crop = self.crop;
        Ok(())
    }
}

/// 64-bit FNV-1a.
fn fnv1a(mut h: u64, bytes: &[u8]) -> u64 {
    for &b in bytes {
        h = (h ^ b as u64).wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

/// A hash of the scene as loaded (geometry, materials, textures, added lights): equal for
/// the same file (and flags) on every machine, whatever its path.
pub fn scene_hash(scene: &Scene) -> String {
    let mut h = 0xcbf2_9ce4_8422_2325u64;
    h = fnv1a(h, bytemuck::cast_slice(&scene.positions));
    h = fnv1a(h, bytemuck::cast_slice(scene.normals.as_deref().unwrap_or(&[])));
    h = fnv1a(h, bytemuck::cast_slice(scene.uvs.as_deref().unwrap_or(&[])));
    h = fnv1a(h, bytemuck::cast_slice(&scene.triangles));
    h = fnv1a(h, bytemuck::cast_slice(&scene.material_ids));
    h = fnv1a(h, format!("{:?}", scene.materials).as_bytes());
    for t in &scene.textures {
        h = fnv1a(h, format!("{} {}x{} {}", t.name, t.width, t.height, t.srgb).as_bytes());
        h = fnv1a(h, &t.rgba8);
    }
    format!("{h:016x}")
}

/// Metadata of a finished render (see `imaging::part::keys`).
pub fn render_info(loaded: &LoadedScene, settings: &RenderSettings, samples: SampleRange, seconds: f64, device: &str) -> RenderInfo {
    let c = &loaded.camera;
    let s = settings;
    let mut info = RenderInfo::default();
    info.set(keys::VERSION, env!("CARGO_PKG_VERSION"));
    info.set(keys::SCENE, loaded.scene.source.clone());
    info.set(keys::SCENE_HASH, scene_hash(&loaded.scene));
    info.set(
        keys::CAMERA,
        format!(
            "eye {} {} {} target {} {} {} up {} {} {} fov_y {}",
            c.eye.x, c.eye.y, c.eye.z, c.target.x, c.target.y, c.target.z, c.up.x, c.up.y, c.up.z, c.fov_y_deg
        ),
    );
    info.set(keys::FULL_SIZE, format!("{}x{}", c.width, c.height));
    info.set(keys::CROP, s.crop.unwrap_or(Crop::full(c.width, c.height)).to_string());
    info.set(keys::INTEGRATOR, s.integrator.name());
    let mut set = format!("sampler {:?} max_depth {} rr_depth {} tri_test {:?}", s.sampler, s.max_depth, s.rr_depth, s.bvh.tri_test);
    if let bidir::render::Integrator::Bdpt(_) | bidir::render::Integrator::Vcm(_) = s.integrator {
        let features = bidir::gpu_data::SceneFeatures::of(&loaded.scene);
        set += &format!(" light_path_len {} light_paths {}", s.light_path_len, s.light_path_ratio_for(&features));
        if s.direct_light_tracing {
            set += " direct_light_tracing";
        }
        set += &format!(" mis {:?}", s.mis_for(&features));
        let candidates = s.connection_candidates_for(&features);
        if candidates > 1 {
            set += &format!(" connection_candidates {candidates}");
        }
    }
    if let bidir::render::Integrator::Vcm(_) = s.integrator {
        set += &format!(" vcm_radius {:?} vcm_alpha {}", s.vcm_radius, s.vcm_alpha);
    }
    info.set(keys::SETTINGS, set);
    info.set(keys::SEED, s.seed.to_string());
    info.set(keys::SAMPLE_RANGE, samples.to_string());
    info.set(keys::SPP, samples.len().to_string());
    info.set(keys::RENDER_TIME, format!("{seconds:.3}"));
    info.set(keys::DEVICE, device);
    info
}

/// Writes the outputs: EXR as a part (the estimate, the film's sums, the metadata: `bidir
/// info`, `bidir merge`), PNG as the `exposure`-scaled estimate.
pub fn write_outputs(
    outputs: &[std::path::PathBuf],
    sums: &bidir::imaging::part::Accumulation,
    img: &bidir::imaging::RgbImage,
    info: &RenderInfo,
    crop: Crop,
    exposure: f32,
) -> anyhow::Result<()> {
    for o in outputs {
        match o.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
            Some("exr") => bidir::imaging::part::write_part(o, sums, info, crop)?,
            _ => bidir::imaging::write_image(o, img, exposure)?,
        }
    }
    Ok(())
}

/// BDPT iterations hold `slices` samples, starting at multiples of it: a range that starts or
/// ends elsewhere is still an unbiased part, but not the whole render's iterations exactly.
pub fn warn_unaligned(args: &PartArgs, settings: &RenderSettings, slices: u32) {
    if let (Some(r), bidir::render::Integrator::Bdpt(_) | bidir::render::Integrator::Vcm(_)) = (args.sample_range, settings.integrator) {
        if slices > 1 && (r.start % slices != 0 || r.end % slices != 0) {
            eprintln!("warning: BDPT renders {slices} samples per iteration here: sample range {r} does not start and end at multiples of {slices}, so merged parts will equal a whole render in expectation, not pixel for pixel (give --sample-slices, or align the ranges)");
        }
    }
}
