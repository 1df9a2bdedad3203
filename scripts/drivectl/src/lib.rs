//! Library side of `drivectl`, shared with the system tests: the link to a
//! running firmware (QEMU or serial) and defmt log decoding.
pub mod cosim;
pub mod defmt_log;
pub mod link;
