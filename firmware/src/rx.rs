//! Receive ring between the UART1 interrupt (producer) and the main loop
//! (consumer): single producer, single consumer, lock-free.
use core::sync::atomic::{AtomicU32, AtomicU8, AtomicUsize, Ordering};

const N: usize = 1024;

pub struct Ring {
    buf: [AtomicU8; N],
    /// Next slot the producer writes (monotonic, wraps at usize).
    head: AtomicUsize,
    /// Next slot the consumer reads.
    tail: AtomicUsize,
    /// Bytes dropped because the ring was full or the UART FIFO overran.
    pub overruns: AtomicU32,
}

impl Ring {
    pub const fn new() -> Self {
        Self {
            buf: [const { AtomicU8::new(0) }; N],
            head: AtomicUsize::new(0),
            tail: AtomicUsize::new(0),
            overruns: AtomicU32::new(0),
        }
    }

    /// Bytes waiting.
    pub fn len(&self) -> usize {
        self.head
            .load(Ordering::Acquire)
            .wrapping_sub(self.tail.load(Ordering::Acquire))
    }

    pub fn is_full(&self) -> bool {
        self.len() >= N
    }

    /// Capacity, bytes.
    pub const fn capacity(&self) -> usize {
        N
    }

    /// Producer side (interrupt context only).
    pub fn push(&self, b: u8) {
        let head = self.head.load(Ordering::Relaxed);
        if head.wrapping_sub(self.tail.load(Ordering::Acquire)) >= N {
            self.overruns.fetch_add(1, Ordering::Relaxed);
            return;
        }
        self.buf[head % N].store(b, Ordering::Relaxed);
        self.head.store(head.wrapping_add(1), Ordering::Release);
    }

    /// Consumer side (main loop only).
    pub fn pop(&self) -> Option<u8> {
        let tail = self.tail.load(Ordering::Relaxed);
        if tail == self.head.load(Ordering::Acquire) {
            return None;
        }
        let b = self.buf[tail % N].load(Ordering::Relaxed);
        self.tail.store(tail.wrapping_add(1), Ordering::Release);
        Some(b)
    }

    pub fn is_empty(&self) -> bool {
        self.tail.load(Ordering::Relaxed) == self.head.load(Ordering::Acquire)
    }
}
