//! The `[cueing]` table of a scenario: how vehicle motion (accelerations and rotation
//! rates, from a recording or a game) becomes platform motion — by classical washout
//! (Reid & Nahon: the scale and high-pass filters of the translational and rotational
//! channels, tilt coordination, the workspace limiter) or by model-predictive cueing (the
//! horizon, the weights, the look-ahead) — the axes used and the point the motion
//! is cued at. Plain data, checked here; `analysis::cueing` runs it.
//!
//! ```toml
//! [cueing]
//! algorithm = "washout"       # or "mpc": model-predictive cueing
//! translation_scale = 0.5     # vehicle specific force × this
//! translation_hp_wn = 2.5     # rad/s: second-order high-pass s²/(s²+2ζωs+ω²)
//! translation_hp_zeta = 1.0
//! translation_hp_wb = 0.5     # rad/s: first-order high-pass s/(s+ω_b) back to neutral; 0 = off
//! tilt = true                 # sustained specific force rendered by tilting
//! tilt_lp_wn = 5.0            # rad/s: second-order low-pass ω²/(s²+2ζωs+ω²)
//! tilt_lp_zeta = 1.0
//! tilt_rate_max_deg_s = 3.0   # tilt never turns faster than this
//! rotation_scale = 0.5        # vehicle rotation rates × this
//! rotation_hp_wn = 1.0        # rad/s: second-order high-pass of the rates, then integrated
//! rotation_hp_zeta = 1.0
//! surge = true                # per axis: x, y, z, roll, pitch, yaw cued or not
//! sway = true
//! heave = true
//! roll = true
//! pitch = true
//! yaw = true
//! reference_m = [0, 0, 0.3]   # the occupant's head in the platform frame
//! workspace_limiter = false   # scale the cue back so that no pose leaves the limits
//! limiter_recovery_s = 1.0    # how fast the limiter gives the full cue back
//! stall_s = 0.5               # live input: silent this long, it has stalled
//! fade_s = 2.0                # and the cue fades to neutral over this long
//! mpc_horizon_steps = 15      # MPC: steps looked ahead: the first the solve interval,
//! mpc_step_s = 0.1            # the others this long (the horizon: 1.41 s)
//! mpc_solve_interval_s = 0.01 # a new plan this often (100 Hz)
//! mpc_force_weight = 1.0      # per (m/s²)² of felt specific-force error
//! mpc_rate_weight = 10.0      # per (rad/s)² of felt rotation-rate error
//! mpc_displacement_weight = 1.0  # per m² (and rad² of yaw) away from neutral
//! mpc_velocity_weight = 0.1   # per (m/s)² and (rad/s)²
//! mpc_tilt_weight = 1.0       # per rad² of roll and pitch
//! mpc_input_weight = 0.001    # per (m/s²)² and (rad/s²)² of acceleration
//! mpc_margin = 0.02           # share of the stroke (range) kept clear of each end
//! mpc_preview = true          # a recording: plan with the motion ahead in it
//! vestibular = false          # track what the otoliths and canals sense
//! ```

use serde::{Deserialize, Serialize};

/// Standard gravity, m/s²: tilt coordination renders a specific force `f` by tilting the
/// platform until gravity's component along it is `f`.
pub const GRAVITY: f64 = 9.80665;

/// How vehicle motion is made into platform motion.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum CueingAlgorithm {
    /// Classical washout: fixed filters, tilt coordination, the optional limiter.
    #[default]
    Washout,
    /// Model-predictive cueing: each step, the motion over a horizon that best reproduces
    /// what the occupant feels within the rig's limits.
    Mpc,
}

impl CueingAlgorithm {
    /// Both, in the order a choice lists them.
    pub const ALL: [CueingAlgorithm; 2] = [CueingAlgorithm::Washout, CueingAlgorithm::Mpc];

    /// The word the file and `--set` use.
    pub fn word(self) -> &'static str {
        match self {
            CueingAlgorithm::Washout => "washout",
            CueingAlgorithm::Mpc => "mpc",
        }
    }

    /// The algorithm a word names, if any.
    pub fn from_word(word: &str) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|a| a.word().eq_ignore_ascii_case(word.trim()))
    }
}

/// The `[cueing]` table.
#[derive(Clone, Debug, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields, default)]
pub struct CueingSettings {
    /// The algorithm: classical washout or model-predictive cueing.
    pub algorithm: CueingAlgorithm,
    /// Multiplies the vehicle's specific force (translational channel and tilt).
    pub translation_scale: f64,
    /// Natural frequency of the translational second-order high-pass, rad/s.
    pub translation_hp_wn: f64,
    /// Damping ratio of the translational second-order high-pass.
    pub translation_hp_zeta: f64,
    /// Break frequency of the translational first-order high-pass that brings the platform
    /// back to neutral, rad/s (0: off).
    pub translation_hp_wb: f64,
    /// Whether sustained specific force is rendered by tilting (surge and sway).
    pub tilt: bool,
    /// Natural frequency of the tilt channel's second-order low-pass, rad/s.
    pub tilt_lp_wn: f64,
    /// Damping ratio of the tilt channel's low-pass.
    pub tilt_lp_zeta: f64,
    /// The fastest tilt, degrees per second (about 3°/s is not felt as rotation).
    pub tilt_rate_max_deg_s: f64,
    /// Multiplies the vehicle's rotation rates.
    pub rotation_scale: f64,
    /// Natural frequency of the rotational second-order high-pass, rad/s.
    pub rotation_hp_wn: f64,
    /// Damping ratio of the rotational high-pass.
    pub rotation_hp_zeta: f64,
    /// Cue motion along x.
    pub surge: bool,
    /// Cue motion along y.
    pub sway: bool,
    /// Cue motion along z.
    pub heave: bool,
    /// Cue roll.
    pub roll: bool,
    /// Cue pitch.
    pub pitch: bool,
    /// Cue yaw.
    pub yaw: bool,
    /// The point the motion is cued at (the occupant's head), platform frame, metres:
    /// rotations turn about it, so tilting does not move the head.
    #[serde(deserialize_with = "crate::ground::text::exactly")]
    pub reference_m: [f64; 3],
    /// Scale the cue back so that no pose leaves the stroke and limits.
    pub workspace_limiter: bool,
    /// Seconds the limiter takes to give the full cue back after scaling it to nothing.
    pub limiter_recovery_s: f64,
    /// Seconds without a sample after which a live input counts as stalled.
    pub stall_s: f64,
    /// Seconds a stalled cue takes to fade to neutral (and a resumed one to come back).
    pub fade_s: f64,
    /// Live input only: how far ahead of the last sample, seconds, each tick extrapolates
    /// the input (0: off — the platform steps from sample to sample).
    pub input_prediction_s: f64,
    /// MPC: the number of steps looked ahead.
    pub mpc_horizon_steps: u32,
    /// MPC: the length of each step, seconds.
    pub mpc_step_s: f64,
    /// MPC: seconds between two plans (the plan is followed in between).
    pub mpc_solve_interval_s: f64,
    /// MPC: weight of the felt specific-force error, per (m/s²)².
    pub mpc_force_weight: f64,
    /// MPC: weight of the felt rotation-rate error, per (rad/s)².
    pub mpc_rate_weight: f64,
    /// MPC: weight of the displacement from neutral, per m² (and per rad² of yaw).
    pub mpc_displacement_weight: f64,
    /// MPC: weight of the velocity, per (m/s)² and (rad/s)².
    pub mpc_velocity_weight: f64,
    /// MPC: weight of roll and pitch (the tilt that renders sustained force), per rad².
    pub mpc_tilt_weight: f64,
    /// MPC: weight of the accelerations, per (m/s²)² and (rad/s²)²: the smoothness.
    pub mpc_input_weight: f64,
    /// MPC: the share of each actuator's stroke (or range) kept clear of either end, and of
    /// its speed and acceleration limits, so that the linearised limits hold exactly.
    pub mpc_margin: f64,
    /// MPC: when a whole recording is cued (`stewart cue`, the viewer), plan with the
    /// vehicle's motion ahead in it rather than the last sample held (a live input never
    /// knows what comes).
    pub mpc_preview: bool,
    /// MPC: track what the vestibular organs sense (otoliths and semicircular canals)
    /// rather than the specific force and rates themselves.
    pub vestibular: bool,
}

impl Default for CueingSettings {
    fn default() -> Self {
        Self {
            translation_scale: 0.5,
            translation_hp_wn: 2.5,
            translation_hp_zeta: 1.0,
            translation_hp_wb: 0.5,
            tilt: true,
            tilt_lp_wn: 5.0,
            tilt_lp_zeta: 1.0,
            tilt_rate_max_deg_s: 3.0,
            rotation_scale: 0.5,
            rotation_hp_wn: 1.0,
            rotation_hp_zeta: 1.0,
            surge: true,
            sway: true,
            heave: true,
            roll: true,
            pitch: true,
            yaw: true,
            reference_m: [0.0; 3],
            workspace_limiter: false,
            limiter_recovery_s: 1.0,
            stall_s: 0.5,
            fade_s: 2.0,
            input_prediction_s: 0.0,
            algorithm: CueingAlgorithm::Washout,
            mpc_horizon_steps: 15,
            mpc_step_s: 0.1,
            mpc_solve_interval_s: 0.01,
            mpc_force_weight: 1.0,
            mpc_rate_weight: 10.0,
            mpc_displacement_weight: 1.0,
            mpc_velocity_weight: 0.1,
            mpc_tilt_weight: 1.0,
            mpc_input_weight: 0.001,
            mpc_margin: 0.02,
            mpc_preview: true,
            vestibular: false,
        }
    }
}

/// A `[cueing]` value refused: the key (`cueing.tilt_lp_wn`, `cueing.reference_m[2]`) and
/// why.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("`{key}` {reason}")]
pub struct CueingProblem {
    /// The key, as the file and `--set` name it.
    pub key: String,
    /// Why.
    pub reason: String,
}

/// The largest scale accepted.
pub const MAX_SCALE: f64 = 10.0;
/// The longest input prediction, seconds (beyond a few samples an extrapolation is a guess).
pub const MAX_PREDICTION_S: f64 = 0.5;
/// The longest MPC horizon, steps (the programme grows with its square).
pub const MAX_HORIZON_STEPS: u32 = 40;
/// The largest MPC weight accepted.
pub const MAX_WEIGHT: f64 = 1e6;
/// The highest filter frequency accepted, rad/s.
pub const MAX_OMEGA: f64 = 1000.0;
/// The largest damping ratio accepted.
pub const MAX_ZETA: f64 = 10.0;

impl CueingSettings {
    /// Whether each of x, y, z, roll, pitch, yaw is cued.
    pub fn axes(&self) -> [bool; 6] {
        [
            self.surge, self.sway, self.heave, self.roll, self.pitch, self.yaw,
        ]
    }

    /// The first value that cannot work, if any: a scale outside 0…10, a filter frequency
    /// or damping ratio that is not positive (the return-to-neutral break frequency may be
    /// 0), a tilt rate that is not positive, a reference point farther than 1000 m, a
    /// recovery time that is not positive; NaN and infinity never.
    pub fn problem(&self) -> Option<CueingProblem> {
        let bad = |key: &str, reason: String| {
            Some(CueingProblem {
                key: format!("cueing.{key}"),
                reason,
            })
        };
        for (key, v) in [
            ("translation_scale", self.translation_scale),
            ("rotation_scale", self.rotation_scale),
        ] {
            if !(0.0..=MAX_SCALE).contains(&v) {
                return bad(key, format!("must be between 0 and {MAX_SCALE}, got {v}"));
            }
        }
        for (key, v, max) in [
            ("translation_hp_wn", self.translation_hp_wn, MAX_OMEGA),
            ("translation_hp_zeta", self.translation_hp_zeta, MAX_ZETA),
            ("tilt_lp_wn", self.tilt_lp_wn, MAX_OMEGA),
            ("tilt_lp_zeta", self.tilt_lp_zeta, MAX_ZETA),
            ("rotation_hp_wn", self.rotation_hp_wn, MAX_OMEGA),
            ("rotation_hp_zeta", self.rotation_hp_zeta, MAX_ZETA),
            ("tilt_rate_max_deg_s", self.tilt_rate_max_deg_s, 360.0),
            ("limiter_recovery_s", self.limiter_recovery_s, 3600.0),
            ("stall_s", self.stall_s, 3600.0),
            ("fade_s", self.fade_s, 3600.0),
        ] {
            if !(v > 0.0 && v <= max) {
                return bad(
                    key,
                    format!("must be a positive number of at most {max}, got {v}"),
                );
            }
        }
        let p = self.input_prediction_s;
        if !(0.0..=MAX_PREDICTION_S).contains(&p) {
            return bad(
                "input_prediction_s",
                format!("must be between 0 (off) and {MAX_PREDICTION_S} s, got {p}"),
            );
        }
        let wb = self.translation_hp_wb;
        if !(0.0..=MAX_OMEGA).contains(&wb) {
            return bad(
                "translation_hp_wb",
                format!("must be between 0 (off) and {MAX_OMEGA} rad/s, got {wb}"),
            );
        }
        if let Some(p) = self.mpc_problem() {
            return Some(p);
        }
        let far = crate::ground::bounds::LENGTH_M;
        for (i, v) in self.reference_m.iter().enumerate() {
            if !(v.is_finite() && v.abs() <= far) {
                return bad(
                    &format!("reference_m[{i}]"),
                    format!("must be a number of metres within ±{far}, got {v}"),
                );
            }
        }
        None
    }

    /// The first MPC value that cannot work: a horizon outside 1…40 steps, a step outside
    /// 5 ms…1 s, a solve interval that is not positive or longer than a step, a weight
    /// below 0 or above 10⁶ (the acceleration's must be positive: it makes the programme
    /// strictly convex), a margin outside 0…0.4.
    fn mpc_problem(&self) -> Option<CueingProblem> {
        let bad = |key: &str, reason: String| {
            Some(CueingProblem {
                key: format!("cueing.{key}"),
                reason,
            })
        };
        // One step plans only the move to the next solve, which the end-at-rest rule
        // pins: the platform would never move.
        if !(2..=MAX_HORIZON_STEPS).contains(&self.mpc_horizon_steps) {
            return bad(
                "mpc_horizon_steps",
                format!(
                    "must be a whole number of steps from 2 to {MAX_HORIZON_STEPS}, got {}",
                    self.mpc_horizon_steps
                ),
            );
        }
        let step = self.mpc_step_s;
        if !(0.005..=1.0).contains(&step) {
            return bad(
                "mpc_step_s",
                format!("must be between 0.005 and 1 s, got {step}"),
            );
        }
        let every = self.mpc_solve_interval_s;
        if !(every >= 0.001 && every <= step) {
            return bad(
                "mpc_solve_interval_s",
                format!("must be between 0.001 s and the step ({step} s), got {every}"),
            );
        }
        for (key, v) in [
            ("mpc_force_weight", self.mpc_force_weight),
            ("mpc_rate_weight", self.mpc_rate_weight),
            ("mpc_displacement_weight", self.mpc_displacement_weight),
            ("mpc_velocity_weight", self.mpc_velocity_weight),
            ("mpc_tilt_weight", self.mpc_tilt_weight),
        ] {
            if !(0.0..=MAX_WEIGHT).contains(&v) {
                return bad(key, format!("must be between 0 and {MAX_WEIGHT}, got {v}"));
            }
        }
        let w = self.mpc_input_weight;
        if !(1e-9..=MAX_WEIGHT).contains(&w) {
            return bad(
                "mpc_input_weight",
                format!("must be between 1e-9 and {MAX_WEIGHT}, got {w}"),
            );
        }
        let m = self.mpc_margin;
        if !(0.0..=0.4).contains(&m) {
            return bad("mpc_margin", format!("must be between 0 and 0.4, got {m}"));
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_defaults_are_sound_and_each_bad_value_names_its_key() {
        assert_eq!(CueingSettings::default().problem(), None);
        type Spoil = fn(&mut CueingSettings);
        let cases: [(Spoil, &str); 6] = [
            (|c| c.translation_scale = -0.1, "cueing.translation_scale"),
            (|c| c.tilt_lp_wn = 0.0, "cueing.tilt_lp_wn"),
            (|c| c.rotation_hp_zeta = f64::NAN, "cueing.rotation_hp_zeta"),
            (|c| c.translation_hp_wb = -1.0, "cueing.translation_hp_wb"),
            (
                |c| c.reference_m[2] = f64::INFINITY,
                "cueing.reference_m[2]",
            ),
            (
                |c| c.tilt_rate_max_deg_s = 1e9,
                "cueing.tilt_rate_max_deg_s",
            ),
        ];
        for (spoil, key) in cases {
            let mut c = CueingSettings::default();
            spoil(&mut c);
            assert_eq!(c.problem().map(|p| p.key), Some(key.to_owned()));
        }
        // Off is allowed for the return to neutral.
        let c = CueingSettings {
            translation_hp_wb: 0.0,
            ..CueingSettings::default()
        };
        assert_eq!(c.problem(), None);
    }
}
