//! Emergency objects (CiA 301 v4.2 §7.2.7): the EMCY frame (COB-ID 0x80 +
//! node; bytes 0..2 the error code little-endian, byte 2 the error register
//! 0x1001, bytes 3..8 manufacturer-specific), the error register and the
//! pre-defined error field 0x1003 (sub 0 the number of errors, sub 1 the
//! newest; each entry is the error code in bits 0..16 and manufacturer
//! information in bits 16..32; writing 0 to sub 0 clears the history).

use crate::frame::CanFrame;

/// Error register bits (CiA 301 v4.2, object 0x1001).
pub mod register {
    pub const GENERIC: u8 = 1 << 0;
    pub const CURRENT: u8 = 1 << 1;
    pub const VOLTAGE: u8 = 1 << 2;
    pub const TEMPERATURE: u8 = 1 << 3;
    pub const COMMUNICATION: u8 = 1 << 4;
    pub const DEVICE_PROFILE: u8 = 1 << 5;
    pub const MANUFACTURER: u8 = 1 << 7;
}

/// Error codes this crate emits itself (CiA 301 v4.2 §7.2.7, emergency error codes).
pub mod code {
    /// Error reset or no error.
    pub const NO_ERROR: u16 = 0x0000;
    /// Life guard error or heartbeat error.
    pub const HEARTBEAT: u16 = 0x8130;
    /// PDO not processed due to length error.
    pub const PDO_LENGTH: u16 = 0x8210;
}

/// Entries kept in 0x1003.
pub const HISTORY: usize = 8;

/// COB-ID of the node's EMCY (0x1014 default): 0x80 + node.
pub const fn cob_id(node: u8) -> u16 {
    0x80 + node as u16
}

/// The error register and the pre-defined error field.
#[derive(Clone, Copy, Debug, Default)]
pub struct Emcy {
    register: u8,
    history: [u32; HISTORY],
    count: u8,
}

impl Emcy {
    /// No error, empty history.
    pub fn new() -> Self {
        Self::default()
    }

    /// Object 0x1001.
    pub fn register(&self) -> u8 {
        self.register
    }

    /// Sets the error register (the application keeps it in step with its
    /// errors; bit 0, generic, is set whenever any error is present).
    pub fn set_register(&mut self, value: u8) {
        self.register = value;
    }

    /// Records an error (newest first in 0x1003, the oldest falls off when
    /// full), ORs `register_bits | GENERIC` into 0x1001 and returns the
    /// EMCY frame.
    pub fn raise(&mut self, node: u8, code: u16, register_bits: u8, mfr: [u8; 5]) -> CanFrame {
        self.register |= register_bits | register::GENERIC;
        self.history.copy_within(0..HISTORY - 1, 1);
        self.history[0] = code as u32 | (u32::from_le_bytes([mfr[0], mfr[1], 0, 0]) << 16);
        self.count = (self.count + 1).min(HISTORY as u8);
        self.frame(node, code, mfr)
    }

    /// Clears the error register and returns the error-reset EMCY (code
    /// 0x0000); the history is kept.
    pub fn reset(&mut self, node: u8) -> CanFrame {
        self.register = 0;
        self.frame(node, code::NO_ERROR, [0; 5])
    }

    fn frame(&self, node: u8, code: u16, mfr: [u8; 5]) -> CanFrame {
        let c = code.to_le_bytes();
        CanFrame::full(
            cob_id(node),
            [
                c[0],
                c[1],
                self.register,
                mfr[0],
                mfr[1],
                mfr[2],
                mfr[3],
                mfr[4],
            ],
        )
    }

    /// 0x1003 sub 0: number of recorded errors.
    pub fn count(&self) -> u8 {
        self.count
    }

    /// 0x1003 sub `n` (1 = newest); `None` beyond the recorded count.
    pub fn history(&self, n: u8) -> Option<u32> {
        if n == 0 || n > self.count {
            return None;
        }
        Some(self.history[n as usize - 1])
    }

    /// Writing 0 to 0x1003 sub 0 clears the history.
    pub fn clear_history(&mut self) {
        self.count = 0;
        self.history = [0; HISTORY];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn emcy_frame_layout() {
        let mut e = Emcy::new();
        // Over-current 0x2310 (CiA 402-2 error codes), current bit.
        let f = e.raise(5, 0x2310, register::CURRENT, [0xA1, 0xA2, 0xA3, 0xA4, 0xA5]);
        // CiA 301 §7.2.7 EMCY layout: 0x85; 10 23; register 0x03 (generic|current).
        assert_eq!(f.id(), 0x085);
        assert_eq!(f.data(), &[0x10, 0x23, 0x03, 0xA1, 0xA2, 0xA3, 0xA4, 0xA5]);
        assert_eq!(e.register(), 0x03);
        assert_eq!(e.count(), 1);
        assert_eq!(e.history(1), Some(0xA2A1_2310));
        let r = e.reset(5);
        assert_eq!(r.data(), &[0, 0, 0, 0, 0, 0, 0, 0]);
        assert_eq!(e.register(), 0);
    }

    #[test]
    fn history_newest_first_and_bounded() {
        let mut e = Emcy::new();
        for c in 1..=10u16 {
            e.raise(1, 0x1000 + c, 0, [0; 5]);
        }
        assert_eq!(e.count(), 8);
        assert_eq!(e.history(1), Some(0x100A));
        assert_eq!(e.history(8), Some(0x1003));
        assert_eq!(e.history(9), None);
        assert_eq!(e.history(0), None);
        e.clear_history();
        assert_eq!(e.count(), 0);
        assert_eq!(e.history(1), None);
    }
}
