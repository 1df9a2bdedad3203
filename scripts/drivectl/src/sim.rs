//! Placeholder: filled in by its issue.
use anyhow::{bail, Result};

#[derive(clap::Args)]
pub struct ReplayArgs {}

pub fn replay(_a: ReplayArgs) -> Result<()> {
    bail!("not implemented yet")
}
