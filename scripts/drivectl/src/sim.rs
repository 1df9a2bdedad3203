//! `drivectl sim replay`: applies a sequence of switching states to the PMSM
//! plant (`models::pmsm::plant`), open loop, at constant electrical speed, from
//! zero current and angle 0, and writes the currents and torque per period.
//!
//! Formats (documented in `docs/pmsm-models.md`):
//! - `--motor` TOML, flat keys, all required except `dead_time_s`:
//!   `r_s_ohm`, `l_d_h`, `l_q_h` (must equal `l_d_h`: surface PMSM),
//!   `psi_pm_wb`, `pole_pairs`, `u_dc_v`, `omega_e_rad_s`, `period_s`,
//!   `dead_time_s` (default 0). Unknown keys are errors.
//! - `--switching` CSV with a header row containing `switch_state_abc`
//!   (other columns ignored); one row per control period; the value is three
//!   characters `SaSbSc` of `0`/`1` (e.g. `101`), optionally in double quotes.
//! - `--out` CSV `step,switch_state_abc,i_d,i_q,torque` (A, A, N m); row k
//!   holds the state applied during period k and the values at its end.
//!
//! All input is read and checked before anything is written; the output is
//! written to a temporary file next to `--out` and renamed into place.
use anyhow::{anyhow, bail, Context, Result};
use models::pmsm::frames::{parse_state_bits, state_bits};
use models::pmsm::params::MotorParams;
use models::pmsm::plant::{Actuation, MechanicalMode, Plant};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct ReplayArgs {
    /// Plant parameters (TOML; keys in docs/pmsm-models.md).
    #[arg(long)]
    pub motor: PathBuf,
    /// Switching states (CSV with a `switch_state_abc` column, one row per period).
    #[arg(long)]
    pub switching: PathBuf,
    /// Output CSV (`step,switch_state_abc,i_d,i_q,torque`).
    #[arg(long)]
    pub out: PathBuf,
}

/// The `--motor` file of `sim replay`.
#[derive(Debug, Clone, Copy, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ReplayConfig {
    /// Stator resistance per phase, ohm.
    pub r_s_ohm: f64,
    /// d-axis inductance, H.
    pub l_d_h: f64,
    /// q-axis inductance, H (must equal `l_d_h`).
    pub l_q_h: f64,
    /// PM flux linkage, Wb.
    pub psi_pm_wb: f64,
    /// Pole pairs.
    pub pole_pairs: u32,
    /// DC-link voltage, V.
    pub u_dc_v: f64,
    /// Constant electrical speed, rad/s.
    pub omega_e_rad_s: f64,
    /// Control period (duration of one CSV row), s.
    pub period_s: f64,
    /// Inverter dead time, s (optional, default 0).
    #[serde(default)]
    pub dead_time_s: f64,
}

/// One output row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReplayRow {
    /// Switch state applied during the period.
    pub state: u8,
    /// d-axis current at the end of the period, A.
    pub i_d_a: f64,
    /// q-axis current at the end of the period, A.
    pub i_q_a: f64,
    /// Torque at the end of the period, N m.
    pub torque_nm: f64,
}

/// 1-based line of the first `key = ...` assignment in a TOML text.
fn toml_key_line(text: &str, key: &str) -> Option<usize> {
    text.lines()
        .position(|l| {
            let l = l.trim_start();
            l.strip_prefix(key)
                .is_some_and(|r| r.trim_start().starts_with('='))
        })
        .map(|i| i + 1)
}

/// Parses and validates the `--motor` TOML text. Errors name the key and, when
/// it can be located, its line.
pub fn parse_config(text: &str) -> Result<ReplayConfig> {
    let c: ReplayConfig = toml::from_str(text).map_err(|e| anyhow!("{e}"))?;
    let m = motor_of(&c);
    let check = || -> std::result::Result<(), models::pmsm::params::ParamError> {
        m.validate()?;
        // Plant::new checks L_d = L_q, dead time and speed.
        Plant::new(
            &m,
            c.dead_time_s,
            MechanicalMode::ConstantSpeed,
            c.omega_e_rad_s,
        )?;
        if !(c.period_s.is_finite() && c.period_s > 0.0) {
            return Err(models::pmsm::params::ParamError {
                field: "period_s",
                reason: "must be finite and > 0",
            });
        }
        if c.dead_time_s >= 0.5 * c.period_s {
            return Err(models::pmsm::params::ParamError {
                field: "dead_time_s",
                reason: "must be below half the period",
            });
        }
        Ok(())
    };
    check().map_err(|e| match toml_key_line(text, e.field) {
        Some(line) => anyhow!("line {line}: {e}"),
        None => anyhow!("{e}"),
    })?;
    Ok(c)
}

fn motor_of(c: &ReplayConfig) -> MotorParams {
    MotorParams {
        r_s_ohm: c.r_s_ohm,
        l_d_h: c.l_d_h,
        l_q_h: c.l_q_h,
        pole_pairs: c.pole_pairs,
        psi_pm_wb: c.psi_pm_wb,
        u_dc_v: c.u_dc_v,
        ..MotorParams::default()
    }
}

/// Parses the `--switching` CSV text into switch states. Errors carry the
/// 1-based line number.
pub fn parse_states(text: &str) -> Result<Vec<u8>> {
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty());
    let (hline, header) = lines
        .next()
        .ok_or_else(|| anyhow!("empty switching file"))?;
    // A UTF-8 byte order mark (spreadsheet exports) is not part of the header.
    let header = header.trim_start_matches('\u{feff}');
    let unquote = |s: &str| s.trim().trim_matches('"').trim().to_string();
    let cols: Vec<String> = header.split(',').map(unquote).collect();
    let col = cols
        .iter()
        .position(|c| c == "switch_state_abc")
        .ok_or_else(|| {
            anyhow!(
                "line {}: no column `switch_state_abc` in header {:?}",
                hline + 1,
                header.trim()
            )
        })?;
    let mut out = Vec::new();
    for (i, l) in lines {
        let fields: Vec<&str> = l.split(',').collect();
        let v = fields.get(col).map(|s| unquote(s)).ok_or_else(|| {
            anyhow!(
                "line {}: row has {} columns, `switch_state_abc` is column {}",
                i + 1,
                fields.len(),
                col + 1
            )
        })?;
        let s = parse_state_bits(&v).ok_or_else(|| {
            anyhow!(
                "line {}: bad switch state {v:?}: expected three characters 0/1 (SaSbSc), e.g. 101 \
                 (a spreadsheet may have dropped leading zeros)",
                i + 1
            )
        })?;
        out.push(s);
    }
    if out.is_empty() {
        bail!("no switching states after the header");
    }
    Ok(out)
}

/// Runs the replay: the plant at constant speed from rest (i = 0, angle 0),
/// each state held for one period. `bench pmsm` times this function.
pub fn simulate(c: &ReplayConfig, states: &[u8]) -> Result<Vec<ReplayRow>> {
    let m = motor_of(c);
    let mut plant = Plant::new(
        &m,
        c.dead_time_s,
        MechanicalMode::ConstantSpeed,
        c.omega_e_rad_s,
    )
    .map_err(|e| anyhow!("{e}"))?;
    let mut rows = Vec::with_capacity(states.len());
    for &s in states {
        plant
            .step(&Actuation::SwitchState(s), c.period_s, 1, |_| {})
            .map_err(|e| anyhow!("{e}"))?;
        let (i_d_a, i_q_a) = plant.i_dq_a();
        if !(i_d_a.is_finite() && i_q_a.is_finite()) {
            bail!(
                "step {}: the currents are not finite numbers (parameters out of any \
                 physical range, e.g. omega_e_rad_s = {} or u_dc_v = {}); nothing written",
                rows.len(),
                c.omega_e_rad_s,
                c.u_dc_v
            );
        }
        rows.push(ReplayRow {
            state: s,
            i_d_a,
            i_q_a,
            torque_nm: m.torque_nm(i_d_a, i_q_a),
        });
    }
    Ok(rows)
}

/// Formats the output CSV (shortest round-trip decimal representation).
pub fn format_rows(rows: &[ReplayRow]) -> String {
    let mut s = String::from("step,switch_state_abc,i_d,i_q,torque\n");
    for (k, r) in rows.iter().enumerate() {
        let b = state_bits(r.state);
        s.push_str(&format!(
            "{k},{},{},{},{}\n",
            std::str::from_utf8(&b).unwrap_or("???"),
            r.i_d_a,
            r.i_q_a,
            r.torque_nm
        ));
    }
    s
}

pub fn replay(a: ReplayArgs) -> Result<()> {
    let mtext = std::fs::read_to_string(&a.motor)
        .with_context(|| format!("reading {}", a.motor.display()))?;
    let c = parse_config(&mtext).with_context(|| format!("in {}", a.motor.display()))?;
    let stext = std::fs::read_to_string(&a.switching)
        .with_context(|| format!("reading {}", a.switching.display()))?;
    let states = parse_states(&stext).with_context(|| format!("in {}", a.switching.display()))?;
    let rows = simulate(&c, &states)?;
    let text = format_rows(&rows);
    let mut tmp = a.out.clone().into_os_string();
    tmp.push(".tmp");
    let tmp = PathBuf::from(tmp);
    std::fs::write(&tmp, text).with_context(|| format!("writing {}", tmp.display()))?;
    std::fs::rename(&tmp, &a.out).with_context(|| format!("renaming to {}", a.out.display()))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    const CFG: &str = "r_s_ohm = 0.555\nl_d_h = 0.00064\nl_q_h = 0.00064\npsi_pm_wb = 0.0092879\n\
                       pole_pairs = 7\nu_dc_v = 48.0\nomega_e_rad_s = 500.0\nperiod_s = 1.5625e-5\n";

    #[test]
    fn config_errors_are_clear() {
        let c = parse_config(CFG).unwrap();
        assert_eq!(c.dead_time_s, 0.0);
        let nan = CFG.replace("u_dc_v = 48.0", "u_dc_v = nan");
        let e = format!("{:#}", parse_config(&nan).unwrap_err());
        assert!(e.contains("line 6") && e.contains("u_dc_v"), "{e}");
        let missing = CFG.replace("period_s = 1.5625e-5\n", "");
        let e = format!("{:#}", parse_config(&missing).unwrap_err());
        assert!(e.contains("period_s"), "{e}");
        let typo = CFG.replace("r_s_ohm", "r_ohm");
        let e = format!("{:#}", parse_config(&typo).unwrap_err());
        assert!(e.contains("r_ohm"), "{e}");
        let salient = CFG.replace("l_q_h = 0.00064", "l_q_h = 0.001");
        let e = format!("{:#}", parse_config(&salient).unwrap_err());
        assert!(e.contains("line 3") && e.contains("l_q_h"), "{e}");
        let bad_period = CFG.replace("period_s = 1.5625e-5", "period_s = -1.0");
        assert!(format!("{:#}", parse_config(&bad_period).unwrap_err()).contains("line 8"));
    }

    /// `MotorParams`/`SamplingParams` load from TOML (feature `std` of `models`):
    /// missing keys take the paper's defaults, unknown keys are rejected.
    #[test]
    fn library_params_load_from_toml() {
        use models::pmsm::params::SamplingParams;
        let m: MotorParams = toml::from_str("r_s_ohm = 0.6\npole_pairs = 4\n").unwrap();
        assert_eq!((m.r_s_ohm, m.pole_pairs), (0.6, 4));
        assert_eq!(m.l_d_h, MotorParams::default().l_d_h);
        assert!(toml::from_str::<MotorParams>("r_ohm = 0.6\n").is_err());
        let d: SamplingParams = toml::from_str("dead_time_s = 1e-7\n").unwrap();
        assert_eq!(d.adc_average_n, 4);
        d.validate().unwrap();
        let d: SamplingParams = toml::from_str("adc_average_n = 0\n").unwrap();
        assert_eq!(d.validate().unwrap_err().field, "adc_average_n");
    }

    #[test]
    fn csv_errors_carry_line_numbers() {
        assert_eq!(
            parse_states("t,switch_state_abc\n0,101\n1,\"000\"\n\n2,111\n").unwrap(),
            [5, 0, 7]
        );
        let e = parse_states("state\n101\n").unwrap_err().to_string();
        assert!(
            e.contains("line 1") && e.contains("switch_state_abc"),
            "{e}"
        );
        let e = parse_states("switch_state_abc\n101\n12\n")
            .unwrap_err()
            .to_string();
        assert!(e.contains("line 3") && e.contains("\"12\""), "{e}");
        let e = parse_states("switch_state_abc\n101\nNaN\n")
            .unwrap_err()
            .to_string();
        assert!(e.contains("line 3"), "{e}");
        let e = parse_states("a,switch_state_abc\n101\n")
            .unwrap_err()
            .to_string();
        assert!(e.contains("line 2"), "{e}");
        assert_eq!(
            parse_states("\u{feff}switch_state_abc\r\n011\r\n").unwrap(),
            [3]
        );
        assert!(parse_states("switch_state_abc\n").is_err());
        assert!(parse_states("").is_err());
    }

    #[test]
    fn rows_are_values_at_the_end_of_each_period() {
        // Standstill, state 100 for one period: i_d = u/R (1 - e^{-RT/L}), u = 32 V.
        let c = ReplayConfig {
            omega_e_rad_s: 0.0,
            ..parse_config(CFG).unwrap()
        };
        let huge = ReplayConfig {
            omega_e_rad_s: 1e300,
            ..parse_config(CFG).unwrap()
        };
        let e = simulate(&huge, &[0b100]).unwrap_err().to_string();
        assert!(e.contains("step 0") && e.contains("omega_e_rad_s"), "{e}");
        let rows = simulate(&c, &[0b100, 0b000]).unwrap();
        let want = 32.0 / 0.555 * (1.0 - (-0.555 * 1.5625e-5 / 0.00064f64).exp());
        assert!((rows[0].i_d_a - want).abs() < 1e-12);
        assert!(rows[0].i_q_a.abs() < 1e-12 && rows[0].torque_nm.abs() < 1e-12);
        let csv = format_rows(&rows);
        assert!(
            csv.starts_with("step,switch_state_abc,i_d,i_q,torque\n0,100,"),
            "{csv}"
        );
        assert!(csv.lines().nth(2).unwrap().starts_with("1,000,"));
    }
}
