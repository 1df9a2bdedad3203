//! Verilator harnesses.
