//! `version` and `status`: what the firmware and the drive are.
use super::super::drive::{DriveOps, DriveStatus, PlKind};
use super::{no_args, Context, Outcome, ParseError, Spec};
use crate::hil::{HilError, PacedStatus};
use core::fmt::{self, Write};

/// The `version` command.
pub const VERSION: Spec = Spec {
    name: "version",
    args: "",
    help: "firmware crate version, git hash, build profile",
};

/// The `status` command.
pub const STATUS: Spec = Spec {
    name: "status",
    args: "",
    help: "uptime [s], ticks, console counters, then the drive: mode, gates, fault, torque \
           [Nm], i_d/i_q [A], electrical speed [rad/s], position [rev], velocity [rev/s], \
           control rate [Hz], periods, overruns, PL",
};

/// `version` or `status`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InfoCmd {
    /// `version`.
    Version,
    /// `status`.
    Status,
}

/// Parses `version` or `status` (`name`).
pub fn parse<'a>(name: &'static str, args: &[&'a str]) -> Result<InfoCmd, ParseError<'a>> {
    match name {
        "version" => no_args(args, InfoCmd::Version, "version"),
        "status" => no_args(args, InfoCmd::Status, "status"),
        _ => Err(ParseError::Unknown(name)),
    }
}

/// Writes the reply of `version` or `status`.
pub fn execute<W: Write>(
    c: InfoCmd,
    ctx: &Context,
    drv: &mut dyn DriveOps,
    out: &mut W,
) -> Result<Outcome, fmt::Error> {
    match c {
        InfoCmd::Version => {
            write!(
                out,
                "firmware {} git {} profile {}\r\n",
                ctx.version, ctx.git_hash, ctx.profile
            )?;
        }
        InfoCmd::Status => {
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
            write!(out, "log: {} frames dropped (ring full)\r\n", s.log_dropped)?;
            write_net(out, &s.net)?;
            let st = drv.status();
            write_status(out, &st)?;
            match drv.sensor_check_due() {
                Some(true) => out.write_str("sensor_check: due (runs at the next enable)\r\n")?,
                Some(false) => out.write_str("sensor_check: passed\r\n")?,
                None => {}
            }
            if let Some(g) = drv.gp0_guard() {
                write_guard(out, &g, st.pl)?;
            }
            if let Some(c) = drv.canopen() {
                write!(out, "canopen: {c}\r\n")?;
            }
        }
    }
    Ok(Outcome::Ok)
}

/// The `net:` and `can:` lines of `status`.
fn write_net<W: Write>(out: &mut W, n: &super::NetStatus) -> fmt::Result {
    match n.ipv4 {
        Some(([a, b, c, d], prefix)) => write!(
            out,
            "net: {a}.{b}.{c}.{d}/{prefix} ({})",
            if n.dhcp { "dhcp" } else { "static" }
        )?,
        None => out.write_str("net: no address")?,
    }
    write!(
        out,
        ", socketcand tcp {}: {}\r\n",
        crate::can_gateway::PORT,
        if n.client {
            "client connected"
        } else {
            "no client"
        }
    )?;
    let c = &n.can;
    write!(
        out,
        "can: {} frames in, {} frames out, {} dropped, {} errors\r\n",
        c.frames_in, c.frames_out, c.dropped, c.errors
    )
}

/// The `gp0_guard:` line of `status`. A failed guard is what an emulator
/// shows (QEMU has no PL behind GP0): the simulated PL, chosen only where
/// `PSS_IDCODE` says emulator (`crate::pl::presence::platform`), answers
/// instead, so the line says the failure is expected there. On a board
/// (any other `pl`) it is the reason the PL is unusable, without that note.
pub fn write_guard<W: Write>(
    out: &mut W,
    g: &crate::pl::presence::Guard,
    pl: PlKind,
) -> fmt::Result {
    let instead = match pl {
        PlKind::Simulated => Some("the simulated PL"),
        PlKind::RtlCosim => Some("the co-simulated RTL, over the bridge,"),
        PlKind::Bitstream(_) | PlKind::Absent => None,
    };
    match (g.check(), instead) {
        (Err(_), Some(who)) => write!(
            out,
            "gp0_guard: {g}; expected under QEMU (PSS_IDCODE reads as an emulator's): no \
             real PL behind GP0, so GP0 is left alone and {who} answers the drive's \
             registers\r\n"
        ),
        _ => write!(out, "gp0_guard: {g}\r\n"),
    }
}

/// The `mode mpdcc` lines of `status`: the paced HIL loop's progress.
pub fn write_paced<W: Write>(out: &mut W, h: &PacedStatus) -> fmt::Result {
    let r = &h.report;
    write!(
        out,
        "mpdcc_loop: {} decisions (kept {}, optimal {}, deadlock {}), {} late, plant time \
         {:.3} ms\r\n",
        r.decisions,
        r.kinds[0],
        r.kinds[1],
        r.kinds[2],
        h.late,
        h.plant_time_s * 1e3
    )?;
    write!(
        out,
        "mpdcc_cycles: mean {:.1}, worst {} PL cycles\r\n",
        r.mean_cycles, r.worst_cycles
    )?;
    if r.periods == 0 {
        out.write_str("mpdcc_period: none measured yet (the first period is the warm-up)\r\n")?;
    } else {
        write!(
            out,
            "mpdcc_period: {} measured; the last: f_sw {:.1} Hz, THD {:.2} %, max current \
             error {:.4} pu\r\n",
            r.periods, r.fsw_hz, r.thd_percent, r.max_i_err_pu
        )?;
    }
    if let Some(e) = h.stopped {
        out.write_str("mpdcc_stopped: ")?;
        write_hil_error(out, e)?;
        out.write_str(" (`mode mpdcc` restarts it)\r\n")?;
    }
    Ok(())
}

/// Why the HIL loop stopped, in words.
fn write_hil_error<W: Write>(out: &mut W, e: HilError) -> fmt::Result {
    match e {
        HilError::Periods => out.write_str("periods out of range"),
        HilError::Core(e) => write!(out, "the core's constants: {e:?}"),
        HilError::Page(e) => write!(out, "MPDCC page: {e}"),
        HilError::Loop(e) => write!(out, "plant: {e}"),
    }
}

/// The drive's `status` lines.
pub fn write_status<W: Write>(out: &mut W, s: &DriveStatus) -> fmt::Result {
    match &s.mpdcc {
        Some(h) => {
            out.write_str("mode: mpdcc\r\n")?;
            write_paced(out, h)?;
        }
        None => write!(out, "mode: {}\r\n", s.mode.name())?,
    }
    let path = if s.mpdtc_autonomous {
        "autonomous (PL front end, PS writes the torque reference)"
    } else {
        "ps-fed (PS Park transform and MPDTC_START)"
    };
    write!(out, "mpdtc_path: {path}\r\n")?;
    let gates = if s.gates_on { "on" } else { "off (safe state)" };
    write!(out, "gates: {gates}\r\n")?;
    out.write_str("fault: ")?;
    s.faults.write_names(out)?;
    out.write_str("\r\n")?;
    let m = &s.measured;
    write!(out, "torque: {:.4} Nm\r\n", m.torque_nm)?;
    write!(out, "torque_ref: {:.4} Nm\r\n", s.torque_ref_nm)?;
    write!(out, "i_d: {:.3} A\r\n", m.i_d_a)?;
    write!(out, "i_q: {:.3} A\r\n", m.i_q_a)?;
    write!(out, "speed: {:.1} rad/s\r\n", m.omega_e_rad_s)?;
    let mo = &s.motion;
    write!(out, "position: {:.6} rev\r\n", mo.position_rev)?;
    write!(out, "position_counts: {} counts\r\n", mo.counts)?;
    write!(out, "velocity: {:.4} rev/s\r\n", mo.velocity_rev_s)?;
    write!(out, "loop: {}\r\n", mo.kind.name())?;
    if let Some(left) = s.aligning_left_s {
        write!(
            out,
            "alignment: running, at most {:.0} ms left (pos, vel, imp wait for its end)\r\n",
            libm::ceil(left * 1e3)
        )?;
    }
    if mo.kind != crate::servo::motion::LoopKind::Torque {
        write!(out, "position_ref: {:.6} rev\r\n", mo.position_ref_rev)?;
        write!(out, "velocity_ref: {:.4} rev/s\r\n", mo.velocity_ref_rev_s)?;
        write!(
            out,
            "following_error: {:.1} counts\r\n",
            mo.following_error_counts
        )?;
    }
    write!(out, "control_rate: {:.0} Hz\r\n", s.control_rate_hz)?;
    write!(out, "periods: {}\r\n", s.periods)?;
    write!(out, "overruns: {}\r\n", s.overruns)?;
    write!(out, "control_irq: {}\r\n", s.control_irq)?;
    let l = &s.control_latency;
    if l.n > 0 {
        write!(
            out,
            "control_latency: min {} mean {:.1} max {} PL cycles (10 ns) after the boundary\r\n",
            l.min,
            l.mean(),
            l.max
        )?;
    }
    write!(out, "pl: {}\r\n", s.pl)?;
    if let Some(k) = s.sim_time_scale {
        write!(out, "sim_time_scale: {k:.2}\r\n")?;
    }
    if let Some(st) = &s.store {
        write!(
            out,
            "config_flash: slot0 {} slot1 {}, running ",
            st.slots[0].name(),
            st.slots[1].name()
        )?;
        match st.loaded {
            Some(k) => write!(out, "slot{k}\r\n")?,
            None => out.write_str("defaults\r\n")?,
        }
    }
    Ok(())
}
