//! `imp <pos> <vel> <kp> <kd> <torque_ff>`: the impedance law.
use super::super::drive::{self, DriveOps};
use super::{mpdcc_owns, number, Outcome, ParseError, Spec};
use core::fmt::{self, Write};
use models::motion::law::Impedance;

/// The `imp` command.
pub const IMP: Spec = Spec {
    name: "imp",
    args: "<rev> <rev/s> <Nm/rev> <Nm s/rev> <Nm>",
    help: "impedance: torque = kp (p - p_meas) + kd (v - v_meas) + t_ff every control period, \
           clamped to torque_limit (0 <= kp <= imp_kp_max, 0 <= kd <= imp_kd_max; gates on)",
};

/// Parses the arguments of `imp`.
pub fn parse<'a>(args: &[&'a str]) -> Result<Impedance, ParseError<'a>> {
    let [p, v, kp, kd, t] = args else {
        return Err(ParseError::BadArgs(
            "imp",
            "expected <pos_rev> <vel_rev_s> <kp_Nm_per_rev> <kd_Nm_s_per_rev> <torque_ff_Nm>",
        ));
    };
    let n = |s: &str| number(s).ok_or(ParseError::BadArgs("imp", "expected five finite numbers"));
    Ok(Impedance {
        p: n(p)?,
        v: n(v)?,
        kp: n(kp)?,
        kd: n(kd)?,
        t_ff: n(t)?,
    })
}

/// Writes the reply of `imp`.
pub fn execute<W: Write>(
    c: Impedance,
    drv: &mut dyn DriveOps,
    out: &mut W,
) -> Result<Outcome, fmt::Error> {
    if mpdcc_owns(drv, out, "imp")? {
        return Ok(Outcome::Final);
    }
    try_drive!(out, "imp", drv.set_impedance(&c));
    write!(
        out,
        "loop: impedance\r\nposition_target: {:.6} rev\r\nvelocity_target: {:.4} rev/s\r\n\
         kp: {:.4} Nm/rev\r\nkd: {:.5} Nm s/rev\r\ntorque_ff: {:.4} Nm\r\n",
        c.p, c.v, c.kp, c.kd, c.t_ff
    )?;
    Ok(Outcome::Ok)
}
