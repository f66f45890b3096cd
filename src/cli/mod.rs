//! Command-line parsing and the subcommands.

mod bench;
mod chart;
mod converge;
mod diff;
mod info;
mod info_kernels;
mod info_scene;
mod merge;
mod part_args;
mod render;
mod render_devices;
pub mod scene_args;
mod settings_args;
pub mod signals;
mod view;

use clap::{Parser, Subcommand};

#[derive(Parser, Debug)]
#[command(name = "bidir", version, about = "Bidirectional path tracing on the GPU through Vulkan compute")]
pub struct Cli {
    /// Vulkan device: an index from `bidir info` or a substring of its name
    /// (default: discrete > integrated > CPU). Also BIDIR_DEVICE. `bidir render` also takes
    /// `all` or a comma-separated list (e.g. 0,1) and renders on every one at once.
    #[arg(long, global = true)]
    pub device: Option<String>,
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// List Vulkan devices (subgroup size and operations, memory) and which one bidir picks;
    /// with a scene file (or --builtin), report on the scene instead (no GPU needed); with an
    /// EXR written by bidir, print its render metadata.
    Info(info::InfoArgs),
    /// Render a scene (default: the built-in Cornell box) to EXR/PNG.
    Render(Box<render::RenderArgs>),
    /// Show the progressive render in a window: drag to look, WASD/QE to move, scroll for
    /// speed, F frame, R reset, 1/2/3 pt/pt-nee/bdpt, +/- exposure, P screenshot, Esc quit.
    View(Box<view::ViewArgs>),
    /// Merge parts of one render (sample ranges, crop windows) into the image one render of
    /// their union makes.
    Merge(merge::MergeArgs),
    /// Compare two EXR images: RMSE, relMSE, mean ratio, heatmap.
    Diff(diff::DiffArgs),
    /// Benchmarks with GPU timestamps (warm-up, repetitions, median).
    #[command(subcommand)]
    Bench(bench::BenchCommand),
    /// Speed against accuracy: RMSE vs a reference over render time, per integrator (CSV, charts).
    Converge(Box<converge::ConvergeArgs>),
    /// Redraw the RMSE chart of `convergence.csv` files written by `bidir converge` (SVG or PNG).
    Chart(chart::ChartArgs),
}

/// Prints a loader's warnings to stderr.
fn print_warnings(warnings: &[String]) {
    for w in warnings {
        eprintln!("warning: {w}");
    }
}

pub fn run() -> anyhow::Result<()> {
    let cli = Cli::parse();
    let mut opts = bidir::vk::ContextOptions::from_env();
    print_warnings(&opts.env_warnings);
    if cli.device.is_some() {
        opts.device = cli.device.clone();
    }
    match cli.command {
        Command::Info(args) => info::run(&args, &opts),
        Command::Render(args) => render::run(&args, &opts),
        Command::View(args) => view::run(&args, &opts),
        Command::Bench(cmd) => bench::run(&cmd, &opts),
        Command::Diff(args) => diff::run(&args),
        Command::Merge(args) => merge::run(&args),
        Command::Converge(args) => converge::run(&args, &opts),
        Command::Chart(args) => chart::run(&args),
    }
}
