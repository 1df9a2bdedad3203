//! When the MPDTC's two-step rotor alignment moves on: each step (the
//! vector `ALIGN_FIRST`, then `ALIGN_D`) ends once the encoder has been
//! still for [`ALIGN_SETTLE_S`], at the earliest that long after the step
//! began, at the latest at the configured alignment time (the first step
//! at its half, the second at its end: the PL's own `MPDTC_ALIGN_TIME`
//! timer). Why 20 ms: docs/mpdtc.md, "Rotor alignment".
//!
//! "Still": the sampled count stays within [`STILL_COUNTS`] of where the
//! window started (one count of dither at an edge is rest, not motion).

/// How long the encoder must be still before a step ends, s.
pub const ALIGN_SETTLE_S: f64 = 0.02;
/// Counts of movement (either way, modulo CPR) still taken as rest.
pub const STILL_COUNTS: u32 = 1;

/// What the control step does with the alignment this period.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AlignAction {
    /// Nothing: the present step goes on.
    Hold,
    /// The first step is over: the vector goes to the d axis.
    SecondStep,
    /// The second step is over: the PL latches the zero now.
    End,
}

/// The alignment's progress, one [`AlignSteps::next`] per control period.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AlignSteps {
    /// 0: first step, 1: second step, 2: ended (waiting for the PL).
    step: u8,
    /// Periods since the present step began.
    elapsed: u64,
    /// Periods the encoder has been still (within the band of `anchor`).
    still: u64,
    /// The count the present still window started at.
    anchor: Option<u32>,
    /// Periods of stillness that end a step.
    settle: u64,
    /// Periods after which the first step ends whatever the encoder does.
    first_max: u64,
    /// Periods since the alignment began.
    total: u64,
    /// When the PL's timer ends the alignment whatever the encoder does
    /// (`MPDTC_ALIGN_TIME`), s.
    align_s: f64,
    /// The control period, s.
    period_s: f64,
}

impl AlignSteps {
    /// An alignment of `align_cycles` PL cycles in control periods of
    /// `period_cycles` PL cycles (> 0), at PL clock `clock_hz`.
    pub fn new(period_cycles: f64, align_cycles: u32, clock_hz: f64) -> Self {
        Self {
            step: 0,
            elapsed: 0,
            still: 0,
            anchor: None,
            settle: libm::ceil(ALIGN_SETTLE_S * clock_hz / period_cycles) as u64,
            first_max: libm::ceil(f64::from(align_cycles / 2) / period_cycles) as u64,
            total: 0,
            align_s: f64::from(align_cycles) / clock_hz,
            period_s: period_cycles / clock_hz,
        }
    }

    /// The longest the alignment can still take, s: until the PL's timer
    /// ends it (it ends sooner once the rotor is still). 0 once its last
    /// step is over (the PL latches the zero at the next period).
    pub fn left_s(&self) -> f64 {
        if self.step >= 2 {
            return 0.0;
        }
        (self.align_s - self.total as f64 * self.period_s).max(0.0)
    }

    /// One control period with the sampled encoder count `pos` of `cpr`
    /// counts per revolution.
    pub fn next(&mut self, pos: u32, cpr: u32) -> AlignAction {
        if self.step >= 2 {
            return AlignAction::Hold;
        }
        self.elapsed += 1;
        self.total += 1;
        let moved = match self.anchor {
            Some(a) => {
                let d = pos.wrapping_sub(a) % cpr.max(1);
                d.min(cpr - d) > STILL_COUNTS
            }
            None => true,
        };
        if moved {
            self.anchor = Some(pos);
            self.still = 0;
        } else {
            self.still += 1;
        }
        // The first sample starts the window: a step that began still has
        // been still since it began.
        let settled = self.still + 1 >= self.settle;
        match self.step {
            0 if settled || self.elapsed >= self.first_max => {
                self.step = 1;
                self.elapsed = 0;
                self.still = 0;
                self.anchor = None;
                AlignAction::SecondStep
            }
            1 if settled => {
                self.step = 2;
                AlignAction::End
            }
            _ => AlignAction::Hold,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 100 MHz, 1000-cycle periods: 20 ms = 2000 periods.
    fn steps(align_cycles: u32) -> AlignSteps {
        AlignSteps::new(1000.0, align_cycles, 1e8)
    }

    /// Periods until `want`, feeding `pos(k)`.
    fn periods_until(a: &mut AlignSteps, want: AlignAction, pos: impl Fn(u64) -> u32) -> u64 {
        (0..1_000_000u64)
            .find(|&k| a.next(pos(k), 4096) == want)
            .expect("the action came")
            + 1
    }

    #[test]
    fn a_held_rotor_ends_each_step_after_the_settle_time() {
        let mut a = steps(20_000_000);
        assert_eq!(periods_until(&mut a, AlignAction::SecondStep, |_| 7), 2000);
        assert_eq!(periods_until(&mut a, AlignAction::End, |_| 7), 2000);
        assert_eq!(a.next(7, 4096), AlignAction::Hold);
    }

    #[test]
    fn motion_restarts_the_window_and_one_count_of_dither_does_not() {
        let mut a = steps(20_000_000);
        // Moves three counts per period for 500 periods, then rests.
        let n = periods_until(&mut a, AlignAction::SecondStep, |k| 3 * k.min(500) as u32);
        assert_eq!(n, 500 + 2000);
        // Dither between 4095 and 0 (one count across the wrap).
        let n = periods_until(
            &mut a,
            AlignAction::End,
            |k| if k % 2 == 0 { 4095 } else { 0 },
        );
        assert_eq!(n, 2000);
        // Two counts is motion: never settles; only the PL's timer ends
        // the second step.
        let mut b = steps(20_000_000);
        b.next(0, 4096);
        for k in 0..10_000u32 {
            assert_ne!(
                b.next(if k % 2 == 0 { 2 } else { 0 }, 4096),
                AlignAction::End
            );
        }
    }

    #[test]
    fn the_time_left_counts_down_from_the_configured_time_to_zero_at_the_end() {
        // 200 ms in 10 us periods: 20,000 periods.
        let mut a = steps(20_000_000);
        assert_eq!(a.left_s(), 0.2);
        periods_until(&mut a, AlignAction::SecondStep, |_| 7);
        // 2000 periods of 10 us gone.
        assert!((a.left_s() - 0.18).abs() < 1e-12, "{}", a.left_s());
        periods_until(&mut a, AlignAction::End, |_| 7);
        assert_eq!(a.left_s(), 0.0);
    }

    #[test]
    fn the_configured_time_bounds_the_first_step() {
        // 2 ms: 100 periods for the first half, below the settle time.
        let mut a = steps(200_000);
        assert_eq!(
            periods_until(&mut a, AlignAction::SecondStep, |k| k as u32),
            100
        );
        // A moving rotor in the first step of a long alignment: its half.
        let mut b = steps(20_000_000);
        assert_eq!(
            periods_until(&mut b, AlignAction::SecondStep, |k| (3 * k) as u32),
            10_000
        );
    }
}
