//! The simulated PL (`simpl::SimPl`) with the bus timing of the Verilated
//! `pl_top` as `cosim::RtlPl` drives it: a read takes three cycles (its
//! register-bus strobe in the first, then the register file's second read
//! stage and R), a write four (AW and W taken, the register-bus write, the
//! register file's decoded write in the third, then B). The model is the
//! same; only the cycles an access occupies change, so a PS-side loop's
//! accesses land on the same PL cycles on both and their results can be
//! compared one for one.
use regmap::bus::BusError;
use simpl::gates::GateOutputs;
use simpl::pl::{Events, Pins, SimPl};
use simpl::PlModel;

/// `SimPl` with `pl_top`'s AXI4-Lite access cycles.
pub struct RtlTimedSimPl(pub SimPl);

impl RtlTimedSimPl {
    fn idle(&mut self, n: u64, ev: &mut Events) {
        for _ in 0..n {
            let (_, e) = self.0.run(1, &Events::ALL);
            ev.merge(&e);
        }
    }
}

impl PlModel for RtlTimedSimPl {
    fn cycles(&self) -> u64 {
        self.0.cycles()
    }
    fn gates(&self) -> GateOutputs {
        self.0.gates()
    }
    fn pins_mut(&mut self) -> &mut Pins {
        &mut self.0.pins
    }
    fn set_adc_fitted(&mut self, fitted: bool) {
        self.0.set_adc_fitted(fitted);
    }
    fn run(&mut self, max: u64, stop: &Events) -> (u64, Events) {
        self.0.run(max, stop)
    }
    fn read(&mut self, addr: usize) -> (Result<u32, BusError>, Events) {
        let (r, mut ev) = self.0.read(addr);
        self.idle(2, &mut ev);
        (r, ev)
    }
    fn write(&mut self, addr: usize, value: u32) -> (Result<(), BusError>, Events) {
        let mut ev = Events::default();
        self.idle(2, &mut ev);
        let (r, e) = self.0.write(addr, value);
        ev.merge(&e);
        self.idle(1, &mut ev);
        (r, ev)
    }
    fn work(&self) -> (u64, u64) {
        PlModel::work(&self.0)
    }
}
