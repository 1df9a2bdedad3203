//! Library side of `drivectl`, shared with the system tests: the link to a
//! running firmware (QEMU or serial), the co-simulation bridge, defmt log
//! decoding and the configuration file.
pub mod children;
pub mod config_file;
pub mod cosim;
pub mod defmt_log;
pub mod frames;
pub mod link;
pub mod motion;
pub mod server;
pub mod step_map;
pub mod tel;
pub mod tel_route;
