//! A CAN frame as the controller's four message words (identifier, DLC,
//! data word 1, data word 2; UG585 appendix B, `TXFIFO_*`/`RXFIFO_*`), and
//! an acceptance filter as its mask and identifier words.

use canopen::frame::MAX_STD_ID;
use canopen::CanFrame;
use regmap::ps_can::{DLC_MASK, DLC_SHIFT, ID_IDE, ID_IDH_MASK, ID_IDH_SHIFT, ID_RTR, ID_SRRRTR};

/// The four words of one message, in register order.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct MessageWords {
    /// `*_ID`.
    pub id: u32,
    /// `*_DLC` (the RX side also carries the timestamp in bits 15:0).
    pub dlc: u32,
    /// `*_DATA1`: bytes 0..=3, byte 0 in bits 31:24.
    pub data1: u32,
    /// `*_DATA2`: bytes 4..=7, byte 4 in bits 31:24.
    pub data2: u32,
}

/// The words of a standard data frame.
pub fn encode(f: &CanFrame) -> MessageWords {
    let mut bytes = [0u8; 8];
    let data = f.data();
    bytes[..data.len()].copy_from_slice(data);
    MessageWords {
        id: (u32::from(f.id()) & ID_IDH_MASK) << ID_IDH_SHIFT,
        dlc: (data.len() as u32) << DLC_SHIFT,
        data1: u32::from_be_bytes([bytes[0], bytes[1], bytes[2], bytes[3]]),
        data2: u32::from_be_bytes([bytes[4], bytes[5], bytes[6], bytes[7]]),
    }
}

/// The frame the words hold; `None` for an extended (IDE) or remote frame,
/// which [`CanFrame`] does not represent. A DLC of 9..=15 means 8 bytes
/// (ISO 11898-1).
pub fn decode(w: &MessageWords) -> Option<CanFrame> {
    if w.id & (ID_IDE | ID_SRRRTR | ID_RTR) != 0 {
        return None;
    }
    let id = ((w.id >> ID_IDH_SHIFT) & ID_IDH_MASK) as u16;
    let len = (((w.dlc >> DLC_SHIFT) & DLC_MASK) as usize).min(8);
    let mut bytes = [0u8; 8];
    bytes[..4].copy_from_slice(&w.data1.to_be_bytes());
    bytes[4..].copy_from_slice(&w.data2.to_be_bytes());
    CanFrame::new(id, &bytes[..len])
}

/// An acceptance filter on the 11-bit identifier: a standard data frame
/// passes when `frame_id & mask == id & mask`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct AcceptanceFilter {
    /// Identifier to compare with (11 bits).
    pub id: u16,
    /// Identifier bits that take part (11 bits; 0x7FF: this one identifier).
    pub mask: u16,
}

impl AcceptanceFilter {
    /// `(AFMR, AFIR)`: the identifier bits of `mask`, and IDE and SRR/RTR
    /// always compared with 0, so that extended and remote frames, which
    /// the node does not use, are blocked by the controller. `None` when the
    /// identifier or the mask has bits above the 11.
    pub fn words(&self) -> Option<(u32, u32)> {
        if self.id > MAX_STD_ID || self.mask > MAX_STD_ID {
            return None;
        }
        let afmr = (u32::from(self.mask) << ID_IDH_SHIFT) | ID_SRRRTR | ID_IDE;
        let afir = u32::from(self.id) << ID_IDH_SHIFT;
        Some((afmr, afir))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_frame_in_words_by_hand() {
        let f = CanFrame::new(0x601, &[0x40, 0x41, 0x60, 0x00, 0xAA]).unwrap();
        let w = encode(&f);
        // 0x601 << 21 = 0xC020_0000; DLC 5 << 28.
        assert_eq!(
            w,
            MessageWords {
                id: 0xC020_0000,
                dlc: 0x5000_0000,
                data1: 0x4041_6000,
                data2: 0xAA00_0000,
            }
        );
        assert_eq!(decode(&w), Some(f));
    }

    #[test]
    fn extended_remote_and_long_dlc() {
        let w = MessageWords {
            id: 0x7FF << 21,
            dlc: 0xF000_1234,
            data1: 0x0102_0304,
            data2: 0x0506_0708,
        };
        // DLC 15 is 8 bytes; the timestamp bits are ignored.
        let f = decode(&w).unwrap();
        assert_eq!((f.id(), f.data()), (0x7FF, &[1, 2, 3, 4, 5, 6, 7, 8][..]));
        for bit in [ID_IDE, ID_SRRRTR, ID_RTR] {
            let x = MessageWords {
                id: w.id | bit,
                ..w
            };
            assert_eq!(decode(&x), None);
        }
    }

    #[test]
    fn filter_words() {
        let f = AcceptanceFilter {
            id: 0x181,
            mask: 0x780,
        };
        // mask 0x780 << 21 = 0xF000_0000, plus SRR (bit 20) and IDE (bit 19).
        assert_eq!(f.words(), Some((0xF018_0000, 0x3020_0000)));
        assert_eq!(AcceptanceFilter { id: 0x800, mask: 1 }.words(), None);
        assert_eq!(AcceptanceFilter { id: 1, mask: 0x800 }.words(), None);
    }
}
