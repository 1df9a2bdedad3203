//! The log's RAM ring: the `defmt` logger encodes each frame into it with
//! the interrupts masked (a copy into RAM, microseconds), and the UART is
//! fed from it later, a FIFO's worth at a time, never waiting for the
//! line. Writing the frame straight to UART0 at 115200 baud cost 86.8 us
//! per byte past the 64-byte FIFO with the interrupts off: a 60-character
//! console line's log frame could hold the control step off for
//! milliseconds on a board (QEMU's UART has no baud timing, so no test
//! there saw it).
//!
//! Whole frames or nothing: a frame that does not fit is dropped at once
//! (the bytes it had put in taken back) and counted, so the stream stays
//! decodable and `status` says how many were lost.

/// A byte ring of `N` bytes (a power of two) that keeps whole frames.
pub struct LogRing<const N: usize> {
    buf: [u8; N],
    /// Bytes written (wrapping): the next byte goes to `head % N`.
    head: u32,
    /// Bytes read (wrapping).
    tail: u32,
    /// `head` when the present frame began.
    frame_start: u32,
    /// The present frame did not fit: its further bytes are dropped.
    frame_lost: bool,
    /// Frames dropped since boot.
    dropped: u32,
}

impl<const N: usize> Default for LogRing<N> {
    fn default() -> Self {
        Self::new()
    }
}

impl<const N: usize> LogRing<N> {
    /// An empty ring.
    pub const fn new() -> Self {
        assert!(N.is_power_of_two() && N <= 1 << 30);
        Self {
            buf: [0; N],
            head: 0,
            tail: 0,
            frame_start: 0,
            frame_lost: false,
            dropped: 0,
        }
    }

    /// Bytes waiting to be sent.
    pub fn len(&self) -> usize {
        self.head.wrapping_sub(self.tail) as usize
    }

    /// Nothing waiting.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Frames dropped because the ring was full.
    pub fn dropped(&self) -> u32 {
        self.dropped
    }

    /// A frame begins.
    pub fn begin_frame(&mut self) {
        self.frame_start = self.head;
        self.frame_lost = false;
    }

    /// Bytes of the present frame; when they do not fit, the whole frame
    /// is taken back.
    pub fn push(&mut self, bytes: &[u8]) {
        if self.frame_lost {
            return;
        }
        if self.len() + bytes.len() > N {
            self.head = self.frame_start;
            self.frame_lost = true;
            return;
        }
        for &b in bytes {
            self.buf[self.head as usize % N] = b;
            self.head = self.head.wrapping_add(1);
        }
    }

    /// The present frame ends (counted if it was dropped).
    pub fn end_frame(&mut self) {
        if self.frame_lost {
            self.dropped = self.dropped.wrapping_add(1);
            self.frame_lost = false;
        }
    }

    /// Takes the present frame back unsent (a measurement's frame).
    pub fn discard_frame(&mut self) {
        self.head = self.frame_start;
        self.frame_lost = false;
    }

    /// Hands waiting bytes, oldest first, to `send` until it refuses one
    /// (a full FIFO) or none are left; returns how many it took. Not
    /// between `begin_frame` and `end_frame` (the logger holds the ring
    /// then, with the interrupts masked): those bytes could be taken back.
    pub fn drain(&mut self, mut send: impl FnMut(u8) -> bool) -> usize {
        let mut n = 0;
        while self.tail != self.head {
            if !send(self.buf[self.tail as usize % N]) {
                break;
            }
            self.tail = self.tail.wrapping_add(1);
            n += 1;
        }
        n
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::vec::Vec;

    fn frame(r: &mut LogRing<16>, bytes: &[u8]) {
        r.begin_frame();
        for c in bytes.chunks(3) {
            r.push(c);
        }
        r.end_frame();
    }

    fn drained(r: &mut LogRing<16>) -> Vec<u8> {
        let mut v = Vec::new();
        r.drain(|b| {
            v.push(b);
            true
        });
        v
    }

    #[test]
    fn frames_come_out_whole_and_in_order_across_the_wrap() {
        let mut r = LogRing::<16>::new();
        for k in 0..10u8 {
            frame(&mut r, &[k, k + 100, k + 200, 0]);
            assert_eq!(drained(&mut r), [k, k + 100, k + 200, 0]);
        }
        assert_eq!(r.dropped(), 0);
        assert!(r.is_empty());
    }

    #[test]
    fn a_frame_that_does_not_fit_is_dropped_whole_and_counted() {
        let mut r = LogRing::<16>::new();
        frame(&mut r, &[1; 10]);
        // 10 + 8 > 16: the second frame goes, the first stays whole.
        frame(&mut r, &[2; 8]);
        assert_eq!(r.dropped(), 1);
        assert_eq!(r.len(), 10);
        // 6 bytes still fit.
        frame(&mut r, &[3; 6]);
        assert_eq!(r.dropped(), 1);
        let out = drained(&mut r);
        assert_eq!(out, [[1u8; 10].as_slice(), &[3; 6]].concat());
        // A frame longer than the ring never fits.
        frame(&mut r, &[4; 17]);
        assert_eq!(r.dropped(), 2);
        assert!(r.is_empty());
    }

    #[test]
    fn a_full_fifo_stops_the_drain_and_the_rest_waits() {
        let mut r = LogRing::<16>::new();
        frame(&mut r, &[7, 8, 9, 10, 11]);
        let mut room = 2;
        let mut got = Vec::new();
        let n = r.drain(|b| {
            if room == 0 {
                return false;
            }
            room -= 1;
            got.push(b);
            true
        });
        assert_eq!((n, got.as_slice()), (2, [7u8, 8].as_slice()));
        assert_eq!(drained(&mut r), [9, 10, 11]);
    }

    #[test]
    fn a_discarded_frame_leaves_nothing() {
        let mut r = LogRing::<16>::new();
        frame(&mut r, &[1, 2]);
        r.begin_frame();
        r.push(&[5, 6, 7]);
        r.discard_frame();
        assert_eq!(drained(&mut r), [1, 2]);
        assert_eq!(r.dropped(), 0);
    }
}
