//! The simulated controller's actuators: each channel follows its last armed set-point
//! through a first-order lag (time constant τ), no faster than a speed limit, and not at
//! all while within a dead band of it — each an option. Values are in the wire's unit.
//!
//! Between two frames the set-point is held, so the lag is integrated exactly:
//! `x ← u + (x − u)·e^(−Δt/τ)`; the speed limit then caps the step at `v_max·Δt`. A disarmed
//! or e-stop frame makes the actuators hold where they are.

/// The model's options.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct ActuatorModel {
    /// First-order time constant, seconds (0: follows at once).
    pub(crate) lag_s: f64,
    /// Largest speed, wire units per second (`None`: unlimited).
    pub(crate) speed_max: Option<f64>,
    /// No motion while the set-point is this close, wire units (0: none).
    pub(crate) dead_band: f64,
}

/// Six actuators following their set-points.
#[derive(Clone, Debug)]
pub(crate) struct Actuators {
    model: ActuatorModel,
    /// Position, set-point held and the time of the last update; `None` before any frame.
    state: Option<([f64; 6], [f64; 6], f64)>,
}

impl Actuators {
    /// Actuators that have received nothing yet.
    pub(crate) fn new(model: ActuatorModel) -> Self {
        Self { model, state: None }
    }

    /// A set-point frame at time `t` (seconds): the actuators move under the previous
    /// set-point until `t`, then take `values` as their new one when `armed` (else hold
    /// where they are). Returns the positions at `t` (what the controller measures), rounded
    /// to the wire's whole numbers. The first frame puts the actuators at its values.
    pub(crate) fn frame(&mut self, t: f64, values: &[i32; 6], armed: bool) -> [i32; 6] {
        let wanted = values.map(f64::from);
        let (mut x, held, since) = self.state.unwrap_or((wanted, wanted, t));
        let dt = (t - since).max(0.0);
        let m = &self.model;
        for k in 0..6 {
            let gap = held[k] - x[k];
            if gap.abs() <= m.dead_band {
                continue;
            }
            let mut step = if m.lag_s > 0.0 {
                gap * (1.0 - (-dt / m.lag_s).exp())
            } else {
                gap
            };
            if let Some(v) = m.speed_max {
                step = step.clamp(-v * dt, v * dt);
            }
            x[k] += step;
        }
        let next = if armed { wanted } else { x };
        self.state = Some((x, next, t));
        x.map(|v| v.round().clamp(f64::from(i32::MIN), f64::from(i32::MAX)) as i32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_step_is_followed_by_the_lag_the_speed_limit_and_the_dead_band() {
        // τ = 0.1 s: after 0.1 s, 1 − 1/e of a 1000-unit step.
        let mut a = Actuators::new(ActuatorModel {
            lag_s: 0.1,
            ..ActuatorModel::default()
        });
        assert_eq!(a.frame(0.0, &[0; 6], true), [0; 6]);
        assert_eq!(a.frame(0.0, &[1000; 6], true), [0; 6]);
        let at = a.frame(0.1, &[1000; 6], true);
        assert_eq!(at[0], (1000.0 * (1.0 - (-1.0f64).exp())).round() as i32);
        // Speed limit 2000/s: 1000 units take 0.5 s.
        let mut b = Actuators::new(ActuatorModel {
            speed_max: Some(2000.0),
            ..ActuatorModel::default()
        });
        b.frame(0.0, &[0; 6], true);
        b.frame(0.0, &[1000; 6], true);
        assert_eq!(b.frame(0.25, &[1000; 6], true)[0], 500);
        assert_eq!(b.frame(1.0, &[1000; 6], true)[0], 1000);
        // Dead band 5: a 4-unit change does not move it, a 6-unit one does.
        let mut c = Actuators::new(ActuatorModel {
            dead_band: 5.0,
            ..ActuatorModel::default()
        });
        c.frame(0.0, &[0; 6], true);
        c.frame(0.0, &[4; 6], true);
        assert_eq!(c.frame(1.0, &[6; 6], true)[0], 0);
        assert_eq!(c.frame(2.0, &[6; 6], true)[0], 6);
        // Disarmed: it holds where it is.
        let mut d = Actuators::new(ActuatorModel {
            speed_max: Some(100.0),
            ..ActuatorModel::default()
        });
        d.frame(0.0, &[0; 6], true);
        d.frame(0.0, &[1000; 6], false);
        assert_eq!(d.frame(5.0, &[1000; 6], true)[0], 0);
    }
}
