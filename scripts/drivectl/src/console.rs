//! Placeholder.
use anyhow::{bail, Result};

#[derive(clap::Args)]
pub struct ConsoleArgs {}
#[derive(clap::Args)]
pub struct SendArgs {}
#[derive(clap::Args)]
pub struct LogArgs {}

pub fn console(_a: ConsoleArgs) -> Result<()> {
    bail!("not implemented yet")
}
pub fn send(_a: SendArgs) -> Result<()> {
    bail!("not implemented yet")
}
pub fn log(_a: LogArgs) -> Result<()> {
    bail!("not implemented yet")
}
