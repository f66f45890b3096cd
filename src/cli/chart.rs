//! `bidir chart`: redraws the RMSE chart of one or more `convergence.csv` files written by
//! `bidir converge` (e.g. runs made on another machine, or several runs side by side).

use anyhow::{bail, Context as _};
use bidir::bench::chart::{self, ChartText, Series};
use std::path::{Path, PathBuf};

#[derive(clap::Args, Debug)]
pub struct ChartArgs {
    /// `convergence.csv` files of `bidir converge` (columns integrator, seconds, spp, rmse, ...).
    #[arg(required = true)]
    pub csv: Vec<PathBuf>,
    /// Output chart: .svg or .png.
    #[arg(short, long)]
    pub output: PathBuf,
    /// Chart title [default: RMSE against render time, or against samples per pixel].
    #[arg(long)]
    pub title: Option<String>,
    /// Horizontal axis: seconds | spp.
    #[arg(long, default_value = "seconds", value_name = "seconds|spp")]
    pub x: String,
}

/// The series of one CSV file, in file order; `prefix` names the file where several are drawn.
fn read_series(path: &Path, by_spp: bool, prefix: Option<&str>) -> anyhow::Result<Vec<Series>> {
    let text = std::fs::read_to_string(path).with_context(|| format!("cannot read {}", path.display()))?;
    let mut lines = text.lines().enumerate();
    let header: Vec<&str> = lines.next().map(|(_, l)| l.split(',').map(str::trim).collect()).unwrap_or_default();
    let col = |name: &str| header.iter().position(|h| *h == name);
    let (Some(ci), Some(cs), Some(cn), Some(cr)) = (col("integrator"), col("seconds"), col("spp"), col("rmse")) else {
        bail!("{}:1: not a convergence.csv of `bidir converge` (needs the columns integrator, seconds, spp, rmse)", path.display());
    };
    let mut series: Vec<Series> = Vec::new();
    for (i, line) in lines {
        if line.trim().is_empty() {
            continue;
        }
        let f: Vec<&str> = line.split(',').map(str::trim).collect();
        let num = |c: usize, what: &str| -> anyhow::Result<f64> {
            match f.get(c).and_then(|v| v.parse::<f64>().ok()) {
                Some(v) if v.is_finite() && v > 0.0 => Ok(v),
                _ => bail!("{}:{}: the {what} column is not a positive number", path.display(), i + 1),
            }
        };
        let x = if by_spp { num(cn, "spp")? } else { num(cs, "seconds")? };
        let y = num(cr, "rmse")?;
        let name = match prefix {
            Some(p) => format!("{p}: {}", f[ci]),
            None => f[ci].to_string(),
        };
        match series.iter_mut().find(|s| s.name == name) {
            Some(s) => s.points.push((x, y)),
            None => series.push(Series { name, points: vec![(x, y)] }),
        }
    }
    if series.is_empty() {
        bail!("{}: no data rows", path.display());
    }
    for s in &mut series {
        s.points.sort_by(|a, b| a.0.total_cmp(&b.0));
    }
    Ok(series)
}

/// A short, distinct name per CSV for the legend: the run's folder for a `convergence.csv`
/// (`converge --out DIR`), else the file's stem; the whole path where those repeat.
fn run_names(paths: &[PathBuf]) -> Vec<String> {
    let short = |p: &PathBuf| -> Option<String> {
        let name = if p.file_name()? == "convergence.csv" { p.parent()?.file_name()? } else { p.file_stem()? };
        Some(name.to_string_lossy().into_owned())
    };
    let names: Vec<String> = paths.iter().map(|p| short(p).unwrap_or_else(|| p.display().to_string())).collect();
    let distinct = names.iter().collect::<std::collections::HashSet<_>>().len() == names.len();
    if distinct {
        names
    } else {
        paths.iter().map(|p| p.display().to_string()).collect()
    }
}

pub fn run(args: &ChartArgs) -> anyhow::Result<()> {
    let by_spp = match args.x.as_str() {
        "seconds" => false,
        "spp" => true,
        other => bail!("--x {other}: seconds | spp"),
    };
    let ext = args.output.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    if !matches!(ext.as_deref(), Some("svg") | Some("png")) {
        bail!("{}: the chart is written as .svg or .png", args.output.display());
    }
    let names = run_names(&args.csv);
    let mut series = Vec::new();
    for (path, name) in args.csv.iter().zip(&names) {
        let prefix = if args.csv.len() > 1 { Some(name.as_str()) } else { None };
        series.extend(read_series(path, by_spp, prefix)?);
    }
    let x_label = if by_spp { "samples per pixel" } else { "render time [s] (sum of pass times)" };
    let title = args.title.clone().unwrap_or_else(|| format!("RMSE against {}", if by_spp { "samples per pixel" } else { "render time" }));
    let text = ChartText { title, x_label: x_label.into(), y_label: "RMSE vs reference".into() };
    let out = &args.output;
    if ext.as_deref() == Some("svg") {
        let svg = chart::log_log_svg(&series, &text).map_err(anyhow::Error::msg)?;
        bidir::imaging::write_atomically(out, |tmp| std::fs::write(tmp, &svg).map_err(|e| e.to_string()))?;
    } else {
        let rgb = chart::log_log_rgb(&series, &text).map_err(anyhow::Error::msg)?;
        let (w, h) = chart::CHART_SIZE;
        bidir::imaging::write_atomically(out, |tmp| bidir::imaging::write_png_rgb8(tmp, &rgb, w, h))?;
    }
    println!("wrote {}", out.display());
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn csv(name: &str, text: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("bidir-chart-{}-{name}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("convergence.csv");
        std::fs::write(&path, text).unwrap();
        path
    }

    #[test]
    fn reads_series_per_integrator_in_x_order() {
        let p = csv("ok", "integrator,seconds,spp,rmse,relmse\nbdpt,0.5,20,0.02,0.1\npt-nee,0.1,10,0.05,0.2\nbdpt,0.1,4,0.04,0.1\n");
        let s = read_series(&p, false, None).unwrap();
        assert_eq!(s.len(), 2);
        assert_eq!(s[0].name, "bdpt");
        assert_eq!(s[0].points, vec![(0.1, 0.04), (0.5, 0.02)]);
        let s = read_series(&p, true, Some("run")).unwrap();
        assert_eq!(s[1].name, "run: pt-nee");
        assert_eq!(s[1].points, vec![(10.0, 0.05)]);
    }

    #[test]
    fn names_runs_apart() {
        let p = |s: &str| PathBuf::from(s);
        assert_eq!(run_names(&[p("a/run1/convergence.csv"), p("b/run2/convergence.csv")]), ["run1", "run2"]);
        assert_eq!(run_names(&[p("r/vcm-sds.csv"), p("r/vcm-cornell.csv")]), ["vcm-sds", "vcm-cornell"]);
        assert_eq!(run_names(&[p("a/x/convergence.csv"), p("b/x/convergence.csv")]), ["a/x/convergence.csv", "b/x/convergence.csv"]);
    }

    #[test]
    fn names_the_file_and_line_of_a_bad_row() {
        let p = csv("bad", "integrator,seconds,spp,rmse\npt,0.1,1,0.5\npt,0.2,2,nan\n");
        let e = read_series(&p, false, None).unwrap_err().to_string();
        assert!(e.ends_with("convergence.csv:3: the rmse column is not a positive number"), "{e}");
        let p = csv("header", "a,b\n1,2\n");
        let e = read_series(&p, false, None).unwrap_err().to_string();
        assert!(e.contains("convergence.csv:1: not a convergence.csv"), "{e}");
    }
}
