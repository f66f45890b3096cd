//! Speed against accuracy: each integrator renders the same scene progressively, one after
//! the other, and at chosen moments its film is read back and compared with a reference
//! (RMSE, relMSE). The result is a curve per integrator, written as a CSV, a log-log chart
//! and the final images.
//!
//! **Time** is render time: the sum of the durations of the integrator's passes (each pass is
//! one submission that the host waits for). Set-up (BVH, upload, pipelines), the read-backs
//! and the metrics are excluded, so a snapshot costs the integrator nothing. The GPU is idle
//! only while a snapshot is read back. A snapshot is taken after the first pass that reaches
//! its moment, so measured times are at or a little past the nominal ones; the curves use
//! the measured ones.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use super::chart::{self, ChartText, Panel, Series};
use crate::imaging::{self, metrics, ImageIoError, RgbImage};
use crate::render::{stop_requested, Integrator, RenderError, RenderSettings, Renderer};
use crate::scene::{Camera, Scene};
use crate::vk::Context;

/// When snapshots are taken.
#[derive(Clone, Debug, PartialEq)]
pub enum Schedule {
    /// `points` log-spaced render times from 1 % of `budget_s` to all of it (seconds).
    Time { budget_s: f64, points: usize },
    /// When the sample count per pixel reaches each value (ascending); passes are capped so
    /// each value is met exactly.
    Spp(Vec<u32>),
}

/// What to compare.
#[derive(Clone, Debug)]
pub struct Options {
    pub integrators: Vec<Integrator>,
    pub schedule: Schedule,
    /// Settings shared by every integrator (seed, depth, BDPT store); its integrator is ignored,
    /// and so is its Russian roulette depth (`rr_depth`).
    pub settings: RenderSettings,
    /// The bounce at which Russian roulette may start, for every integrator (`--rr-depth`); None:
    /// each integrator's own default (`render::default_rr_depth`: 5 for pt and pt-nee, 3 for
    /// BDPT and VCM).
    pub rr_depth: Option<u32>,
    /// Independent runs per integrator, with seeds `settings.seed`, `settings.seed + 1`, ...:
    /// their curves are averaged and their stability figures' worst is reported.
    pub seeds: u32,
}

/// One snapshot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Point {
    /// Render time so far (sum of pass times).
    pub seconds: f64,
    pub spp: u32,
    pub rmse: f64,
    pub rel_mse: f64,
    /// The schedule's moments (indices of its times or sample counts) this snapshot stands
    /// for: taken for `moment`; a pass that already went past the following moments (no new
    /// samples since) makes it stand for them too, through `through`.
    pub moment: u32,
    pub through: u32,
}

impl Point {
    /// A snapshot for moment `moment` alone.
    pub fn new(seconds: f64, spp: u32, rmse: f64, rel_mse: f64, moment: u32) -> Point {
        Point { seconds, spp, rmse, rel_mse, moment, through: moment }
    }
}

/// An integrator's snapshots and final image.
#[derive(Clone, Debug)]
pub struct Curve {
    pub integrator: Integrator,
    pub points: Vec<Point>,
    pub image: RgbImage,
    /// Seconds spent creating the renderer (not render time).
    pub setup_s: f64,
    pub nan_samples: u32,
    /// How the curve behaves: the largest ratio RMSE(t_{i+1}) / RMSE(t_i) between consecutive
    /// snapshots (1 or below for a curve that only descends; a firefly landing makes it
    /// jump), the worst over the seeds.
    pub stability: f64,
}

/// The largest ratio of consecutive RMSEs of `points` (0 with fewer than two snapshots).
pub fn stability(points: &[Point]) -> f64 {
    points.windows(2).map(|w| w[1].rmse / w[0].rmse).fold(0.0, f64::max)
}

/// One curve from several seeds' curves of the same schedule: per moment of the schedule the
/// mean time and samples and the root mean square of the RMSEs (so the square root of the mean
/// MSE; relMSE averaged) of each seed's snapshot for that moment (the one that stands for it:
/// a seed whose pass went past a moment answers it with the snapshot taken after that pass),
/// over the moments every seed answered and some seed took a snapshot for; the stability
/// figure is the worst seed's. The image is the last seed's.
pub fn average(mut curves: Vec<Curve>) -> Curve {
    let n = curves.len() as f64;
    let mut moments: Vec<u32> = curves.iter().flat_map(|c| c.points.iter().map(|p| p.moment)).collect();
    moments.sort_unstable();
    moments.dedup();
    let points = moments
        .into_iter()
        .filter_map(|k| {
            let at: Option<Vec<&Point>> = curves.iter().map(|c| c.points.iter().find(|p| (p.moment..=p.through).contains(&k))).collect();
            let at = at?;
            let mean = |f: &dyn Fn(&Point) -> f64| at.iter().map(|p| f(p)).sum::<f64>() / n;
            Some(Point {
                seconds: mean(&|p| p.seconds),
                spp: mean(&|p| p.spp as f64).round() as u32,
                rmse: mean(&|p| p.rmse * p.rmse).sqrt(),
                rel_mse: mean(&|p| p.rel_mse),
                moment: k,
                through: k,
            })
        })
        .collect();
    let stability = curves.iter().map(|c| c.stability).fold(0.0, f64::max);
    let setup_s = curves.iter().map(|c| c.setup_s).sum::<f64>() / n;
    let nan_samples = curves.iter().map(|c| c.nan_samples).sum();
    let last = curves.pop().expect("at least one seed");
    Curve { integrator: last.integrator, points, image: last.image, setup_s, nan_samples, stability }
}

/// Why a convergence run cannot start or failed.
#[derive(Debug, thiserror::Error)]
pub enum ConvergeError {
    #[error("no integrators to compare")]
    NoIntegrators,
    #[error("integrator {0} is listed twice")]
    Duplicate(String),
    #[error("the time budget (--time) must be a positive, finite number of seconds, got {0}")]
    Time(f64),
    #[error("the number of snapshots (--points) must be 1 to 1000, got {0}")]
    Points(usize),
    #[error("sample counts (--spp-points) must be positive and ascending, got {0:?}")]
    Spp(Vec<u32>),
    #[error("the number of seeds (--seeds) must be 1 to 1000, got {0}")]
    Seeds(u32),
    #[error("the reference is {rw}x{rh} pixels but the camera renders {cw}x{ch} (match them with --width/--height)")]
    Size { rw: u32, rh: u32, cw: u32, ch: u32 },
    #[error("{integrator}: {source}")]
    Render { integrator: String, source: RenderError },
    #[error("drawing {what}: {msg}")]
    Chart { what: &'static str, msg: String },
    #[error(transparent)]
    Write(#[from] ImageIoError),
}

/// `points` render times, log-spaced from `budget_s / 100` to `budget_s` (one point: the
/// budget itself).
pub fn log_spaced_times(budget_s: f64, points: usize) -> Vec<f64> {
    if points <= 1 {
        return vec![budget_s];
    }
    let first = budget_s / 100.0;
    (0..points).map(|i| first * 100f64.powf(i as f64 / (points - 1) as f64)).collect()
}

/// Checks everything that can be checked before any rendering.
pub fn check(opts: &Options, camera: &Camera, reference: &RgbImage) -> Result<(), ConvergeError> {
    if opts.integrators.is_empty() {
        return Err(ConvergeError::NoIntegrators);
    }
    for (i, a) in opts.integrators.iter().enumerate() {
        if opts.integrators[..i].contains(a) {
            return Err(ConvergeError::Duplicate(a.name()));
        }
    }
    match &opts.schedule {
        Schedule::Time { budget_s, points } => {
            if !(budget_s.is_finite() && *budget_s > 0.0) {
                return Err(ConvergeError::Time(*budget_s));
            }
            if !(1..=1000).contains(points) {
                return Err(ConvergeError::Points(*points));
            }
        }
        Schedule::Spp(spp) => {
            if spp.is_empty() || spp[0] == 0 || spp.windows(2).any(|w| w[0] >= w[1]) {
                return Err(ConvergeError::Spp(spp.clone()));
            }
        }
    }
    if opts.seeds == 0 || opts.seeds > 1000 {
        return Err(ConvergeError::Seeds(opts.seeds));
    }
    if (reference.width, reference.height) != (camera.width, camera.height) {
        return Err(ConvergeError::Size { rw: reference.width, rh: reference.height, cw: camera.width, ch: camera.height });
    }
    Ok(())
}

/// Renders every integrator in turn, `opts.seeds` times each (curves averaged, see
/// [`average`]); `on_point` hears of each snapshot as it is taken. After
/// [`request_stop`](crate::render::request_stop) the integrator in flight ends with a last
/// snapshot after its current pass and the rest are skipped.
pub fn run(
    ctx: &Context,
    scene: &Scene,
    camera: &Camera,
    reference: &RgbImage,
    opts: &Options,
    mut on_point: impl FnMut(Integrator, &Point),
) -> Result<Vec<Curve>, ConvergeError> {
    check(opts, camera, reference)?;
    let mut curves = Vec::new();
    for &integrator in &opts.integrators {
        if stop_requested() && !curves.is_empty() {
            break;
        }
        let mut runs = Vec::new();
        for k in 0..opts.seeds {
            if stop_requested() && !runs.is_empty() {
                break;
            }
            let settings = settings_for(opts, integrator, k);
            let c = curve(ctx, scene, camera, reference, &opts.schedule, settings, &mut on_point)
                .map_err(|source| ConvergeError::Render { integrator: integrator.name(), source })?;
            runs.push(c);
        }
        curves.push(average(runs));
    }
    Ok(curves)
}

/// The settings of `integrator`'s run with seed offset `k`: the shared ones with its own
/// Russian roulette depth unless `--rr-depth` set one for all. (Until session 57 every integrator
/// took pt's, 5, so that converge's BDPT ran longer paths than `bidir render`'s: on the H200 its
/// Cornell box rendered 9,655 spp in 1 s against `render --time 1`'s 11,669.)
pub fn settings_for(opts: &Options, integrator: Integrator, k: u32) -> RenderSettings {
    RenderSettings {
        integrator,
        seed: opts.settings.seed.wrapping_add(k),
        rr_depth: opts.rr_depth.unwrap_or_else(|| crate::render::default_rr_depth(integrator)),
        ..opts.settings.clone()
    }
}

fn curve(
    ctx: &Context,
    scene: &Scene,
    camera: &Camera,
    reference: &RgbImage,
    schedule: &Schedule,
    settings: RenderSettings,
    on_point: &mut impl FnMut(Integrator, &Point),
) -> Result<Curve, RenderError> {
    let integrator = settings.integrator;
    let start = Instant::now();
    let mut r = Renderer::new(ctx, scene, camera, settings)?;
    let setup_s = start.elapsed().as_secs_f64();
    let mut rendered = 0.0;
    let mut points: Vec<Point> = Vec::new();
    let mut image = None;
    let mut snapshot = |r: &mut Renderer, rendered: f64, moment: u32| -> Result<(), RenderError> {
        if let Some(last) = points.last_mut().filter(|p| p.spp == r.samples()) {
            last.through = moment; // a long pass already passed this moment
            return Ok(());
        }
        let img = r.image()?;
        let p = Point::new(rendered, r.samples(), metrics::rmse(&img, reference), metrics::rel_mse(&img, reference), moment);
        on_point(integrator, &p);
        points.push(p);
        image = Some(img);
        Ok(())
    };
    match schedule {
        Schedule::Time { budget_s, points } => {
            for (k, target) in log_spaced_times(*budget_s, *points).into_iter().enumerate() {
                let left = target - rendered;
                if left > 0.0 || r.samples() == 0 {
                    let t = Instant::now();
                    r.render_time(Duration::from_secs_f64(left.max(0.0)), |_| {})?;
                    rendered += t.elapsed().as_secs_f64();
                }
                snapshot(&mut r, rendered, k as u32)?;
                if stop_requested() {
                    break;
                }
            }
        }
        Schedule::Spp(spps) => {
            for (k, &n) in spps.iter().enumerate() {
                let t = Instant::now();
                r.render_spp(n, |_| {})?;
                rendered += t.elapsed().as_secs_f64();
                snapshot(&mut r, rendered, k as u32)?;
                if stop_requested() {
                    break;
                }
            }
        }
    }
    let image = match image {
        Some(i) => i,
        None => r.image()?,
    };
    let stability = stability(&points);
    Ok(Curve { integrator, points, image, setup_s, nan_samples: r.nan_samples()?, stability })
}

/// `integrator,seconds,spp,rmse,relmse`, one row per snapshot.
pub fn csv(curves: &[Curve]) -> String {
    let mut out = String::from("integrator,seconds,spp,rmse,relmse\n");
    for c in curves {
        for p in &c.points {
            out += &format!("{},{:.6},{},{:.7},{:.7}\n", c.integrator.name(), p.seconds, p.spp, p.rmse, p.rel_mse);
        }
    }
    out
}

/// `integrator,stability`: the worst ratio of consecutive RMSEs per integrator.
pub fn stability_csv(curves: &[Curve]) -> String {
    let mut out = String::from("integrator,stability\n");
    for c in curves {
        out += &format!("{},{:.4}\n", c.integrator.name(), c.stability);
    }
    out
}

/// A file-name-safe form of an integrator's name: `bdpt:k=4` → `bdpt_k4`.
pub fn file_stem(integrator: Integrator) -> String {
    integrator.name().replace(':', "_").replace('=', "")
}

/// The x axis of the chart.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum XAxis {
    Seconds,
    Spp,
}

/// What the written files are called and how the images are shown.
pub struct Presentation {
    pub title: String,
    pub x_axis: XAxis,
    /// Exposure in stops of the PNG images.
    pub exposure: f32,
}

/// Writes into `dir` (which must exist): `convergence.csv`, `convergence.png`,
/// `convergence.svg`, `<integrator>.exr` and `.png` per integrator, and `side_by_side.png`
/// (the final images and the reference). Everything is drawn in memory first, then each file
/// is written to a temporary name and renamed. Returns the paths written.
pub fn write_outputs(dir: &Path, curves: &[Curve], reference: &RgbImage, how: &Presentation) -> Result<Vec<PathBuf>, ConvergeError> {
    let series: Vec<Series> = curves
        .iter()
        .map(|c| Series {
            name: c.integrator.name(),
            points: c.points.iter().map(|p| (if how.x_axis == XAxis::Seconds { p.seconds } else { p.spp as f64 }, p.rmse)).collect(),
        })
        .collect();
    let x_label = match how.x_axis {
        XAxis::Seconds => "render time [s] (sum of pass times)",
        XAxis::Spp => "samples per pixel",
    };
    let text = ChartText { title: how.title.clone(), x_label: x_label.into(), y_label: "RMSE vs reference".into() };
    let chart_err = |what| move |msg| ConvergeError::Chart { what, msg };
    let svg = chart::log_log_svg(&series, &text).map_err(chart_err("the SVG chart"))?;
    let png = chart::log_log_rgb(&series, &text).map_err(chart_err("the PNG chart"))?;
    let strip = side_by_side(curves, reference, how.exposure).map_err(chart_err("the side-by-side image"))?;

    let mut written = Vec::new();
    let mut text_file = |name: &str, contents: &str| -> Result<(), ConvergeError> {
        let path = dir.join(name);
        imaging::write_atomically(&path, |tmp| std::fs::write(tmp, contents).map_err(|e| e.to_string()))?;
        written.push(path);
        Ok(())
    };
    text_file("convergence.csv", &csv(curves))?;
    text_file("stability.csv", &stability_csv(curves))?;
    text_file("convergence.svg", &svg)?;
    let mut png_file = |name: &str, rgb: &[u8], (w, h): (u32, u32)| -> Result<(), ConvergeError> {
        let path = dir.join(name);
        imaging::write_atomically(&path, |tmp| imaging::write_png_rgb8(tmp, rgb, w, h))?;
        written.push(path);
        Ok(())
    };
    png_file("convergence.png", &png, chart::CHART_SIZE)?;
    png_file("side_by_side.png", &strip.0, (strip.1, strip.2))?;
    for c in curves {
        for ext in ["exr", "png"] {
            let path = dir.join(format!("{}.{ext}", file_stem(c.integrator)));
            imaging::write_image(&path, &c.image, how.exposure)?;
            written.push(path);
        }
    }
    Ok(written)
}

/// The final images, then the reference, each labelled with its name, samples, time and RMSE.
fn side_by_side(curves: &[Curve], reference: &RgbImage, exposure: f32) -> Result<(Vec<u8>, u32, u32), String> {
    let mut pixels: Vec<(Vec<String>, Vec<u8>)> = curves
        .iter()
        .map(|c| {
            let last = c.points.last().copied().unwrap_or(Point::new(0.0, 0, f64::NAN, f64::NAN, 0));
            let lines = vec![c.integrator.name(), format!("{} spp, {:.3} s", last.spp, last.seconds), format!("RMSE {:.5}", last.rmse)];
            (lines, imaging::to_srgb8(&c.image, exposure))
        })
        .collect();
    pixels.push((vec!["reference".into()], imaging::to_srgb8(reference, exposure)));
    let panels: Vec<Panel> =
        pixels.iter().map(|(lines, rgb)| Panel { lines: lines.clone(), rgb, width: reference.width, height: reference.height }).collect();
    chart::side_by_side(&panels)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::Join;

    fn opts(integrators: Vec<Integrator>, schedule: Schedule) -> Options {
        Options { integrators, schedule, settings: RenderSettings::new(Integrator::Pt), rr_depth: None, seeds: 1 }
    }

    #[test]
    fn each_integrator_takes_its_own_roulette_depth_unless_one_is_given() {
        let all = vec![Integrator::PtNee, Integrator::Bdpt(crate::render::Join::DEFAULT)];
        let mut o = opts(all, Schedule::Spp(vec![1]));
        o.settings.seed = 7;
        let pt_nee = settings_for(&o, Integrator::PtNee, 0);
        let bdpt = settings_for(&o, Integrator::Bdpt(crate::render::Join::DEFAULT), 2);
        assert_eq!((pt_nee.rr_depth, bdpt.rr_depth), (5, 3));
        assert_eq!((pt_nee.seed, bdpt.seed), (7, 9));
        assert_eq!(bdpt.integrator, Integrator::Bdpt(crate::render::Join::DEFAULT));
        o.rr_depth = Some(4);
        assert_eq!(settings_for(&o, Integrator::PtNee, 0).rr_depth, 4);
        assert_eq!(settings_for(&o, Integrator::Bdpt(crate::render::Join::DEFAULT), 0).rr_depth, 4);
    }

    #[test]
    fn times_are_log_spaced_from_one_percent_to_the_budget() {
        let t = log_spaced_times(20.0, 12);
        assert_eq!(t.len(), 12);
        assert!((t[0] - 0.2).abs() < 1e-12 && (t[11] - 20.0).abs() < 1e-9);
        let ratio = t[1] / t[0];
        for w in t.windows(2) {
            assert!((w[1] / w[0] - ratio).abs() < 1e-9);
        }
        assert_eq!(log_spaced_times(5.0, 1), vec![5.0]);
        assert_eq!(log_spaced_times(5.0, 2), vec![0.05, 5.0]);
    }

    #[test]
    fn bad_input_is_refused_before_rendering() {
        let cam = Camera::cornell_box();
        let reference = RgbImage::new(cam.width, cam.height);
        let time = |s: f64, n: usize| Schedule::Time { budget_s: s, points: n };
        let all = vec![Integrator::Pt, Integrator::Bdpt(Join::K(4))];
        let err = |o: Options, r: &RgbImage| check(&o, &cam, r).unwrap_err().to_string();
        assert!(check(&opts(all.clone(), time(20.0, 12)), &cam, &reference).is_ok());
        assert_eq!(err(opts(vec![], time(1.0, 2)), &reference), "no integrators to compare");
        assert_eq!(
            err(opts(vec![Integrator::Pt, Integrator::PtNee, Integrator::Pt], time(1.0, 2)), &reference),
            "integrator pt is listed twice"
        );
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(err(opts(all.clone(), time(bad, 12)), &reference).contains("(--time) must be a positive"));
        }
        assert!(err(opts(all.clone(), time(1.0, 0)), &reference).contains("--points"));
        for bad in [vec![], vec![0, 4], vec![4, 4], vec![16, 4]] {
            assert!(err(opts(all.clone(), Schedule::Spp(bad)), &reference).contains("--spp-points"));
        }
        assert!(check(&opts(all.clone(), Schedule::Spp(vec![1, 4, 16])), &cam, &reference).is_ok());
        let small = RgbImage::new(128, 256);
        assert_eq!(
            err(opts(all, time(1.0, 2)), &small),
            "the reference is 128x256 pixels but the camera renders 256x256 (match them with --width/--height)"
        );
    }

    #[test]
    fn csv_rows_and_file_names() {
        let p = |s: f64, n: u32, e: f64| Point::new(s, n, e, 2.0 * e, n);
        let curves = vec![
            Curve {
                integrator: Integrator::PtNee,
                points: vec![p(0.25, 1, 0.5), p(2.0, 8, 0.125)],
                image: RgbImage::new(1, 1),
                setup_s: 0.0,
                nan_samples: 0,
                stability: 0.25,
            },
            Curve {
                integrator: Integrator::Bdpt(Join::K(4)),
                points: vec![p(1.5, 3, 0.25)],
                image: RgbImage::new(1, 1),
                setup_s: 0.0,
                nan_samples: 0,
                stability: 0.25,
            },
        ];
        assert_eq!(
            csv(&curves),
            "integrator,seconds,spp,rmse,relmse\npt-nee,0.250000,1,0.5000000,1.0000000\npt-nee,2.000000,8,0.1250000,0.2500000\nbdpt:k=4,1.500000,3,0.2500000,0.5000000\n"
        );
        let stems: Vec<String> =
            [Integrator::Pt, Integrator::PtNee, Integrator::Bdpt(Join::Full), Integrator::Bdpt(Join::K(1)), Integrator::Bdpt(Join::K(4))]
                .map(file_stem)
                .into();
        assert_eq!(stems, ["pt", "pt-nee", "bdpt_full", "bdpt_single", "bdpt_k4"]);
        assert_eq!(stability_csv(&curves), "integrator,stability\npt-nee,0.2500\nbdpt:k=4,0.2500\n");
    }

    #[test]
    fn seeds_average_and_worst_stability() {
        // Snapshots for moments 0, 1, 2, ... of the schedule.
        let p = |s: f64, n: u32, e: f64| Point::new(s, n, e, e, n.trailing_zeros());
        // A curve that only descends, and one that jumps up 1.5x at its third snapshot.
        let a = vec![p(1.0, 1, 0.4), p(2.0, 2, 0.2), p(4.0, 4, 0.1)];
        let b = vec![p(3.0, 1, 0.3), p(4.0, 2, 0.2), p(6.0, 4, 0.3), p(8.0, 8, 0.1)];
        assert_eq!(stability(&a), 0.5);
        assert!((stability(&b) - 1.5).abs() < 1e-12);
        let curve = |points: Vec<Point>| Curve {
            integrator: Integrator::Vcm(crate::render::vcm::VcmMode::FULL),
            stability: stability(&points),
            points,
            image: RgbImage::new(1, 1),
            setup_s: 1.0,
            nan_samples: 1,
        };
        let avg = average(vec![curve(a), curve(b)]);
        assert_eq!(avg.points.len(), 3, "only the snapshots every seed took");
        assert_eq!((avg.points[0].seconds, avg.points[0].spp), (2.0, 1));
        assert!((avg.points[0].rmse - (0.125f64).sqrt()).abs() < 1e-12, "root mean square of 0.4 and 0.3");
        assert!((avg.stability - 1.5).abs() < 1e-12, "the worst seed's figure");
        assert_eq!(avg.nan_samples, 2);
        // A seed whose long pass went past moment 1 answers it with the snapshot taken after
        // that pass (at or past moment 1's time): moments stay aligned, whatever each seed
        // skipped; a moment no seed took a snapshot for is left out.
        // Seed a's first pass ran to 2.5 s, past moments 0 and 1: one snapshot for both.
        let a = vec![Point { through: 1, ..p(2.5, 1, 0.3) }, p(4.0, 4, 0.1)];
        let b = vec![p(1.0, 1, 0.4), p(2.0, 2, 0.2), p(4.0, 4, 0.1)];
        let avg = average(vec![curve(a), curve(b)]);
        let moments: Vec<(u32, f64)> = avg.points.iter().map(|q| (q.moment, q.seconds)).collect();
        assert_eq!(moments, [(0, 1.75), (1, 2.25), (2, 4.0)], "a's one snapshot beside each of b's");
        let both = average(vec![
            curve(vec![p(1.0, 1, 0.4), Point { through: 2, ..p(2.5, 2, 0.25) }]),
            curve(vec![p(1.0, 1, 0.4), Point { through: 2, ..p(2.0, 2, 0.2) }]),
        ]);
        assert_eq!(both.points.iter().map(|q| q.moment).collect::<Vec<_>>(), [0, 1], "neither took one for moment 2");
        assert!(check(
            &Options { seeds: 0, ..opts(vec![Integrator::Pt], Schedule::Spp(vec![1])) },
            &Camera::cornell_box(),
            &RgbImage::new(256, 256)
        )
        .unwrap_err()
        .to_string()
        .contains("--seeds"));
    }
}
