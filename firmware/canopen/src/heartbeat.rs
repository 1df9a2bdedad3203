//! Heartbeat (CiA 301 v4.2 §7.2.8): the producer sends COB-ID 0x700 +
//! node with the NMT state byte every 0x1017 milliseconds (0 = off); the
//! consumer watches other nodes listed in 0x1016 (each entry: node-ID in
//! bits 16..24, time in ms in bits 0..16; node 0 or time 0 = unused) and
//! reports a node whose heartbeat is later than its time. Monitoring of a
//! node starts with its first heartbeat. Times are in
//! microseconds from any monotonic clock.

/// Entries of 0x1016.
pub const CONSUMERS: usize = 4;

/// The heartbeat producer.
#[derive(Clone, Copy, Debug, Default)]
pub struct Producer {
    period_ms: u16,
    next_us: Option<u64>,
}

impl Producer {
    /// A producer with period 0x1017 = `period_ms` (0: off).
    pub fn new(period_ms: u16) -> Self {
        Self {
            period_ms,
            next_us: None,
        }
    }

    /// Object 0x1017.
    pub fn period_ms(&self) -> u16 {
        self.period_ms
    }

    /// Writes 0x1017; the next heartbeat goes at the next tick.
    pub fn set_period_ms(&mut self, ms: u16) {
        self.period_ms = ms;
        self.next_us = None;
    }

    /// True when a heartbeat is due at `now_us` (then the next one is
    /// scheduled one period later).
    pub fn tick(&mut self, now_us: u64) -> bool {
        if self.period_ms == 0 {
            return false;
        }
        let due = match self.next_us {
            None => true,
            Some(t) => now_us >= t,
        };
        if due {
            self.next_us = Some(now_us.saturating_add(self.period_ms as u64 * 1000));
        }
        due
    }
}

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Watch {
    entry: u32,
    last_us: Option<u64>,
    expired: bool,
}

impl Watch {
    fn node(&self) -> u8 {
        (self.entry >> 16) as u8
    }
    fn time_ms(&self) -> u16 {
        self.entry as u16
    }
    fn active(&self) -> bool {
        self.node() != 0 && self.time_ms() != 0
    }
}

/// The heartbeat consumer.
#[derive(Clone, Copy, Debug, Default)]
pub struct Consumer {
    watch: [Watch; CONSUMERS],
}

/// 0x1016 entry refusals.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ConsumerError {
    /// Sub-index outside 1..=CONSUMERS.
    NoSuchEntry,
    /// Another active entry already watches that node (CiA 301
    /// object 0x1016: abort 0x0604 0043).
    Duplicate,
}

impl Consumer {
    /// No node watched.
    pub fn new() -> Self {
        Self::default()
    }

    /// 0x1016 sub `sub` (1..=CONSUMERS).
    pub fn entry(&self, sub: u8) -> Option<u32> {
        let i = (sub as usize).checked_sub(1)?;
        self.watch.get(i).map(|w| w.entry)
    }

    /// Writes 0x1016 sub `sub`; monitoring of the node restarts with its
    /// next heartbeat.
    pub fn set_entry(&mut self, sub: u8, value: u32) -> Result<(), ConsumerError> {
        let i = (sub as usize)
            .checked_sub(1)
            .filter(|&i| i < CONSUMERS)
            .ok_or(ConsumerError::NoSuchEntry)?;
        let new = Watch {
            entry: value,
            last_us: None,
            expired: false,
        };
        if new.active()
            && self
                .watch
                .iter()
                .enumerate()
                .any(|(j, w)| j != i && w.active() && w.node() == new.node())
        {
            return Err(ConsumerError::Duplicate);
        }
        self.watch[i] = new;
        Ok(())
    }

    /// Records a heartbeat (or boot-up) from `node` at `now_us`.
    pub fn on_heartbeat(&mut self, node: u8, now_us: u64) {
        for w in self
            .watch
            .iter_mut()
            .filter(|w| w.active() && w.node() == node)
        {
            w.last_us = Some(now_us);
            w.expired = false;
        }
    }

    /// The first watched node whose heartbeat is overdue at `now_us` and not
    /// yet reported; each loss is reported once, until the node's next
    /// heartbeat.
    pub fn tick(&mut self, now_us: u64) -> Option<u8> {
        for w in self.watch.iter_mut().filter(|w| w.active()) {
            if let Some(last) = w.last_us {
                if !w.expired && now_us > last.saturating_add(w.time_ms() as u64 * 1000) {
                    w.expired = true;
                    return Some(w.node());
                }
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn producer_period() {
        let mut p = Producer::new(0);
        assert!(!p.tick(0));
        p.set_period_ms(100);
        assert!(p.tick(1_000));
        assert!(!p.tick(100_999));
        assert!(p.tick(101_000));
        assert!(!p.tick(150_000));
    }

    #[test]
    fn consumer_reports_once_per_loss() {
        let mut c = Consumer::new();
        // Node 0x0A, 500 ms: 0x000A_01F4.
        c.set_entry(1, 0x000A_01F4).unwrap();
        assert_eq!(c.entry(1), Some(0x000A_01F4));
        // Not monitored before the first heartbeat.
        assert_eq!(c.tick(10_000_000), None);
        c.on_heartbeat(0x0A, 1_000_000);
        assert_eq!(c.tick(1_500_000), None);
        assert_eq!(c.tick(1_500_001), Some(0x0A));
        assert_eq!(c.tick(2_000_000), None);
        c.on_heartbeat(0x0A, 2_100_000);
        assert_eq!(c.tick(2_600_001), Some(0x0A));
    }

    #[test]
    fn consumer_entry_rules() {
        let mut c = Consumer::new();
        assert_eq!(c.set_entry(0, 1), Err(ConsumerError::NoSuchEntry));
        assert_eq!(c.set_entry(5, 1), Err(ConsumerError::NoSuchEntry));
        c.set_entry(1, 0x000A_0064).unwrap();
        assert_eq!(c.set_entry(2, 0x000A_00C8), Err(ConsumerError::Duplicate));
        // Same node with time 0 is unused, so allowed.
        c.set_entry(2, 0x000A_0000).unwrap();
        // Rewriting the same entry is allowed.
        c.set_entry(1, 0x000A_00C8).unwrap();
        assert_eq!(c.entry(9), None);
    }
}
