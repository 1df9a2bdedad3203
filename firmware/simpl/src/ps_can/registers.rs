//! The model's register file: `SR` from the state, the RX and TX windows,
//! and [`RegisterBus`] decoding every offset of the controller.

use super::confinement::State;
use super::{BusMode, PsCanModel, AFR_BITS, BTR_BITS, ERROR_WARNING_AT, ESR_BITS, MSR_BITS};
use regmap::bus::{BusError, RegisterBus};
use regmap::ps_can as reg;

impl PsCanModel {
    fn status(&self) -> u32 {
        let mode = match self.mode() {
            BusMode::Configuration => reg::SR_CONFIG,
            BusMode::Normal => reg::SR_NORMAL,
            BusMode::Loopback => reg::SR_LBACK,
            BusMode::Snoop => reg::SR_SNOOP,
            BusMode::Sleep => reg::SR_SLEEP,
        };
        let estat = match (self.cen, self.errors.state()) {
            (false, _) => reg::ESTAT_CONFIG,
            (true, State::Active) => reg::ESTAT_ACTIVE,
            (true, State::Passive) => reg::ESTAT_PASSIVE,
            (true, State::BusOff) => reg::ESTAT_BUS_OFF,
        };
        let mut sr = mode | estat << reg::SR_ESTAT_SHIFT;
        if self.cen {
            // Between frames the modelled bus is always idle.
            sr |= reg::SR_BIDLE;
        }
        if self.errors.tec() >= ERROR_WARNING_AT || self.errors.rec() >= ERROR_WARNING_AT {
            sr |= reg::SR_ERRWRN;
        }
        if self.hpb.is_some() {
            sr |= reg::SR_TXBFLL;
        }
        if self.tx_fifo.is_full() {
            sr |= reg::SR_TXFLL;
        }
        sr
    }

    /// Reads of the RX FIFO window; `DATA2` removes the message.
    fn read_rx(&mut self, offset: usize) -> u32 {
        let Some(m) = self.rx_fifo.front().copied() else {
            self.isr |= reg::IXR_RXUFLW;
            return 0;
        };
        match offset {
            reg::RXFIFO_ID => m.id,
            reg::RXFIFO_DLC => m.dlc,
            reg::RXFIFO_DATA1 => m.data1,
            _ => {
                self.rx_fifo.pop();
                m.data2
            }
        }
    }

    /// Writes of a TX window (`hpb`: the high-priority buffer).
    fn write_tx(&mut self, word: usize, v: u32, hpb: bool) {
        let stage = if hpb {
            &mut self.hpb_stage
        } else {
            &mut self.tx_stage
        };
        match word {
            0 => stage.id = v,
            1 => stage.dlc = v & (reg::DLC_MASK << reg::DLC_SHIFT),
            2 => stage.data1 = v,
            _ => {
                stage.data2 = v;
                let m = *stage;
                let queued = if !hpb {
                    self.tx_fifo.push(m)
                } else if self.hpb.is_none() {
                    self.hpb = Some(m);
                    true
                } else {
                    false
                };
                if !queued {
                    self.dropped_tx_writes += 1;
                }
                self.assert_levels();
            }
        }
    }

    /// The offset of `addr` in this controller, if it is one of its
    /// registers.
    fn offset(&self, addr: usize) -> Option<usize> {
        let off = addr.checked_sub(self.base)?;
        (off <= reg::LAST_OFFSET && off % 4 == 0).then_some(off)
    }

    /// Index of the filter whose mask (`false`) or identifier (`true`)
    /// register is at `off`.
    fn filter_slot(off: usize) -> Option<(usize, bool)> {
        (0..reg::FILTER_COUNT).find_map(|n| {
            if reg::afmr(n) == Some(off) {
                Some((n, false))
            } else if reg::afir(n) == Some(off) {
                Some((n, true))
            } else {
                None
            }
        })
    }
}

impl RegisterBus for PsCanModel {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        let off = self.offset(addr).ok_or(BusError::SlaveError)?;
        Ok(match off {
            reg::SRR => u32::from(self.cen) * reg::SRR_CEN,
            reg::MSR => self.msr,
            reg::BRPR => self.brpr,
            reg::BTR => self.btr,
            reg::ECR => {
                u32::from(self.errors.tec()) << reg::ECR_TEC_SHIFT
                    | u32::from(self.errors.rec()) << reg::ECR_REC_SHIFT
            }
            reg::ESR => self.esr,
            reg::SR => self.status(),
            reg::ISR => self.isr,
            reg::IER => self.ier,
            reg::TCR => self.tcr,
            reg::WIR => self.wir,
            reg::RXFIFO_ID..=reg::RXFIFO_DATA2 => self.read_rx(off),
            reg::AFR => self.afr,
            _ => match Self::filter_slot(off) {
                Some((n, false)) => self.afmr[n],
                Some((n, true)) => self.afir[n],
                // ICR and the TX windows are write-only: they read 0.
                None => 0,
            },
        })
    }

    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        let off = self.offset(addr).ok_or(BusError::SlaveError)?;
        match off {
            reg::SRR => {
                if value & reg::SRR_SRST != 0 {
                    self.reset();
                } else {
                    self.cen = value & reg::SRR_CEN != 0;
                }
            }
            reg::MSR | reg::BRPR | reg::BTR if self.cen => self.ignored_config_writes += 1,
            reg::MSR => self.msr = value & MSR_BITS,
            reg::BRPR => self.brpr = value & reg::BRPR_BRP_MASK,
            reg::BTR => self.btr = value & BTR_BITS,
            reg::ESR => self.esr &= !(value & ESR_BITS),
            reg::IER => self.ier = value & reg::IXR_ALL,
            reg::ICR => {
                self.isr &= !(value & reg::IXR_ALL);
                self.assert_levels();
            }
            reg::TCR => self.tcr = value & 1,
            reg::WIR => self.wir = value & 0xFFFF,
            reg::TXFIFO_ID..=reg::TXFIFO_DATA2 => {
                self.write_tx((off - reg::TXFIFO_ID) / 4, value, false)
            }
            reg::TXHPB_ID..=reg::TXHPB_DATA2 => {
                self.write_tx((off - reg::TXHPB_ID) / 4, value, true)
            }
            reg::AFR => self.afr = value & AFR_BITS,
            // ECR, SR, ISR and the RX window are read-only: writes are
            // ignored.
            _ => match Self::filter_slot(off) {
                Some((n, _)) if self.afr & (1 << n) != 0 => self.ignored_filter_writes += 1,
                Some((n, false)) => self.afmr[n] = value,
                Some((n, true)) => self.afir[n] = value,
                None => {}
            },
        }
        Ok(())
    }
}
