//! A message as the controller's four words, and a bounded FIFO of them.

/// One message: the words of `*_ID`, `*_DLC`, `*_DATA1`, `*_DATA2`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Message {
    /// Identifier register: IDH 31:21, SRR/RTR 20, IDE 19, IDL 18:1, RTR 0.
    pub id: u32,
    /// DLC in bits 31:28 (the RX side adds the timestamp in 15:0).
    pub dlc: u32,
    /// Data bytes 0..=3, byte 0 in bits 31:24.
    pub data1: u32,
    /// Data bytes 4..=7.
    pub data2: u32,
}

/// Messages a FIFO holds: the TX and RX FIFOs are 64 deep.
pub const DEPTH: usize = 64;

/// A FIFO of [`DEPTH`] messages.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Fifo {
    slots: [Message; DEPTH],
    head: usize,
    len: usize,
}

impl Default for Fifo {
    fn default() -> Self {
        Self {
            slots: [Message::default(); DEPTH],
            head: 0,
            len: 0,
        }
    }
}

impl Fifo {
    /// Messages held.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True when empty.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// True when full.
    pub fn is_full(&self) -> bool {
        self.len == DEPTH
    }

    /// Appends `m`; false (and nothing changes) when full.
    pub fn push(&mut self, m: Message) -> bool {
        if self.is_full() {
            return false;
        }
        self.slots[(self.head + self.len) % DEPTH] = m;
        self.len += 1;
        true
    }

    /// The oldest message.
    pub fn front(&self) -> Option<&Message> {
        (!self.is_empty()).then(|| &self.slots[self.head])
    }

    /// Removes and returns the oldest message.
    pub fn pop(&mut self) -> Option<Message> {
        let m = *self.front()?;
        self.head = (self.head + 1) % DEPTH;
        self.len -= 1;
        Some(m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keeps_order_across_the_wrap_and_refuses_when_full() {
        let m = |i: u32| Message {
            id: i,
            ..Message::default()
        };
        let mut f = Fifo::default();
        for i in 0..10 {
            assert!(f.push(m(i)));
        }
        for i in 0..10 {
            assert_eq!(f.pop(), Some(m(i)));
        }
        for i in 0..64 {
            assert!(f.push(m(100 + i)));
        }
        assert!(f.is_full());
        assert!(!f.push(m(999)));
        for i in 0..64 {
            assert_eq!(f.pop(), Some(m(100 + i)));
        }
        assert_eq!(f.pop(), None);
    }
}
