//! Teleoperation of the manual pose: velocity commands from the keyboard or a gamepad,
//! rate-limited per axis, that stop at the edge of the reachable set (stroke, servo range,
//! a servo that cannot reach) and say why. The link, when armed, follows the manual pose,
//! so the same input drives the hardware.
//!
//! Keys (manual mode): W/S ±x, A/D ±y, R/F ±z, J/L ∓roll, I/K ±pitch, Q/E ±yaw; hold Shift
//! for fine moves. Gamepad: hold the left bumper (dead-man) — left stick x/y, right stick
//! z/yaw, D-pad roll/pitch; the right bumper for fine moves. Input from the gamepad goes
//! through [`PadState`], so tests drive the same mapping with synthetic states.

use stewart_kinematics::model::actuator::ActuatorKind;
use stewart_kinematics::{Geometry, Pose};

use crate::i18n::Lang;

/// A fine move is this fraction of the full rate.
const FINE: f64 = 0.2;
/// Stick travel below this is ignored (sticks rarely rest at zero).
const DEADZONE: f32 = 0.12;
/// Bisection steps to find the edge of the reachable set along one move.
const EDGE_STEPS: usize = 30;

/// A velocity command: each axis (x, y, z, roll, pitch, yaw) from −1 to 1 of its rate.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct TeleopCommand {
    /// Fractions of the rates, in pose order.
    pub(crate) velocity: [f64; 6],
    /// Move at a fifth of the rates.
    pub(crate) fine: bool,
}

impl TeleopCommand {
    /// Whether it moves anything.
    pub(crate) fn moving(&self) -> bool {
        self.velocity.iter().any(|v| *v != 0.0)
    }

    /// Both commands together, each axis clamped to ±1.
    pub(crate) fn plus(self, other: TeleopCommand) -> TeleopCommand {
        TeleopCommand {
            velocity: std::array::from_fn(|k| {
                (self.velocity[k] + other.velocity[k]).clamp(-1.0, 1.0)
            }),
            fine: self.fine || other.fine,
        }
    }
}

/// The keys of each axis, (positive, negative), in pose order.
pub(crate) const KEYS: [(egui::Key, egui::Key); 6] = [
    (egui::Key::W, egui::Key::S),
    (egui::Key::A, egui::Key::D),
    (egui::Key::R, egui::Key::F),
    (egui::Key::L, egui::Key::J),
    (egui::Key::I, egui::Key::K),
    (egui::Key::Q, egui::Key::E),
];

/// The command of the keys held down (`down` tells whether a key is held).
pub(crate) fn from_keys(down: impl Fn(egui::Key) -> bool, shift: bool) -> TeleopCommand {
    TeleopCommand {
        velocity: KEYS.map(|(plus, minus)| {
            f64::from(u8::from(down(plus))) - f64::from(u8::from(down(minus)))
        }),
        fine: shift,
    }
}

/// What a gamepad reports: sticks from −1 to 1 (up and right positive), the D-pad, the
/// dead-man (left bumper) and fine (right bumper) buttons.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct PadState {
    /// Left stick x, y.
    pub(crate) left: [f32; 2],
    /// Right stick x, y.
    pub(crate) right: [f32; 2],
    /// D-pad x (right +1), y (up +1).
    pub(crate) dpad: [i8; 2],
    /// The dead-man button is held.
    pub(crate) deadman: bool,
    /// The fine button is held.
    pub(crate) fine: bool,
}

/// The command of a gamepad: nothing unless the dead-man button is held; stick travel
/// inside the dead zone counts as zero and the rest is rescaled to reach 1.
pub(crate) fn from_pad(p: &PadState) -> TeleopCommand {
    if !p.deadman {
        return TeleopCommand::default();
    }
    let stick = |v: f32| {
        if !v.is_finite() || v.abs() < DEADZONE {
            0.0
        } else {
            f64::from(v.signum() * (v.abs().min(1.0) - DEADZONE) / (1.0 - DEADZONE))
        }
    };
    TeleopCommand {
        // Stick up moves forward (+x), stick right moves right (−y, y points left).
        velocity: [
            stick(p.left[1]),
            -stick(p.left[0]),
            stick(p.right[1]),
            f64::from(p.dpad[0]),
            f64::from(p.dpad[1]),
            -stick(p.right[0]),
        ],
        fine: p.fine,
    }
}

/// How fast a full command moves the platform.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Rates {
    /// Metres per second along x, y, z.
    pub(crate) linear_m_s: f64,
    /// Degrees per second about roll, pitch, yaw.
    pub(crate) angular_deg_s: f64,
}

impl Rates {
    /// A quarter of the platform radius per second, 15° per second.
    pub(crate) fn for_geometry(g: &Geometry) -> Self {
        Self {
            linear_m_s: 0.25 * g.plate_radius(stewart_kinematics::model::geometry::Plate::Platform),
            angular_deg_s: 15.0,
        }
    }
}

/// Why a pose cannot be taken.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum ReachEdge {
    /// A coordinate is NaN or infinite.
    NotANumber,
    /// No horn angle of servo `servo` (from 1) closes its rod; `ratio` is |L|/√(M²+N²)
    /// (shown as the percentage beyond 1).
    Servo {
        /// Servo number from 1.
        servo: usize,
        /// Above 1 when unreachable.
        ratio: f64,
    },
    /// Actuator `n` (from 1) would pass its `limit`: below it when `below`.
    Limit {
        /// Actuator number from 1.
        n: usize,
        /// The value it would take (m or °).
        value: f64,
        /// The limit passed.
        limit: f64,
        /// Whether it is the lower limit.
        below: bool,
        /// The actuators' kind (the value's unit and words follow it).
        kind: ActuatorKind,
    },
}

impl ReachEdge {
    /// The reason in `lang`.
    pub(crate) fn words(&self, lang: Lang) -> String {
        match *self {
            ReachEdge::NotANumber => lang.tr("teleop.not_a_number").to_owned(),
            ReachEdge::Servo { servo, ratio } => lang.fmt(
                "teleop.servo_unreachable",
                &[
                    ("n", &servo),
                    (
                        "pct",
                        &stewart_kinematics::model::rotary::percent(100.0 * (ratio - 1.0)),
                    ),
                ],
            ),
            ReachEdge::Limit {
                n,
                value,
                limit,
                below,
                kind,
            } => {
                let key = if below {
                    "teleop.below"
                } else {
                    "teleop.above"
                };
                lang.fmt_kind(
                    key,
                    kind,
                    &[
                        ("n", &n),
                        ("value", &format!("{value:.3}")),
                        ("limit", &format!("{limit:.3}")),
                    ],
                )
            }
        }
    }
}

/// Why `pose` cannot be taken: a leg outside its stroke, a servo outside its range or
/// unable to reach; `None` when it can.
pub(crate) fn unreachable(g: &Geometry, pose: &Pose) -> Option<ReachEdge> {
    let c = pose.to_coordinates();
    if c.iter().any(|v| !v.is_finite()) {
        return Some(ReachEdge::NotANumber);
    }
    let [lo, hi] = g.quantity_limits();
    let kind = g.actuator().kind();
    let values = match g.actuator_values_at(pose) {
        Ok(values) => values,
        Err(e) => {
            return Some(ReachEdge::Servo {
                servo: e.servo,
                ratio: e.ratio,
            });
        }
    };
    values.iter().enumerate().find_map(|(k, &value)| {
        let n = k + 1;
        let limit = |limit, below| ReachEdge::Limit {
            n,
            value,
            limit,
            below,
            kind,
        };
        match (lo, hi) {
            (Some(lo), _) if value < lo => Some(limit(lo, true)),
            (_, Some(hi)) if value > hi => Some(limit(hi, false)),
            _ => None,
        }
    })
}

/// Move `pose` by `command` for `dt` seconds at `rates`. A move that would leave the
/// reachable set stops at its edge (found by bisection) and returns the reason; from a pose
/// already outside, moves are free (so that one can come back).
pub(crate) fn step(
    g: &Geometry,
    pose: &Pose,
    command: &TeleopCommand,
    rates: Rates,
    dt: f64,
) -> (Pose, Option<ReachEdge>) {
    if !(command.moving() && dt.is_finite() && dt > 0.0) {
        return (*pose, None);
    }
    let scale = if command.fine { FINE } else { 1.0 };
    let from = pose.to_coordinates();
    let to: [f64; 6] = std::array::from_fn(|k| {
        let rate = if k < 3 {
            rates.linear_m_s
        } else {
            rates.angular_deg_s.to_radians()
        };
        from[k] + command.velocity[k].clamp(-1.0, 1.0) * rate * scale * dt
    });
    let at =
        |s: f64| Pose::from_coordinates(std::array::from_fn(|k| from[k] + s * (to[k] - from[k])));
    let Some(why) = unreachable(g, &at(1.0)) else {
        return (at(1.0), None);
    };
    if unreachable(g, pose).is_some() {
        return (at(1.0), Some(why));
    }
    let (mut inside, mut outside) = (0.0, 1.0);
    for _ in 0..EDGE_STEPS {
        let mid = 0.5 * (inside + outside);
        if unreachable(g, &at(mid)).is_none() {
            inside = mid;
        } else {
            outside = mid;
        }
    }
    (at(inside), Some(why))
}

#[cfg(test)]
mod tests {
    use super::*;
    use stewart_kinematics::Scenario;

    #[test]
    fn keys_and_pads_map_to_axes() {
        let held = [egui::Key::W, egui::Key::D, egui::Key::Q];
        let c = from_keys(|k| held.contains(&k), true);
        assert_eq!(c.velocity, [1.0, -1.0, 0.0, 0.0, 0.0, 1.0]);
        assert!(c.fine);
        let pad = PadState {
            left: [0.0, 1.0],
            right: [0.05, -1.0],
            dpad: [1, 0],
            deadman: true,
            fine: false,
        };
        // Stick fully up: +x at the full rate; the right stick's x inside the dead zone.
        assert_eq!(from_pad(&pad).velocity, [1.0, 0.0, -1.0, 1.0, 0.0, 0.0]);
        // Without the dead-man button nothing moves, whatever the sticks say.
        assert!(
            !from_pad(&PadState {
                deadman: false,
                ..pad
            })
            .moving()
        );
        // Half travel past the dead zone is rescaled: (0.56 − 0.12) / 0.88 = 0.5.
        let half = from_pad(&PadState {
            left: [0.56, 0.0],
            ..pad
        });
        assert!((half.velocity[1] + 0.5).abs() < 1e-6, "{:?}", half.velocity);
        let both = c.plus(from_pad(&pad));
        assert_eq!(both.velocity, [1.0, -1.0, -1.0, 1.0, 0.0, 1.0]);
    }

    #[test]
    fn a_move_goes_at_the_rate_and_stops_at_the_stroke() {
        let s = Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}"));
        let g = &s.geometry;
        let rates = Rates {
            linear_m_s: 0.1,
            angular_deg_s: 10.0,
        };
        let home = g.home_pose();
        let up = TeleopCommand {
            velocity: [0.0, 0.0, 1.0, 0.0, 0.0, 0.5],
            fine: false,
        };
        let (p, why) = step(g, &home, &up, rates, 0.5);
        assert_eq!(why, None);
        assert!((p.position.z - home.position.z - 0.05).abs() < 1e-12);
        assert!((p.yaw.degrees() - 2.5).abs() < 1e-9);
        let fine = TeleopCommand { fine: true, ..up };
        let (p, _) = step(g, &home, &fine, rates, 0.5);
        assert!((p.position.z - home.position.z - 0.01).abs() < 1e-12);
        // Up for ten seconds: the legs reach their 1.30 m maximum and the move stops there.
        let straight_up = TeleopCommand {
            velocity: [0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
            fine: false,
        };
        let (p, why) = step(g, &home, &straight_up, rates, 10.0);
        let why = why.unwrap_or_else(|| panic!("not stopped")).words(Lang::En);
        assert!(why.contains("above its limit 1.300 m"), "{why}");
        let longest = g.leg_lengths(&p).into_iter().fold(0.0, f64::max);
        assert!((longest - 1.3).abs() < 1e-6, "{longest}");
        assert_eq!(unreachable(g, &p), None);
        // From the edge, moving further does nothing; moving back is free.
        let (q, why) = step(g, &p, &straight_up, rates, 0.1);
        assert!(why.is_some());
        assert!((q.position.z - p.position.z).abs() < 1e-6);
        let down = TeleopCommand {
            velocity: [0.0, 0.0, -1.0, 0.0, 0.0, 0.0],
            fine: false,
        };
        assert_eq!(step(g, &p, &down, rates, 0.1).1, None);
    }

    #[test]
    fn servos_stop_where_a_horn_cannot_reach() {
        let s = Scenario::preset("servo-desk").unwrap_or_else(|e| panic!("{e}"));
        let g = &s.geometry;
        let rates = Rates::for_geometry(g);
        let up = TeleopCommand {
            velocity: [0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
            fine: false,
        };
        let (p, why) = step(g, &g.home_pose(), &up, rates, 100.0);
        assert!(why.is_some());
        assert_eq!(unreachable(g, &p), None);
        // Just above the stopping point the platform is out of reach.
        let mut beyond = p;
        beyond.position.z += 1e-6;
        assert!(unreachable(g, &beyond).is_some());
    }
}
