//! The drive as a CANopen device (CiA 301 with the CiA 402 drive profile):
//! its application objects, and the EDS (CiA 306) that describes them.
//! The protocol (NMT, SDO, PDO, SYNC, heartbeat, EMCY and the CiA 402 state
//! machine) is the `canopen` crate's; this module is what the drive puts
//! behind it.
//!
//! - [`objects`]: identity, the CiA 402 process and profile objects, and
//!   every configuration parameter as a vendor object, over a
//!   [`objects::ProcessImage`] the control loop exchanges at its boundary
//!   and a [`objects::ConfigPort`] to the drive's configuration.
//! - [`axis`]: the drive functions behind the CiA 402 state machine and
//!   the modes' set-points, on the servo.
//! - [`link`]: node, dictionary and axis in one value, with the counters
//!   `status` shows; what a transport talks to.
//! - [`eds`]: the EDS text, generated from the same tables; the committed
//!   file `docs/canopen/drive.eds` is checked against it.
//!
//! # Units (the factor group)
//!
//! One choice for every object, no scaling objects to configure:
//!
//! | quantity | unit | type |
//! |---|---|---|
//! | position (0x6064, 0x607A, 0x607D, 0x60F4) | encoder counts of the motor shaft (`enc_cpr` per turn, 0x608F) | INTEGER32 |
//! | velocity (0x606C, 0x60FF, 0x6081) | counts/s | INTEGER32 / UNSIGNED32 |
//! | acceleration (0x6083, 0x6084) | counts/s² | UNSIGNED32 |
//! | torque (0x6071, 0x6077, 0x6072) | per mille of the rated torque 0x6076 | INTEGER16 / UNSIGNED16 |
//! | rated torque (0x6076) | mN m, the configured `torque_limit` | UNSIGNED32 |
//! | vendor configuration (0x2000..) | the parameter's own unit (`config list`) | REAL32 or UNSIGNED32 |
//!
//! These are CiA 402's own default units for torque (per mille of rated
//! torque) and the "increments" of its position factor with a factor of 1.

/// The drive's node-ID (CiA 301: 1..=127).
pub const NODE_ID: u8 = 1;

pub mod axis;
pub mod eds;
pub mod link;
pub mod objects;

#[cfg(test)]
mod tests;

pub use axis::Axis;
pub use link::{Link, LinkStatus};
pub use objects::{ConfigPort, ConfigValues, DriveObjects, ProcessImage};
