//! CAN bus load of a cyclic CANopen exchange: how long a frame holds the
//! bus, and what share of a bit rate a SYNC with one RPDO and one TPDO
//! per drive takes, so the README can say how many drives one bus carries
//! at which SYNC rate.
//!
//! Frame length, classical base frame (11-bit identifier), ISO 11898-1:
//! start of frame 1, identifier 11, RTR 1, IDE 1, r0 1, DLC 4, data 8n,
//! CRC 15, CRC delimiter 1, ACK slot 1, ACK delimiter 1, end of frame 7:
//! `8n + 44` bits, of which the `34 + 8n` bits from the start of frame to
//! the end of the CRC are stuffed (a stuff bit after five equal bits, at
//! worst one per four bits after the first). Add the 3-bit intermission
//! before the next frame.

/// Bits of the intermission between frames.
pub const INTERMISSION_BITS: u32 = 3;

/// Bits a base frame with `bytes` data bytes (0..=8) holds the bus,
/// intermission included, with the worst case of bit stuffing
/// (`stuffed`) or none.
pub fn frame_bits(bytes: u32, stuffed: bool) -> u32 {
    let n = bytes.min(8);
    let plain = 8 * n + 44;
    let stuff = if stuffed { (34 + 8 * n - 1) / 4 } else { 0 };
    plain + stuff + INTERMISSION_BITS
}

/// One drive's cyclic PDOs: data bytes of its RPDO and its TPDO, one of
/// each per SYNC.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout {
    pub rpdo_bytes: u32,
    pub tpdo_bytes: u32,
}

/// The layout the drive's documentation recommends for CSP: RPDO
/// controlword (2) + target position (4), TPDO statusword (2) + position
/// actual value (4).
pub const CSP_LAYOUT: Layout = Layout {
    rpdo_bytes: 6,
    tpdo_bytes: 6,
};

/// Share of the bus (1.0 = full) `drives` drives take at `sync_hz` on a
/// bus of `bit_rate` bit/s: one SYNC (no data) per cycle and each drive's
/// RPDO and TPDO, worst-case stuffing.
pub fn load(drives: u32, layout: Layout, sync_hz: f64, bit_rate: f64) -> f64 {
    let per_cycle = frame_bits(0, true)
        + drives * (frame_bits(layout.rpdo_bytes, true) + frame_bits(layout.tpdo_bytes, true));
    f64::from(per_cycle) * sync_hz / bit_rate
}

/// The most drives one bus carries at `sync_hz` with the load at most
/// `max_load` (e.g. 0.8, headroom for SDO, EMCY and heartbeats).
pub fn max_drives(layout: Layout, sync_hz: f64, bit_rate: f64, max_load: f64) -> u32 {
    let mut n = 0;
    while n < 1000 && load(n + 1, layout, sync_hz, bit_rate) <= max_load {
        n += 1;
    }
    n
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_lengths_by_hand() {
        // SYNC: 44 bits, stuffing floor(33 / 4) = 8, intermission 3.
        assert_eq!(frame_bits(0, true), 55);
        assert_eq!(frame_bits(0, false), 47);
        // 8 bytes: 108 + floor(97 / 4) = 24 + 3 = 135, the figure CAN
        // textbooks give for a worst-case 8-byte base frame (plus the
        // intermission).
        assert_eq!(frame_bits(8, true), 135);
        // 6 bytes: 92 + floor(81 / 4) = 20 + 3.
        assert_eq!(frame_bits(6, true), 115);
        // More than 8 bytes is 8.
        assert_eq!(frame_bits(9, true), 135);
    }

    #[test]
    fn drives_at_one_kilohertz_on_one_megabit() {
        // One drive: 55 + 2 x 115 = 285 bits per ms of 1000.
        assert!((load(1, CSP_LAYOUT, 1000.0, 1e6) - 0.285).abs() < 1e-12);
        // Six: 55 + 6 x 230 = 1435 bits per ms: 143.5 %, over the bus.
        assert!((load(6, CSP_LAYOUT, 1000.0, 1e6) - 1.435).abs() < 1e-12);
        // At 80 %: 3 drives (745 bits), not 4 (975).
        assert_eq!(max_drives(CSP_LAYOUT, 1000.0, 1e6, 0.8), 3);
        // Twelve drives need the SYNC at 250 Hz: 55 + 12 x 230 = 2815
        // bits per 4 ms, 70 %.
        assert!((load(12, CSP_LAYOUT, 250.0, 1e6) - 0.70375).abs() < 1e-12);
        assert_eq!(max_drives(CSP_LAYOUT, 250.0, 1e6, 0.8), 13);
    }

    /// The table of docs/canopen.md is this module's.
    #[test]
    fn the_documented_table_is_computed_here() {
        extern crate std;
        use std::format;
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/canopen.md");
        let doc = std::fs::read_to_string(path).unwrap();
        for hz in [1000u32, 500, 250] {
            let mut row = format!("| {hz} Hz |");
            for d in [1, 6, 12] {
                row += &format!(
                    " {:.1} % |",
                    100.0 * load(d, CSP_LAYOUT, f64::from(hz), 1e6)
                );
            }
            row += &format!(" {} |", max_drives(CSP_LAYOUT, f64::from(hz), 1e6, 0.8));
            assert!(doc.contains(&row), "docs/canopen.md lacks {row:?}");
        }
    }
}
