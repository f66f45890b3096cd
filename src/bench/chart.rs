//! Charts for convergence runs, drawn with `plotters`: a log-log line chart (SVG and PNG) and
//! a labelled side-by-side strip of images (PNG).
//!
//! Text needs glyphs. plotters' default `ttf` feature finds system fonts through fontconfig
//! and freetype (C libraries the build machine and every user would need, and the chosen
//! font would differ from machine to machine). bidir instead enables `ab_glyph`, a pure-Rust
//! rasteriser, and embeds one small font (Noto Mono, SIL Open Font License,
//! `assets/fonts/`): no system library, the same pixels everywhere, 108 KB in the binary.
//! The SVG names the font family `sans-serif`; viewers use their own, the layout is
//! measured with Noto Mono (wider, so labels never overlap).

use plotters::coord::combinators::{BindKeyPoints, LogCoord, WithKeyPoints};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::FontStyle;

/// Noto Mono Regular; its licence is `assets/fonts/OFL.txt`.
const FONT: &[u8] = include_bytes!("../../assets/fonts/NotoMono-Regular.ttf");

/// Registers the embedded font under the family every text style here uses, once.
fn register_font() -> Result<(), String> {
    static DONE: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    let ok = *DONE.get_or_init(|| plotters::style::register_font("sans-serif", FontStyle::Normal, FONT).is_ok());
    if ok {
        Ok(())
    } else {
        Err("the embedded font does not parse".into())
    }
}

/// One line of the chart: a name and its (x, y) points, x ascending.
#[derive(Debug)]
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
}

/// Titles of a line chart.
pub struct ChartText {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
}

/// Chart size in pixels (PNG) and user units (SVG).
pub const CHART_SIZE: (u32, u32) = (960, 640);

/// Distinct colours (dark enough on white), reused in order.
const COLOURS: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
    RGBColor(140, 86, 75),
    RGBColor(127, 127, 127),
];

/// A log-log chart as an SVG document.
pub fn log_log_svg(series: &[Series], text: &ChartText) -> Result<String, String> {
    register_font()?;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, CHART_SIZE).into_drawing_area();
        draw_log_log(&root, series, text).map_err(|e| e.to_string())?;
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(svg)
}

/// A log-log chart as 8-bit RGB pixels of [`CHART_SIZE`].
pub fn log_log_rgb(series: &[Series], text: &ChartText) -> Result<Vec<u8>, String> {
    register_font()?;
    let (w, h) = CHART_SIZE;
    let mut rgb = vec![255u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, (w, h)).into_drawing_area();
        draw_log_log(&root, series, text).map_err(|e| e.to_string())?;
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(rgb)
}

/// Axis ranges: every positive point, widened by a quarter of a decade-ish margin (x 1.25,
/// so end points do not sit on the frame). Non-positive values cannot be drawn on a log axis.
fn log_range(values: impl Iterator<Item = f64>) -> std::ops::Range<f64> {
    let (lo, hi) = values.filter(|v| v.is_finite() && *v > 0.0).fold((f64::INFINITY, 0.0f64), |(lo, hi), v| (lo.min(v), hi.max(v)));
    if lo > hi {
        return 0.1..1.0;
    }
    let (lo, hi) = if hi / lo < 2.0 { (lo / 1.5, hi * 1.5) } else { (lo / 1.25, hi * 1.25) };
    lo..hi
}

/// Tick values on a log axis over `range`: labelled ones (1, 2, 5 times powers of ten, or
/// 1..9 times them where that would give fewer than three) and grid-only ones (1..9 times
/// powers of ten). plotters' own log ticks start at the first power of ten inside the range,
/// so a range like 0.025..0.85 would get a single label.
fn log_ticks(range: &std::ops::Range<f64>) -> (Vec<f64>, Vec<f64>) {
    let within = |mantissas: &[f64]| -> Vec<f64> {
        let (k0, k1) = (range.start.log10().floor() as i32, range.end.log10().ceil() as i32);
        (k0..=k1).flat_map(|k| mantissas.iter().map(move |m| m * 10f64.powi(k))).filter(|v| range.contains(v)).collect()
    };
    let all: Vec<f64> = (1..=9).map(f64::from).collect();
    let bold = within(&[1.0, 2.0, 5.0]);
    let bold = if bold.len() < 3 { within(&all) } else { bold };
    (bold, within(&all))
}

/// Tick labels with three significant digits at most, without trailing zeros.
fn tick(v: &f64) -> String {
    if *v <= 0.0 || !v.is_finite() {
        return String::new();
    }
    let decimals = (2 - v.log10().floor() as i32).max(0) as usize;
    let s = format!("{v:.decimals$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        s
    }
}

fn log_axis(range: std::ops::Range<f64>) -> WithKeyPoints<LogCoord<f64>> {
    let (bold, light) = log_ticks(&range);
    range.log_scale().with_key_points(bold).with_light_points(light)
}

fn draw_log_log<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    series: &[Series],
    text: &ChartText,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    root.fill(&WHITE)?;
    let xs = log_range(series.iter().flat_map(|s| s.points.iter().map(|p| p.0)));
    let ys = log_range(series.iter().flat_map(|s| s.points.iter().map(|p| p.1)));
    let mut chart = ChartBuilder::on(root)
        .caption(&text.title, ("sans-serif", 20))
        .margin(16)
        .x_label_area_size(48)
        .y_label_area_size(72)
        .build_cartesian_2d(log_axis(xs), log_axis(ys))?;
    chart
        .configure_mesh()
        .x_desc(text.x_label.as_str())
        .y_desc(text.y_label.as_str())
        .x_label_formatter(&tick)
        .y_label_formatter(&tick)
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 16))
        .light_line_style(RGBColor(238, 238, 238))
        .bold_line_style(RGBColor(190, 190, 190))
        .draw()?;
    for (i, s) in series.iter().enumerate() {
        let colour = COLOURS[i % COLOURS.len()];
        let points: Vec<(f64, f64)> = s.points.iter().copied().filter(|(x, y)| *x > 0.0 && *y > 0.0).collect();
        chart
            .draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))?
            .label(s.name.as_str())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], colour.stroke_width(2)));
        chart.draw_series(points.into_iter().map(|p| Circle::new(p, 3, colour.filled())))?;
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .label_font(("sans-serif", 15))
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .draw()?;
    Ok(())
}

/// One image of a side-by-side strip and the lines of text above it.
pub struct Panel<'a> {
    pub lines: Vec<String>,
    /// 8-bit sRGB pixels, rows top to bottom.
    pub rgb: &'a [u8],
    pub width: u32,
    pub height: u32,
}

const GAP: u32 = 6;
const LINE_HEIGHT: u32 = 18;

/// The panels in a row on a dark background, each under its text; returns the pixels and
/// their size. Panels may differ in size.
pub fn side_by_side(panels: &[Panel]) -> Result<(Vec<u8>, u32, u32), String> {
    register_font()?;
    let lines = panels.iter().map(|p| p.lines.len()).max().unwrap_or(0) as u32;
    let header = lines * LINE_HEIGHT + GAP;
    let w = GAP + panels.iter().map(|p| p.width + GAP).sum::<u32>();
    let h = header + panels.iter().map(|p| p.height).max().unwrap_or(0) + GAP;
    let mut rgb = [40u8, 40, 40].repeat((w * h) as usize);
    let mut x0 = GAP;
    for p in panels {
        if p.rgb.len() != (p.width * p.height * 3) as usize {
            return Err(format!("a panel of {}x{} has {} bytes", p.width, p.height, p.rgb.len()));
        }
        for y in 0..p.height {
            let src = &p.rgb[(y * p.width * 3) as usize..((y + 1) * p.width * 3) as usize];
            let dst = (((header + y) * w + x0) * 3) as usize;
            rgb[dst..dst + src.len()].copy_from_slice(src);
        }
        x0 += p.width + GAP;
    }
    {
        let root = BitMapBackend::with_buffer(&mut rgb, (w, h)).into_drawing_area();
        let style = TextStyle::from(("sans-serif", 14)).color(&WHITE);
        let mut x0 = GAP as i32;
        for p in panels {
            for (i, line) in p.lines.iter().enumerate() {
                root.draw_text(line, &style, (x0, GAP as i32 / 2 + (i as u32 * LINE_HEIGHT) as i32)).map_err(|e| e.to_string())?;
            }
            x0 += (p.width + GAP) as i32;
        }
        root.present().map_err(|e| e.to_string())?;
    }
    Ok((rgb, w, h))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn demo() -> (Vec<Series>, ChartText) {
        let series = vec![
            Series { name: "pt".into(), points: vec![(0.1, 0.2), (1.0, 0.07), (10.0, 0.02)] },
            Series { name: "bdpt:full".into(), points: vec![(0.12, 0.1), (1.1, 0.03), (9.0, 0.01)] },
        ];
        let text = ChartText { title: "demo".into(), x_label: "render time [s]".into(), y_label: "RMSE".into() };
        (series, text)
    }

    #[test]
    fn ticks_read_well() {
        let t = |v: f64| tick(&v);
        assert_eq!([t(0.001), t(0.02), t(0.5), t(1.0), t(20.0), t(100.0), t(0.0456)], ["0.001", "0.02", "0.5", "1", "20", "100", "0.0456"]);
    }

    #[test]
    fn log_ticks_label_every_decade_part() {
        let (bold, light) = log_ticks(&(0.025..0.85));
        let r = |v: &[f64]| v.iter().map(|x| (x * 1e6).round() / 1e6).collect::<Vec<_>>();
        assert_eq!(r(&bold), [0.05, 0.1, 0.2, 0.5]);
        assert_eq!(light.len(), 7 + 8);
        let (bold, _) = log_ticks(&(0.5..1.5));
        assert_eq!(r(&bold), [0.5, 0.6, 0.7, 0.8, 0.9, 1.0]);
    }

    #[test]
    fn ranges_cover_every_positive_point() {
        let r = log_range([0.5, 0.0, 20.0, f64::NAN].into_iter());
        assert!(r.start < 0.5 && r.end > 20.0 && r.start > 0.0);
        assert_eq!(log_range(std::iter::empty()), 0.1..1.0);
    }

    #[test]
    fn svg_has_titles_legend_and_lines() {
        let (series, text) = demo();
        let svg = log_log_svg(&series, &text).unwrap();
        for s in ["demo", "render time [s]", "RMSE", "pt", "bdpt:full", "<polyline", "<circle"] {
            assert!(svg.contains(s), "SVG lacks {s}");
        }
    }

    #[test]
    fn png_pixels_hold_lines_in_both_colours_and_text() {
        let (series, text) = demo();
        let rgb = log_log_rgb(&series, &text).unwrap();
        let count = |c: RGBColor| rgb.chunks_exact(3).filter(|p| p == &[c.0, c.1, c.2]).count();
        assert!(count(COLOURS[0]) > 200 && count(COLOURS[1]) > 200, "{} {}", count(COLOURS[0]), count(COLOURS[1]));
        // Text is anti-aliased black on white: grey levels between the two appear only if
        // glyphs were drawn (the grid's greys are the two mesh colours).
        let grey = rgb.chunks_exact(3).filter(|p| p[0] == p[1] && p[1] == p[2] && (30..180).contains(&p[0])).count();
        assert!(grey > 500, "only {grey} grey text pixels");
    }

    #[test]
    fn side_by_side_places_panels_under_their_labels() {
        let red = [200u8, 0, 0].repeat(16 * 8);
        let blue = [0u8, 0, 200].repeat(10 * 12);
        let panels = [
            Panel { lines: vec!["red".into()], rgb: &red, width: 16, height: 8 },
            Panel { lines: vec!["blue".into(), "second".into()], rgb: &blue, width: 10, height: 12 },
        ];
        let (rgb, w, h) = side_by_side(&panels).unwrap();
        assert_eq!((w, h), (GAP + 16 + GAP + 10 + GAP, 2 * LINE_HEIGHT + GAP + 12 + GAP));
        let at = |x: u32, y: u32| &rgb[((y * w + x) * 3) as usize..((y * w + x) * 3 + 3) as usize];
        let header = 2 * LINE_HEIGHT + GAP;
        assert_eq!(at(GAP, header), [200, 0, 0]);
        assert_eq!(at(GAP + 15, header + 7), [200, 0, 0]);
        assert_eq!(at(GAP + 16 + GAP, header + 11), [0, 0, 200]);
        assert_eq!(at(0, 0), [40, 40, 40]);
        let bad = [Panel { lines: vec![], rgb: &red[..5], width: 16, height: 8 }];
        assert!(side_by_side(&bad).is_err());
    }
}
