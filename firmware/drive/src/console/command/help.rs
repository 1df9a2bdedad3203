//! `help [command]`: the command list from [`super::COMMANDS`], or one
//! command's line.
use super::super::{write_err, ErrorCode};
use super::{clip, spec, write_spec, Outcome, ParseError, Spec, COMMANDS};
use core::fmt::{self, Write};

/// The `help` command.
pub const HELP: Spec = Spec {
    name: "help",
    args: "[command]",
    help: "list the commands, or describe one",
};

/// `help [command]`: the topic, if any.
pub fn parse<'a>(args: &[&'a str]) -> Result<Option<&'a str>, ParseError<'a>> {
    match args {
        [] => Ok(None),
        [topic] => Ok(Some(topic)),
        _ => Err(ParseError::BadArgs("help", "takes at most one argument")),
    }
}

/// Writes the reply of `help [topic]`.
pub fn execute<W: Write>(topic: Option<&str>, out: &mut W) -> Result<Outcome, fmt::Error> {
    match topic {
        None => {
            out.write_str("commands (arguments in [], units in brackets):\r\n")?;
            for s in COMMANDS {
                write_spec(out, s)?;
            }
            out.write_str("replies end with `OK` or `ERR <code> <message>`\r\n")?;
        }
        Some(topic) => match spec(topic) {
            Some(s) => {
                write_spec(out, s)?;
                // A limit that follows from the link, not from the table.
                if s.name == super::tel::TEL.name {
                    super::tel::write_max_rates(out)?;
                }
            }
            None => {
                let (w, more) = clip(topic);
                write_err(
                    out,
                    ErrorCode::BadArgs,
                    format_args!("help: no command `{w}{more}`"),
                )?;
                return Ok(Outcome::Final);
            }
        },
    }
    Ok(Outcome::Ok)
}
