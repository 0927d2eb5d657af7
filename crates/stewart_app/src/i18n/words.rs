//! What the core returns as data, in the reader's words: setting labels, pose
//! coordinates, the quantity plotted, trajectory kinds, diagnostics findings and the
//! architecture verdict. The core writes no sentences: the catalogues hold every word, in
//! English (what the command line writes) and in Chinese.

use stewart_kinematics::analysis::architecture::ArchitectureReport;
use stewart_kinematics::io::settings::{Setting, TrajectoryChoice};
use stewart_kinematics::model::actuator::{ActuatorKind, Quantity};
use stewart_kinematics::{analysis::checks::Finding, analysis::checks::FindingKind};

use super::Lang;

/// The pose's coordinates in file order, as keys of `pose.*`.
pub(crate) const COORDINATES: [&str; 6] = ["x", "y", "z", "roll", "pitch", "yaw"];

/// A pose coordinate's name (`roll` → 横滚); `x`, `y`, `z` stay letters.
pub(crate) fn coordinate(lang: Lang, name: &str) -> &'static str {
    lang.tr(&format!("pose.{name}"))
}

/// The catalogue key of a setting's label and the numbers that fill it: `{n}` the joint,
/// horn or servo number from 1, `{axis}` the pivot axis or trajectory channel.
fn setting_key(setting: &Setting) -> (String, usize, String) {
    let key = setting.key.as_str();
    let (base, indexes) = match key.split_once('[') {
        Some((base, rest)) => (
            base,
            rest.trim_end_matches(']')
                .split("][")
                .map(|i| i.parse::<usize>().unwrap_or(0))
                .collect::<Vec<_>>(),
        ),
        None => (key, Vec::new()),
    };
    let index = indexes.first().copied().unwrap_or(0);
    let parts: Vec<&str> = base.split('.').collect();
    let axis_of = |k: usize| ["x", "y", "z"].get(k).copied().unwrap_or("x").to_owned();
    match parts.as_slice() {
        ["geometry", joints] if joints.ends_with("_joints_m") => (
            format!("setting.{base}"),
            index + 1,
            axis_of(indexes.get(1).copied().unwrap_or(0)),
        ),
        ["trajectory", channel, part] if COORDINATES.contains(channel) => (
            format!("setting.trajectory.channel.{part}"),
            index + 1,
            (*channel).to_owned(),
        ),
        ["pivot", _] | ["cueing", "reference_m"] => {
            (format!("setting.{base}"), index + 1, axis_of(index))
        }
        _ => (format!("setting.{base}"), index + 1, String::new()),
    }
}

/// A setting's label (`base radius`, `底座半径`).
pub(crate) fn setting_label(lang: Lang, setting: &Setting) -> String {
    let (key, n, axis) = setting_key(setting);
    let axis = if axis.is_empty() {
        String::new()
    } else {
        coordinate(lang, &axis).to_owned()
    };
    lang.fmt(&key, &[("n", &n), ("axis", &axis)])
}

/// A setting's label with its unit for a platform of `kind`'s actuators, as sliders
/// show it: `base radius (m)`, `actuator stiffness (N·m/rad)`.
pub(crate) fn setting_label_with_unit(lang: Lang, setting: &Setting, kind: ActuatorKind) -> String {
    match setting.unit.symbol_for(kind) {
        "" => setting_label(lang, setting),
        unit => format!("{} ({unit})", setting_label(lang, setting)),
    }
}

/// What the actuators exert: `leg force` / `腿力`, `servo torque` / `舵机力矩`.
pub(crate) fn effort_name(lang: Lang, q: &Quantity) -> &'static str {
    lang.tr_kind("quantity.effort", q.actuator)
}

/// What is plotted: `leg length` / `腿长`, `servo angle` / `舵机角`.
pub(crate) fn quantity_name(lang: Lang, q: &Quantity) -> &'static str {
    lang.tr_kind("quantity.name", q.actuator)
}

/// A trajectory kind's name.
pub(crate) fn trajectory_choice(lang: Lang, choice: TrajectoryChoice) -> &'static str {
    lang.tr(match choice {
        TrajectoryChoice::Sinusoid => "trajectory.sinusoid",
        TrajectoryChoice::Circle => "trajectory.circle",
        TrajectoryChoice::FigureEight => "trajectory.figure_eight",
        TrajectoryChoice::Helix => "trajectory.helix",
        TrajectoryChoice::Sway => "trajectory.sway",
        TrajectoryChoice::Keyframes => "trajectory.keyframes",
    })
}

/// The catalogue key of a finding's sentence.
fn finding_key(kind: FindingKind) -> &'static str {
    match kind {
        FindingKind::StrokeMax => "finding.stroke_max",
        FindingKind::StrokeMin => "finding.stroke_min",
        FindingKind::LegSpeed => "finding.leg_speed",
        FindingKind::LegAccel => "finding.leg_accel",
        FindingKind::LegJerk => "finding.leg_jerk",
        FindingKind::BaseCone => "finding.base_cone",
        FindingKind::PlatformCone => "finding.platform_cone",
        FindingKind::LegCollision => "finding.leg_collision",
        FindingKind::NearSingular => "finding.near_singular",
        FindingKind::ArchitectureSingular => "finding.architecture_singular",
        FindingKind::Jump => "finding.jump",
        FindingKind::RigidBody => "finding.rigid_body",
        FindingKind::Unreachable => "finding.unreachable",
        FindingKind::ServoMax => "finding.servo_max",
        FindingKind::ServoMin => "finding.servo_min",
        FindingKind::ServoSpeed => "finding.servo_speed",
        FindingKind::ServoAccel => "finding.servo_accel",
        FindingKind::ServoJerk => "finding.servo_jerk",
        FindingKind::HornCone => "finding.horn_cone",
        FindingKind::RodPlatformCone => "finding.rod_platform_cone",
        FindingKind::RodCollision => "finding.rod_collision",
        FindingKind::RodHornCollision => "finding.rod_horn_collision",
        FindingKind::ServoJump => "finding.servo_jump",
    }
}

/// A finding's time in seconds: three decimals, or as many more (up to nine) as the time
/// needs to be told from its neighbours (a table row 0.5 ms or 1.5 µs after another is
/// not named by the other's time); never a negative zero.
pub(crate) fn time_text(t: f64) -> String {
    let close_enough = 1e-10 * t.abs().max(1.0);
    let text = (3..=9)
        .map(|decimals| format!("{t:.decimals$}"))
        .find(|text| {
            text.parse::<f64>()
                .is_ok_and(|v| (v - t).abs() <= close_enough)
        })
        .unwrap_or_else(|| format!("{t:.9}"));
    match text.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_owned(),
        _ => text,
    }
}

/// A small positive amount with three decimals, or three significant digits where three
/// decimals would show it as zero (`0.000` for a limit of 0.19 µm).
fn small_amount(v: f64) -> String {
    if v != 0.0 && v.is_finite() && v.abs() < 0.0005 {
        let digits = (2 - v.abs().log10().floor() as i32).clamp(3, 12) as usize;
        format!("{v:.digits$}")
    } else {
        format!("{v:.3}")
    }
}

/// A diagnostics finding in words (the English of `stewart check`).
pub(crate) fn finding(lang: Lang, f: &Finding) -> String {
    let number = |k: usize| f.legs.get(k).copied().unwrap_or(0);
    let names: Vec<String> = f.legs.iter().map(|l| format!("L{l}")).collect();
    let leg = match names.len() {
        0 => String::new(),
        1 => lang.fmt("finding.leg_one", &[("a", &names[0])]),
        _ => lang.fmt(
            "finding.leg_many",
            &[("list", &names.join(lang.tr("finding.and")))],
        ),
    };
    let span = if f.count > 1 {
        lang.fmt(
            "finding.span_many",
            &[
                ("from", &time_text(f.first_time)),
                ("to", &time_text(f.last_time)),
                ("count", &f.count),
            ],
        )
    } else {
        lang.fmt("finding.span_one", &[("at", &time_text(f.first_time))])
    };
    let over = -f.margin;
    let (worst, limit) = (f.worst_value, f.limit);
    let singular = if worst.is_finite() {
        format!("{worst:.1}")
    } else {
        lang.tr("finding.singular_value").to_owned()
    };
    let args: [(&str, &dyn std::fmt::Display); 28] = [
        ("leg", &leg),
        ("servo", &lang.fmt("finding.servo", &[("n", &number(0))])),
        ("rod", &lang.fmt("finding.rod", &[("n", &number(0))])),
        ("a", &number(0)),
        ("b", &number(1)),
        ("span", &span),
        ("when", &time_text(f.worst_time)),
        ("limit", &limit),
        ("limit_m", &format!("{limit:.4}")),
        ("limit_mm", &format!("{:.1}", limit * 1e3)),
        ("limit_mm3", &small_amount(limit * 1e3)),
        ("limit_deg3", &small_amount(limit)),
        ("limit_e", &format!("{limit:.1e}")),
        ("worst_m", &format!("{worst:.4}")),
        ("worst_m3", &format!("{worst:.3}")),
        ("worst_2", &format!("{worst:.2}")),
        ("worst_1", &format!("{worst:.1}")),
        ("worst_0", &format!("{worst:.0}")),
        ("worst_mm", &format!("{:.1}", worst * 1e3)),
        ("worst_mm2", &format!("{:.2}", worst * 1e3)),
        ("worst_e", &format!("{worst:.3e}")),
        ("singular", &singular),
        ("over_mm", &format!("{:.1}", over * 1e3)),
        ("over_3", &format!("{over:.3}")),
        ("over_2", &format!("{over:.2}")),
        ("over_1", &format!("{over:.1}")),
        ("over_0", &format!("{over:.0}")),
        ("over_pct", &format!("{:.2}", over * 100.0)),
    ];
    lang.fmt(finding_key(f.kind), &args)
}

/// The architecture verdict in words (the English of `stewart check` and `stewart fk`).
pub(crate) fn architecture(lang: Lang, report: &ArchitectureReport) -> String {
    if !report.singular {
        return lang.fmt(
            "architecture.sound",
            &[("worst", &format!("{:.3}", report.worst_inverse_condition))],
        );
    }
    let why = lang.tr(if report.projective_correspondence {
        "architecture.why_projective"
    } else {
        "architecture.why_complex"
    });
    lang.fmt(
        "architecture.singular",
        &[("why", &why), ("twist", &weakest_twist(lang, report))],
    )
}

/// The twist the legs cannot resist, in words: its dominant rotation and translation directions and the rotation's share.
fn weakest_twist(lang: Lang, report: &ArchitectureReport) -> String {
    let w = report.home.weakest_twist;
    let part = |v: [f64; 3], key: &str| {
        let norm = v.iter().map(|c| c * c).sum::<f64>().sqrt();
        (norm >= 0.05).then(|| {
            let [x, y, z] = v.map(|c| format!("{:.2}", c / norm));
            lang.fmt(key, &[("x", &x), ("y", &y), ("z", &z)])
        })
    };
    let parts: Vec<String> = [
        part([w[3], w[4], w[5]], "architecture.rotation_along"),
        part([w[0], w[1], w[2]], "architecture.translation_along"),
    ]
    .into_iter()
    .flatten()
    .collect();
    let share = (w[3] * w[3] + w[4] * w[4] + w[5] * w[5]) * 100.0;
    lang.fmt(
        "architecture.twist",
        &[
            ("parts", &parts.join(lang.tr("architecture.combined_with"))),
            ("share", &format!("{share:.0}")),
        ],
    )
}

/// A scenario's description in `lang`: a preset's own (unedited) description is
/// translated, any other is shown as written.
pub(crate) fn description(lang: Lang, name: &str, description: &str) -> String {
    let key = format!("preset.{name}");
    let english = super::catalogue_text(Lang::En, &key);
    match (english, super::catalogue_text(lang, &key)) {
        (Some(en), Some(text)) if en == description => text.to_owned(),
        _ => description.to_owned(),
    }
}
