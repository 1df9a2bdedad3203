//! `canopen`: the protocol core of the drive's CANopen slave (CiA 301 v4.2)
//! with the CiA 402-2 drive profile, and the socketcand text protocol that
//! carries CAN frames over TCP. Pure protocol logic: no driver, no socket,
//! no heap. Frames go in and out as values; the drive's own state stays the
//! source of truth and is reached through the [`od::ObjectDictionary`]
//! trait the application implements.
//!
//! Modules, one job each:
//! - [`frame`]: the 11-bit CAN frame and a bounded list of frames.
//! - [`od`]: object dictionary entries, the application's access trait, a
//!   static table type, and the checks (access, length, range) shared by
//!   SDO and PDO; every refusal is an [`od::Abort`] code.
//! - [`sdo`]: the SDO server (expedited and segmented upload/download).
//! - [`nmt`]: the NMT slave state machine and which services each state
//!   allows.
//! - [`pdo`]: 4 RPDOs and 4 TPDOs: communication and mapping parameters,
//!   the remapping rules, packing and unpacking.
//! - [`sync`]: the SYNC consumer.
//! - [`heartbeat`]: heartbeat producer (0x1017) and consumer (0x1016).
//! - [`emcy`]: EMCY frames, the error register (0x1001) and the
//!   pre-defined error field (0x1003).
//! - [`cia402`]: the CiA 402 drive state machine, controlword/statusword
//!   and modes of operation.
//! - [`socketcand`]: the socketcand TCP text protocol, server side.
//! - [`node`]: the node tying the services together.
//! - [`busload`]: how much of a CAN bus a cyclic exchange takes.
#![cfg_attr(not(test), no_std)]
#![forbid(unsafe_code)]

pub mod busload;
pub mod cia402;
pub mod emcy;
pub mod frame;
pub mod heartbeat;
pub mod nmt;
pub mod node;
pub mod od;
pub mod pdo;
pub mod sdo;
pub mod socketcand;
pub mod sync;

pub use frame::{CanFrame, Frames};
pub use od::{Abort, ObjectDictionary};
