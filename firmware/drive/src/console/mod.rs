//! The UART console: line editor, command grammar and replies.
//!
//! Protocol (what a host script can rely on):
//! - the firmware prints the prompt [`PROMPT`] (no newline) when it is ready
//!   for a line;
//! - a line ends with CR, LF or CRLF; an empty line only prints a new prompt;
//! - every command answers with zero or more lines and then exactly one final
//!   line, `OK` or `ERR <code> <message>`; every output line ends with CRLF;
//! - error codes are the kebab-case words of [`ErrorCode`].
//!
//! The target only moves bytes; everything here runs on the host in tests.

mod command;
pub mod drive;
mod editor;

pub use command::{
    execute, parse, write_parse_error, Action, CaptureCmd, Command, ConfigCmd, Context, DebugCmd,
    FaultCmd, InfoCmd, ModeSel, MotionCmd, NetStatus, ParseError, Spec, Status, Sweep, TelCmd,
    TelOps, COMMANDS, STALL_MAX_MS, STEP_WINDOW_DEFAULT_S, STEP_WINDOW_MAX_S,
};
pub use drive::{
    Bench, DriveError, DriveOps, DriveStatus, Injection, MmuReport, PlKind, StoreStatus,
};
pub use editor::{LineEditor, LineError, LINE_MAX};

/// Printed when the console is ready for a line.
pub const PROMPT: &str = "drive> ";

/// Error codes of the final `ERR <code> <message>` line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorCode {
    /// The first word is not a command.
    UnknownCommand,
    /// Wrong number or format of arguments.
    BadArgs,
    /// The line did not fit the line buffer ([`LINE_MAX`] bytes).
    LineTooLong,
    /// The line is not valid UTF-8.
    BadEncoding,
    /// The line holds a control character.
    BadChar,
    /// `enable` in mode off.
    ModeOff,
    /// `enable` while a fault is latched.
    FaultLatched,
    /// `step` with the gates off.
    GatesOff,
    /// No usable PL behind the drivers.
    PlAbsent,
    /// A PL register access failed.
    BusError,
    /// The control loop did not complete a request in time.
    Timeout,
    /// Not available in this build or setup.
    Unsupported,
    /// A change that needs the gates off, with them on.
    GatesOn,
    /// The configuration flash failed.
    FlashError,
    /// A PMSM or page command while `mode mpdcc` runs the MPDCC HIL loop.
    MpdccMode,
    /// The sensor check found a wrong current channel or encoder.
    SensorCheck,
    /// `calibrate`: a fit beyond its bound or a phase refused.
    Calibration,
    /// A long command stopped by Ctrl-C.
    Interrupted,
    /// A position, velocity or impedance command during the MPDTC's rotor
    /// alignment.
    Aligning,
    /// `pos zero` while a loop holds a position.
    Holding,
    /// `calibrate` while the rotor turns.
    RotorTurning,
    /// A command that moves the motor while a CANopen master owns it.
    CanopenOwns,
}

impl ErrorCode {
    /// The word printed after `ERR`.
    pub fn as_str(self) -> &'static str {
        match self {
            ErrorCode::UnknownCommand => "unknown-command",
            ErrorCode::BadArgs => "bad-args",
            ErrorCode::LineTooLong => "line-too-long",
            ErrorCode::BadEncoding => "bad-encoding",
            ErrorCode::BadChar => "bad-char",
            ErrorCode::ModeOff => "mode-off",
            ErrorCode::MpdccMode => "mpdcc-mode",
            ErrorCode::FaultLatched => "fault-latched",
            ErrorCode::GatesOff => "gates-off",
            ErrorCode::PlAbsent => "pl-absent",
            ErrorCode::BusError => "bus-error",
            ErrorCode::Timeout => "timeout",
            ErrorCode::Unsupported => "unsupported",
            ErrorCode::GatesOn => "gates-on",
            ErrorCode::FlashError => "flash-error",
            ErrorCode::SensorCheck => "sensor-check",
            ErrorCode::Calibration => "calibration",
            ErrorCode::Interrupted => "interrupted",
            ErrorCode::Aligning => "aligning",
            ErrorCode::Holding => "holding",
            ErrorCode::RotorTurning => "rotor-turning",
            ErrorCode::CanopenOwns => "canopen-owns",
        }
    }
}

/// Writes the final `ERR <code> <message>` line.
pub fn write_err<W: core::fmt::Write>(
    out: &mut W,
    code: ErrorCode,
    msg: core::fmt::Arguments<'_>,
) -> core::fmt::Result {
    write!(out, "ERR {} {}\r\n", code.as_str(), msg)
}

/// Writes the final `ERR` line for a line the editor rejected.
pub fn write_line_error<W: core::fmt::Write>(out: &mut W, e: LineError) -> core::fmt::Result {
    match e {
        LineError::TooLong => write_err(
            out,
            ErrorCode::LineTooLong,
            format_args!("line longer than {LINE_MAX} bytes, discarded"),
        ),
        LineError::BadEncoding => write_err(
            out,
            ErrorCode::BadEncoding,
            format_args!("line is not valid UTF-8, discarded"),
        ),
        LineError::BadChar(b) => write_err(
            out,
            ErrorCode::BadChar,
            format_args!("control character 0x{b:02x} in line, discarded"),
        ),
    }
}
