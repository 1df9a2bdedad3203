//! Placeholder: filled in by its issue.
use anyhow::{bail, Result};

#[derive(clap::Args)]
pub struct Args {
    /// Print one JSON object instead of tables.
    #[arg(long)]
    pub json: bool,
    /// Directory for CSV files and plots.
    #[arg(long)]
    pub out: Option<std::path::PathBuf>,
}

#[derive(clap::Args)]
pub struct BenchArgs {}

pub fn run(_a: Args) -> Result<()> {
    bail!("not implemented yet")
}

pub fn bench(_a: BenchArgs) -> Result<()> {
    bail!("not implemented yet")
}
