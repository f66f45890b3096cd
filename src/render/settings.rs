//! What a render is asked for: the integrator, its sampler and MIS heuristic, and
//! [`RenderSettings`], whose `None` fields the defaults in `defaults.rs` resolve per device and
//! scene.

use super::bdpt::{self, Join};
use super::defaults::{default_connection_candidates, default_light_path_ratio, default_mis};
use super::{vcm, ShadowQueue};
use crate::bvh::{BuildOptions, BvhLayout};
use crate::gpu_data::SceneFeatures;
use crate::imaging::Crop;
use std::time::Duration;

/// Which estimator renders the image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Integrator {
    /// Path tracing with BSDF sampling only.
    Pt,
    /// Path tracing with next-event estimation and MIS (the thesis' explicit sampling).
    PtNee,
    /// Bidirectional path tracing (megakernel: light pass, camera pass), MIS-weighted.
    Bdpt(Join),
    /// Vertex connection and merging over BDPT's light vertex cache (`vcm.rs`).
    Vcm(vcm::VcmMode),
}

impl Integrator {
    pub fn name(self) -> String {
        match self {
            Integrator::Pt => "pt".into(),
            Integrator::PtNee => "pt-nee".into(),
            Integrator::Bdpt(j) => format!("bdpt:{}", j.name()),
            Integrator::Vcm(m) => match (m.merge, m.connect, m.normalized().merge_all) {
                (true, true, false) => "vcm".into(),
                (true, true, true) => "vcm:merge-all".into(),
                (false, _, _) => "vcm:no-merge".into(),
                (true, false, _) => "vcm:no-connect".into(),
            },
        }
    }

    /// Whether it traces light paths into a store sized by the full image's pixel count
    /// (whatever the crop), which bounds its sample slices.
    pub fn stores_light_vertices(self) -> bool {
        matches!(self, Integrator::Bdpt(_) | Integrator::Vcm(_))
    }
}

impl std::str::FromStr for Integrator {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "pt" => Ok(Integrator::Pt),
            "pt-nee" => Ok(Integrator::PtNee),
            // The GPU-native variant won on RMSE against time (docs/integrators.md), with
            // one connection per camera vertex ([`Join::DEFAULT`]).
            "bdpt" => Ok(Integrator::Bdpt(Join::DEFAULT)),
            "vcm" => Ok(Integrator::Vcm(vcm::VcmMode::FULL)),
            "vcm:merge-all" => Ok(Integrator::Vcm(vcm::VcmMode::MERGE_ALL)),
            "vcm:no-merge" => Ok(Integrator::Vcm(vcm::VcmMode::NO_MERGE)),
            "vcm:no-connect" => Ok(Integrator::Vcm(vcm::VcmMode::NO_CONNECT)),
            _ => match s.strip_prefix("bdpt:") {
                Some(j) => Ok(Integrator::Bdpt(j.parse()?)),
                None => Err(format!(
                    "unknown integrator '{s}' (pt | pt-nee | bdpt | bdpt:full | bdpt:single | bdpt:k=N | bdpt:lvc | bdpt:lvc=N | vcm | vcm:merge-all | vcm:no-merge | vcm:no-connect)"
                )),
            },
        }
    }
}

/// How BDPT and VCM weigh their strategies (multiple importance sampling; Veach 1997, section
/// 9.2.4). Either is unbiased; they differ in noise.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mis {
    /// The balance heuristic: each strategy's weight in proportion to its pdf.
    Balance,
    /// The power heuristic with exponent 2: in proportion to the pdf's square.
    Power,
}

impl std::str::FromStr for Mis {
    type Err = String;
    fn from_str(s: &str) -> Result<Mis, String> {
        match s {
            "balance" => Ok(Mis::Balance),
            "power" => Ok(Mis::Power),
            other => Err(format!("{other}: balance | power")),
        }
    }
}

/// Where random numbers come from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sampler {
    /// Independent uniform numbers from a counter-based hash.
    Independent,
    /// Owen-scrambled Sobol' points (Burley 2020), four dimensions per stratified group, each
    /// sampling decision starting a group, for the pixel and the path's first vertex (its
    /// light sample and BSDF sample, however many dimensions they take); the rest hashed.
    /// Measured best at equal time for pt-nee and bdpt (docs/results.md, "Sobol' dimensions"
    /// and "A group of Sobol' dimensions per sampling decision").
    Sobol,
    /// Sobol' for the first `n` dimensions (`u32::MAX`: all; at most
    /// [`Sampler::MAX_SOBOL_DIMS`] otherwise), the rest hashed.
    SobolDims(u32),
}

impl Sampler {
    /// The most leading Sobol' dimensions `sobol:N` takes (a sample draws far fewer).
    pub const MAX_SOBOL_DIMS: u32 = 1 << 16;

    /// The kernels' SPEC_SAMPLER (glsl/common/rng.glsl).
    pub fn spec(self) -> crate::vk::Spec {
        let value = match self {
            Sampler::Independent => crate::gpu::abi::SAMPLER_INDEPENDENT,
            Sampler::Sobol => crate::gpu::abi::SOBOL_FIRST_VERTEX,
            Sampler::SobolDims(u32::MAX) => crate::gpu::abi::SOBOL_ALL_DIMS,
            Sampler::SobolDims(n) => n,
        };
        crate::vk::Spec { id: crate::gpu::abi::SPEC_SAMPLER, value }
    }

    /// The name `from_str` reads back.
    pub fn name(self) -> String {
        match self {
            Sampler::Independent => "independent".into(),
            Sampler::Sobol => "sobol".into(),
            Sampler::SobolDims(u32::MAX) => "sobol:all".into(),
            Sampler::SobolDims(n) => format!("sobol:{n}"),
        }
    }
}

impl std::str::FromStr for Sampler {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "independent" => Ok(Sampler::Independent),
            "sobol" => Ok(Sampler::Sobol),
            "sobol:all" => Ok(Sampler::SobolDims(u32::MAX)),
            _ => match s.strip_prefix("sobol:").map(str::parse::<u32>) {
                Some(Ok(n)) if (1..=Sampler::MAX_SOBOL_DIMS).contains(&n) => Ok(Sampler::SobolDims(n)),
                _ => Err(format!(
                    "unknown sampler '{s}' (independent | sobol | sobol:N with 1 <= N <= {} | sobol:all)",
                    Sampler::MAX_SOBOL_DIMS
                )),
            },
        }
    }
}

#[cfg(test)]
mod sampler_tests {
    use super::Sampler;
    use crate::gpu::abi;

    /// Each sampler's name reads back as itself, and its specialisation constant is the one
    /// rng.glsl reads: the default Sobol' for the pixel and the first vertex, `sobol:all`
    /// everywhere, `sobol:N` the first N dimensions; `sobol:N` past the cap (where it could
    /// meet the other two's values) or 0 is refused.
    #[test]
    fn samplers_read_back_and_give_their_specialisation() {
        for (sampler, spec) in [
            (Sampler::Independent, abi::SAMPLER_INDEPENDENT),
            (Sampler::Sobol, abi::SOBOL_FIRST_VERTEX),
            (Sampler::SobolDims(u32::MAX), abi::SOBOL_ALL_DIMS),
            (Sampler::SobolDims(12), 12),
            (Sampler::SobolDims(Sampler::MAX_SOBOL_DIMS), Sampler::MAX_SOBOL_DIMS),
        ] {
            assert_eq!(sampler.name().parse::<Sampler>(), Ok(sampler), "{}", sampler.name());
            assert_eq!(sampler.spec().value, spec, "{}", sampler.name());
            assert_eq!(sampler.spec().id, abi::SPEC_SAMPLER);
        }
        for bad in ["sobol:0", "sobol:65537", "sobol:4294967294", "sobol:", "halton"] {
            assert!(bad.parse::<Sampler>().is_err(), "{bad} was accepted");
        }
    }

    /// `--wavefront-finish` reads back what it names and refuses odd, too small or too large
    /// counts (a batch's launches are even, and the finishing launch needs a dispatch entry).
    #[test]
    fn wavefront_finishes_read_back() {
        use super::WavefrontFinish;
        let most = abi::WF_MAX_BATCH - 2;
        for f in [WavefrontFinish::Off, WavefrontFinish::Auto, WavefrontFinish::After(2), WavefrontFinish::After(most)] {
            assert_eq!(f.name().parse::<WavefrontFinish>(), Ok(f), "{}", f.name());
        }
        for bad in ["0", "1", "3", &(most + 2).to_string(), "on", ""] {
            assert!(bad.parse::<WavefrontFinish>().is_err(), "{bad} was accepted");
        }
    }
}

/// `RenderSettings::wavefront_overlap`'s default (`--wavefront-overlap`).
pub const DEFAULT_WAVEFRONT_OVERLAP: u32 = 4;

/// How the wavefront forms' passes end (`--wavefront-finish`; src/render/bdpt_wavefront.rs,
/// src/render/pt_wavefront.rs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WavefrontFinish {
    /// Launches until one queues no ray.
    Off,
    /// A finishing launch, in which every path still live runs to its end tracing its own
    /// rays, after this many launches (even, from 2 to `WF_MAX_BATCH - 2`).
    After(u32),
    /// The finishing launch after as many launches as the last pass of the kind took to leave
    /// fewer paths live than a quarter of what the trace kernels run at once.
    Auto,
}

impl WavefrontFinish {
    /// The name `from_str` reads back.
    pub fn name(self) -> String {
        match self {
            WavefrontFinish::Off => "off".into(),
            WavefrontFinish::After(n) => n.to_string(),
            WavefrontFinish::Auto => "auto".into(),
        }
    }
}

impl std::str::FromStr for WavefrontFinish {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        let most = crate::gpu::abi::WF_MAX_BATCH - 2;
        match s {
            "off" => Ok(WavefrontFinish::Off),
            "auto" => Ok(WavefrontFinish::Auto),
            _ => match s.parse::<u32>() {
                Ok(n) if (2..=most).contains(&n) && n % 2 == 0 => Ok(WavefrontFinish::After(n)),
                _ => Err(format!("--wavefront-finish {s}: auto | off | an even count of launches from 2 to {most}")),
            },
        }
    }
}

/// How to render.
#[derive(Clone, Debug)]
pub struct RenderSettings {
    pub integrator: Integrator,
    /// Most path segments (0: unbounded, Russian roulette ends paths).
    pub max_depth: u32,
    /// First bounce at which Russian roulette may end a path.
    pub rr_depth: u32,
    pub seed: u32,
    pub sampler: Sampler,
    /// BDPT: light vertices stored per light path (a reservoir over an unbounded path).
    pub light_path_len: u32,
    /// BDPT with the light vertex cache: light paths per iteration as a multiple of the
    /// pixel count (the megakernel joins need 1: they pair a light path with each pixel).
    /// `None` takes [`default_light_path_ratio`] for the integrator and scene.
    pub light_path_ratio: Option<f32>,
    /// Compile the mirror/glass/texture/alpha code in even where the scene has none (to
    /// measure what specialisation buys).
    pub all_material_code: bool,
    /// Samples of a pixel a pass renders at once, each by its own invocation (0: as many as
    /// it takes to give the GPU about 2^20 invocations, or a wavefront form about 2^23 slots
    /// (BDPT's 2^24), within their memory; 1 on CPU devices, which are full anyway). Small
    /// images otherwise leave a large GPU mostly idle.
    pub sample_slices: u32,
    /// GPU time one submission should take (passes are sized to it; keeps lavapipe
    /// responsive and far from the GPU timeout).
    pub pass_target: Duration,
    /// How the BVH is built; [`Renderer::new`](super::Renderer::new) sets its `layout`, `max_leaf_tris` and
    /// `quality` from `bvh_layout`, `bvh_leaf_size` and `bvh_quality` (set those, not these).
    pub bvh: BuildOptions,
    /// The BVH layout the integrators traverse (`--bvh`): `bvh2`, `cwbvh` or `bvh4`; `None`
    /// takes the device's faster one for the integrator and scene ([`default_bvh_layout`](super::default_bvh_layout),
    /// [`wavefront_bvh_layout`](super::wavefront_bvh_layout)).
    pub bvh_layout: Option<BvhLayout>,
    /// Most triangles per BVH leaf (`--bvh-leaf-size`) and obvhs's quality preset
    /// (`--bvh-quality`); `None` takes the layout's default ([`default_bvh_build`](super::default_bvh_build)). The image
    /// is the same either way.
    pub bvh_leaf_size: Option<u32>,
    pub bvh_quality: Option<u32>,
    /// Index of the first sample rendered (`--sample-range START..`): a render of samples
    /// `a..b` uses the random numbers a render from 0 uses for them, so disjoint ranges are
    /// independent parts of one estimate (see `film::merge`).
    pub sample_start: u32,
    /// Render only this window of the camera's image (`--crop`); the projection, the random
    /// numbers of every pixel and BDPT's light paths stay those of the full image.
    pub crop: Option<Crop>,
    /// Run the first-hit pass for alpha and these AOV layers (`None`: no alpha, no cost).
    pub first_hit: Option<crate::imaging::aov::Aovs>,
    /// VCM: the first iteration's merge radius (a fraction of the scene's diagonal until the
    /// renderer resolves it to scene units).
    pub vcm_radius: vcm::VcmRadius,
    /// VCM: radius reduction exponent alpha, r_i = r_1 i^((alpha - 1) / 2).
    pub vcm_alpha: f32,
    /// pt and pt-nee: start an invocation's next sample where its path ends
    /// (`--path-regeneration`); `None` takes [`default_path_regeneration`](super::default_path_regeneration). Either gives the
    /// same image.
    pub path_regeneration: Option<bool>,
    /// pt-nee: trace the light sample's shadow ray in the step after the one that drew it,
    /// through the same call as the extension rays (`--one-trace`); `None` takes
    /// [`default_one_trace`](super::default_one_trace). Either gives the same image.
    pub one_trace: Option<bool>,
    /// pt-nee's and BDPT's/VCM's camera and light passes: queue the shadow rays for a kernel
    /// of their own (`--shadow-queue`; BDPT and VCM use its slots only); `None` takes
    /// [`default_shadow_queue`](super::default_shadow_queue) / [`default_camera_pass_queue`](super::default_camera_pass_queue), `Some(None)` is off. The image
    /// is the same up to the order of float sums.
    pub shadow_queue: Option<Option<ShadowQueue>>,
    /// BDPT and VCM: keep light tracing (t = 1) as a strategy for direct lighting, the paths light ->
    /// surface -> eye (`--direct-light-tracing`). Off (the default) those are left to the
    /// camera path's light samples and emitter hits, which the pixel's stratified samples
    /// draw: less noise and fewer shadow rays (glsl/common/bdpt.glsl; docs/integrators.md).
    /// Either is unbiased.
    pub direct_light_tracing: bool,
    /// BDPT and VCM: the MIS heuristic (`--mis`); `None` takes [`default_mis`] for the
    /// integrator and scene.
    pub mis: Option<Mis>,
    /// BDPT and VCM with the light vertex cache (`bdpt`, `bdpt:lvc=N`, `vcm`): each
    /// connection's light vertex is resampled from this many uniform draws by its unshadowed
    /// contribution (`--connection-candidates`); 1 draws it uniformly; `None` takes
    /// [`default_connection_candidates`] for the integrator and scene. Every count
    /// is unbiased: more candidates lower the variance per sample and cost time
    /// ([`MAX_CONNECTION_CANDIDATES`] at most; docs/results.md, "Connections resampled from
    /// several candidates"). The candidates belong to a block of 16 x 8 pixels at one sample,
    /// vertex count and connection, drawn by hashes of that group's key, and the subgroup's
    /// connecting lanes share their reads where they can read all its groups' candidates at
    /// once (glsl/common/bdpt_camera_path.glsl):
    /// which lanes connect together changes nothing, so either form, a crop and a sample range
    /// (at multiples of the slice count) make the whole render's choices. The other joins
    /// ignore it.
    pub connection_candidates: Option<u32>,
    /// BDPT and VCM with the light vertex cache: list the cache with an invocation per slot of
    /// the store (`Some(true)`) or per light path (`Some(false)`); `None` takes
    /// [`default_lvc_listing_per_slot`](super::default_lvc_listing_per_slot) for the device.
    /// The listing, and so the image, is the same either way: a knob for the tests, which run
    /// on a CPU device, where the default is per path.
    pub lvc_listing_per_slot: Option<bool>,
    /// pt and pt-nee: the wavefront path tracer (`--wavefront`; pt_wavefront.rs), whose
    /// segments and shadow rays are traced by the trace kernels between its launches, instead
    /// of the megakernel; bdpt with the light vertex cache's fixed joins: its light and camera
    /// passes so (bdpt_wavefront.rs). `None` takes [`default_wavefront`](super::default_wavefront); `Some(true)` for an integrator
    /// without a wavefront form is an error. Either gives the same image (up to the order of
    /// float sums).
    pub wavefront: Option<bool>,
    /// The wavefront forms' passes (BDPT's light and camera passes, the path tracer's): how
    /// each ends (`--wavefront-finish`). Every way gives the same image (up to the order of
    /// float sums and ties between equally near triangles).
    pub wavefront_finish: WavefrontFinish,
    /// BDPT's wavefront passes with a finishing launch: the camera pass's last this many launches
    /// run beside the next iteration's light pass, and its first beside that pass's tail
    /// (`--wavefront-overlap`; bdpt.rs, `iterate_side_by_side`); None: each pass alone. The image
    /// is the same up to the order of float sums.
    pub wavefront_overlap: Option<u32>,
    /// Count the rays the integrator kernels trace, their node visits and triangle tests
    /// (`Renderer::traversal_counts`; slower kernels: for `bidir bench render --count`).
    pub count_traversal: bool,
}

impl RenderSettings {
    /// The MIS heuristic BDPT and VCM run with in a scene of `features`: `--mis`, or
    /// [`default_mis`] for the integrator and scene. Resolved where the kernels are built (so
    /// an integrator switch takes the new integrator's default) and where a part records it.
    pub fn mis_for(&self, features: &SceneFeatures) -> Mis {
        self.mis.unwrap_or_else(|| default_mis(self.integrator, features))
    }

    /// Light paths per pixel BDPT with the light vertex cache traces in a scene of `features`:
    /// `--light-paths`, or [`default_light_path_ratio`]. Resolved as [`Self::mis_for`] is.
    pub fn light_path_ratio_for(&self, features: &SceneFeatures) -> f32 {
        self.light_path_ratio.unwrap_or_else(|| default_light_path_ratio(self.integrator, features))
    }

    /// Candidates of each connection to the light vertex cache in a scene of `features`:
    /// `--connection-candidates`, or [`default_connection_candidates`]; 1 for the joins without
    /// the cache, which ignore it. Resolved as [`Self::mis_for`] is.
    pub fn connection_candidates_for(&self, features: &SceneFeatures) -> u32 {
        match self.integrator {
            Integrator::Bdpt(bdpt::Join::Lvc(_)) | Integrator::Vcm(_) => {
                self.connection_candidates.unwrap_or_else(|| default_connection_candidates(self.integrator, features))
            }
            _ => 1,
        }
    }

    /// These settings for another integrator: Russian roulette follows the new integrator's
    /// default unless it was set by hand.
    pub fn with_integrator(&self, integrator: Integrator) -> RenderSettings {
        let mut s = self.clone();
        s.integrator = integrator;
        if self.rr_depth == default_rr_depth(self.integrator) {
            s.rr_depth = default_rr_depth(integrator);
        }
        s
    }

    pub fn new(integrator: Integrator) -> Self {
        RenderSettings {
            integrator,
            max_depth: 0,
            rr_depth: default_rr_depth(integrator),
            seed: 0,
            sampler: Sampler::Sobol,
            light_path_len: 8,
            light_path_ratio: None,
            sample_slices: 0,
            all_material_code: false,
            pass_target: Duration::from_millis(250),
            bvh: BuildOptions::default(),
            bvh_layout: None,
            bvh_leaf_size: None,
            bvh_quality: None,
            sample_start: 0,
            crop: None,
            first_hit: None,
            vcm_radius: vcm::VcmRadius::default(),
            vcm_alpha: 0.75,
            path_regeneration: None,
            one_trace: None,
            shadow_queue: None,
            direct_light_tracing: false,
            mis: None,
            connection_candidates: None,
            lvc_listing_per_slot: None,
            wavefront: None,
            wavefront_finish: WavefrontFinish::Auto,
            wavefront_overlap: Some(DEFAULT_WAVEFRONT_OVERLAP),
            count_traversal: false,
        }
    }
}

/// The first bounce at which Russian roulette may end a path, by integrator. Measured on the
/// Cornell box (NVIDIA H200, docs/results.md): path tracers gain from longer paths before
/// roulette (pt-nee from bounce 5: 28-33 % lower MSE at equal time than from bounce 3), BDPT
/// does not (its light paths already carry the long paths; from 5 its MSE rose 15-45 %).
pub fn default_rr_depth(integrator: Integrator) -> u32 {
    match integrator {
        Integrator::Pt | Integrator::PtNee => 5,
        Integrator::Bdpt(_) | Integrator::Vcm(_) => 3,
    }
}

/// Most candidates [`RenderSettings::connection_candidates`] takes. Each costs the p_hat of a
/// connection and a share of a read (glsl/common/bdpt_camera_path.glsl): past 16 the H200
/// measured no gain at equal time (docs/results.md, "Candidates shared within the subgroup"),
/// and 32 candidates of one group are as many as NVIDIA's 32-lane subgroups read at once (with
/// more groups in the subgroup, or fewer lanes connecting, each lane reads its own).
pub const MAX_CONNECTION_CANDIDATES: u32 = 32;
