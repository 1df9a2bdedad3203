//! Paper 001: induction machine + five-level ANPC inverter, MPDCC.
pub mod binsearch;
pub mod fixed;
