//! Paper 000: PMSM + 2-level inverter, FOC baseline, MPDTC.
