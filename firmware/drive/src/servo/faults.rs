//! Fault history: the last [`HISTORY_LEN`] faults with the drive time they
//! were seen at and a snapshot of the last [`SNAPSHOT_LEN`] control
//! periods' samples before it.
use super::Measured;
use crate::pl::fault::Faults;
use core::fmt::{self, Write};

/// Faults kept in the history.
pub const HISTORY_LEN: usize = 16;
/// Samples (control periods) in a snapshot.
pub const SNAPSHOT_LEN: usize = 8;

/// One control period's sample.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Sample {
    /// Measurement of that period.
    pub measured: Measured,
    /// Torque reference, N m.
    pub torque_ref_nm: f64,
}

/// The last [`SNAPSHOT_LEN`] samples, oldest first once full.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Snapshot {
    buf: [Sample; SNAPSHOT_LEN],
    next: usize,
    len: usize,
}

impl Snapshot {
    /// Adds the newest sample (the oldest drops out when full).
    pub fn push(&mut self, s: Sample) {
        self.buf[self.next] = s;
        self.next = (self.next + 1) % SNAPSHOT_LEN;
        self.len = (self.len + 1).min(SNAPSHOT_LEN);
    }
    /// Samples held, oldest first.
    pub fn samples(&self) -> impl Iterator<Item = &Sample> {
        let start = (self.next + SNAPSHOT_LEN - self.len) % SNAPSHOT_LEN;
        (0..self.len).map(move |k| &self.buf[(start + k) % SNAPSHOT_LEN])
    }
    /// Number of samples held.
    pub fn len(&self) -> usize {
        self.len
    }
    /// No sample yet.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}

/// One fault as it was latched.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FaultRecord {
    /// Bit of the fault in [`Faults`] (its code is `bit + 1`).
    pub bit: usize,
    /// Drive time when the control step saw it: control periods run and
    /// missed times their period, s.
    pub time_s: f64,
    /// The samples of the control periods before.
    pub snapshot: Snapshot,
}

impl FaultRecord {
    /// Stable code (see [`Faults::code`]).
    pub fn code(&self) -> u32 {
        Faults::code(self.bit)
    }
    /// Name (see [`Faults::NAMES`]).
    pub fn name(&self) -> &'static str {
        Faults::NAMES[self.bit]
    }

    /// `t=<s> s code <c> <NAME>: <n> samples, i_d <min>..<max> A, i_q
    /// <min>..<max> A, last torque <x> Nm (ref <x> Nm)`.
    pub fn write_summary<W: Write>(&self, out: &mut W) -> fmt::Result {
        write!(
            out,
            "t={:.6} s code {} {}: {} samples",
            self.time_s,
            self.code(),
            self.name(),
            self.snapshot.len()
        )?;
        let mut it = self.snapshot.samples();
        let Some(first) = it.next() else {
            return Ok(());
        };
        let (mut d, mut q) = (
            (first.measured.i_d_a, first.measured.i_d_a),
            (first.measured.i_q_a, first.measured.i_q_a),
        );
        let mut last = first;
        for s in it {
            d = (d.0.min(s.measured.i_d_a), d.1.max(s.measured.i_d_a));
            q = (q.0.min(s.measured.i_q_a), q.1.max(s.measured.i_q_a));
            last = s;
        }
        write!(
            out,
            ", i_d {:.3}..{:.3} A, i_q {:.3}..{:.3} A, last torque {:.4} Nm (ref {:.4} Nm)",
            d.0, d.1, q.0, q.1, last.measured.torque_nm, last.torque_ref_nm
        )
    }
}

/// The last [`HISTORY_LEN`] faults.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FaultHistory {
    buf: [Option<FaultRecord>; HISTORY_LEN],
    next: usize,
    /// Faults recorded since boot (also those that dropped out).
    pub total: u32,
}

impl Default for FaultHistory {
    fn default() -> Self {
        Self {
            buf: [None; HISTORY_LEN],
            next: 0,
            total: 0,
        }
    }
}

impl FaultHistory {
    /// Records a fault (the oldest drops out when full).
    pub fn push(&mut self, r: FaultRecord) {
        self.buf[self.next] = Some(r);
        self.next = (self.next + 1) % HISTORY_LEN;
        self.total = self.total.saturating_add(1);
    }
    /// The records, oldest first.
    pub fn records(&self) -> impl Iterator<Item = &FaultRecord> {
        (0..HISTORY_LEN).filter_map(move |k| self.buf[(self.next + k) % HISTORY_LEN].as_ref())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::string::String;

    fn sample(i_q: f64) -> Sample {
        Sample {
            measured: Measured {
                i_d_a: -i_q / 10.0,
                i_q_a: i_q,
                torque_nm: i_q / 10.0,
                omega_e_rad_s: 0.0,
            },
            torque_ref_nm: 0.4,
        }
    }

    #[test]
    fn snapshot_keeps_the_last_samples_oldest_first() {
        let mut s = Snapshot::default();
        assert!(s.is_empty());
        for k in 0..11 {
            s.push(sample(f64::from(k)));
        }
        let q: std::vec::Vec<f64> = s.samples().map(|x| x.measured.i_q_a).collect();
        assert_eq!(q, [3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0]);
        let r = FaultRecord {
            bit: 4,
            time_s: 0.0125,
            snapshot: s,
        };
        let mut o = String::new();
        r.write_summary(&mut o).unwrap();
        assert_eq!(
            o,
            "t=0.012500 s code 5 ADC_STUCK: 8 samples, i_d -1.000..-0.300 A, \
             i_q 3.000..10.000 A, last torque 1.0000 Nm (ref 0.4000 Nm)"
        );
        let empty = FaultRecord {
            snapshot: Snapshot::default(),
            ..r
        };
        let mut o = String::new();
        empty.write_summary(&mut o).unwrap();
        assert_eq!(o, "t=0.012500 s code 5 ADC_STUCK: 0 samples");
    }

    #[test]
    fn history_keeps_the_last_16() {
        let mut h = FaultHistory::default();
        assert_eq!(h.records().count(), 0);
        for k in 0..20 {
            h.push(FaultRecord {
                bit: k % 6,
                time_s: f64::from(k as u32),
                snapshot: Snapshot::default(),
            });
        }
        let t: std::vec::Vec<f64> = h.records().map(|r| r.time_s).collect();
        assert_eq!(t.len(), HISTORY_LEN);
        assert_eq!(t[0], 4.0);
        assert_eq!(t[15], 19.0);
        assert_eq!(h.total, 20);
    }
}
