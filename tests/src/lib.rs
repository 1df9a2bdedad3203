//! Harness for system tests (QEMU).
