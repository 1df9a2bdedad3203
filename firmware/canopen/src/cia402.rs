//! The CiA 402-2 drive state machine ("power drive system" finite state
//! automaton of CiA 402-2), its controlword 0x6040
//! and statusword 0x6041, and the modes of operation 0x6060 / 0x6061 with
//! the supported drive modes 0x6502.
//!
//! The machine never touches hardware: each call returns the transitions it
//! made, numbered as in CiA 402-2, with the [`Action`] the application owes
//! (power stage on/off, drive function on/off, quick stop ramp, fault
//! reaction). The application reports back what only it knows: that
//! initialisation ended, that a fault occurred, that the fault reaction or
//! the quick stop ended, and the statusword's inputs (voltage present,
//! warning, target reached, internal limit).
//!
//! Controlword commands (CiA 402-2 command coding, bits 7 3 2 1 0):
//! shutdown `0 x 1 1 0`, switch on `0 0 1 1 1`, switch on + enable
//! operation `0 1 1 1 1`, disable voltage `0 x x 0 x`, quick stop
//! `0 x 0 1 x`, disable operation `0 0 1 1 1`, enable operation
//! `0 1 1 1 1`, fault reset: bit 7 rising 0 -> 1. While bit 7 stays 1 no
//! command is decoded.

use crate::od::Abort;

/// Controlword bits (CiA 402-2, object 0x6040).
pub mod cw {
    pub const SWITCH_ON: u16 = 1 << 0;
    pub const ENABLE_VOLTAGE: u16 = 1 << 1;
    pub const QUICK_STOP: u16 = 1 << 2;
    pub const ENABLE_OPERATION: u16 = 1 << 3;
    pub const FAULT_RESET: u16 = 1 << 7;
    pub const HALT: u16 = 1 << 8;
}

/// Statusword bits (CiA 402-2, object 0x6041).
pub mod sw {
    pub const READY_TO_SWITCH_ON: u16 = 1 << 0;
    pub const SWITCHED_ON: u16 = 1 << 1;
    pub const OPERATION_ENABLED: u16 = 1 << 2;
    pub const FAULT: u16 = 1 << 3;
    pub const VOLTAGE_ENABLED: u16 = 1 << 4;
    /// Active low: 0 while a quick stop is active.
    pub const QUICK_STOP: u16 = 1 << 5;
    pub const SWITCH_ON_DISABLED: u16 = 1 << 6;
    pub const WARNING: u16 = 1 << 7;
    pub const REMOTE: u16 = 1 << 9;
    pub const TARGET_REACHED: u16 = 1 << 10;
    pub const INTERNAL_LIMIT_ACTIVE: u16 = 1 << 11;
    /// Bits the application may set freely: 8 (manufacturer-specific),
    /// 12..=13 (operation-mode specific), 14..=15 (manufacturer-specific).
    pub const APPLICATION_BITS: u16 = 0xF100;
}

/// Modes of operation (0x6060 values, CiA 402-2).
pub mod mode {
    pub const PROFILE_POSITION: i8 = 1;
    pub const VELOCITY: i8 = 2;
    pub const PROFILE_VELOCITY: i8 = 3;
    pub const PROFILE_TORQUE: i8 = 4;
    pub const HOMING: i8 = 6;
    pub const INTERPOLATED_POSITION: i8 = 7;
    pub const CYCLIC_SYNC_POSITION: i8 = 8;
    pub const CYCLIC_SYNC_VELOCITY: i8 = 9;
    pub const CYCLIC_SYNC_TORQUE: i8 = 10;
    /// The first manufacturer-specific mode (negative values).
    pub const VENDOR: i8 = -1;
}

/// The bit of 0x6502 (supported drive modes) that stands for `mode`:
/// modes 1..=10 (5 is reserved) use bit `mode - 1`; manufacturer-specific
/// modes -1..=-16 use bits 16..=31.
pub fn supported_bit(mode: i8) -> Option<u32> {
    match mode {
        1..=4 | 6..=10 => Some(1 << (mode - 1)),
        -16..=-1 => Some(1 << (15 - mode as i32)),
        _ => None,
    }
}

/// States of the drive (CiA 402-2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum State {
    NotReadyToSwitchOn,
    SwitchOnDisabled,
    ReadyToSwitchOn,
    SwitchedOn,
    OperationEnabled,
    QuickStopActive,
    FaultReactionActive,
    Fault,
}

impl State {
    /// The state bits of the statusword (bits 0..=3, 5, 6), with the bits
    /// CiA 402-2 marks "x" set to 0.
    pub fn status_bits(self) -> u16 {
        match self {
            State::NotReadyToSwitchOn => 0x0000,
            State::SwitchOnDisabled => 0x0040,
            State::ReadyToSwitchOn => 0x0021,
            State::SwitchedOn => 0x0023,
            State::OperationEnabled => 0x0027,
            State::QuickStopActive => 0x0007,
            State::FaultReactionActive => 0x000F,
            State::Fault => 0x0008,
        }
    }
}

/// A decoded controlword command.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Command {
    Shutdown,
    /// Also "disable operation" (same coding, meaning depends on state).
    SwitchOn,
    /// "Switch on + enable operation" and "enable operation".
    EnableOperation,
    DisableVoltage,
    QuickStop,
    FaultReset,
}

/// Decodes a controlword given the previous one (for the fault reset
/// edge); `None` while bit 7 stays set.
pub fn decode(cw: u16, previous: u16) -> Option<Command> {
    let fr = cw & cw::FAULT_RESET != 0;
    if fr {
        return (previous & cw::FAULT_RESET == 0).then_some(Command::FaultReset);
    }
    let b = cw & 0x000F;
    Some(if b & cw::ENABLE_VOLTAGE == 0 {
        Command::DisableVoltage
    } else if b & cw::QUICK_STOP == 0 {
        Command::QuickStop
    } else if b & cw::SWITCH_ON == 0 {
        Command::Shutdown
    } else if b & cw::ENABLE_OPERATION == 0 {
        Command::SwitchOn
    } else {
        Command::EnableOperation
    })
}

/// What the application must do for a transition.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    /// Nothing (transitions 1, 2, 7).
    None,
    /// Switch the power stage on, drive function still off (3).
    PowerOn,
    /// Enable the drive function: gates on, control loops run (4, 16).
    EnableOperation,
    /// Disable the drive function, power stage stays on (5).
    DisableOperation,
    /// Switch the power stage off; the drive function was already off (6, 10).
    PowerOff,
    /// Disable the drive function and switch the power stage off:
    /// gates off at once (8, 9, 12, 14).
    DisableAndPowerOff,
    /// Start the quick stop: ramp down as quick stop option code 0x605A
    /// says, then report [`Drive::quick_stop_complete`] (11).
    QuickStop { option_code: i16 },
    /// Start the fault reaction, then report
    /// [`Drive::fault_reaction_complete`] (13).
    FaultReaction,
    /// Clear the fault condition (15).
    ResetFault,
}

/// One transition of the state machine.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Transition {
    /// Its number in CiA 402-2 (0..=16).
    pub number: u8,
    pub from: State,
    pub to: State,
    pub action: Action,
}

/// The transitions one controlword made: none, one, or two ("switch on +
/// enable operation" from Ready to switch on is 3 then 4).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Outcome {
    steps: [Option<Transition>; 2],
}

impl Outcome {
    fn one(t: Transition) -> Self {
        Self {
            steps: [Some(t), None],
        }
    }

    /// The transitions, in order.
    pub fn iter(&self) -> impl Iterator<Item = &Transition> {
        self.steps.iter().flatten()
    }

    /// True when nothing changed.
    pub fn is_empty(&self) -> bool {
        self.steps[0].is_none()
    }

    /// The transition numbers, 0 padded (for tests and logs).
    pub fn numbers(&self) -> [u8; 2] {
        [
            self.steps[0].map_or(0, |t| t.number),
            self.steps[1].map_or(0, |t| t.number),
        ]
    }
}

/// The drive: state, controlword, statusword inputs and modes.
#[derive(Clone, Copy, Debug)]
pub struct Drive {
    state: State,
    controlword: u16,
    quick_stop_option: i16,
    voltage_enabled: bool,
    warning: bool,
    remote: bool,
    target_reached: bool,
    internal_limit: bool,
    app_bits: u16,
    mode: i8,
    supported: u32,
}

impl Drive {
    /// A drive in Not ready to switch on. `supported` is 0x6502 (see
    /// [`supported_bit`]); `initial_mode` must be one of them (else the
    /// mode is 0, none); `quick_stop_option` is 0x605A (0..=8).
    pub fn new(supported: u32, initial_mode: i8, quick_stop_option: i16) -> Self {
        let mode = match supported_bit(initial_mode) {
            Some(b) if supported & b != 0 => initial_mode,
            _ => 0,
        };
        Self {
            state: State::NotReadyToSwitchOn,
            controlword: 0,
            quick_stop_option,
            voltage_enabled: false,
            warning: false,
            remote: true,
            target_reached: false,
            internal_limit: false,
            app_bits: 0,
            mode,
            supported,
        }
    }

    /// The current state.
    pub fn state(&self) -> State {
        self.state
    }

    fn go(&mut self, number: u8, to: State, action: Action) -> Transition {
        let t = Transition {
            number,
            from: self.state,
            to,
            action,
        };
        self.state = to;
        t
    }

    /// Transition 1: self-test and initialisation done.
    pub fn initialised(&mut self) -> Option<Transition> {
        (self.state == State::NotReadyToSwitchOn)
            .then(|| self.go(1, State::SwitchOnDisabled, Action::None))
    }

    /// Transition 13: a fault occurred (in any state but the fault states).
    pub fn fault(&mut self) -> Option<Transition> {
        match self.state {
            State::FaultReactionActive | State::Fault => None,
            _ => Some(self.go(13, State::FaultReactionActive, Action::FaultReaction)),
        }
    }

    /// Transition 14: the fault reaction ended.
    pub fn fault_reaction_complete(&mut self) -> Option<Transition> {
        (self.state == State::FaultReactionActive)
            .then(|| self.go(14, State::Fault, Action::DisableAndPowerOff))
    }

    /// Transition 12 at the end of a quick stop whose option code (0..=4)
    /// leaves Quick stop active; with codes 5..=8 the drive stays there.
    pub fn quick_stop_complete(&mut self) -> Option<Transition> {
        (self.state == State::QuickStopActive && (0..=4).contains(&self.quick_stop_option))
            .then(|| self.go(12, State::SwitchOnDisabled, Action::DisableAndPowerOff))
    }

    /// Writes 0x6040 and runs the transitions its command asks for. A
    /// command the current state does not accept changes nothing.
    pub fn controlword(&mut self, value: u16) -> Outcome {
        let previous = self.controlword;
        self.controlword = value;
        let Some(cmd) = decode(value, previous) else {
            return Outcome::default();
        };
        use Command as C;
        use State as S;
        let t = match (self.state, cmd) {
            (S::SwitchOnDisabled, C::Shutdown) => self.go(2, S::ReadyToSwitchOn, Action::None),
            (S::ReadyToSwitchOn, C::SwitchOn) => self.go(3, S::SwitchedOn, Action::PowerOn),
            (S::ReadyToSwitchOn, C::EnableOperation) => {
                let a = self.go(3, S::SwitchedOn, Action::PowerOn);
                let b = self.go(4, S::OperationEnabled, Action::EnableOperation);
                return Outcome {
                    steps: [Some(a), Some(b)],
                };
            }
            (S::ReadyToSwitchOn, C::DisableVoltage | C::QuickStop) => {
                self.go(7, S::SwitchOnDisabled, Action::None)
            }
            (S::SwitchedOn, C::EnableOperation) => {
                self.go(4, S::OperationEnabled, Action::EnableOperation)
            }
            (S::SwitchedOn, C::Shutdown) => self.go(6, S::ReadyToSwitchOn, Action::PowerOff),
            (S::SwitchedOn, C::DisableVoltage | C::QuickStop) => {
                self.go(10, S::SwitchOnDisabled, Action::PowerOff)
            }
            (S::OperationEnabled, C::SwitchOn) => {
                self.go(5, S::SwitchedOn, Action::DisableOperation)
            }
            (S::OperationEnabled, C::Shutdown) => {
                self.go(8, S::ReadyToSwitchOn, Action::DisableAndPowerOff)
            }
            (S::OperationEnabled, C::DisableVoltage) => {
                self.go(9, S::SwitchOnDisabled, Action::DisableAndPowerOff)
            }
            (S::OperationEnabled, C::QuickStop) => {
                let option_code = self.quick_stop_option;
                self.go(11, S::QuickStopActive, Action::QuickStop { option_code })
            }
            (S::QuickStopActive, C::DisableVoltage) => {
                self.go(12, S::SwitchOnDisabled, Action::DisableAndPowerOff)
            }
            (S::QuickStopActive, C::EnableOperation)
                if (5..=8).contains(&self.quick_stop_option) =>
            {
                self.go(16, S::OperationEnabled, Action::EnableOperation)
            }
            (S::Fault, C::FaultReset) => self.go(15, S::SwitchOnDisabled, Action::ResetFault),
            _ => return Outcome::default(),
        };
        Outcome::one(t)
    }

    /// The last controlword written (0x6040 read back).
    pub fn controlword_value(&self) -> u16 {
        self.controlword
    }

    /// Object 0x6041.
    pub fn statusword(&self) -> u16 {
        let mut s = self.state.status_bits() | self.app_bits;
        let flags = [
            (self.voltage_enabled, sw::VOLTAGE_ENABLED),
            (self.warning, sw::WARNING),
            (self.remote, sw::REMOTE),
            (self.target_reached, sw::TARGET_REACHED),
            (self.internal_limit, sw::INTERNAL_LIMIT_ACTIVE),
        ];
        for (on, bit) in flags {
            if on {
                s |= bit;
            }
        }
        s
    }

    /// Statusword bit 4: the power stage's supply is present.
    pub fn set_voltage_enabled(&mut self, on: bool) {
        self.voltage_enabled = on;
    }
    /// Statusword bit 7.
    pub fn set_warning(&mut self, on: bool) {
        self.warning = on;
    }
    /// Statusword bit 9: the controlword is processed (default on).
    pub fn set_remote(&mut self, on: bool) {
        self.remote = on;
    }
    /// Statusword bit 10.
    pub fn set_target_reached(&mut self, on: bool) {
        self.target_reached = on;
    }
    /// Statusword bit 11.
    pub fn set_internal_limit(&mut self, on: bool) {
        self.internal_limit = on;
    }
    /// Statusword bits 8, 12..=15 (masked with [`sw::APPLICATION_BITS`]).
    pub fn set_application_bits(&mut self, bits: u16) {
        self.app_bits = bits & sw::APPLICATION_BITS;
    }

    /// Object 0x605A.
    pub fn quick_stop_option(&self) -> i16 {
        self.quick_stop_option
    }

    /// Writes 0x605A (0..=8 supported here).
    pub fn set_quick_stop_option(&mut self, code: i16) -> Result<(), Abort> {
        if !(0..=8).contains(&code) {
            return Err(Abort::ValueRange);
        }
        self.quick_stop_option = code;
        Ok(())
    }

    /// Object 0x6060 as last written.
    pub fn mode(&self) -> i8 {
        self.mode
    }

    /// Object 0x6061: the mode in effect. Mode changes take effect at once
    /// here, so it equals 0x6060.
    pub fn mode_display(&self) -> i8 {
        self.mode
    }

    /// Object 0x6502.
    pub fn supported_modes(&self) -> u32 {
        self.supported
    }

    /// Writes 0x6060; a mode not in 0x6502 is refused with 0x0609 0030.
    pub fn set_mode(&mut self, mode: i8) -> Result<(), Abort> {
        match supported_bit(mode) {
            Some(b) if self.supported & b != 0 => {
                self.mode = mode;
                Ok(())
            }
            _ => Err(Abort::ValueRange),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use State::*;

    // Controlwords as CiA 402-2 codes them (bits 7 3 2 1 0).
    const SHUTDOWN: u16 = 0x0006;
    const SWITCH_ON: u16 = 0x0007;
    const ENABLE_OP: u16 = 0x000F;
    const DISABLE_VOLTAGE: u16 = 0x0000;
    const QUICK_STOP: u16 = 0x0002;
    const FAULT_RESET: u16 = 0x0080;

    // CSP | CSV | CST | PP | PV | HM | vendor -1:
    // bits 7, 8, 9, 0, 2, 5, 16 = 0x0001_03A5.
    const SUPPORTED: u32 = 0x0001_03A5;

    fn drive_in(state: State, qs_option: i16) -> Drive {
        let mut d = Drive::new(SUPPORTED, mode::CYCLIC_SYNC_POSITION, qs_option);
        if state == NotReadyToSwitchOn {
            return d;
        }
        d.initialised();
        let path: &[u16] = match state {
            SwitchOnDisabled => &[],
            ReadyToSwitchOn => &[SHUTDOWN],
            SwitchedOn => &[SHUTDOWN, SWITCH_ON],
            OperationEnabled => &[SHUTDOWN, SWITCH_ON, ENABLE_OP],
            QuickStopActive => &[SHUTDOWN, SWITCH_ON, ENABLE_OP, QUICK_STOP],
            FaultReactionActive | Fault => &[],
            NotReadyToSwitchOn => &[],
        };
        for &c in path {
            d.controlword(c);
        }
        if matches!(state, FaultReactionActive | Fault) {
            d.fault();
        }
        if state == Fault {
            d.fault_reaction_complete();
        }
        assert_eq!(d.state(), state);
        d
    }

    #[test]
    fn statusword_per_state() {
        // CiA 402-2 statusword state coding, "x" bits 0, remote (bit 9) on:
        // 0x0200 | state bits.
        let expect = [
            (NotReadyToSwitchOn, 0x0200),
            (SwitchOnDisabled, 0x0240),
            (ReadyToSwitchOn, 0x0221),
            (SwitchedOn, 0x0223),
            (OperationEnabled, 0x0227),
            (QuickStopActive, 0x0207),
            (FaultReactionActive, 0x020F),
            (Fault, 0x0208),
        ];
        for (s, sw) in expect {
            assert_eq!(drive_in(s, 2).statusword(), sw, "{s:?}");
        }
    }

    #[test]
    fn statusword_inputs() {
        let mut d = drive_in(OperationEnabled, 2);
        d.set_voltage_enabled(true);
        d.set_warning(true);
        d.set_target_reached(true);
        d.set_internal_limit(true);
        d.set_application_bits(0xFFFF);
        // 0x0027 | 0x10 | 0x80 | 0x200 | 0x400 | 0x800 | 0xF100 = 0xFFB7.
        assert_eq!(d.statusword(), 0xFFB7);
        d.set_remote(false);
        d.set_application_bits(0);
        // Without bit 9 and the application bits: 0x0CB7.
        assert_eq!(d.statusword(), 0x0CB7);
    }

    #[test]
    fn every_controlword_transition() {
        // (from, controlword, to, transition numbers, action of the last).
        let cases: &[(State, u16, State, [u8; 2], Action)] = &[
            (
                SwitchOnDisabled,
                SHUTDOWN,
                ReadyToSwitchOn,
                [2, 0],
                Action::None,
            ),
            (
                ReadyToSwitchOn,
                SWITCH_ON,
                SwitchedOn,
                [3, 0],
                Action::PowerOn,
            ),
            (
                ReadyToSwitchOn,
                ENABLE_OP,
                OperationEnabled,
                [3, 4],
                Action::EnableOperation,
            ),
            (
                ReadyToSwitchOn,
                DISABLE_VOLTAGE,
                SwitchOnDisabled,
                [7, 0],
                Action::None,
            ),
            (
                ReadyToSwitchOn,
                QUICK_STOP,
                SwitchOnDisabled,
                [7, 0],
                Action::None,
            ),
            (
                SwitchedOn,
                ENABLE_OP,
                OperationEnabled,
                [4, 0],
                Action::EnableOperation,
            ),
            (
                SwitchedOn,
                SHUTDOWN,
                ReadyToSwitchOn,
                [6, 0],
                Action::PowerOff,
            ),
            (
                SwitchedOn,
                DISABLE_VOLTAGE,
                SwitchOnDisabled,
                [10, 0],
                Action::PowerOff,
            ),
            (
                SwitchedOn,
                QUICK_STOP,
                SwitchOnDisabled,
                [10, 0],
                Action::PowerOff,
            ),
            (
                OperationEnabled,
                SWITCH_ON,
                SwitchedOn,
                [5, 0],
                Action::DisableOperation,
            ),
            (
                OperationEnabled,
                SHUTDOWN,
                ReadyToSwitchOn,
                [8, 0],
                Action::DisableAndPowerOff,
            ),
            (
                OperationEnabled,
                DISABLE_VOLTAGE,
                SwitchOnDisabled,
                [9, 0],
                Action::DisableAndPowerOff,
            ),
            (
                OperationEnabled,
                QUICK_STOP,
                QuickStopActive,
                [11, 0],
                Action::QuickStop { option_code: 2 },
            ),
            (
                QuickStopActive,
                DISABLE_VOLTAGE,
                SwitchOnDisabled,
                [12, 0],
                Action::DisableAndPowerOff,
            ),
            (
                Fault,
                FAULT_RESET,
                SwitchOnDisabled,
                [15, 0],
                Action::ResetFault,
            ),
            // "x" bits set: shutdown with bit 3 set (0x0E), disable voltage
            // with bits 0 and 2 set (0x05), quick stop with bits 0, 3 set (0x0B).
            (
                SwitchOnDisabled,
                0x000E,
                ReadyToSwitchOn,
                [2, 0],
                Action::None,
            ),
            (
                OperationEnabled,
                0x0005,
                SwitchOnDisabled,
                [9, 0],
                Action::DisableAndPowerOff,
            ),
            (
                OperationEnabled,
                0x000B,
                QuickStopActive,
                [11, 0],
                Action::QuickStop { option_code: 2 },
            ),
            // Halt (bit 8) and mode-specific bits do not change the command.
            (
                SwitchedOn,
                0x017F,
                OperationEnabled,
                [4, 0],
                Action::EnableOperation,
            ),
        ];
        for &(from, cw, to, nums, action) in cases {
            let mut d = drive_in(from, 2);
            let out = d.controlword(cw);
            assert_eq!(d.state(), to, "{from:?} cw {cw:#06x}");
            assert_eq!(out.numbers(), nums, "{from:?} cw {cw:#06x}");
            assert_eq!(out.iter().last().map(|t| t.action), Some(action));
            assert_eq!(out.iter().next().map(|t| t.from), Some(from));
        }
    }

    #[test]
    fn automatic_and_reported_transitions() {
        let mut d = Drive::new(SUPPORTED, mode::CYCLIC_SYNC_POSITION, 2);
        assert_eq!(d.initialised().map(|t| t.number), Some(1));
        assert_eq!(d.state(), SwitchOnDisabled);
        assert_eq!(d.initialised(), None);
        // 13 from every state but the fault states; 14 after it.
        for s in [
            NotReadyToSwitchOn,
            SwitchOnDisabled,
            ReadyToSwitchOn,
            SwitchedOn,
            OperationEnabled,
            QuickStopActive,
        ] {
            let mut d = drive_in(s, 2);
            let t = d.fault().unwrap();
            assert_eq!(
                (t.number, t.to, t.action),
                (13, FaultReactionActive, Action::FaultReaction)
            );
            assert_eq!(d.fault(), None);
            assert_eq!(d.fault_reaction_complete().map(|t| t.number), Some(14));
            assert_eq!(d.state(), Fault);
            assert_eq!(d.fault(), None);
        }
        // 12 when a quick stop with option 0..=4 completes.
        for code in 0..=4 {
            let mut d = drive_in(QuickStopActive, code);
            assert_eq!(d.quick_stop_complete().map(|t| t.number), Some(12));
            assert_eq!(d.state(), SwitchOnDisabled);
        }
        // Options 5..=8 stay in Quick stop active, and 16 re-enables.
        for code in 5..=8 {
            let mut d = drive_in(QuickStopActive, code);
            assert_eq!(d.quick_stop_complete(), None);
            assert_eq!(d.state(), QuickStopActive);
            let out = d.controlword(ENABLE_OP);
            assert_eq!(out.numbers(), [16, 0]);
            assert_eq!(d.state(), OperationEnabled);
        }
        assert_eq!(drive_in(OperationEnabled, 2).quick_stop_complete(), None);
        assert_eq!(drive_in(Fault, 2).fault_reaction_complete(), None);
    }

    #[test]
    fn invalid_controlwords_change_nothing() {
        let all = [
            SHUTDOWN,
            SWITCH_ON,
            ENABLE_OP,
            DISABLE_VOLTAGE,
            QUICK_STOP,
            FAULT_RESET,
        ];
        let refused: &[(State, &[u16])] = &[
            (NotReadyToSwitchOn, &all),
            (
                SwitchOnDisabled,
                &[
                    SWITCH_ON,
                    ENABLE_OP,
                    DISABLE_VOLTAGE,
                    QUICK_STOP,
                    FAULT_RESET,
                ],
            ),
            (ReadyToSwitchOn, &[SHUTDOWN, FAULT_RESET]),
            (SwitchedOn, &[SWITCH_ON, FAULT_RESET]),
            (OperationEnabled, &[ENABLE_OP, FAULT_RESET]),
            // Option code 2: enable operation does not leave quick stop.
            (
                QuickStopActive,
                &[SHUTDOWN, SWITCH_ON, ENABLE_OP, QUICK_STOP, FAULT_RESET],
            ),
            (FaultReactionActive, &all),
            (
                Fault,
                &[SHUTDOWN, SWITCH_ON, ENABLE_OP, DISABLE_VOLTAGE, QUICK_STOP],
            ),
        ];
        for &(s, cws) in refused {
            for &cw in cws {
                let mut d = drive_in(s, 2);
                let sw = d.statusword();
                let out = d.controlword(cw);
                assert!(out.is_empty(), "{s:?} cw {cw:#06x}");
                assert_eq!(d.state(), s);
                assert_eq!(d.statusword(), sw);
            }
        }
    }

    #[test]
    fn fault_reset_needs_a_rising_edge() {
        let mut d = drive_in(Fault, 2);
        d.controlword(0x0080);
        assert_eq!(d.state(), SwitchOnDisabled);
        // Back to Fault with bit 7 still set: holding it does nothing.
        d.fault();
        d.fault_reaction_complete();
        assert!(d.controlword(0x0080).is_empty());
        assert_eq!(d.state(), Fault);
        // Bit 7 held with a shutdown coding in SOD: nothing decoded.
        let mut d = drive_in(SwitchOnDisabled, 2);
        d.controlword(0x0086);
        assert!(d.controlword(0x0086).is_empty());
        assert_eq!(d.state(), SwitchOnDisabled);
        // 0 -> 1 edge after a 0.
        let mut d = drive_in(Fault, 2);
        d.controlword(0x0080);
        d.fault();
        d.fault_reaction_complete();
        d.controlword(0x0000);
        assert_eq!(d.controlword(0x0080).numbers(), [15, 0]);
    }

    #[test]
    fn modes_of_operation() {
        // CiA 402-2 0x6502: PP bit 0, PV bit 2, HM bit 5, CSP 7, CSV 8, CST 9.
        assert_eq!(supported_bit(1), Some(0x0001));
        assert_eq!(supported_bit(3), Some(0x0004));
        assert_eq!(supported_bit(6), Some(0x0020));
        assert_eq!(supported_bit(8), Some(0x0080));
        assert_eq!(supported_bit(9), Some(0x0100));
        assert_eq!(supported_bit(10), Some(0x0200));
        assert_eq!(supported_bit(-1), Some(0x0001_0000));
        assert_eq!(supported_bit(5), None);
        assert_eq!(supported_bit(0), None);
        let mut d = drive_in(OperationEnabled, 2);
        assert_eq!(d.mode(), 8);
        assert_eq!(d.set_mode(mode::CYCLIC_SYNC_TORQUE), Ok(()));
        assert_eq!(d.mode_display(), 10);
        assert_eq!(d.set_mode(mode::VENDOR), Ok(()));
        assert_eq!(d.mode_display(), -1);
        assert_eq!(d.set_mode(mode::VELOCITY), Err(Abort::ValueRange));
        assert_eq!(d.set_mode(0), Err(Abort::ValueRange));
        assert_eq!(d.mode(), -1);
        assert_eq!(d.supported_modes(), 0x0001_03A5);
        assert_eq!(d.set_quick_stop_option(9), Err(Abort::ValueRange));
        assert_eq!(d.set_quick_stop_option(6), Ok(()));
    }
}
