//! `mpdcc [run [<periods>]]`: paper 001's hardware-in-the-loop run.
use super::super::drive::{self, DriveOps};
use super::{mpdcc_owns, Outcome, ParseError, Spec};
use crate::hil::HilReport;
use core::fmt::{self, Write};

/// The `mpdcc` command.
pub const MPDCC: Spec = Spec {
    name: "mpdcc",
    args: "[run [<periods>]]",
    help: "paper 001's hardware-in-the-loop run: the induction machine and 5L-ANPC plant \
           on the PS feed the PL's MPDCC core each T_s through its register page; `run` \
           one warm-up and <periods> (default 1, 1..=20) measured fundamental periods, \
           without arguments the last run: decisions (kept, optimal, deadlock), core \
           cycles mean/worst [PL cycles], f_sw [Hz], THD [%], max current error [pu]",
};

/// Parses the arguments of `mpdcc`.
pub fn parse<'a>(args: &[&'a str]) -> Result<Option<u32>, ParseError<'a>> {
    match args {
        [] => Ok(None),
        ["run"] => Ok(Some(1)),
        ["run", n] => match n.parse::<u32>() {
            Ok(n) if (1..=crate::hil::MAX_PERIODS).contains(&n) => Ok(Some(n)),
            _ => Err(ParseError::BadArgs(
                "mpdcc",
                "periods must be a whole number in 1..=20",
            )),
        },
        _ => Err(ParseError::BadArgs(
            "mpdcc",
            "expected `mpdcc` or `mpdcc run [<periods>]`",
        )),
    }
}

/// Writes the reply of `mpdcc` (`run`: `Some(periods)`).
pub fn execute<W: Write>(
    run: Option<u32>,
    drv: &mut dyn DriveOps,
    out: &mut W,
) -> Result<Outcome, fmt::Error> {
    if run.is_some() && mpdcc_owns(drv, out, "mpdcc")? {
        return Ok(Outcome::Final);
    }
    let r = match run {
        Some(n) => try_drive!(out, "mpdcc", drv.mpdcc_run(n)),
        None => match drv.mpdcc_report() {
            Some(r) => r,
            None => {
                out.write_str("mpdcc: no run yet (`mpdcc run [<periods>]`)\r\n")?;
                return Ok(Outcome::Ok);
            }
        },
    };
    write_mpdcc(out, &r)?;
    Ok(Outcome::Ok)
}

/// The report of an `mpdcc run`, one `key: value unit` per line.
pub fn write_mpdcc<W: Write>(out: &mut W, r: &HilReport) -> fmt::Result {
    write!(
        out,
        "mpdcc: {} measured fundamental periods after 1 warm-up (plant on the PS, core on \
         the PL page)\r\n",
        r.periods
    )?;
    write!(
        out,
        "decisions: {} (kept {}, optimal {}, deadlock {})\r\n",
        r.decisions, r.kinds[0], r.kinds[1], r.kinds[2]
    )?;
    write!(
        out,
        "core_cycles: mean {:.1}, worst {} (PL clock cycles)\r\n",
        r.mean_cycles, r.worst_cycles
    )?;
    write!(out, "f_sw: {:.1} Hz\r\n", r.fsw_hz)?;
    write!(out, "thd: {:.2} %\r\n", r.thd_percent)?;
    write!(out, "i_err_max: {:.4} pu\r\n", r.max_i_err_pu)
}
