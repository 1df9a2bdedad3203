//! `drivectl config pull|push`: the drive's configuration as a TOML file,
//! checked against the drive's own `config schema` before anything is sent.
//!
//! File format: one `name = value` per parameter (the table's units; a
//! comment line above each gives unit, range and description); integers
//! are written as TOML integers, the rest as floats. A push may hold a
//! subset of the parameters; unknown names, non-numbers, NaN, infinities,
//! fractions for integer parameters and values out of range are refused
//! with every error listed, and nothing is sent.
use crate::link::{Final, Session};
use anyhow::{anyhow, bail, Context as _, Result};
use serde::Deserialize;
use std::fmt::Write as _;
use std::time::Duration;

/// One parameter of `config schema`.
#[derive(Debug, Clone, Deserialize, PartialEq)]
pub struct ParamSchema {
    pub name: String,
    pub unit: String,
    pub min: f64,
    pub max: f64,
    pub default: f64,
    pub description: String,
    pub integer: bool,
    pub gates_off: bool,
}

/// Parses the JSON line of `config schema`.
pub fn parse_schema(line: &str) -> Result<Vec<ParamSchema>> {
    serde_json::from_str(line).context("`config schema` is not the expected JSON array")
}

/// The value of a `config list` / `config get` line `<name> = <value> <unit>...`.
pub fn parse_value_line(line: &str) -> Result<(String, f64)> {
    let (name, rest) = line
        .split_once(" = ")
        .ok_or_else(|| anyhow!("not a `name = value` line: {line:?}"))?;
    let v = rest
        .split_whitespace()
        .next()
        .and_then(|v| v.parse::<f64>().ok())
        .ok_or_else(|| anyhow!("no number in {line:?}"))?;
    Ok((name.to_string(), v))
}

/// The TOML text of `values` (in schema order).
pub fn to_toml(schema: &[ParamSchema], values: &[(String, f64)]) -> Result<String> {
    let mut out = String::from(
        "# Configuration of the predictive servo drive (`drivectl config pull`).\n\
         # Push it back with `drivectl config push FILE` (checked against `config schema`).\n",
    );
    for p in schema {
        let v = values
            .iter()
            .find(|(n, _)| *n == p.name)
            .map(|(_, v)| *v)
            .ok_or_else(|| anyhow!("the drive listed no value for {}", p.name))?;
        writeln!(
            out,
            "\n# {} [{}], range {}..{}, default {}{}",
            p.description,
            p.unit,
            p.min,
            p.max,
            p.default,
            if p.gates_off { "" } else { " (live)" }
        )?;
        if p.integer {
            writeln!(out, "{} = {}", p.name, v as i64)?;
        } else {
            // `{:?}` keeps a decimal point (a TOML float) and round-trips.
            writeln!(out, "{} = {:?}", p.name, v)?;
        }
    }
    Ok(out)
}

/// The values of a TOML file, checked against `schema`: every error is
/// listed, none is returned if any.
pub fn parse_toml(text: &str, schema: &[ParamSchema]) -> Result<Vec<(String, f64)>> {
    let table: toml::Table = text.parse().context("not a TOML file")?;
    let mut vals = Vec::new();
    let mut errs = Vec::new();
    for (name, v) in &table {
        let Some(p) = schema.iter().find(|p| p.name == *name) else {
            errs.push(format!("{name}: no such parameter"));
            continue;
        };
        let x = match v {
            toml::Value::Integer(i) => *i as f64,
            toml::Value::Float(f) => *f,
            other => {
                errs.push(format!(
                    "{name}: expected a number, got {}",
                    other.type_str()
                ));
                continue;
            }
        };
        if !x.is_finite() {
            errs.push(format!("{name}: {x} is not finite"));
        } else if p.integer && x.fract() != 0.0 {
            errs.push(format!("{name}: {x} is not a whole number"));
        } else if !(p.min..=p.max).contains(&x) {
            errs.push(format!(
                "{name}: {x} {} is out of range [{}..{}]",
                p.unit, p.min, p.max
            ));
        } else {
            vals.push((name.clone(), x));
        }
    }
    if !errs.is_empty() {
        bail!("{}", errs.join("; "));
    }
    // In the table's order.
    vals.sort_by_key(|(n, _)| schema.iter().position(|p| p.name == *n));
    Ok(vals)
}

fn ok_lines(s: &mut Session, line: &str, t: Duration) -> Result<Vec<String>> {
    let r = s.command(line, t)?;
    match r.fin {
        Final::Ok => Ok(r.lines),
        Final::Err { code, message } => bail!("`{line}`: ERR {code} {message}"),
    }
}

/// Parameter values by name, in the table's units.
pub type Values = Vec<(String, f64)>;

/// The drive's schema and present values.
pub fn pull(s: &mut Session, t: Duration) -> Result<(Vec<ParamSchema>, Values)> {
    let schema_line = ok_lines(s, "config schema", t)?;
    let schema = parse_schema(schema_line.first().map(String::as_str).unwrap_or(""))?;
    let values = ok_lines(s, "config list", t)?
        .iter()
        .map(|l| parse_value_line(l))
        .collect::<Result<Vec<_>>>()?;
    Ok((schema, values))
}

/// Sets `values` with `config set`, in passes until no more succeed (one
/// value may need another first, e.g. `enc_zero` below a new `enc_cpr`).
/// Returns the refusals of the last pass.
fn set_all(s: &mut Session, values: &[(String, f64)], t: Duration) -> Result<Vec<String>> {
    let mut left: Vec<&(String, f64)> = values.iter().collect();
    loop {
        let mut errs = Vec::new();
        let mut next = Vec::new();
        for v in &left {
            let r = s.command(&format!("config set {} {}", v.0, v.1), t)?;
            if let Final::Err { code, message } = r.fin {
                errs.push(format!("{}: ERR {code} {message}", v.0));
                next.push(*v);
            }
        }
        if next.is_empty() || next.len() == left.len() {
            return Ok(errs);
        }
        left = next;
    }
}

/// Pushes `text` (checked against the drive's schema first), then saves it
/// to the drive's flash. All or nothing: on a refusal the previous values
/// are set again and the error says which were refused.
pub fn push(s: &mut Session, text: &str, t: Duration) -> Result<usize> {
    let (schema, before) = pull(s, t)?;
    let values = parse_toml(text, &schema)?;
    let errs = set_all(s, &values, t)?;
    if !errs.is_empty() {
        let restore = set_all(s, &before, t)?;
        let restored = if restore.is_empty() {
            "the previous values are back"
        } else {
            "restoring the previous values failed too"
        };
        bail!("the drive refused: {} ({restored})", errs.join("; "));
    }
    ok_lines(s, "config save", t)?;
    Ok(values.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn schema() -> Vec<ParamSchema> {
        let mut line = String::new();
        drive::config::write_schema(&mut line).unwrap();
        parse_schema(&line).unwrap()
    }

    #[test]
    fn pull_file_round_trips() {
        let s = schema();
        let values: Vec<(String, f64)> = s.iter().map(|p| (p.name.clone(), p.default)).collect();
        let text = to_toml(&s, &values).unwrap();
        assert!(text.contains("\nmotor_pole_pairs = 7\n"), "{text}");
        assert!(text.contains("\nu_dc = 48.0\n"), "{text}");
        assert!(text.contains("\nmpdtc_t_tol = 0.08\n"), "{text}");
        assert_eq!(parse_toml(&text, &s).unwrap(), values);
    }

    #[test]
    fn bad_files_are_refused_with_every_error() {
        let s = schema();
        let e = parse_toml(
            "mpdtc_t_tol = 0.9\nmotor_pole_pairs = 7.5\nfrob = 1\nu_dc = \"48\"\nobs_kp = nan\n",
            &s,
        )
        .unwrap_err()
        .to_string();
        for want in [
            "mpdtc_t_tol: 0.9 Nm is out of range [0..0.5]",
            "motor_pole_pairs: 7.5 is not a whole number",
            "frob: no such parameter",
            "u_dc: expected a number, got string",
            "obs_kp: NaN is not finite",
        ] {
            assert!(e.contains(want), "{want}: {e}");
        }
        assert!(parse_toml("this is = not toml =", &s).is_err());
        // A subset is fine, in table order.
        assert_eq!(
            parse_toml("mpdtc_p = 0.2\nmotor_r_s = 0.6\n", &s).unwrap(),
            [("motor_r_s".to_string(), 0.6), ("mpdtc_p".to_string(), 0.2)]
        );
    }

    #[test]
    fn value_lines() {
        assert_eq!(
            parse_value_line("mpdtc_t_tol = 0.08 Nm  [0..0.5]  MPDTC band").unwrap(),
            ("mpdtc_t_tol".to_string(), 0.08)
        );
        assert!(parse_value_line("fault: none").is_err());
    }
}
