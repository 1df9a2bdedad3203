//! The drive's CANopen device as a transport reaches it: a received frame
//! goes to the device together with the servo and the PL
//! (`control::with_canopen`, the drive's state locked as for a console
//! command), and what it answers comes back to be sent. Time passes with
//! [`tick`]; frames the control interrupt produced (an EMCY of a fault)
//! wait in `control`'s queue for [`take_from_control`].
//!
//! A configuration object written over SDO is checked against the whole
//! configuration in the dictionary (as `config set`); the drive installs
//! it right after the answer, outside the lock, the way the console does.
//! 0x1010 "save" is `config save`, 0x1011 "load" `config reset`.
use crate::control;
use canopen::{CanFrame, Frames};
use drive::config::Config;
use drive::fieldbus::{ConfigValues, Link};
use drive::servo::{Servo, ServoConfig};
use regmap::bus::RegisterBus;

/// The dictionary's view of the configuration: the servo's, and whether
/// the gates are on (read back; a failed read counts as on, refusing
/// the parameters that need them off).
fn refresh<B: RegisterBus>(link: &mut Link<ConfigValues>, servo: &mut Servo, bus: &mut B) {
    let sc = *servo.config();
    link.obj.config = ConfigValues {
        values: Config::from_servo(&sc),
        base: sc,
        gates_on: servo.gates_on(bus).unwrap_or(true),
    };
}

/// What the dictionary's configuration now differs in from the servo's:
/// the configuration to install.
fn changed(link: &Link<ConfigValues>, servo: &Servo) -> Option<ServoConfig> {
    let c = &link.obj.config;
    (c.values != Config::from_servo(servo.config())).then(|| c.values.apply(&c.base))
}

/// A received frame; the frames to send, in order.
pub fn on_frame(f: &CanFrame) -> Frames {
    let r = control::with_canopen(|link, servo, bus| {
        refresh(link, servo, bus);
        let out = link.on_frame(f, servo, bus);
        let install = changed(link, servo);
        let req = core::mem::take(&mut link.obj.requests);
        (out, install, req, *servo.config())
    });
    let Some((out, install, req, base)) = r else {
        return Frames::new();
    };
    if let Some(cfg) = install {
        if control::reconfigure(&cfg).is_err() {
            defmt::warn!("canopen: a configuration object was not installed");
        }
    }
    if req.restore && control::reconfigure(&Config::default().apply(&base)).is_err() {
        defmt::warn!("canopen: 0x1011 restore refused (gates on?)");
    }
    if req.save && control::save_config().is_err() {
        defmt::warn!("canopen: 0x1010 save failed (flash)");
    }
    out.unwrap_or_default()
}

/// Time passes (uptime, microseconds): heartbeat, event-driven TPDOs and
/// the master's heartbeat; the frames to send.
pub fn tick(now_us: u64) -> Frames {
    control::with_canopen(|link, servo, bus| link.tick(now_us, servo, bus).unwrap_or_default())
        .unwrap_or_default()
}

/// The frames the control interrupt produced since the last call, as
/// many as one list holds.
pub fn take_from_control() -> Frames {
    let mut out = Frames::new();
    control::take_can_out(&mut out);
    out
}
