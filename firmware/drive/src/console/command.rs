//! Command grammar: the command table, the parser and the replies.
//!
//! The table [`COMMANDS`] is the single source of `help` and of the parser's
//! list of names, so a command cannot exist without its help line.

use super::{write_err, ErrorCode};
use core::fmt::{self, Write};

/// One console command: its name, its arguments (with units) and what it does.
pub struct Spec {
    /// First word of the line.
    pub name: &'static str,
    /// Argument synopsis, units in brackets.
    pub args: &'static str,
    /// One-line description.
    pub help: &'static str,
}

/// Every console command.
pub const COMMANDS: &[Spec] = &[
    Spec {
        name: "help",
        args: "[command]",
        help: "list the commands, or describe one",
    },
    Spec {
        name: "version",
        args: "",
        help: "firmware crate version, git hash, build profile",
    },
    Spec {
        name: "status",
        args: "",
        help:
            "uptime [s], timer ticks [count] and rate [Hz], console counters, gates, PL bitstream",
    },
    Spec {
        name: "debug",
        args: "panic",
        help: "diagnostics: `debug panic` forces a firmware panic (gates off, message, halt)",
    },
];

/// A parsed command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Command<'a> {
    /// `help [command]`.
    Help(Option<&'a str>),
    /// `version`.
    Version,
    /// `status`.
    Status,
    /// `debug panic`.
    DebugPanic,
}

/// Why a line is not a valid command.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParseError<'a> {
    /// The first word is not in [`COMMANDS`].
    Unknown(&'a str),
    /// The command exists; its arguments are wrong.
    BadArgs(&'static str, &'static str),
}

/// What the caller must do after the reply.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    /// Nothing: print the prompt again.
    None,
    /// Panic on purpose (`debug panic`).
    Panic,
}

/// Live values the `status` command reports.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Status {
    /// Time since boot from the global timer, microseconds.
    pub uptime_us: u64,
    /// Periodic timer interrupts since boot.
    pub ticks: u32,
    /// Nominal rate of the periodic timer interrupt, Hz.
    pub tick_hz: u32,
    /// Lines the console received.
    pub lines: u32,
    /// Lines answered with `ERR`.
    pub errors: u32,
    /// Received bytes lost because the receive buffer was full.
    pub rx_overruns: u32,
    /// Whether the PL gate-enable bit is set (false = safe state).
    pub gates_enabled: bool,
    /// PL `ID` register (`regmap::ID_VALUE` when our bitstream is loaded).
    pub pl_id: u32,
    /// PL `VERSION` register (register-map version, major.minor).
    pub pl_version: u32,
}

/// What the commands need to know about the firmware.
pub struct Context {
    /// Crate version (`CARGO_PKG_VERSION`).
    pub version: &'static str,
    /// Git commit of the build, `unknown` outside a checkout.
    pub git_hash: &'static str,
    /// `release` or `debug`.
    pub profile: &'static str,
    /// Live status values.
    pub status: Status,
}

fn spec(name: &str) -> Option<&'static Spec> {
    COMMANDS.iter().find(|s| s.name == name)
}

/// Parses one line (the editor has already rejected control characters and
/// invalid UTF-8). Words are separated by spaces; names are case-sensitive.
pub fn parse(line: &str) -> Result<Command<'_>, ParseError<'_>> {
    let mut words = line.split_whitespace();
    let Some(name) = words.next() else {
        return Err(ParseError::BadArgs("", "empty line"));
    };
    let args: heapless::Vec<&str, 4> = {
        let mut v = heapless::Vec::new();
        for w in words {
            if v.push(w).is_err() {
                return match spec(name) {
                    Some(s) => Err(ParseError::BadArgs(s.name, "too many arguments")),
                    None => Err(ParseError::Unknown(name)),
                };
            }
        }
        v
    };
    let no_args = |c: Command<'static>, n: &'static str| {
        if args.is_empty() {
            Ok(c)
        } else {
            Err(ParseError::BadArgs(n, "takes no arguments"))
        }
    };
    match name {
        "help" => match args.as_slice() {
            [] => Ok(Command::Help(None)),
            [topic] => Ok(Command::Help(Some(topic))),
            _ => Err(ParseError::BadArgs("help", "takes at most one argument")),
        },
        "version" => no_args(Command::Version, "version"),
        "status" => no_args(Command::Status, "status"),
        "debug" => match args.as_slice() {
            ["panic"] => Ok(Command::DebugPanic),
            _ => Err(ParseError::BadArgs("debug", "expected `debug panic`")),
        },
        _ => Err(ParseError::Unknown(name)),
    }
}

/// At most this many bytes of an offending word are echoed in an error.
const ECHO_MAX: usize = 24;

fn clip(s: &str) -> (&str, &str) {
    if s.len() <= ECHO_MAX {
        return (s, "");
    }
    let mut end = ECHO_MAX;
    while !s.is_char_boundary(end) {
        end -= 1;
    }
    (&s[..end], "...")
}

/// Writes the final `ERR` line for a parse error.
pub fn write_parse_error<W: Write>(out: &mut W, e: ParseError<'_>) -> fmt::Result {
    match e {
        ParseError::Unknown(w) => {
            let (w, more) = clip(w);
            write_err(
                out,
                ErrorCode::UnknownCommand,
                format_args!("`{w}{more}` (try `help`)"),
            )
        }
        ParseError::BadArgs(cmd, why) => {
            write_err(out, ErrorCode::BadArgs, format_args!("{cmd}: {why}"))
        }
    }
}

fn write_spec<W: Write>(out: &mut W, s: &Spec) -> fmt::Result {
    let sep = if s.args.is_empty() { "" } else { " " };
    let used = s.name.len() + sep.len() + s.args.len();
    write!(out, "  {}{}{}", s.name, sep, s.args)?;
    for _ in used..22 {
        out.write_char(' ')?;
    }
    write!(out, " {}\r\n", s.help)
}

/// The `pl:` status line: whether our bitstream is there and speaks the
/// register map this firmware was built against.
fn write_pl<W: Write>(out: &mut W, id: u32, version: u32) -> fmt::Result {
    let v = |x: u32| (x >> 16, x & 0xffff);
    let (want_major, want_minor) = v(crate::regmap::VERSION.reset);
    if id != crate::regmap::ID_VALUE {
        return write!(out, "pl: no bitstream (ID reads 0x{id:08x})\r\n");
    }
    let (major, minor) = v(version);
    write!(out, "pl: bitstream present, register map v{major}.{minor}")?;
    if major != want_major {
        write!(
            out,
            " INCOMPATIBLE (firmware expects v{want_major}.{want_minor})"
        )?;
    }
    out.write_str("\r\n")
}

/// Writes the reply of `cmd`, ending with `OK` or `ERR`.
pub fn execute<W: Write>(
    cmd: Command<'_>,
    ctx: &Context,
    out: &mut W,
) -> Result<Action, fmt::Error> {
    match cmd {
        Command::Help(None) => {
            out.write_str("commands (arguments in [], units in brackets):\r\n")?;
            for s in COMMANDS {
                write_spec(out, s)?;
            }
            out.write_str("replies end with `OK` or `ERR <code> <message>`\r\n")?;
        }
        Command::Help(Some(topic)) => match spec(topic) {
            Some(s) => write_spec(out, s)?,
            None => {
                let (w, more) = clip(topic);
                write_err(
                    out,
                    ErrorCode::BadArgs,
                    format_args!("help: no command `{w}{more}`"),
                )?;
                return Ok(Action::None);
            }
        },
        Command::Version => {
            write!(
                out,
                "firmware {} git {} profile {}\r\n",
                ctx.version, ctx.git_hash, ctx.profile
            )?;
        }
        Command::Status => {
            let s = &ctx.status;
            write!(
                out,
                "uptime: {}.{:06} s\r\n",
                s.uptime_us / 1_000_000,
                s.uptime_us % 1_000_000
            )?;
            write!(out, "ticks: {} (rate {} Hz)\r\n", s.ticks, s.tick_hz)?;
            write!(
                out,
                "console: {} lines, {} errors, {} rx overruns\r\n",
                s.lines, s.errors, s.rx_overruns
            )?;
            let gates = if s.gates_enabled {
                "enabled"
            } else {
                "off (safe state)"
            };
            write!(out, "gates: {gates}\r\n")?;
            write_pl(out, s.pl_id, s.pl_version)?;
        }
        Command::DebugPanic => return Ok(Action::Panic),
    }
    out.write_str("OK\r\n")?;
    Ok(Action::None)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::string::String;

    fn ctx() -> Context {
        Context {
            version: "1.2.3",
            git_hash: "abc1234",
            profile: "release",
            status: Status {
                uptime_us: 12_000_042,
                ticks: 12_000,
                tick_hz: 1000,
                lines: 5,
                errors: 2,
                rx_overruns: 0,
                gates_enabled: false,
                pl_id: 0,
                pl_version: 0,
            },
        }
    }

    /// Parses and executes `line` the way the firmware does.
    fn reply(line: &str) -> String {
        let mut out = String::new();
        match parse(line) {
            Ok(c) => {
                execute(c, &ctx(), &mut out).unwrap();
            }
            Err(e) => write_parse_error(&mut out, e).unwrap(),
        }
        out
    }

    /// Every reply ends with exactly one final line.
    fn assert_one_final_line(r: &str) {
        let finals = r
            .split("\r\n")
            .filter(|l| *l == "OK" || l.starts_with("ERR "))
            .count();
        assert_eq!(finals, 1, "{r:?}");
        assert!(r.ends_with("\r\n"));
        let last = r.trim_end().rsplit("\r\n").next().unwrap();
        assert!(last == "OK" || last.starts_with("ERR "), "{r:?}");
    }

    #[test]
    fn help_lists_every_command_with_its_arguments() {
        let r = reply("help");
        for s in COMMANDS {
            assert!(r.contains(s.name) && r.contains(s.args), "{}", s.name);
        }
        assert_one_final_line(&r);
        assert!(r.ends_with("OK\r\n"));
    }

    #[test]
    fn help_on_one_command() {
        assert!(reply("help status").starts_with("  status"));
        assert_eq!(
            reply("help nothing"),
            "ERR bad-args help: no command `nothing`\r\n"
        );
    }

    #[test]
    fn version_reply() {
        assert_eq!(
            reply("version"),
            "firmware 1.2.3 git abc1234 profile release\r\nOK\r\n"
        );
    }

    #[test]
    fn status_reply_has_units() {
        let r = reply("  status  ");
        assert!(r.contains("uptime: 12.000042 s\r\n"), "{r}");
        assert!(r.contains("ticks: 12000 (rate 1000 Hz)\r\n"), "{r}");
        assert!(r.contains("gates: off (safe state)\r\n"), "{r}");
        assert_one_final_line(&r);
    }

    #[test]
    fn status_tells_whether_the_bitstream_is_loaded_and_compatible() {
        let line = |id, version| {
            let mut out = String::new();
            write_pl(&mut out, id, version).unwrap();
            out
        };
        let ours = crate::regmap::VERSION.reset;
        assert_eq!(line(0, 0), "pl: no bitstream (ID reads 0x00000000)\r\n");
        assert_eq!(
            line(crate::regmap::ID_VALUE, ours),
            std::format!(
                "pl: bitstream present, register map v{}.{}\r\n",
                ours >> 16,
                ours & 0xffff
            )
        );
        // A minor bump is compatible, a major one is flagged.
        assert!(!line(crate::regmap::ID_VALUE, ours + 1).contains("INCOMPATIBLE"));
        assert!(line(crate::regmap::ID_VALUE, ours + 0x1_0000).contains("INCOMPATIBLE"));
    }

    #[test]
    fn unknown_command() {
        assert_eq!(
            reply("frobnicate 3"),
            "ERR unknown-command `frobnicate` (try `help`)\r\n"
        );
        // Names are case-sensitive.
        assert!(reply("HELP").starts_with("ERR unknown-command"));
    }

    #[test]
    fn long_unknown_word_is_clipped_on_a_char_boundary() {
        let w = "é".repeat(40);
        let r = reply(&w);
        assert!(r.starts_with("ERR unknown-command `"), "{r}");
        assert!(r.contains("...`"), "{r}");
        assert!(r.len() < 80);
    }

    #[test]
    fn arguments_are_checked() {
        assert_eq!(
            reply("version x"),
            "ERR bad-args version: takes no arguments\r\n"
        );
        assert_eq!(
            reply("status x y"),
            "ERR bad-args status: takes no arguments\r\n"
        );
        assert_eq!(
            reply("debug"),
            "ERR bad-args debug: expected `debug panic`\r\n"
        );
        assert_eq!(
            reply("help a b"),
            "ERR bad-args help: takes at most one argument\r\n"
        );
        assert_eq!(
            reply("status 1 2 3 4 5 6"),
            "ERR bad-args status: too many arguments\r\n"
        );
    }

    #[test]
    fn debug_panic_asks_for_a_panic_and_prints_no_final_line() {
        let mut out = String::new();
        let a = execute(parse("debug panic").unwrap(), &ctx(), &mut out).unwrap();
        assert_eq!(a, Action::Panic);
        assert!(out.is_empty());
    }

    #[test]
    fn every_table_entry_parses() {
        for s in COMMANDS {
            let line = if s.args.starts_with('[') || s.args.is_empty() {
                String::from(s.name)
            } else {
                std::format!("{} {}", s.name, s.args)
            };
            assert!(parse(&line).is_ok(), "{line}");
        }
    }
}
