//! `bidir bench traversal`'s report: per ray kind, and the whole run as JSON and as the
//! printed table.

use super::RayKind;
use crate::bench::driver_rt::DriverKindResult;
use crate::bench::json::Json;
use crate::bvh::{BvhLayout, Collapse};
use crate::trace::sort::SortKind;
use crate::trace::TraceOptions;
use glam::Vec3;

/// One ray kind's measurement.
#[derive(Clone, Debug)]
pub struct KindResult {
    pub kind: RayKind,
    pub rays: u32,
    pub times_ms: Vec<f64>,
    pub median_ms: f64,
    /// Median time of the ray sort before the trace (secondary rays with `Options::sort`).
    pub sort_median_ms: Option<f64>,
    pub mrays_per_s: f64,
    pub nodes_per_ray: f64,
    /// Bytes of node data fetched per ray (nodes visited × the layout's node size).
    pub node_bytes_per_ray: f64,
    pub tris_per_ray: f64,
    pub hit_fraction: f64,
    /// The same rays through the driver's ray-tracing pipeline (`Options::driver_rt`).
    pub driver: Option<DriverKindResult>,
}

/// The whole report.
#[derive(Clone, Debug)]
pub struct Report {
    pub device: String,
    pub triangles: usize,
    /// The trace kernels as they ran (`Options::trace` with the build's layout and test, the
    /// scene's alpha features where masks were honoured, the persistent workgroups launched,
    /// and what does not apply to the layout or launch off).
    pub trace: TraceOptions,
    /// Materials with an alpha mask (counted whether or not `trace.alpha` honoured them).
    pub alpha_materials: usize,
    pub sort: Option<SortKind>,
    /// The driver's compile statistics of the timed closest- and any-hit kernels ("name
    /// value; ..."), where it reports them (VK_KHR_pipeline_executable_properties).
    pub kernel_stats: Vec<(String, String)>,
    pub bvh_build_ms: f64,
    pub bvh_nodes: usize,
    pub bvh_leaves: usize,
    pub bvh_depth: usize,
    pub bvh_bytes: u64,
    /// The tree's SAH (`Bvh::sah_cost`; binary and 4-wide layouts).
    pub bvh_sah: Option<f64>,
    /// The build quality (`BuildOptions::quality`), and PLOC's search distance and
    /// single-neighbour depth where set (`BuildOptions::ploc`).
    pub quality: u32,
    pub ploc: Option<(u32, usize)>,
    /// Whether any-hit rays traversed their own copy of the 4-wide nodes (`GpuBvh::any_hit_copy`).
    pub any_hit_copy: bool,
    /// How the 4-wide nodes were grouped (`BuildOptions::collapse`; `None` for other layouts).
    pub collapse: Option<Collapse>,
    pub width: u32,
    pub height: u32,
    pub light: Vec3,
    pub results: Vec<KindResult>,
    /// The driver's bottom-level acceleration structure: GPU build time (ms) and bytes.
    pub driver_build: Option<(f64, u64)>,
}

impl Report {
    pub fn to_json(&self) -> Json {
        let t = &self.trace;
        Json::obj(vec![
            ("device", Json::Str(self.device.clone())),
            ("triangles", Json::Int(self.triangles as i64)),
            ("tri_test", Json::Str(t.tri_test.name().into())),
            ("bvh_layout", Json::Str(t.layout.name().into())),
            ("alpha", Json::Bool(t.alpha.is_some())),
            ("alpha_materials", Json::Int(self.alpha_materials as i64)),
            ("persistent", Json::Bool(t.persistent.is_some())),
            ("persistent_groups", Json::Int(t.persistent.unwrap_or(0) as i64)),
            ("speculative", Json::Bool(t.speculative)),
            ("lockstep", Json::Bool(t.lockstep)),
            ("refill_lanes", Json::Int(t.refill_lanes as i64)),
            ("share_leaves", Json::Bool(t.share_leaves)),
            ("packet", Json::Bool(t.packet)),
            ("postpone", Json::Bool(t.postpone)),
            ("short_stack", Json::Bool(t.short_stack)),
            ("int_slabs", Json::Bool(t.int_slabs)),
            ("rays_per_invocation", Json::Int(t.rays_per_invocation as i64)),
            ("sort", Json::Str(self.sort.map_or("none".to_string(), |k| k.name()))),
            ("workgroup_size", Json::Int(t.workgroup_size as i64)),
            ("kernel_statistics", Json::obj(self.kernel_stats.iter().map(|(k, v)| (k.as_str(), Json::Str(v.clone()))).collect())),
            ("width", Json::Int(self.width as i64)),
            ("height", Json::Int(self.height as i64)),
            ("light", Json::Arr(self.light.to_array().iter().map(|&x| Json::Num(x as f64)).collect())),
            (
                "driver_rt_build",
                match self.driver_build {
                    None => Json::Null,
                    Some((ms, bytes)) => Json::obj(vec![("blas_build_ms", Json::Num(ms)), ("blas_bytes", Json::Int(bytes as i64))]),
                },
            ),
            (
                "bvh",
                Json::obj(vec![
                    ("build_ms", Json::Num(self.bvh_build_ms)),
                    ("nodes", Json::Int(self.bvh_nodes as i64)),
                    ("leaves", Json::Int(self.bvh_leaves as i64)),
                    ("depth", Json::Int(self.bvh_depth as i64)),
                    ("bytes", Json::Int(self.bvh_bytes as i64)),
                    ("sah", self.bvh_sah.map_or(Json::Null, Json::Num)),
                    ("quality", Json::Int(self.quality as i64)),
                    ("any_hit_copy", Json::Bool(self.any_hit_copy)),
                    ("collapse", self.collapse.map_or(Json::Null, |c| Json::Str(c.to_string()))),
                    (
                        "ploc",
                        self.ploc.map_or(Json::Null, |(d, k)| {
                            Json::obj(vec![("distance", Json::Int(d as i64)), ("depth", Json::Int(k as i64))])
                        }),
                    ),
                ]),
            ),
            (
                "results",
                Json::Arr(
                    self.results
                        .iter()
                        .map(|r| {
                            Json::obj(vec![
                                ("rays", Json::Str(r.kind.name().into())),
                                ("count", Json::Int(r.rays as i64)),
                                ("median_ms", Json::Num(r.median_ms)),
                                ("sort_median_ms", Json::Num(r.sort_median_ms.unwrap_or(f64::NAN))),
                                ("mrays_per_s", Json::Num(r.mrays_per_s)),
                                ("nodes_per_ray", Json::Num(r.nodes_per_ray)),
                                ("node_bytes_per_ray", Json::Num(r.node_bytes_per_ray)),
                                ("tris_per_ray", Json::Num(r.tris_per_ray)),
                                ("hit_fraction", Json::Num(r.hit_fraction)),
                                ("times_ms", Json::Arr(r.times_ms.iter().map(|&t| Json::Num(t)).collect())),
                                ("driver_rt", r.driver.as_ref().map_or(Json::Null, DriverKindResult::to_json)),
                            ])
                        })
                        .collect(),
                ),
            ),
        ])
    }

    pub fn print(&self) {
        let t = &self.trace;
        println!(
            "device {} | {} triangles | {} test{} | {}x{} | {} {:.1} ms build{}, {} nodes of {} B, {} leaves, depth {}, {:.1} MiB{}",
            self.device,
            self.triangles,
            t.tri_test.name(),
            if t.alpha.is_some() { format!(", alpha masks ({} materials)", self.alpha_materials) } else { String::new() }
                + &t.persistent.map_or(String::new(), |g| format!(", persistent threads ({g} groups)"))
                + if t.layout != BvhLayout::Cwbvh && !t.speculative { ", not speculative" } else { "" }
                + if t.layout != BvhLayout::Cwbvh && t.speculative && !t.lockstep { ", divergent loops" } else { "" }
                + &if t.refill_lanes > 0 { format!(", dynamic fetch at {} done lanes", t.refill_lanes) } else { String::new() }
                + if t.share_leaves { ", leaf tests shared among lanes" } else { "" }
                + if t.packet { ", packet traversal" } else { "" }
                + if t.postpone { ", triangle postponing" } else { "" }
                + if t.short_stack { ", short stack (registers + shared memory)" } else { "" }
                + if !t.int_slabs { ", float slab test" } else { "" }
                + &if t.rays_per_invocation > 1 { format!(", {} rays per invocation", t.rays_per_invocation) } else { String::new() }
                + &self.sort.map_or(String::new(), |k| format!(", secondary rays {}", k.describe()))
                + &format!(", workgroups of {}", t.workgroup_size),
            self.width,
            self.height,
            t.layout.name(),
            self.bvh_build_ms,
            format!(" (quality {}", self.quality)
                + &self.ploc.map_or(String::new(), |(d, k)| format!(", PLOC {d},{k}"))
                + if self.any_hit_copy { ", any-hit copy" } else { "" }
                + &self.collapse.map_or(String::new(), |c| format!(", {c} collapse"))
                + ")",
            self.bvh_nodes,
            t.layout.node_size(),
            self.bvh_leaves,
            self.bvh_depth,
            self.bvh_bytes as f64 / (1 << 20) as f64,
            self.bvh_sah.map_or(String::new(), |c| format!(", SAH {c:.2}"))
        );
        println!(
            "{:<8} {:>10} {:>10} {:>12} {:>11} {:>12} {:>10} {:>6} {:>8}",
            "rays", "count", "median ms", "Mrays/s", "nodes/ray", "node B/ray", "tris/ray", "hit %", "sort ms"
        );
        for r in &self.results {
            println!(
                "{:<8} {:>10} {:>10.3} {:>12.1} {:>11.1} {:>12.0} {:>10.1} {:>6.1} {:>8}",
                r.kind.name(),
                r.rays,
                r.median_ms,
                r.mrays_per_s,
                r.nodes_per_ray,
                r.node_bytes_per_ray,
                r.tris_per_ray,
                100.0 * r.hit_fraction,
                r.sort_median_ms.map_or("-".to_string(), |t| format!("{t:.3}"))
            );
        }
        if let Some((ms, bytes)) = self.driver_build {
            crate::bench::driver_rt::print_header(ms, bytes);
            for r in &self.results {
                if let Some(d) = &r.driver {
                    d.print(r.kind.name(), r.rays, r.mrays_per_s);
                }
            }
        }
        for (kernel, stats) in &self.kernel_stats {
            println!("{kernel}: {stats}");
        }
    }
}
