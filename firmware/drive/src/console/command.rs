//! Command grammar: the dispatcher. Each command family lives in its own
//! file below (its table entry, parsing, execution and reply lines); this
//! file splits the line into words, hands them to the family that owns the
//! first one, and ends the reply.
//!
//! The table [`COMMANDS`] is the single source of `help` and of the parser's
//! list of names, so a command cannot exist without its help line.

use super::drive::{self, DriveError, DriveOps};
use super::{write_err, ErrorCode};
use core::fmt::{self, Write};

/// The value of a drive call, or its `ERR` line written and the family's
/// `execute` returning [`Outcome::Final`].
macro_rules! try_drive {
    ($out:ident, $name:expr, $e:expr) => {
        match $e {
            Ok(v) => v,
            Err(e) => {
                drive::write_error($out, $name, e)?;
                return Ok(Outcome::Final);
            }
        }
    };
}

mod calibrate;
mod capture;
mod config;
mod debug;
mod fault;
mod help;
mod imp;
mod info;
mod motion;
mod r#move;
mod mpdcc;
mod pos;
mod selftest;
mod sim;
mod sweep;
mod tel;
#[cfg(test)]
mod tests;
mod vel;

pub use capture::CaptureCmd;
pub use config::ConfigCmd;
pub use debug::{DebugCmd, STALL_MAX_MS};
pub use fault::FaultCmd;
pub use info::InfoCmd;
pub use motion::{ModeSel, MotionCmd, STEP_WINDOW_DEFAULT_S, STEP_WINDOW_MAX_S};
pub use pos::PosCmd;
pub use sim::SimCmd;
pub use sweep::Sweep;
pub use tel::{TelCmd, TelOps};

/// One console command: its name, its arguments (with units) and what it does.
pub struct Spec {
    /// First word of the line.
    pub name: &'static str,
    /// Argument synopsis, units in brackets.
    pub args: &'static str,
    /// One-line description.
    pub help: &'static str,
}

/// Every console command, in `help` order.
pub const COMMANDS: &[&Spec] = &[
    &help::HELP,
    &info::VERSION,
    &info::STATUS,
    &motion::MODE,
    &motion::ENABLE,
    &motion::DISABLE,
    &motion::TORQUE,
    &motion::STEP,
    &vel::VEL,
    &pos::POS,
    &imp::IMP,
    &r#move::MOVE,
    &fault::FAULT,
    &config::CONFIG,
    &debug::DEBUG,
    &capture::CAPTURE,
    &sweep::SWEEP,
    &mpdcc::MPDCC,
    &tel::TEL,
    &selftest::SELFTEST,
    &calibrate::CALIBRATE,
    &sim::SIM,
];

/// A parsed command line: the family that owns its first word and what
/// that family parsed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Command<'a> {
    /// `help [command]`.
    Help(Option<&'a str>),
    /// `version`, `status`.
    Info(InfoCmd),
    /// `mode`, `enable`, `disable`, `torque`, `step`.
    Motion(MotionCmd),
    /// `fault [clear|history]`.
    Fault(FaultCmd),
    /// `config ...`.
    Config(ConfigCmd<'a>),
    /// `debug ...`.
    Debug(DebugCmd),
    /// `capture ...`.
    Capture(CaptureCmd),
    /// `sweep ...`.
    Sweep(Sweep),
    /// `mpdcc` (the last report) or `mpdcc run [periods]`.
    Mpdcc(Option<u32>),
    /// `tel ...`.
    Tel(TelCmd),
    /// `selftest sensors`.
    SelftestSensors,
    /// `sim ...`.
    Sim(SimCmd<'a>),
    /// `calibrate [phase]`.
    Calibrate(models::calibration::Phases),
    /// `vel <rev/s>`.
    Vel(f64),
    /// `pos <rev>|zero`.
    Pos(PosCmd),
    /// `imp ...`.
    Imp(models::motion::law::Impedance),
    /// `move <rev> [<window_ms>]`: distance rev, window s.
    Move(f64, f64),
}

/// Why a line is not a valid command.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParseError<'a> {
    /// The first word is not in [`COMMANDS`].
    Unknown(&'a str),
    /// The command exists; its arguments are wrong.
    BadArgs(&'static str, &'static str),
    /// `tel start` refused.
    Tel(crate::telemetry::SpecError<'a>),
}

/// What the caller must do after the reply.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    /// The reply ended with `OK`: print the prompt again.
    None,
    /// The reply ended with an `ERR` line (the drive refused or failed the
    /// command): the caller counts it as an error, then prompts again.
    Refused,
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
    /// Lines answered with `ERR` (the grammar's, the editor's or the drive's).
    pub errors: u32,
    /// Received bytes lost because the receive buffer was full.
    pub rx_overruns: u32,
    /// Log frames dropped because the log's RAM ring was full.
    pub log_dropped: u32,
    /// The network path (Ethernet, socketcand, CANopen).
    pub net: NetStatus,
}

/// The network path's state for `status`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NetStatus {
    /// IPv4 address and prefix length, bits; `None` while there is none.
    pub ipv4: Option<([u8; 4], u8)>,
    /// Whether the address came from DHCP (else the static fallback).
    pub dhcp: bool,
    /// Whether a socketcand client is connected.
    pub client: bool,
    /// The socketcand session's and node's counters.
    pub can: crate::can_gateway::Counts,
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

/// How a family's `execute` ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Outcome {
    /// Its reply lines are written: the dispatcher ends them with `OK`.
    Ok,
    /// Its final line (`ERR`) is written.
    Final,
    /// `debug panic`: no final line, the caller panics.
    Panic,
}

fn spec(name: &str) -> Option<&'static Spec> {
    COMMANDS.iter().copied().find(|s| s.name == name)
}

/// Parses one line (the editor has already rejected control characters and
/// invalid UTF-8). Words are separated by spaces; names are case-sensitive.
pub fn parse(line: &str) -> Result<Command<'_>, ParseError<'_>> {
    let mut words = line.split_whitespace();
    let Some(name) = words.next() else {
        return Err(ParseError::BadArgs("", "empty line"));
    };
    let Some(s) = spec(name) else {
        return Err(ParseError::Unknown(name));
    };
    let args: heapless::Vec<&str, 5> = {
        let mut v = heapless::Vec::new();
        for w in words {
            if v.push(w).is_err() {
                return Err(ParseError::BadArgs(s.name, "too many arguments"));
            }
        }
        v
    };
    let args = args.as_slice();
    match s.name {
        "help" => help::parse(args).map(Command::Help),
        "version" | "status" => info::parse(s.name, args).map(Command::Info),
        "mode" | "enable" | "disable" | "torque" | "step" => {
            motion::parse(s.name, args).map(Command::Motion)
        }
        "fault" => fault::parse(args).map(Command::Fault),
        "config" => config::parse(args).map(Command::Config),
        "debug" => debug::parse(args).map(Command::Debug),
        "capture" => capture::parse(args).map(Command::Capture),
        "sweep" => sweep::parse(args).map(Command::Sweep),
        "mpdcc" => mpdcc::parse(args).map(Command::Mpdcc),
        "tel" => tel::parse(args).map(Command::Tel),
        "selftest" => selftest::parse(args).map(|()| Command::SelftestSensors),
        "sim" => sim::parse(args).map(Command::Sim),
        "calibrate" => calibrate::parse(args).map(Command::Calibrate),
        "vel" => vel::parse(args).map(Command::Vel),
        "pos" => pos::parse(args).map(Command::Pos),
        "imp" => imp::parse(args).map(Command::Imp),
        "move" => r#move::parse(args).map(|(d, w)| Command::Move(d, w)),
        _ => Err(ParseError::Unknown(name)),
    }
}

/// Writes the reply of `cmd`, ending with `OK` or `ERR`.
pub fn execute<W: Write>(
    cmd: Command<'_>,
    ctx: &Context,
    drv: &mut dyn DriveOps,
    out: &mut W,
) -> Result<Action, fmt::Error> {
    if moves_motor(&cmd) && drv.canopen().is_some_and(|c| c.owns) {
        drive::write_error(out, name_of(&cmd), DriveError::CanopenOwns)?;
        return Ok(Action::Refused);
    }
    let done = match cmd {
        Command::Help(topic) => help::execute(topic, out)?,
        Command::Info(c) => info::execute(c, ctx, drv, out)?,
        Command::Motion(c) => motion::execute(c, drv, out)?,
        Command::Fault(c) => fault::execute(c, drv, out)?,
        Command::Config(c) => config::execute(c, drv, out)?,
        Command::Debug(c) => debug::execute(c, drv, out)?,
        Command::Capture(c) => capture::execute(c, drv, out)?,
        Command::Sweep(c) => sweep::execute(c, drv, out)?,
        Command::Mpdcc(run) => mpdcc::execute(run, drv, out)?,
        Command::Tel(c) => tel::execute(c, drv.telemetry(), out)?,
        Command::SelftestSensors => selftest::execute(drv, out)?,
        Command::Sim(c) => sim::execute(c, drv, out)?,
        Command::Calibrate(p) => calibrate::execute(p, drv, out)?,
        Command::Vel(v) => vel::execute(v, drv, out)?,
        Command::Pos(c) => pos::execute(c, drv, out)?,
        Command::Imp(c) => imp::execute(c, drv, out)?,
        Command::Move(d, w) => r#move::execute((d, w), drv, out)?,
    };
    match done {
        Outcome::Ok => {
            out.write_str("OK\r\n")?;
            Ok(Action::None)
        }
        Outcome::Final => Ok(Action::Refused),
        Outcome::Panic => Ok(Action::Panic),
    }
}

/// Whether `cmd` moves the motor or changes how it is driven: refused
/// while a CANopen master owns it. Queries, `disable` (a way to stop that
/// is always there), the capture, telemetry, fault and debug commands and
/// the simulated world's `sim` are not.
fn moves_motor(cmd: &Command<'_>) -> bool {
    match cmd {
        Command::Motion(m) => !matches!(
            m,
            MotionCmd::Mode(None) | MotionCmd::Torque(None) | MotionCmd::Disable
        ),
        Command::Config(c) => matches!(c, ConfigCmd::Set(..) | ConfigCmd::Reset),
        Command::Sweep(_)
        | Command::Mpdcc(_)
        | Command::SelftestSensors
        | Command::Calibrate(_)
        | Command::Vel(_)
        | Command::Pos(_)
        | Command::Imp(_)
        | Command::Move(..) => true,
        Command::Help(_)
        | Command::Info(_)
        | Command::Fault(_)
        | Command::Debug(_)
        | Command::Capture(_)
        | Command::Tel(_)
        | Command::Sim(_) => false,
    }
}

/// The command's name, as its `ERR` lines start.
fn name_of(cmd: &Command<'_>) -> &'static str {
    match cmd {
        Command::Motion(m) => match m {
            MotionCmd::Mode(_) => "mode",
            MotionCmd::Enable => "enable",
            MotionCmd::Disable => "disable",
            MotionCmd::Torque(_) => "torque",
            MotionCmd::Step(..) => "step",
        },
        Command::Config(_) => "config",
        Command::Sweep(_) => "sweep",
        Command::Mpdcc(_) => "mpdcc",
        Command::SelftestSensors => "selftest",
        Command::Calibrate(_) => "calibrate",
        Command::Vel(_) => "vel",
        Command::Pos(_) => "pos",
        Command::Imp(_) => "imp",
        Command::Move(..) => "move",
        Command::Help(_) => "help",
        Command::Info(_) => "status",
        Command::Fault(_) => "fault",
        Command::Debug(_) => "debug",
        Command::Capture(_) => "capture",
        Command::Tel(_) => "tel",
        Command::Sim(_) => "sim",
    }
}

/// A command that needs the PMSM's gates or the MPDCC page: in `mode mpdcc`
/// they belong to the HIL loop, so it is refused (its `ERR` line written).
fn mpdcc_owns<W: Write>(
    drv: &mut dyn DriveOps,
    out: &mut W,
    name: &str,
) -> Result<bool, fmt::Error> {
    if drv.mpdcc_live().is_some() {
        drive::write_error(out, name, DriveError::MpdccMode)?;
        return Ok(true);
    }
    Ok(false)
}

/// `c` when there are no arguments.
fn no_args<'a, T>(args: &[&str], c: T, name: &'static str) -> Result<T, ParseError<'a>> {
    if args.is_empty() {
        Ok(c)
    } else {
        Err(ParseError::BadArgs(name, "takes no arguments"))
    }
}

/// A number argument: decimal, finite (NaN and infinities are refused here,
/// the limit is the drive's).
fn number(s: &str) -> Option<f64> {
    s.parse::<f64>().ok().filter(|x| x.is_finite())
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
        ParseError::Tel(e) => write_err(out, ErrorCode::BadArgs, format_args!("tel: {e}")),
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
