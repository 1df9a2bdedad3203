//! Command grammar: the command table, the parser and the replies.
//!
//! The table [`COMMANDS`] is the single source of `help` and of the parser's
//! list of names, so a command cannot exist without its help line.

use super::drive::{self, DriveError, DriveOps};
use super::{write_err, ErrorCode};
use crate::config::{self, Config};
use crate::pl::capture::{self as pl_capture, CapState, Channel, Trigger};
use crate::pl::top::Mode;
use crate::servo::{bandwidth_hz, SweepPoint};
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
        help: "uptime [s], ticks, console counters, then the drive: mode, gates, fault, torque \
               [Nm], i_d/i_q [A], speed [rad/s], control rate [Hz], periods, overruns, PL",
    },
    Spec {
        name: "mode",
        args: "[off|foc|mpdtc|mpdcc]",
        help: "print or set the control mode; any change turns the gates off; `mpdcc` runs \
               paper 001's hardware-in-the-loop arrangement continuously (the IM + 5L-ANPC \
               plant on the PS feeds the PL's MPDCC core one decision per control period; \
               progress in `status`), the PMSM gates stay off",
    },
    Spec {
        name: "enable",
        args: "",
        help: "gates on (refused in mode off or with a fault latched)",
    },
    Spec {
        name: "disable",
        args: "",
        help: "gates off",
    },
    Spec {
        name: "torque",
        args: "[<Nm>]",
        help: "print or set the torque reference [Nm] (|x| <= the limit, 1.0 Nm)",
    },
    Spec {
        name: "step",
        args: "<Nm> [<window_ms>]",
        help: "torque step from the reference to <Nm>, torque sampled at the control rate for \
               the window [ms] (default 2, at most 20); prints settling [ms], overshoot [%], \
               switching [kHz], final [Nm]",
    },
    Spec {
        name: "fault",
        args: "[clear|history]",
        help: "list the latched faults, clear them (the gates stay off until `enable`), or \
               the last 16 with drive time [s], code and the samples before [A, Nm]",
    },
    Spec {
        name: "config",
        args: "list|get <name>|set <name> <value>|reset|schema|save",
        help: "parameters with units and ranges: `list` every one, `get`/`set` one (checked; \
               most need the gates off), `reset` to the defaults, `schema` the table as one \
               JSON line, `save` to flash (loaded at boot)",
    },
    Spec {
        name: "debug",
        args: "panic|stall <ms>|bench|fault <f>",
        help: "diagnostics: `panic` forces a firmware panic (gates off, message, halt); \
               `stall <ms>` stops the control loop and heartbeat for <ms> of PL time (the \
               simulated PL's under QEMU); `bench` counts guest instructions of the control \
               code; `fault <f>` makes a fault happen (<f>: external, adc-stuck or overrun)",
    },
    Spec {
        name: "capture",
        args: "arm <trigger> [<pre_samples>]|trigger|status|dump",
        help: "PL capture buffer at the control rate (1024 samples: i_d, i_q [A], torque, \
               torque_ref [Nm], switching state, ADC_IA): `arm` with trigger manual, step \
               (reference step >= 0.05 Nm), fault, or <channel>>x / <channel><x (channel i_d, \
               i_q [A], torque, torque_ref [Nm]) and pre-trigger samples (default 64, at most \
               1023); `trigger` triggers by hand; `status`; `dump` prints the record as CSV",
    },
    Spec {
        name: "sweep",
        args: "<f_start_hz> <f_stop_hz> <amplitude_nm> [<points>]",
        help: "frequency response of the torque loop: a sine torque reference per frequency \
               (log spaced, default 6 points, 2..=32), gain [dB] and phase [deg] of the \
               captured torque against the captured reference, one `f_hz gain_db phase_deg` \
               line each, then the -3 dB bandwidth [Hz]; gates on, f_stop <= control rate / 4",
    },
    Spec {
        name: "mpdcc",
        args: "[run [<periods>]]",
        help: "paper 001's hardware-in-the-loop run: the induction machine and 5L-ANPC plant \
               on the PS feed the PL's MPDCC core each T_s through its register page; `run` \
               one warm-up and <periods> (default 1, 1..=20) measured fundamental periods, \
               without arguments the last run: decisions (kept, optimal, deadlock), core \
               cycles mean/worst [PL cycles], f_sw [Hz], THD [%], max current error [pu]",
    },
    // Telemetry (`console/tel.rs`).
    Spec {
        name: "tel",
        args: "list|start <rate_hz> <channels>|stop|status",
        help: "live telemetry: `list` the channels with units, `start` a stream of up to 8 \
               comma-separated <channels> at <rate_hz> of drive time (1..=10000, one control period's value \
               per sample) as binary frames between the replies, `stop`, `status` (samples \
               taken, sent, dropped)",
    },
];

/// What `mode` selects: a PL mode of the PMSM drive, or paper 001's HIL
/// loop (the PL in mode off, the MPDCC page driven from the PS).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ModeSel {
    /// `off`, `foc`, `mpdtc`.
    Pl(Mode),
    /// `mpdcc`.
    Mpdcc,
}

impl ModeSel {
    /// Parses a console name.
    pub fn from_name(s: &str) -> Option<Self> {
        match s {
            "mpdcc" => Some(ModeSel::Mpdcc),
            _ => Mode::from_name(s).map(ModeSel::Pl),
        }
    }
}

/// A parsed command line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Command<'a> {
    /// `help [command]`.
    Help(Option<&'a str>),
    /// `version`.
    Version,
    /// `status`.
    Status,
    /// `debug panic`.
    DebugPanic,
    /// `mode [m]`.
    Mode(Option<ModeSel>),
    /// `enable`.
    Enable,
    /// `disable`.
    Disable,
    /// `torque [Nm]` (the number is checked against the limit by the drive).
    Torque(Option<f64>),
    /// `step <Nm> [<window_ms>]`, window in seconds.
    Step(f64, f64),
    /// `fault`.
    Fault,
    /// `fault clear`.
    FaultClear,
    /// `fault history`.
    FaultHistory,
    /// `debug fault <f>`.
    DebugFault(drive::Injection),
    /// `debug stall <ms>`.
    DebugStall(u32),
    /// `debug bench`.
    DebugBench,
    /// `config list`.
    ConfigList,
    /// `config get <name>`.
    ConfigGet(&'a str),
    /// `config set <name> <value>` (the value is checked by the table).
    ConfigSet(&'a str, &'a str),
    /// `config reset`.
    ConfigReset,
    /// `config schema`.
    ConfigSchema,
    /// `config save`.
    ConfigSave,
    /// `capture arm <trigger> [pre]`.
    CaptureArm(Trigger, u32),
    /// `capture trigger`.
    CaptureTrigger,
    /// `capture status`.
    CaptureStatus,
    /// `capture dump`.
    CaptureDump,
    /// `sweep <f_start_hz> <f_stop_hz> <amplitude_nm> [points]`.
    Sweep {
        /// First frequency, Hz.
        f_start_hz: f64,
        /// Last frequency, Hz.
        f_stop_hz: f64,
        /// Sine amplitude, N m.
        amp_nm: f64,
        /// Number of frequencies.
        points: u32,
    },
    /// `mpdcc` (the last report) or `mpdcc run [periods]`.
    Mpdcc(Option<u32>),
    /// `tel ...`.
    Tel(super::tel::TelCmd),
}

/// Default pre-trigger length of `capture arm`, samples.
pub const CAPTURE_PRE_DEFAULT: u32 = 64;
/// Reference step that triggers `capture arm step`, N m.
pub const CAPTURE_STEP_NM: f64 = 0.05;
/// Default number of `sweep` frequencies.
pub const SWEEP_POINTS_DEFAULT: u32 = 6;
/// Most `sweep` frequencies.
pub const SWEEP_POINTS_MAX: u32 = 32;

/// `capture arm`'s trigger word.
fn capture_trigger(w: &str) -> Option<Trigger> {
    match w {
        "manual" => return Some(Trigger::Manual),
        "step" => return Some(Trigger::RefStep(CAPTURE_STEP_NM)),
        "fault" => return Some(Trigger::Fault),
        _ => {}
    }
    let (i, falling) = match (w.find('>'), w.find('<')) {
        (Some(i), None) => (i, false),
        (None, Some(i)) => (i, true),
        _ => return None,
    };
    let channel = Channel::from_name(&w[..i])?;
    let level = number(&w[i + 1..])?;
    Some(Trigger::Threshold {
        channel,
        level,
        falling,
    })
}

fn parse_capture<'a>(args: &[&'a str]) -> Result<Command<'a>, ParseError<'a>> {
    const USAGE: &str = "expected `capture arm <trigger> [pre_samples]`, `capture trigger`, \
                         `capture status` or `capture dump`";
    match args {
        ["trigger"] => Ok(Command::CaptureTrigger),
        ["status"] => Ok(Command::CaptureStatus),
        ["dump"] => Ok(Command::CaptureDump),
        ["arm", t, rest @ ..] if rest.len() <= 1 => {
            let t = capture_trigger(t).ok_or(ParseError::BadArgs(
                "capture",
                "trigger must be manual, step, fault or <channel>>x / <channel><x with channel \
                 i_d, i_q, torque or torque_ref and a finite level",
            ))?;
            let pre = match rest {
                [] => CAPTURE_PRE_DEFAULT,
                [p] => match p.parse::<u32>() {
                    Ok(p) if p < pl_capture::DEPTH => p,
                    _ => {
                        return Err(ParseError::BadArgs(
                            "capture",
                            "pre_samples must be a whole number in 0..=1023",
                        ))
                    }
                },
                _ => unreachable!(),
            };
            Ok(Command::CaptureArm(t, pre))
        }
        _ => Err(ParseError::BadArgs("capture", USAGE)),
    }
}

fn parse_sweep<'a>(args: &[&'a str]) -> Result<Command<'a>, ParseError<'a>> {
    let (f0, f1, a, n) = match args {
        [f0, f1, a] => (*f0, *f1, *a, None),
        [f0, f1, a, n] => (*f0, *f1, *a, Some(*n)),
        _ => {
            return Err(ParseError::BadArgs(
                "sweep",
                "expected <f_start_hz> <f_stop_hz> <amplitude_nm> [points]",
            ))
        }
    };
    let (Some(f_start_hz), Some(f_stop_hz)) = (number(f0), number(f1)) else {
        return Err(ParseError::BadArgs(
            "sweep",
            "frequencies must be finite numbers [Hz]",
        ));
    };
    if !(f_start_hz > 0.0 && f_stop_hz > f_start_hz) {
        return Err(ParseError::BadArgs(
            "sweep",
            "need 0 < f_start_hz < f_stop_hz",
        ));
    }
    let amp_nm = number(a).ok_or(ParseError::BadArgs(
        "sweep",
        "amplitude must be a finite number [Nm]",
    ))?;
    let points = match n {
        None => SWEEP_POINTS_DEFAULT,
        Some(n) => match n.parse::<u32>() {
            Ok(n) if (2..=SWEEP_POINTS_MAX).contains(&n) => n,
            _ => {
                return Err(ParseError::BadArgs(
                    "sweep",
                    "points must be a whole number in 2..=32",
                ))
            }
        },
    };
    Ok(Command::Sweep {
        f_start_hz,
        f_stop_hz,
        amp_nm,
        points,
    })
}

/// Default `step` window, s.
pub const STEP_WINDOW_DEFAULT_S: f64 = 2e-3;
/// Longest `step` window, s (the recorder holds 1280 samples: 20 ms at 64 kHz).
pub const STEP_WINDOW_MAX_S: f64 = 20e-3;
/// Longest `debug stall`, ms.
pub const STALL_MAX_MS: u32 = 10_000;

/// A number argument: decimal, finite (NaN and infinities are refused here,
/// the limit is the drive's).
fn number(s: &str) -> Option<f64> {
    s.parse::<f64>().ok().filter(|x| x.is_finite())
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
            ["bench"] => Ok(Command::DebugBench),
            ["fault", f] => drive::Injection::from_name(f)
                .map(Command::DebugFault)
                .ok_or(ParseError::BadArgs(
                    "debug",
                    "fault takes external, adc-stuck or overrun",
                )),
            ["stall", ms] => match ms.parse::<u32>() {
                Ok(ms) if (1..=STALL_MAX_MS).contains(&ms) => Ok(Command::DebugStall(ms)),
                _ => Err(ParseError::BadArgs(
                    "debug",
                    "stall takes a whole number of ms in 1..=10000",
                )),
            },
            _ => Err(ParseError::BadArgs(
                "debug",
                "expected `debug panic`, `debug stall <ms>`, `debug bench` or `debug fault <f>`",
            )),
        },
        "mode" => {
            match args.as_slice() {
                [] => Ok(Command::Mode(None)),
                [m] => ModeSel::from_name(m).map(|m| Command::Mode(Some(m))).ok_or(
                    ParseError::BadArgs("mode", "expected off, foc, mpdtc or mpdcc"),
                ),
                _ => Err(ParseError::BadArgs("mode", "takes at most one argument")),
            }
        }
        "enable" => no_args(Command::Enable, "enable"),
        "disable" => no_args(Command::Disable, "disable"),
        "torque" => match args.as_slice() {
            [] => Ok(Command::Torque(None)),
            [x] => number(x)
                .map(|x| Command::Torque(Some(x)))
                .ok_or(ParseError::BadArgs(
                    "torque",
                    "expected a finite number [Nm]",
                )),
            _ => Err(ParseError::BadArgs("torque", "takes at most one argument")),
        },
        "step" => {
            let (nm, w) = match args.as_slice() {
                [nm] => (*nm, None),
                [nm, w] => (*nm, Some(*w)),
                _ => return Err(ParseError::BadArgs("step", "expected <Nm> [<window_ms>]")),
            };
            let nm =
                number(nm).ok_or(ParseError::BadArgs("step", "expected a finite torque [Nm]"))?;
            let w = match w {
                None => STEP_WINDOW_DEFAULT_S,
                Some(w) => match number(w) {
                    Some(ms) if ms > 0.0 && ms * 1e-3 <= STEP_WINDOW_MAX_S => ms * 1e-3,
                    _ => {
                        return Err(ParseError::BadArgs(
                            "step",
                            "window must be a number of ms in (0, 20]",
                        ))
                    }
                },
            };
            Ok(Command::Step(nm, w))
        }
        "fault" => match args.as_slice() {
            [] => Ok(Command::Fault),
            ["clear"] => Ok(Command::FaultClear),
            ["history"] => Ok(Command::FaultHistory),
            _ => Err(ParseError::BadArgs(
                "fault",
                "expected `fault`, `fault clear` or `fault history`",
            )),
        },
        "config" => match args.as_slice() {
            ["list"] => Ok(Command::ConfigList),
            ["get", n] => Ok(Command::ConfigGet(n)),
            ["set", n, v] => Ok(Command::ConfigSet(n, v)),
            ["reset"] => Ok(Command::ConfigReset),
            ["schema"] => Ok(Command::ConfigSchema),
            ["save"] => Ok(Command::ConfigSave),
            _ => Err(ParseError::BadArgs(
                "config",
                "expected `config list|get <name>|set <name> <value>|reset|schema|save`",
            )),
        },
        "capture" => parse_capture(args.as_slice()),
        "tel" => super::tel::parse(args.as_slice()).map(Command::Tel),
        "sweep" => parse_sweep(args.as_slice()),
        "mpdcc" => match args.as_slice() {
            [] => Ok(Command::Mpdcc(None)),
            ["run"] => Ok(Command::Mpdcc(Some(1))),
            ["run", n] => match n.parse::<u32>() {
                Ok(n) if (1..=crate::mpdcc::hil::MAX_PERIODS).contains(&n) => {
                    Ok(Command::Mpdcc(Some(n)))
                }
                _ => Err(ParseError::BadArgs(
                    "mpdcc",
                    "periods must be a whole number in 1..=20",
                )),
            },
            _ => Err(ParseError::BadArgs(
                "mpdcc",
                "expected `mpdcc` or `mpdcc run [<periods>]`",
            )),
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

/// The `ERR bad-args` line of a refused `config` value.
fn config_error<W: Write>(
    out: &mut W,
    name: &str,
    e: config::ConfigError,
) -> Result<Action, fmt::Error> {
    let (w, more) = clip(name);
    write_err(
        out,
        ErrorCode::BadArgs,
        format_args!("config: {w}{more}: {e}"),
    )?;
    Ok(Action::None)
}

/// Writes the reply of `cmd`, ending with `OK` or `ERR`.
pub fn execute<W: Write>(
    cmd: Command<'_>,
    ctx: &Context,
    drv: &mut dyn DriveOps,
    out: &mut W,
) -> Result<Action, fmt::Error> {
    macro_rules! try_drive {
        ($name:expr, $e:expr) => {
            match $e {
                Ok(v) => v,
                Err(e) => {
                    drive::write_error(out, $name, e)?;
                    return Ok(Action::None);
                }
            }
        };
    }
    // The PMSM's gates and the MPDCC page belong to the HIL loop in
    // `mode mpdcc`.
    let pmsm_or_page = match cmd {
        Command::Enable => Some("enable"),
        Command::Step(..) => Some("step"),
        Command::Sweep { .. } => Some("sweep"),
        Command::Mpdcc(Some(_)) => Some("mpdcc"),
        _ => None,
    };
    if let Some(name) = pmsm_or_page {
        if drv.mpdcc_live().is_some() {
            drive::write_error(out, name, DriveError::MpdccMode)?;
            return Ok(Action::None);
        }
    }
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
            drive::write_status(out, &drv.status())?;
        }
        Command::DebugPanic => return Ok(Action::Panic),
        Command::Mode(None) => match drv.mpdcc_live() {
            Some(_) => out.write_str("mode: mpdcc\r\n")?,
            None => write!(out, "mode: {}\r\n", drv.mode().name())?,
        },
        Command::Mode(Some(ModeSel::Pl(m))) => {
            try_drive!("mode", drv.set_mode(m));
            write!(out, "mode: {}\r\ngates: off (safe state)\r\n", m.name())?;
        }
        Command::Mode(Some(ModeSel::Mpdcc)) => {
            try_drive!("mode", drv.set_mpdcc_mode());
            out.write_str(
                "mode: mpdcc\r\ngates: off (safe state)\r\nmpdcc_loop: started, one decision \
                 per control period (IM + 5L-ANPC plant on the PS, core on the PL; `status`)\r\n",
            )?;
        }
        Command::Enable => {
            try_drive!("enable", drv.enable());
            out.write_str("gates: on\r\n")?;
        }
        Command::Disable => {
            try_drive!("disable", drv.disable());
            out.write_str("gates: off (safe state)\r\n")?;
        }
        Command::Torque(None) => write!(out, "torque_ref: {:.4} Nm\r\n", drv.torque_ref())?,
        Command::Torque(Some(x)) => {
            try_drive!("torque", drv.set_torque_ref(x));
            write!(out, "torque_ref: {:.4} Nm\r\n", drv.torque_ref())?;
        }
        Command::Step(nm, w) => {
            let r = try_drive!("step", drv.step(nm, w));
            drive::write_step(out, &r)?;
        }
        Command::Fault => {
            let f = try_drive!("fault", drv.faults());
            out.write_str("fault: ")?;
            f.write_names(out)?;
            out.write_str("\r\n")?;
        }
        Command::FaultClear => {
            let f = try_drive!("fault", drv.clear_faults());
            out.write_str("fault: ")?;
            f.write_names(out)?;
            out.write_str("\r\ngates: off (safe state)\r\n")?;
        }
        Command::FaultHistory => {
            let mut shown = 0;
            let mut total = 0;
            for k in 0..crate::servo::faults::HISTORY_LEN {
                let (r, t) = try_drive!("fault", drv.fault_record(k));
                total = t;
                let Some(r) = r else { break };
                shown += 1;
                write!(out, "#{shown} ")?;
                r.write_summary(out)?;
                out.write_str("\r\n")?;
            }
            write!(out, "history: {shown} shown, {total} since boot\r\n")?;
        }
        Command::DebugFault(f) => {
            try_drive!("debug", drv.inject(f));
            out.write_str("injected\r\n")?;
        }
        Command::DebugStall(ms) => {
            try_drive!("debug", drv.stall(ms));
            write!(out, "stalled: {ms} ms\r\n")?;
        }
        Command::DebugBench => {
            let b = try_drive!("debug", drv.bench());
            write!(out, "foc_step: {} instructions\r\n", b.foc_step)?;
            write!(out, "mpdtc_period: {} instructions\r\n", b.mpdtc_period)?;
            write!(out, "mpdcc_boundary: {} instructions\r\n", b.mpdcc_boundary)?;
            write!(out, "mpdcc_expm: {} instructions\r\n", b.mpdcc_expm)?;
            write!(out, "runs: {}\r\n", b.runs)?;
        }
        Command::ConfigList => {
            let c = Config::from_servo(&try_drive!("config", drv.config()));
            for (p, &v) in config::PARAMS.iter().zip(c.values()) {
                config::write_list_line(out, p, v)?;
                out.write_str("\r\n")?;
            }
        }
        Command::ConfigGet(name) => {
            let c = Config::from_servo(&try_drive!("config", drv.config()));
            let Some((i, p)) = config::lookup(name) else {
                return config_error(out, name, config::ConfigError::UnknownName);
            };
            config::write_value(out, p, c.values()[i])?;
            out.write_str("\r\n")?;
        }
        Command::ConfigSet(name, value) => {
            let sc = try_drive!("config", drv.config());
            let mut c = Config::from_servo(&sc);
            let set = config::parse_value(value).and_then(|v| c.set(&sc, name, v));
            if let Err(e) = set {
                return config_error(out, name, e);
            }
            try_drive!("config", drv.reconfigure(&c.apply(&sc)));
            if let Some((i, p)) = config::lookup(name) {
                config::write_value(out, p, c.values()[i])?;
                out.write_str("\r\n")?;
            }
        }
        Command::ConfigReset => {
            let sc = try_drive!("config", drv.config());
            let c = Config::default();
            if let Err(e) = c.check(&sc) {
                return config_error(out, "reset", e);
            }
            try_drive!("config", drv.reconfigure(&c.apply(&sc)));
            out.write_str("config: defaults\r\n")?;
        }
        Command::ConfigSave => {
            let slot = try_drive!("config", drv.save_config());
            write!(out, "config: saved to slot{slot}\r\n")?;
        }
        Command::ConfigSchema => {
            config::write_schema(out)?;
            out.write_str("\r\n")?;
        }
        Command::CaptureArm(t, pre) => {
            try_drive!("capture", drv.capture_arm(t, pre));
            write!(out, "capture: armed, pre {pre} samples\r\n")?;
        }
        Command::CaptureTrigger => {
            try_drive!("capture", drv.capture_trigger());
            out.write_str("capture: triggered by hand\r\n")?;
        }
        Command::CaptureStatus => {
            let st = try_drive!("capture", drv.capture_status());
            write!(out, "capture: {}\r\n", st.state.name())?;
            write!(out, "samples: {}\r\n", st.count)?;
            write!(out, "trigger_index: {}\r\n", st.trig_index)?;
            write!(
                out,
                "sample_period: {:.3} us\r\n",
                drv.capture_period_s() * 1e6
            )?;
        }
        Command::CaptureDump => {
            let st = try_drive!("capture", drv.capture_status());
            if st.state != CapState::Done {
                write_err(
                    out,
                    ErrorCode::BadArgs,
                    format_args!(
                        "capture: no complete record (state {}; `capture arm` first)",
                        st.state.name()
                    ),
                )?;
                return Ok(Action::None);
            }
            let ts = drv.capture_period_s();
            out.write_str("t_ms,i_d_A,i_q_A,torque_Nm,torque_ref_Nm,sw_state,adc_ia_raw\r\n")?;
            for i in 0..st.count {
                let x = try_drive!("capture", drv.capture_sample(i));
                let t = (f64::from(i) - f64::from(st.trig_index)) * ts * 1e3;
                write!(
                    out,
                    "{t:.4},{:.3},{:.3},{:.4},{:.4},{},{}\r\n",
                    x.i_d_a, x.i_q_a, x.torque_nm, x.torque_ref_nm, x.sw, x.sel as i16
                )?;
            }
        }
        Command::Sweep {
            f_start_hz,
            f_stop_hz,
            amp_nm,
            points,
        } => {
            let rate = drv.status().control_rate_hz;
            if f_stop_hz > 0.25 * rate {
                write_err(
                    out,
                    ErrorCode::BadArgs,
                    format_args!(
                        "sweep: f_stop {f_stop_hz} Hz is above a quarter of the control rate \
                         ({rate:.0} Hz)"
                    ),
                )?;
                return Ok(Action::None);
            }
            let mut pts: heapless::Vec<SweepPoint, { SWEEP_POINTS_MAX as usize }> =
                heapless::Vec::new();
            let ratio = f_stop_hz / f_start_hz;
            out.write_str("f_hz gain_db phase_deg\r\n")?;
            for k in 0..points {
                let f = f_start_hz * libm::pow(ratio, f64::from(k) / f64::from(points - 1));
                let p = match drv.sweep_point(f, amp_nm) {
                    Ok(p) => p,
                    Err(e) => {
                        drv.sweep_end();
                        drive::write_error(out, "sweep", e)?;
                        return Ok(Action::None);
                    }
                };
                write!(out, "{:.1} {:.2} {:.1}\r\n", p.f_hz, p.gain_db, p.phase_deg)?;
                // Capacity is SWEEP_POINTS_MAX, the parser's bound on `points`.
                let _ = pts.push(p);
            }
            drv.sweep_end();
            match bandwidth_hz(&pts) {
                Some(b) => write!(out, "bandwidth: {b:.0} Hz\r\n")?,
                None => write!(
                    out,
                    "bandwidth: none (gain above -3 dB up to {f_stop_hz:.0} Hz)\r\n"
                )?,
            }
        }
        Command::Mpdcc(run) => {
            let r = match run {
                Some(n) => try_drive!("mpdcc", drv.mpdcc_run(n)),
                None => match drv.mpdcc_report() {
                    Some(r) => r,
                    None => {
                        out.write_str("mpdcc: no run yet (`mpdcc run [<periods>]`)\r\n")?;
                        out.write_str("OK\r\n")?;
                        return Ok(Action::None);
                    }
                },
            };
            drive::write_mpdcc(out, &r)?;
        }
        Command::Tel(c) => return super::tel::execute(c, drv.telemetry(), out),
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
            },
        }
    }

    /// Parses and executes `line` the way the firmware does.
    fn reply(line: &str) -> String {
        reply_on(&mut TestDrive::new(), line)
    }

    fn reply_on(d: &mut TestDrive, line: &str) -> String {
        let mut out = String::new();
        match parse(line) {
            Ok(c) => {
                execute(c, &ctx(), d, &mut out).unwrap();
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
    fn mpdcc_command() {
        assert_eq!(
            reply("mpdcc"),
            "mpdcc: no run yet (`mpdcc run [<periods>]`)\r\nOK\r\n"
        );
        // The test drive has no MPDCC page.
        assert_eq!(
            reply("mpdcc run"),
            "ERR unsupported mpdcc: not available here\r\n"
        );
        for bad in ["mpdcc run 0", "mpdcc run 21", "mpdcc run x", "mpdcc go"] {
            assert!(reply(bad).starts_with("ERR bad-args mpdcc: "), "{bad}");
        }
        assert_eq!(parse("mpdcc run 20"), Ok(Command::Mpdcc(Some(20))));
        let r = crate::mpdcc::hil::HilReport {
            periods: 2,
            decisions: 2400,
            kinds: [2300, 96, 4],
            mean_cycles: 91.96,
            worst_cycles: 166,
            fsw_hz: 116.72,
            thd_percent: 7.791,
            max_i_err_pu: 0.12345,
        };
        let mut out = String::new();
        drive::write_mpdcc(&mut out, &r).unwrap();
        assert_eq!(
            out,
            "mpdcc: 2 measured fundamental periods after 1 warm-up (plant on the PS, core on \
             the PL page)\r\n\
             decisions: 2400 (kept 2300, optimal 96, deadlock 4)\r\n\
             core_cycles: mean 92.0, worst 166 (PL clock cycles)\r\n\
             f_sw: 116.7 Hz\r\n\
             thd: 7.79 %\r\n\
             i_err_max: 0.1235 pu\r\n"
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
            "ERR bad-args debug: expected `debug panic`, `debug stall <ms>`, `debug bench` or `debug fault <f>`\r\n"
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
        let a = execute(
            parse("debug panic").unwrap(),
            &ctx(),
            &mut TestDrive::new(),
            &mut out,
        )
        .unwrap();
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
            if !line.contains(['<', '|']) {
                assert!(parse(&line).is_ok(), "{line}");
            }
            // Every alternative of the synopsis, placeholders filled in.
            let args = s
                .args
                .replace("<Nm>", "0.1")
                .replace("<window_ms>", "2")
                .replace("<ms>", "5")
                .replace("<f>", "adc-stuck")
                .replace("<trigger>", "torque>0.2")
                .replace("<pre_samples>", "10")
                .replace("<f_start_hz>", "100")
                .replace("<f_stop_hz>", "1000")
                .replace("<amplitude_nm>", "0.1")
                .replace("<points>", "4")
                .replace("<periods>", "2")
                .replace("<rate_hz>", "1000")
                .replace("<channels>", "torque,i_q")
                .replace(['[', ']'], "");
            for alt in args.split('|') {
                let line = std::format!("{} {}", s.name, alt);
                assert!(parse(&line).is_ok(), "{line}");
            }
        }
    }

    use crate::console::drive::{Bench, DriveError, DriveOps, DriveStatus, Injection, PlKind};
    use crate::pl::fake::FakePl;
    use crate::pl::fault::Faults;
    use crate::servo::faults::FaultRecord;
    use crate::servo::{Servo, ServoConfig, StepResult};

    /// The console's view of a drive: the real `Servo` on the fake PL,
    /// control periods run by hand.
    struct TestDrive {
        servo: Servo,
        pl: FakePl,
        stalled_ms: u32,
        /// `mode mpdcc`'s loop (its progress set by hand).
        hil: Option<crate::mpdcc::hil::PacedStatus>,
    }

    impl TestDrive {
        fn new() -> Self {
            let mut servo = Servo::new(&ServoConfig::default()).unwrap();
            let mut pl = FakePl::new();
            servo.init(&mut pl).unwrap();
            Self {
                servo,
                pl,
                stalled_ms: 0,
                hil: None,
            }
        }
    }

    impl DriveOps for TestDrive {
        fn mode(&mut self) -> Mode {
            self.servo.mode()
        }
        fn set_mode(&mut self, m: Mode) -> Result<(), DriveError> {
            self.servo.set_mode(&mut self.pl, m)?;
            self.hil = None;
            Ok(())
        }
        fn set_mpdcc_mode(&mut self) -> Result<(), DriveError> {
            self.servo.set_mode(&mut self.pl, Mode::Off)?;
            self.hil = Some(Default::default());
            Ok(())
        }
        fn mpdcc_live(&mut self) -> Option<crate::mpdcc::hil::PacedStatus> {
            self.hil
        }
        fn enable(&mut self) -> Result<(), DriveError> {
            Ok(self.servo.enable(&mut self.pl)?)
        }
        fn disable(&mut self) -> Result<(), DriveError> {
            Ok(self.servo.disable(&mut self.pl)?)
        }
        fn torque_ref(&mut self) -> f64 {
            self.servo.torque_ref_nm()
        }
        fn set_torque_ref(&mut self, nm: f64) -> Result<(), DriveError> {
            Ok(self.servo.set_torque_ref(nm)?)
        }
        fn step(&mut self, nm: f64, window_s: f64) -> Result<StepResult, DriveError> {
            self.servo.begin_step(&mut self.pl, nm, window_s)?;
            for _ in 0..2000 {
                self.servo.control_step(&mut self.pl).unwrap();
                if let Some(r) = self.servo.step_result() {
                    return Ok(r);
                }
            }
            Err(DriveError::Timeout)
        }
        fn faults(&mut self) -> Result<Faults, DriveError> {
            Ok(self.servo.faults(&mut self.pl).unwrap())
        }
        fn clear_faults(&mut self) -> Result<Faults, DriveError> {
            Ok(self.servo.clear_faults(&mut self.pl)?)
        }
        fn stall(&mut self, ms: u32) -> Result<(), DriveError> {
            self.stalled_ms += ms;
            Ok(())
        }
        fn status(&mut self) -> DriveStatus {
            DriveStatus {
                mode: self.servo.mode(),
                mpdtc_autonomous: !self.servo.config().mpdtc_ps_fed,
                gates_on: self.servo.gates_on(&mut self.pl).unwrap(),
                faults: self.servo.faults(&mut self.pl).unwrap(),
                measured: self.servo.measured(),
                torque_ref_nm: self.servo.torque_ref_nm(),
                control_rate_hz: self.servo.control_rate_hz(),
                periods: self.servo.periods(),
                overruns: self.servo.overruns(),
                pl: PlKind::Simulated,
                sim_time_scale: Some(4.0),
                store: None,
                mpdcc: self.hil,
            }
        }
        fn bench(&mut self) -> Result<Bench, DriveError> {
            Err(DriveError::Unsupported)
        }
        fn config(&mut self) -> Result<ServoConfig, DriveError> {
            Ok(*self.servo.config())
        }
        fn fault_record(&mut self, k: usize) -> Result<(Option<FaultRecord>, u32), DriveError> {
            let h = self.servo.fault_history();
            Ok((h.records().nth(k).copied(), h.total))
        }
        fn inject(&mut self, f: Injection) -> Result<(), DriveError> {
            match f {
                Injection::AdcStuck => {
                    crate::pl::adc::Adc(&mut self.pl)
                        .set_enabled(false)
                        .unwrap();
                    Ok(())
                }
                _ => Err(DriveError::Unsupported),
            }
        }
        fn reconfigure(&mut self, cfg: &ServoConfig) -> Result<(), DriveError> {
            Ok(self.servo.reconfigure(&mut self.pl, cfg)?)
        }
    }

    #[test]
    fn status_lists_the_drive_with_units() {
        let r = reply("status");
        for line in [
            "uptime: 12.000042 s",
            "ticks: 12000 (rate 1000 Hz)",
            "mode: off",
            "mpdtc_path: autonomous (PL front end, PS writes the torque reference)",
            "gates: off (safe state)",
            "fault: none",
            "torque: 0.0000 Nm",
            "torque_ref: 0.0000 Nm",
            "i_d: 0.000 A",
            "i_q: 0.000 A",
            "speed: 0.0 rad/s",
            "control_rate: 63939 Hz",
            "periods: 0",
            "overruns: 0",
            "pl: simulated",
            "sim_time_scale: 4.00",
        ] {
            assert!(r.contains(&std::format!("{line}\r\n")), "{line}: {r}");
        }
        assert_one_final_line(&r);
    }

    #[test]
    fn mode_enable_disable() {
        let mut d = TestDrive::new();
        assert_eq!(reply_on(&mut d, "mode"), "mode: off\r\nOK\r\n");
        assert_eq!(
            reply_on(&mut d, "enable"),
            "ERR mode-off enable: mode is off (set `mode foc` or `mode mpdtc` first)\r\n"
        );
        assert!(reply_on(&mut d, "mode foc").ends_with("OK\r\n"));
        assert_eq!(reply_on(&mut d, "enable"), "gates: on\r\nOK\r\n");
        assert!(reply_on(&mut d, "status").contains("gates: on\r\n"));
        // A mode change turns the gates off.
        assert_eq!(
            reply_on(&mut d, "mode mpdtc"),
            "mode: mpdtc\r\ngates: off (safe state)\r\nOK\r\n"
        );
        assert!(reply_on(&mut d, "status").contains("gates: off (safe state)\r\n"));
        assert_eq!(
            reply_on(&mut d, "disable"),
            "gates: off (safe state)\r\nOK\r\n"
        );
    }

    /// `mode mpdcc`: the PMSM gates go off and stay off, the MPDCC page
    /// belongs to the loop, `status` shows its progress; another mode ends it.
    #[test]
    fn mpdcc_mode_owns_the_page_and_keeps_the_gates_off() {
        let mut d = TestDrive::new();
        assert!(reply_on(&mut d, "mode foc").ends_with("OK\r\n"));
        assert_eq!(reply_on(&mut d, "enable"), "gates: on\r\nOK\r\n");
        let r = reply_on(&mut d, "mode mpdcc");
        assert!(
            r.starts_with("mode: mpdcc\r\ngates: off (safe state)\r\nmpdcc_loop: started"),
            "{r}"
        );
        assert!(!d.servo.gates_on(&mut d.pl).unwrap());
        assert_eq!(d.servo.mode(), Mode::Off);
        assert_eq!(reply_on(&mut d, "mode"), "mode: mpdcc\r\nOK\r\n");
        for (line, name) in [
            ("enable", "enable"),
            ("step 0.2", "step"),
            ("sweep 10 100 0.1", "sweep"),
            ("mpdcc run", "mpdcc"),
        ] {
            let r = reply_on(&mut d, line);
            assert!(
                r.starts_with(&format!("ERR mpdcc-mode {name}: ")),
                "{line}: {r}"
            );
            assert_one_final_line(&r);
        }
        assert!(!d.servo.gates_on(&mut d.pl).unwrap());
        let mut h = crate::mpdcc::hil::PacedStatus::default();
        h.report.decisions = 1200;
        h.report.kinds = [900, 290, 10];
        h.report.mean_cycles = 99.04;
        h.report.worst_cycles = 173;
        h.late = 2;
        h.plant_time_s = 0.03;
        d.hil = Some(h);
        let st = reply_on(&mut d, "status");
        assert!(st.contains("\r\nmode: mpdcc\r\nmpdcc_loop: 1200 decisions (kept 900, optimal 290, deadlock 10), 2 late, plant time 30.000 ms\r\nmpdcc_cycles: mean 99.0, worst 173 PL cycles\r\nmpdcc_period: none measured yet"), "{st}");
        h.report.periods = 3;
        h.report.fsw_hz = 251.25;
        h.report.thd_percent = 4.567;
        h.report.max_i_err_pu = 0.12345;
        h.stopped = Some(crate::mpdcc::hil::HilError::Page(
            crate::pl::mpdcc::MpdccError::Timeout,
        ));
        d.hil = Some(h);
        let st = reply_on(&mut d, "status");
        assert!(st.contains("mpdcc_period: 3 measured; the last: f_sw 251.2 Hz, THD 4.57 %, max current error 0.1235 pu\r\nmpdcc_stopped: MPDCC page: "), "{st}");
        assert!(reply_on(&mut d, "mode off").ends_with("OK\r\n"));
        assert_eq!(reply_on(&mut d, "mode"), "mode: off\r\nOK\r\n");
        let st = reply_on(&mut d, "status");
        assert!(
            st.contains("\r\nmode: off\r\n") && !st.contains("mpdcc"),
            "{st}"
        );
    }

    #[test]
    fn bad_mode_and_torque_arguments_change_nothing() {
        let mut d = TestDrive::new();
        assert!(reply_on(&mut d, "mode foc").ends_with("OK\r\n"));
        assert!(reply_on(&mut d, "torque 0.25").ends_with("OK\r\n"));
        for bad in [
            "mode FOC",
            "mode 1",
            "mode foc mpdtc",
            "torque nan",
            "torque NaN",
            "torque inf",
            "torque -inf",
            "torque infinity",
            "torque 1.5",
            "torque -1.0001",
            "torque 1e3",
            "torque abc",
            "torque 0.1Nm",
            "torque 0.1 0.2",
        ] {
            let r = reply_on(&mut d, bad);
            assert!(r.starts_with("ERR bad-args "), "{bad}: {r}");
            assert_one_final_line(&r);
        }
        assert_eq!(reply_on(&mut d, "mode"), "mode: foc\r\nOK\r\n");
        assert_eq!(
            reply_on(&mut d, "torque"),
            "torque_ref: 0.2500 Nm\r\nOK\r\n"
        );
        assert_eq!(
            reply_on(&mut d, "torque -1"),
            "torque_ref: -1.0000 Nm\r\nOK\r\n"
        );
    }

    #[test]
    fn step_needs_gates_and_prints_the_metrics() {
        let mut d = TestDrive::new();
        assert!(reply_on(&mut d, "mode foc").ends_with("OK\r\n"));
        assert_eq!(
            reply_on(&mut d, "step 0.4"),
            "ERR gates-off step: gates are off (`enable` first)\r\n"
        );
        for bad in [
            "step",
            "step x",
            "step 0.4 0",
            "step 0.4 21",
            "step 0.4 -1",
            "step 2",
        ] {
            assert!(reply_on(&mut d, bad).starts_with("ERR bad-args "), "{bad}");
        }
        assert!(reply_on(&mut d, "enable").ends_with("OK\r\n"));
        let r = reply_on(&mut d, "step 0.4 1");
        // The fake PL has no motor: the torque stays 0, never settles.
        assert!(
            r.starts_with("settling_time: none (not settled within 1.00 ms)\r\n"),
            "{r}"
        );
        assert!(r.contains("overshoot: 0.0 %\r\n"), "{r}");
        assert!(r.contains("switching: ") && r.contains(" kHz\r\n"), "{r}");
        assert!(r.ends_with("final: 0.0000 Nm\r\nOK\r\n"), "{r}");
        assert_eq!(
            reply_on(&mut d, "torque"),
            "torque_ref: 0.4000 Nm\r\nOK\r\n"
        );
        // A step of zero (or below the resolution) has no settling time.
        for same in ["step 0.4", "step 0.42"] {
            let r = reply_on(&mut d, same);
            assert!(
                r.starts_with(
                    "ERR bad-args step: the reference is already 0.4000 Nm; a step to 0.4"
                ),
                "{r}"
            );
            assert!(
                r.ends_with("is smaller than 0.0500 Nm and has no settling time\r\n"),
                "{r}"
            );
        }
        assert_eq!(
            reply_on(&mut d, "torque"),
            "torque_ref: 0.4000 Nm\r\nOK\r\n"
        );
    }

    #[test]
    fn faults_are_listed_cleared_and_block_enable() {
        let mut d = TestDrive::new();
        d.pl.set(crate::regmap::FAULT_STATUS_ADDR, Faults::WATCHDOG | 1);
        assert_eq!(
            reply_on(&mut d, "fault"),
            "fault: OVERCURRENT WATCHDOG\r\nOK\r\n"
        );
        assert!(reply_on(&mut d, "mode mpdtc").ends_with("OK\r\n"));
        assert_eq!(
            reply_on(&mut d, "enable"),
            "ERR fault-latched enable: fault latched: OVERCURRENT WATCHDOG (`fault clear` first)\r\n"
        );
        assert!(reply_on(&mut d, "status").contains("fault: OVERCURRENT WATCHDOG\r\n"));
        assert_eq!(
            reply_on(&mut d, "fault clear"),
            "fault: none\r\ngates: off (safe state)\r\nOK\r\n"
        );
        assert_eq!(reply_on(&mut d, "fault x").lines().count(), 1);
        assert_eq!(reply_on(&mut d, "enable"), "gates: on\r\nOK\r\n");
    }

    #[test]
    fn debug_stall_and_bench_arguments() {
        let mut d = TestDrive::new();
        assert_eq!(
            reply_on(&mut d, "debug stall 300"),
            "stalled: 300 ms\r\nOK\r\n"
        );
        assert_eq!(d.stalled_ms, 300);
        for bad in [
            "debug stall",
            "debug stall 0",
            "debug stall -5",
            "debug stall 10001",
            "debug stall 1.5",
        ] {
            assert!(reply_on(&mut d, bad).starts_with("ERR bad-args "), "{bad}");
        }
        assert_eq!(d.stalled_ms, 300);
        assert_eq!(
            reply_on(&mut d, "debug bench"),
            "ERR unsupported debug: not available here\r\n"
        );
    }

    #[test]
    fn config_list_get_set_reset_schema() {
        let mut d = TestDrive::new();
        let r = reply_on(&mut d, "config list");
        let lines: std::vec::Vec<&str> = r.trim_end().split("\r\n").collect();
        assert_eq!(lines.len(), crate::config::N_PARAMS + 1, "{r}");
        assert!(
            lines.contains(&"mpdtc_t_tol = 0.08 Nm  [0..0.5]  MPDTC torque tolerance band T_tol")
        );
        assert!(lines.contains(&"dead_time = 50 cycles  [0..1023]  inverter dead time (DEAD_TIME), PL clock cycles of 10 ns"));
        assert_one_final_line(&r);
        assert_eq!(
            reply_on(&mut d, "config get mpdtc_t_tol"),
            "mpdtc_t_tol = 0.08 Nm\r\nOK\r\n"
        );
        assert_eq!(
            reply_on(&mut d, "config set mpdtc_t_tol 0.05"),
            "mpdtc_t_tol = 0.05 Nm\r\nOK\r\n"
        );
        assert_eq!(
            reply_on(&mut d, "config get mpdtc_t_tol"),
            "mpdtc_t_tol = 0.05 Nm\r\nOK\r\n"
        );
        let r = reply_on(&mut d, "config schema");
        assert_eq!(r.matches("\r\n").count(), 2, "{r}");
        assert!(r.starts_with("[{\"name\":\"motor_r_s\""), "{r}");
        assert!(r.ends_with("]\r\nOK\r\n"), "{r}");
        assert_eq!(
            reply_on(&mut d, "config reset"),
            "config: defaults\r\nOK\r\n"
        );
        assert_eq!(
            reply_on(&mut d, "config get mpdtc_t_tol"),
            "mpdtc_t_tol = 0.08 Nm\r\nOK\r\n"
        );
    }

    #[test]
    fn config_bad_input_changes_nothing() {
        let mut d = TestDrive::new();
        let before = *d.servo.config();
        for (bad, msg) in [
            ("config", "config: expected `config list|get <name>|set <name> <value>|reset|schema|save`"),
            ("config set mpdtc_t_tol", "config: expected `config list|get <name>|set <name> <value>|reset|schema|save`"),
            ("config get nothing", "config: nothing: no such parameter (see `config list`)"),
            ("config set nothing 1", "config: nothing: no such parameter (see `config list`)"),
            ("config set mpdtc_t_tol nan", "config: mpdtc_t_tol: expected a finite number"),
            ("config set mpdtc_t_tol inf", "config: mpdtc_t_tol: expected a finite number"),
            ("config set mpdtc_t_tol -inf", "config: mpdtc_t_tol: expected a finite number"),
            ("config set mpdtc_t_tol 0.1Nm", "config: mpdtc_t_tol: expected a finite number"),
            ("config set mpdtc_t_tol 0.6", "config: mpdtc_t_tol: out of range [0..0.5] Nm"),
            ("config set motor_pole_pairs 7.5", "config: motor_pole_pairs: expected a whole number"),
            ("config set obs_kp 1000", "config: obs_kp: invalid parameter `obs_kp_v_per_a`: observer unstable: roots of eq. (16) outside the unit circle"),
        ] {
            assert_eq!(
                reply_on(&mut d, bad),
                std::format!("ERR bad-args {msg}\r\n"),
                "{bad}"
            );
        }
        assert_eq!(d.servo.config(), &before);
        // With the gates on, only the torque limit may change.
        assert!(reply_on(&mut d, "mode foc").ends_with("OK\r\n"));
        assert!(reply_on(&mut d, "enable").ends_with("OK\r\n"));
        assert_eq!(
            reply_on(&mut d, "config set mpdtc_t_tol 0.05"),
            "ERR gates-on config: needs the gates off (`disable` first)\r\n"
        );
        assert_eq!(d.servo.config(), &before);
        assert_eq!(
            reply_on(&mut d, "config set torque_limit 0.5"),
            "torque_limit = 0.5 Nm\r\nOK\r\n"
        );
        assert!(reply_on(&mut d, "torque 0.6").starts_with("ERR bad-args "));
        assert_eq!(
            reply_on(&mut d, "config reset"),
            "config: defaults\r\nOK\r\n"
        );
        assert_eq!(d.servo.config(), &before);
    }
}
