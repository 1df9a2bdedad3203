//! Closed-loop runs of paper 001's drive (`models::mpdcc::closed_loop`) and
//! the parameter file they start from.
use anyhow::{anyhow, Context, Result};
use models::mpdcc::closed_loop::{self, LoopConfig, LoopResult, TraceSample};
use models::mpdcc::controller::Controller;
use models::mpdcc::mpdcc_fixed::{FpgaConfig, MpdccFixed};
use models::mpdcc::params::DriveParams;
use std::path::Path;

/// Loads and validates the parameter file (defaults when absent). Errors
/// name the file and, for invalid values, the field.
pub fn load_params(path: Option<&Path>) -> Result<DriveParams> {
    let Some(f) = path else {
        let p = DriveParams::default();
        p.validate()
            .map_err(|e| anyhow!("built-in parameters: {e}"))?;
        return Ok(p);
    };
    let text = std::fs::read_to_string(f).with_context(|| format!("reading {}", f.display()))?;
    let p =
        toml::from_str::<DriveParams>(&text).with_context(|| format!("parsing {}", f.display()))?;
    p.validate().map_err(|e| anyhow!("{}: {e}", f.display()))?;
    Ok(p)
}

/// The bit-exact FPGA model with the Taylor correction factor `p`.
pub fn fpga_for(p: &DriveParams) -> Result<MpdccFixed> {
    MpdccFixed::new(
        p,
        FpgaConfig::with_p(models::mpdcc::mpdcc_fixed::p_taylor(&p.machine)),
    )
    .map_err(|e| anyhow!("FPGA model: {e}"))
}

/// One closed-loop run; errors name the implementation.
pub fn run_loop(
    p: &DriveParams,
    cfg: &LoopConfig,
    ctrl: &mut dyn Controller,
    shadow: Option<&mut dyn Controller>,
    trace: &mut dyn FnMut(&TraceSample),
) -> Result<LoopResult> {
    closed_loop::run(p, cfg, ctrl, shadow, trace)
        .map_err(|e| anyhow!("{} closed loop: {e}", ctrl.name()))
}

/// A kept waveform: (`delta_i` in pu, its samples).
pub type Trace = (f64, Vec<TraceSample>);
