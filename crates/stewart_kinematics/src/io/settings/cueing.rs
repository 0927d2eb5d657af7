//! The `[cueing]` table's settings: each number (and each switch, as 0 or 1) read and
//! written by key, a written value checked as the file reader checks it.

use crate::model::cueing_settings::CueingSettings;

/// A number or switch of `[cueing]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CueingKey {
    /// `translation_scale`.
    TranslationScale,
    /// `translation_hp_wn`.
    TranslationHpWn,
    /// `translation_hp_zeta`.
    TranslationHpZeta,
    /// `translation_hp_wb`.
    TranslationHpWb,
    /// `tilt` (a switch).
    Tilt,
    /// `tilt_lp_wn`.
    TiltLpWn,
    /// `tilt_lp_zeta`.
    TiltLpZeta,
    /// `tilt_rate_max_deg_s`.
    TiltRateMax,
    /// `rotation_scale`.
    RotationScale,
    /// `rotation_hp_wn`.
    RotationHpWn,
    /// `rotation_hp_zeta`.
    RotationHpZeta,
    /// Axis `i` (surge, sway, heave, roll, pitch, yaw) cued or not (a switch).
    Axis(usize),
    /// Component `i` (x, y, z) of the reference point.
    Reference(usize),
    /// `workspace_limiter` (a switch).
    Limiter,
    /// `limiter_recovery_s`.
    LimiterRecovery,
    /// `stall_s`.
    Stall,
    /// `fade_s`.
    Fade,
    /// `input_prediction_s`.
    Prediction,
    /// `mpc_horizon_steps` (a whole number).
    HorizonSteps,
    /// `mpc_step_s`.
    Step,
    /// `mpc_solve_interval_s`.
    SolveInterval,
    /// `mpc_force_weight`.
    ForceWeight,
    /// `mpc_rate_weight`.
    RateWeight,
    /// `mpc_displacement_weight`.
    DisplacementWeight,
    /// `mpc_velocity_weight`.
    VelocityWeight,
    /// `mpc_tilt_weight`.
    TiltWeight,
    /// `mpc_input_weight`.
    InputWeight,
    /// `mpc_margin`.
    Margin,
    /// `mpc_preview` (a switch).
    Preview,
    /// `vestibular` (a switch).
    Vestibular,
}

/// The axes' keys in the file, x to yaw.
pub const AXES: [&str; 6] = ["surge", "sway", "heave", "roll", "pitch", "yaw"];

/// A field of the table: a number, a whole number, or a switch.
enum Field<'a> {
    Number(&'a mut f64),
    Count(&'a mut u32),
    Switch(&'a mut bool),
}

fn field(c: &mut CueingSettings, key: CueingKey) -> Option<Field<'_>> {
    use CueingKey::*;
    use Field::{Count, Number, Switch};
    Some(match key {
        TranslationScale => Number(&mut c.translation_scale),
        TranslationHpWn => Number(&mut c.translation_hp_wn),
        TranslationHpZeta => Number(&mut c.translation_hp_zeta),
        TranslationHpWb => Number(&mut c.translation_hp_wb),
        Tilt => Switch(&mut c.tilt),
        TiltLpWn => Number(&mut c.tilt_lp_wn),
        TiltLpZeta => Number(&mut c.tilt_lp_zeta),
        TiltRateMax => Number(&mut c.tilt_rate_max_deg_s),
        RotationScale => Number(&mut c.rotation_scale),
        RotationHpWn => Number(&mut c.rotation_hp_wn),
        RotationHpZeta => Number(&mut c.rotation_hp_zeta),
        Axis(i) => Switch(match i {
            0 => &mut c.surge,
            1 => &mut c.sway,
            2 => &mut c.heave,
            3 => &mut c.roll,
            4 => &mut c.pitch,
            5 => &mut c.yaw,
            _ => return None,
        }),
        Reference(i) => Number(c.reference_m.get_mut(i)?),
        Limiter => Switch(&mut c.workspace_limiter),
        LimiterRecovery => Number(&mut c.limiter_recovery_s),
        Stall => Number(&mut c.stall_s),
        Fade => Number(&mut c.fade_s),
        Prediction => Number(&mut c.input_prediction_s),
        HorizonSteps => Count(&mut c.mpc_horizon_steps),
        Step => Number(&mut c.mpc_step_s),
        SolveInterval => Number(&mut c.mpc_solve_interval_s),
        ForceWeight => Number(&mut c.mpc_force_weight),
        RateWeight => Number(&mut c.mpc_rate_weight),
        DisplacementWeight => Number(&mut c.mpc_displacement_weight),
        VelocityWeight => Number(&mut c.mpc_velocity_weight),
        TiltWeight => Number(&mut c.mpc_tilt_weight),
        InputWeight => Number(&mut c.mpc_input_weight),
        Margin => Number(&mut c.mpc_margin),
        Preview => Switch(&mut c.mpc_preview),
        Vestibular => Switch(&mut c.vestibular),
    })
}

/// The value of `key` (a switch as 1 or 0).
pub(super) fn get(c: &CueingSettings, key: CueingKey) -> Option<f64> {
    let mut copy = c.clone();
    Some(match field(&mut copy, key)? {
        Field::Number(v) => *v,
        Field::Count(n) => f64::from(*n),
        Field::Switch(b) => f64::from(u8::from(*b)),
    })
}

/// Write `v` at `key` (a switch takes 1 or 0), refused with the reason when the table
/// would not work (left unchanged then).
pub(super) fn set(c: &mut CueingSettings, key: CueingKey, v: f64) -> Result<(), String> {
    let mut edited = c.clone();
    match field(&mut edited, key) {
        Some(Field::Number(x)) => *x = v,
        Some(Field::Count(n)) if v.fract() == 0.0 && (0.0..=f64::from(u32::MAX)).contains(&v) => {
            *n = v as u32
        }
        Some(Field::Count(_)) => return Err(format!("must be a whole number, got {v}")),
        Some(Field::Switch(b)) => *b = v != 0.0,
        None => return Err("no such item".to_owned()),
    }
    if let Some(p) = edited.problem() {
        // Named with its key: it may be another key's rule (the step and the solve
        // interval bound each other); [`super::Setting::set`] drops its own.
        return Err(format!("`{}` {}", p.key, p.reason));
    }
    *c = edited;
    Ok(())
}
