//! The Verilated RTL against its Rust models: one module per file of this
//! directory, in one test binary (one compilation and one link instead of
//! one per file; docs/ARCHITECTURE.md, "Tests and their budget"). A test is `<module>::<name>`: run one file's
//! tests with `cargo test -p rtl-sim --test rtl <module>::`. The
//! system tests check that no file of the directory is left out.
mod adc_period;
mod autonomous_loop;
mod axil;
mod closed_loop;
mod cosim;
mod gate_driver;
mod mpdcc_core;
mod mpdcc_explorer;
mod mpdcc_hil;
mod mpdcc_lane;
mod mpdcc_table;
mod mpdtc_core;
mod mpdtc_frontend;
mod mpdtc_seq;
mod pl_blocks;
mod rtl_resources;
mod simpl_equiv;
