//! Command-line parsing and the subcommands.

mod info;
mod info_scene;
pub mod scene_args;

use clap::{Parser, Subcommand};

#[derive(Parser, Debug)]
#[command(name = "bidir", version, about = "Bidirectional path tracing on the GPU through Vulkan compute")]
pub struct Cli {
    /// Vulkan device: an index from `bidir info` or a substring of its name
    /// (default: discrete > integrated > CPU). Also BIDIR_DEVICE.
    #[arg(long, global = true)]
    pub device: Option<String>,
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// List Vulkan devices (subgroup size and operations, memory) and which one bidir picks;
    /// with a scene file (or --builtin), report on the scene instead (no GPU needed).
    Info(info::InfoArgs),
}

pub fn run() -> anyhow::Result<()> {
    let cli = Cli::parse();
    let mut opts = bidir::vk::ContextOptions::from_env();
    if cli.device.is_some() {
        opts.device = cli.device.clone();
    }
    match cli.command {
        Command::Info(args) => info::run(&args, &opts),
    }
}
