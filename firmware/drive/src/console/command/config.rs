//! `config list|get|set|reset|schema|save`: the parameter table.
use super::super::drive::{self, DriveOps};
use super::super::{write_err, ErrorCode};
use super::{clip, Outcome, ParseError, Spec};
use crate::config::{self, Config};
use core::fmt::{self, Write};

/// The `config` command.
pub const CONFIG: Spec = Spec {
    name: "config",
    args: "list|get <name>|set <name> <value>|reset|schema|save",
    help: "parameters with units and ranges: `list` every one, `get`/`set` one (checked; \
           most need the gates off), `reset` to the defaults, `schema` the table as one \
           JSON line, `save` to flash (loaded at boot)",
};

/// A `config` subcommand.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ConfigCmd<'a> {
    /// `config list`.
    List,
    /// `config get <name>`.
    Get(&'a str),
    /// `config set <name> <value>` (the value is checked by the table).
    Set(&'a str, &'a str),
    /// `config reset`.
    Reset,
    /// `config schema`.
    Schema,
    /// `config save`.
    Save,
}

/// Parses the arguments of `config`.
pub fn parse<'a>(args: &[&'a str]) -> Result<ConfigCmd<'a>, ParseError<'a>> {
    match args {
        ["list"] => Ok(ConfigCmd::List),
        ["get", n] => Ok(ConfigCmd::Get(n)),
        ["set", n, v] => Ok(ConfigCmd::Set(n, v)),
        ["reset"] => Ok(ConfigCmd::Reset),
        ["schema"] => Ok(ConfigCmd::Schema),
        ["save"] => Ok(ConfigCmd::Save),
        _ => Err(ParseError::BadArgs(
            "config",
            "expected `config list|get <name>|set <name> <value>|reset|schema|save`",
        )),
    }
}

/// The `ERR bad-args` line of a refused `config` value.
fn config_error<W: Write>(
    out: &mut W,
    name: &str,
    e: config::ConfigError,
) -> Result<Outcome, fmt::Error> {
    let (w, more) = clip(name);
    write_err(
        out,
        ErrorCode::BadArgs,
        format_args!("config: {w}{more}: {e}"),
    )?;
    Ok(Outcome::Final)
}

/// Writes the reply of `config`.
pub fn execute<W: Write>(
    c: ConfigCmd<'_>,
    drv: &mut dyn DriveOps,
    out: &mut W,
) -> Result<Outcome, fmt::Error> {
    match c {
        ConfigCmd::List => {
            let c = Config::from_servo(&try_drive!(out, "config", drv.config()));
            for (p, &v) in config::PARAMS.iter().zip(c.values()) {
                config::write_list_line(out, p, v)?;
                out.write_str("\r\n")?;
            }
        }
        ConfigCmd::Get(name) => {
            let c = Config::from_servo(&try_drive!(out, "config", drv.config()));
            let Some((i, p)) = config::lookup(name) else {
                return config_error(out, name, config::ConfigError::UnknownName);
            };
            config::write_value(out, p, c.values()[i])?;
            out.write_str("\r\n")?;
        }
        ConfigCmd::Set(name, value) => {
            let sc = try_drive!(out, "config", drv.config());
            let mut c = Config::from_servo(&sc);
            let set = config::parse_value(value).and_then(|v| c.set(&sc, name, v));
            if let Err(e) = set {
                return config_error(out, name, e);
            }
            try_drive!(out, "config", drv.reconfigure(&c.apply(&sc)));
            if let Some((i, p)) = config::lookup(name) {
                config::write_value(out, p, c.values()[i])?;
                out.write_str("\r\n")?;
            }
        }
        ConfigCmd::Reset => {
            let sc = try_drive!(out, "config", drv.config());
            let c = Config::default();
            if let Err(e) = c.check(&sc) {
                return config_error(out, "reset", e);
            }
            try_drive!(out, "config", drv.reconfigure(&c.apply(&sc)));
            out.write_str("config: defaults\r\n")?;
        }
        ConfigCmd::Save => {
            let slot = try_drive!(out, "config", drv.save_config());
            write!(out, "config: saved to slot{slot}\r\n")?;
        }
        ConfigCmd::Schema => {
            config::write_schema(out)?;
            out.write_str("\r\n")?;
        }
    }
    Ok(Outcome::Ok)
}
