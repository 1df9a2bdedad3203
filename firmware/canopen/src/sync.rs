//! The SYNC consumer (CiA 301 v4.2 §7.2.5): SYNC frames on COB-ID 0x80
//! (object 0x1005, fixed here) carry no data, or one counter byte when the
//! producer's synchronous counter overflow value (0x1019) is not 0. Which
//! TPDOs a SYNC makes due is the PDO module's decision; this module only
//! validates the frame.

/// COB-ID of SYNC (0x1005 default, 11-bit, consumer).
pub const SYNC_COB_ID: u16 = 0x080;

/// A received SYNC.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Sync {
    /// The counter byte (1..=240) if the producer sends one.
    pub counter: Option<u8>,
}

/// Decodes a SYNC frame's data: 0 bytes, or 1 counter byte in 1..=240
/// (CiA 301 §7.2.5). Any other length or counter is not a valid SYNC
/// and returns `None`.
pub fn decode(data: &[u8]) -> Option<Sync> {
    match data {
        [] => Some(Sync { counter: None }),
        [c @ 1..=240] => Some(Sync { counter: Some(*c) }),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sync_frames() {
        assert_eq!(decode(&[]), Some(Sync { counter: None }));
        assert_eq!(decode(&[1]), Some(Sync { counter: Some(1) }));
        assert_eq!(decode(&[240]), Some(Sync { counter: Some(240) }));
        assert_eq!(decode(&[0]), None);
        assert_eq!(decode(&[241]), None);
        assert_eq!(decode(&[1, 2]), None);
    }
}
