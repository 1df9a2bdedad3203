//! The CAN frame every service consumes and produces: an 11-bit identifier
//! (CiA 301 uses the base frame format only) and 0..=8 data bytes. Remote
//! frames are not modelled: CiA 301 v4.2 advises against RTR and this node
//! never answers them.

/// Largest 11-bit CAN identifier.
pub const MAX_STD_ID: u16 = 0x7FF;

/// A classical CAN base frame (11-bit identifier, up to 8 data bytes).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct CanFrame {
    id: u16,
    len: u8,
    data: [u8; 8],
}

impl CanFrame {
    /// A frame with identifier `id` (11 bits) and payload `data` (at most
    /// 8 bytes); `None` when either is out of range.
    pub fn new(id: u16, data: &[u8]) -> Option<Self> {
        if id > MAX_STD_ID || data.len() > 8 {
            return None;
        }
        let mut d = [0u8; 8];
        d[..data.len()].copy_from_slice(data);
        Some(Self {
            id,
            len: data.len() as u8,
            data: d,
        })
    }

    /// An 8-byte frame; the identifier is masked to 11 bits (internal use
    /// with identifiers the node computed itself).
    pub(crate) fn full(id: u16, data: [u8; 8]) -> Self {
        Self {
            id: id & MAX_STD_ID,
            len: 8,
            data,
        }
    }

    /// The 11-bit identifier (COB-ID).
    pub fn id(&self) -> u16 {
        self.id
    }

    /// The data bytes (DLC of them).
    pub fn data(&self) -> &[u8] {
        &self.data[..self.len as usize]
    }
}

/// How many frames one call into the node can produce at most.
pub const MAX_FRAMES: usize = 8;

/// A bounded list of frames to transmit, in order. Pushing past
/// [`MAX_FRAMES`] drops the frame and counts it in [`Frames::dropped`], so a
/// burst never panics.
#[derive(Clone, Debug, Default)]
pub struct Frames {
    buf: [CanFrame; MAX_FRAMES],
    len: usize,
    dropped: usize,
}

impl Frames {
    /// An empty list.
    pub fn new() -> Self {
        Self::default()
    }

    /// Appends a frame, or counts it as dropped when full.
    pub fn push(&mut self, f: CanFrame) {
        if self.len < MAX_FRAMES {
            self.buf[self.len] = f;
            self.len += 1;
        } else {
            self.dropped += 1;
        }
    }

    /// Appends `other`'s frames in order (those that do not fit counted as
    /// dropped).
    pub fn append(&mut self, other: &Frames) {
        for f in other.iter() {
            self.push(*f);
        }
    }

    /// The frames, oldest first.
    pub fn as_slice(&self) -> &[CanFrame] {
        &self.buf[..self.len]
    }

    /// Iterates over the frames, oldest first.
    pub fn iter(&self) -> core::slice::Iter<'_, CanFrame> {
        self.as_slice().iter()
    }

    /// Number of frames held.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True when no frame is held.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Frames that did not fit.
    pub fn dropped(&self) -> usize {
        self.dropped
    }
}

impl<'a> IntoIterator for &'a Frames {
    type Item = &'a CanFrame;
    type IntoIter = core::slice::Iter<'a, CanFrame>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_limits() {
        assert!(CanFrame::new(0x800, &[]).is_none());
        assert!(CanFrame::new(0x7FF, &[0; 9]).is_none());
        let f = CanFrame::new(0x123, &[1, 2]).unwrap();
        assert_eq!(f.id(), 0x123);
        assert_eq!(f.data(), &[1, 2]);
    }

    #[test]
    fn frames_bounded() {
        let mut fs = Frames::new();
        for i in 0..10u16 {
            fs.push(CanFrame::new(i, &[]).unwrap());
        }
        assert_eq!(fs.len(), 8);
        assert_eq!(fs.dropped(), 2);
        assert_eq!(fs.as_slice()[7].id(), 7);
    }
}
