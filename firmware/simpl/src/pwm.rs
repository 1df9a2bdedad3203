//! `pwm_center`: the centre-aligned up-down counter and the three
//! comparators, and its closed form between events.
//!
//! The counter runs 0, 1, .., P-1, P-1, .., 1, 0, 0, 1, .. (P = PWM_PERIOD,
//! loaded with the duties at the bottom), leg x's upper switch is requested
//! while `count < duty_x`. Events (cycles the event-driven loop must step
//! one by one): the bottom, the top, and, when the comparators drive the
//! gates, a comparator output change.

/// Registers of `pwm_center` (reset values of the RTL).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Pwm {
    /// Up-down counter (`cnt_q`).
    pub count: u16,
    /// Counting down (`down_q`).
    pub down: bool,
    /// Period loaded at the last bottom (`period_q`).
    pub period: u16,
    /// Duties of legs a, b, c loaded at the last bottom.
    pub duty: [u16; 3],
}

impl Default for Pwm {
    fn default() -> Self {
        Self {
            count: 0,
            // So that the registers load at the first edge.
            down: true,
            period: 2,
            duty: [0; 3],
        }
    }
}

impl Pwm {
    /// Requested switching state `SaSbSc` of this cycle.
    pub fn s(&self) -> u8 {
        let on = |d: u16| u8::from(self.count < d);
        (on(self.duty[0]) << 2) | (on(self.duty[1]) << 1) | on(self.duty[2])
    }

    /// The last cycle of the down ramp: the registers load at its edge (a
    /// PWM period starts).
    pub fn bottom(&self) -> bool {
        self.down && self.count == 0
    }

    fn top(&self) -> bool {
        !self.down && self.count.wrapping_add(1) >= self.period
    }

    /// One clock edge with the register values `period`, `duty` (a, b, c).
    pub fn step(&mut self, period: u16, duty: [u16; 3]) {
        if self.bottom() {
            self.down = false;
            self.period = period;
            self.duty = duty;
        } else if self.top() {
            self.down = true;
        } else if self.down {
            self.count -= 1;
        } else {
            self.count += 1;
        }
    }

    /// Cycles from now in which the counter only counts: no bottom, no top
    /// and, if `track_s`, no comparator change.
    pub fn quiet(&self, track_s: bool) -> u64 {
        if self.bottom() || self.top() {
            return 0;
        }
        let c = u64::from(self.count);
        let mut k;
        if self.down {
            k = c;
            if track_s {
                for d in self.duty.map(u64::from) {
                    if c >= d {
                        k = k.min(c - d + 1);
                    }
                }
            }
        } else {
            k = u64::from(self.period) - 1 - c;
            if track_s {
                for d in self.duty.map(u64::from) {
                    if c < d {
                        k = k.min(d - c);
                    }
                }
            }
        }
        k
    }

    /// Applies `k` quiet cycles (`k <= quiet(..)`).
    pub fn skip(&mut self, k: u64) {
        let k = k as u16;
        if self.down {
            self.count -= k;
        } else {
            self.count += k;
        }
    }
}
