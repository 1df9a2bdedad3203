//! The control interrupt (`IRQ_EN`, `IRQ_STATUS`, `BOUNDARY_AGE`; the PL's
//! `irq_o` on `IRQ_F2P[0]`, GIC SPI 61): enabling it, taking it at the
//! start of the control step, and the step's start latency after the
//! control-period boundary.
use regmap::bus::{BusError, RegisterBus};
use regmap::regs::top::{BoundaryAge, IrqEn, IrqEnValue, IrqStatus, IrqStatusValue};

/// Enables the boundary interrupt and clears stale flags.
pub fn enable<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<(), BusError> {
    clear(bus)?;
    IrqEn::write(bus, IrqEnValue::from_bits(0).with_boundary(true))
}

/// Clears every flag (W1C): boundaries crossed before the control loop
/// starts are no steps it owes.
pub fn clear<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<(), BusError> {
    IrqStatus::write(bus, IrqStatusValue::from_bits(0b111))
}

/// What the handler found when it took the interrupt.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Taken {
    /// `IRQ_STATUS` before the acknowledge.
    pub status: IrqStatusValue,
    /// `BOUNDARY_AGE`: PL cycles since the boundary.
    pub age: u32,
}

/// Reads the flags and the age, then acknowledges the flags read (the
/// line drops; a boundary in the same cycle still sets its flag).
pub fn take<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<Taken, BusError> {
    let mut w = [0; 2];
    bus.read_many(&[BoundaryAge::ADDR, IrqStatus::ADDR], &mut w)?;
    let (age, status) = (w[0], IrqStatusValue::from_bits(w[1]));
    if status.bits() != 0 {
        IrqStatus::write(bus, status)?;
    }
    Ok(Taken { status, age })
}

/// Start latency of the control step after the boundary, PL cycles.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Latency {
    /// Samples.
    pub n: u64,
    /// Smallest, PL cycles.
    pub min: u32,
    /// Largest, PL cycles.
    pub max: u32,
    /// Sum, PL cycles.
    pub sum: u64,
}

impl Latency {
    /// Adds one sample.
    pub fn add(&mut self, cycles: u32) {
        self.min = if self.n == 0 {
            cycles
        } else {
            self.min.min(cycles)
        };
        self.max = self.max.max(cycles);
        self.sum += u64::from(cycles);
        self.n += 1;
    }

    /// Mean, PL cycles (0 without samples).
    pub fn mean(&self) -> f64 {
        if self.n == 0 {
            0.0
        } else {
            self.sum as f64 / self.n as f64
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pl::fake::FakePl;

    #[test]
    fn take_reads_age_and_acknowledges_what_it_read() {
        let mut pl = FakePl::new();
        enable(&mut pl).unwrap();
        assert_eq!(IrqEn::read(&mut pl).unwrap().bits(), 1);
        pl.set(IrqStatus::ADDR, 0b101);
        pl.set(BoundaryAge::ADDR, 37);
        let t = take(&mut pl).unwrap();
        assert!(t.status.boundary() && t.status.missed() && !t.status.fault());
        assert_eq!(t.age, 37);
        // W1C of what was read: nothing left.
        assert_eq!(IrqStatus::read(&mut pl).unwrap().bits(), 0);
    }

    #[test]
    fn latency_min_mean_max() {
        let mut l = Latency::default();
        assert_eq!(l.mean(), 0.0);
        for c in [12, 4, 20] {
            l.add(c);
        }
        assert_eq!((l.n, l.min, l.max), (3, 4, 20));
        assert_eq!(l.mean(), 12.0);
    }
}

/// Where a PL that runs in guest time (QEMU's co-simulation) is after a
/// sync: boundaries crossed, and PL cycles since the last one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SyncPoint {
    /// Timer count (one per PL cycle) read before the sync.
    pub now: u64,
    /// PL cycles since the last boundary at the sync (`u64::MAX`: unknown).
    pub since: u64,
    /// Whether the boundaries' phase is known (no register write since the
    /// last boundary seen).
    pub phase_known: bool,
}

/// Timer count of the next PL tick of a co-simulated PL, so that it comes
/// after the next boundary and before the one after it (one boundary per
/// tick: two would be a control step lost). `period` in PL cycles, `lag`
/// the cycles a boundary needs to show after its strobe, `poll_div` the
/// share of a period the ticks poll at while the phase is unknown.
///
/// - Phase unknown: poll every `period / poll_div`.
/// - The last boundary less than a period ago: just after the next one.
/// - A period or more ago: the boundary is due (the ADC's average that
///   ends a period is a cycle late, or `since` was taken a cycle early):
///   poll soon. Planning a whole period ahead from there put the tick just
///   after the boundary after next: two boundaries in one sync, an
///   overrun.
pub fn next_cosim_tick(p: SyncPoint, period: u64, lag: u64, poll_div: u64) -> u64 {
    let poll = p.now + (period / poll_div).max(1);
    if !p.phase_known {
        poll
    } else if p.since < period {
        (p.now + period + lag).saturating_sub(p.since)
    } else {
        poll
    }
}

/// Whether the boundaries' phase is known after a sync that reported
/// `boundaries` (new ones), with `wrote`: the sync ends a console section
/// that wrote registers. Such a section may have moved the boundaries
/// (a mode change, a new ADC period), and its sync cannot tell whether a
/// boundary it reports came before or after the writes (a PWM bottom of
/// the old timing in the section's own accesses is one): the phase stays
/// unknown until a later sync reports a boundary. Taken as known from a
/// boundary of the old timing, the next tick was planned a period after
/// it and the first step of the new timing started up to a period late
/// (974 PL cycles after its boundary after `mode off`, against the
/// poll's 195).
pub fn phase_known_after(known: bool, wrote: bool, boundaries: u32) -> bool {
    !wrote && (known || boundaries > 0)
}

#[cfg(test)]
mod cosim_tick_tests {
    use super::*;

    /// A tick's entry and sync cost, varied: a console section or another
    /// handler may hold the tick off for some cycles.
    fn jitter(k: u64) -> u64 {
        // SplitMix64's finaliser: consecutive k give unrelated values.
        let mut z = k.wrapping_add(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Ticks paced by [`next_cosim_tick`] against boundaries every
    /// `period` cycles from `phase` (`late` of them one cycle late, as an
    /// ADC average can be), each sync `d(k)` cycles after its tick and
    /// each step `step` cycles long; returns the most boundaries one sync
    /// saw and the boundaries seen in all.
    fn pace(
        period: u64,
        planned_period: u64,
        phase: u64,
        late: impl Fn(u64) -> bool,
        d: impl Fn(u64) -> u64,
        step: u64,
    ) -> (u32, u64) {
        let boundary = |k: u64| 10_000 + phase + k * period + u64::from(late(k));
        let (mut next_k, mut last, mut worst, mut seen) = (0u64, None::<u64>, 0u32, 0u64);
        let mut t = 10_000;
        let mut k = 0;
        while seen < 300 && k < 10_000 {
            k += 1;
            let sync = t + d(k);
            let mut n = 0;
            while boundary(next_k) <= sync {
                last = Some(boundary(next_k));
                next_k += 1;
                n += 1;
            }
            worst = worst.max(n);
            seen += u64::from(n);
            let p = SyncPoint {
                now: t,
                since: last.map_or(u64::MAX, |b| sync - b),
                phase_known: last.is_some(),
            };
            let plan = next_cosim_tick(p, planned_period, 4, 8);
            // The control step, when one is due, runs before the next
            // tick and plans it no earlier than its own end.
            t = if n > 0 {
                plan.max(sync + step + 4)
            } else {
                plan
            };
        }
        (worst, seen)
    }

    #[test]
    fn every_tick_serves_one_boundary_whatever_the_phase_and_the_sync_cost() {
        for phase in 0..1564 {
            for d in [0u64, 3, 17, 40] {
                let vary = move |k: u64| jitter(k + d) % 64;
                let (worst, seen) = pace(1564, 1564, phase, |_| false, vary, 300);
                assert_eq!(worst, 1, "phase {phase} d {d}");
                assert_eq!(seen, 300, "phase {phase} d {d}");
                // An average a cycle late now and then.
                let (worst, _) = pace(1564, 1564, phase, |k| k % 5 == 0, vary, 300);
                assert_eq!(worst, 1, "phase {phase} d {d}, late boundaries");
            }
        }
    }

    /// PL cycles from the first boundary of a new timing to the sync
    /// that sees it, after a console section whose writes moved the
    /// boundaries to `off` cycles after its sync, that sync reporting one
    /// boundary of the old timing `a` cycles before it.
    fn first_new_boundary_seen_after(
        rule: impl Fn(bool, bool, u32) -> bool,
        a: u64,
        off: u64,
        period: u64,
    ) -> u64 {
        let s = 100_000;
        let first = s + off;
        let mut known = rule(false, true, 1);
        let mut t = next_cosim_tick(
            SyncPoint {
                now: s,
                since: a,
                phase_known: known,
            },
            period,
            4,
            8,
        );
        // The last boundary a sync reports until a new one: the old one.
        let last = s - a;
        let mut prev = s;
        loop {
            // New boundaries in (prev, t].
            let n = (first..)
                .step_by(period as usize)
                .take_while(|b| *b <= t)
                .filter(|b| *b > prev)
                .count() as u32;
            if n > 0 {
                return t - first;
            }
            known = rule(known, false, n);
            let since = t - last;
            prev = t;
            t = next_cosim_tick(
                SyncPoint {
                    now: t,
                    since,
                    phase_known: known,
                },
                period,
                4,
                8,
            );
        }
    }

    #[test]
    fn a_boundary_reported_with_the_writes_leaves_the_phase_unknown() {
        for period in [1564u64, 6256] {
            for a in [19u64, 385, 1_500] {
                for off in 1..=period {
                    let late = first_new_boundary_seen_after(phase_known_after, a, off, period);
                    assert!(
                        late <= period / 8,
                        "period {period} a {a} off {off}: {late}"
                    );
                }
            }
        }
        // The former rule: any boundary reported fixed the phase.
        let former = |known: bool, _wrote: bool, n: u32| known || n > 0;
        let worst = (1..=1564)
            .map(|off| first_new_boundary_seen_after(former, 385, off, 1564))
            .max()
            .unwrap();
        assert!(worst > 1_000, "{worst}");
    }

    #[test]
    fn a_period_planned_one_cycle_short_still_serves_one_boundary() {
        // The period the firmware used to plan with (1,563 for 1,564):
        // a sync one cycle before a boundary then saw `since` = period and
        // planned a whole period on, past the boundary after next (two
        // boundaries in one sync: the overrun of the co-simulated MPDTC).
        let p = SyncPoint {
            now: 10_000,
            since: 1563,
            phase_known: true,
        };
        let next = next_cosim_tick(p, 1563, 4, 8);
        // The boundary is due at 10,001; the one after it at 11,565.
        assert!(next < 11_565, "{next}");
        for phase in 0..1564 {
            let (worst, _) = pace(
                1564,
                1563,
                phase,
                |_| false,
                |k| jitter(k + phase) % 64,
                300,
            );
            assert_eq!(worst, 1, "phase {phase}");
        }
    }
}
