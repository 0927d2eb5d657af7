//! The first connected gamepad, read each frame through `gilrs` into a [`PadState`]; the
//! mapping to motion lives in [`crate::viewer::state::teleop`], where tests reach it with synthetic states.

use gilrs::{Axis, Button, Gilrs};

use crate::viewer::state::teleop::PadState;

/// Gamepad input, when the system offers it.
pub(crate) struct Gamepads {
    gilrs: Option<Gilrs>,
    /// Why there is no gamepad support, the system's words (said in the Motion panel).
    pub(crate) note: Option<String>,
}

impl Gamepads {
    /// Start listening; a system without gamepad support leaves a note and no input.
    pub(crate) fn new() -> Self {
        match Gilrs::new() {
            Ok(gilrs) => Self {
                gilrs: Some(gilrs),
                note: None,
            },
            Err(e) => Self {
                gilrs: None,
                note: Some(e.to_string()),
            },
        }
    }

    /// The first connected gamepad's state and name, `None` when none is connected.
    pub(crate) fn poll(&mut self) -> Option<(PadState, String)> {
        let gilrs = self.gilrs.as_mut()?;
        while gilrs.next_event().is_some() {}
        let (_, pad) = gilrs.gamepads().find(|(_, g)| g.is_connected())?;
        let axis = |a| pad.value(a);
        let button = |b| pad.is_pressed(b);
        let dpad = |plus, minus| i8::from(button(plus)) - i8::from(button(minus));
        Some((
            PadState {
                left: [axis(Axis::LeftStickX), axis(Axis::LeftStickY)],
                right: [axis(Axis::RightStickX), axis(Axis::RightStickY)],
                dpad: [
                    dpad(Button::DPadRight, Button::DPadLeft),
                    dpad(Button::DPadUp, Button::DPadDown),
                ],
                deadman: button(Button::LeftTrigger),
                fine: button(Button::RightTrigger),
            },
            pad.name().to_owned(),
        ))
    }
}

impl Default for Gamepads {
    fn default() -> Self {
        Self::new()
    }
}
