//! The head-up readout drawn over the 3D view and burnt into exported frames: a title,
//! the time, the pose and the six leg lengths or servo angles, in the top-left corner
//! (exports frame the platform below it), on a box of the background colour.

use stewart_kinematics::{Geometry, Pose};
use stewart_render::{Anchor, TextItem, TextSize, Theme};

use crate::i18n::Lang;
use crate::i18n::words::coordinate;

/// Line height as a fraction of the view's shorter side (legible at 720p and 4K alike).
const SIZE: f32 = 0.027;

/// Where the readout starts: fractions of the view's width and height from its top-left.
const CORNER: [f32; 2] = [0.015, 0.02];

/// The share of a view's height (`view`: width and height, pixels) that the readout
/// `text` covers from the top, its box included.
pub(crate) fn height_share(text: &str, view: [f32; 2]) -> f32 {
    let px = TextSize::OfView(SIZE).px(view);
    let rows = text.split('\n').count() as f32;
    // The renderer's box reaches a quarter line below the last row.
    (CORNER[1] * view[1] + px * (rows + 0.25)) / view[1].max(1.0)
}

/// The readout's lines in `lang`: `title`, the time (`None`: the manual pose), the pose,
/// the six actuator values (or why the pose is out of reach). `solved`: the values when
/// they are known already (a frame's: `SceneFrame::actuator_values`), so the pose is not
/// solved twice; else (or when a servo cannot reach, to say which) they are solved here.
pub(crate) fn lines(
    lang: Lang,
    title: &str,
    geometry: &Geometry,
    time: Option<f64>,
    pose: &Pose,
    solved: Option<[f64; 6]>,
) -> String {
    let [x, y, z, roll, pitch, yaw] = pose.to_coordinates();
    let mut out = Vec::new();
    if !title.trim().is_empty() {
        out.push(title.trim().to_owned());
    }
    out.push(match time {
        Some(t) => format!("t = {t:.3} s"),
        None => lang.tr("readout.manual").to_owned(),
    });
    out.push(format!("x {x:+.4}  y {y:+.4}  z {z:+.4} m"));
    let [roll_name, pitch_name, yaw_name] =
        ["roll", "pitch", "yaw"].map(|name| coordinate(lang, name));
    out.push(format!(
        "{roll_name} {:+.2}°  {pitch_name} {:+.2}°  {yaw_name} {:+.2}°",
        roll.to_degrees(),
        pitch.to_degrees(),
        yaw.to_degrees()
    ));
    let q = geometry.quantity();
    // Four decimals of a metre, two of a degree.
    let decimals = if q.unit == "m" { 4 } else { 2 };
    let unit = if q.unit == "m" { " m" } else { q.unit };
    match solved.map_or_else(|| geometry.actuator_values_at(pose), Ok) {
        Ok(v) => {
            for half in [0..3, 3..6] {
                let row: Vec<String> = half
                    .map(|k| format!("{}{} {:.*}", q.symbol, k + 1, decimals, v[k]))
                    .collect();
                out.push(format!("{}{unit}", row.join("  ")));
            }
        }
        Err(e) => out.push(lang.fmt(
            "teleop.servo_unreachable",
            &[
                ("n", &e.servo),
                (
                    "pct",
                    &stewart_kinematics::model::rotary::percent(100.0 * e.excess),
                ),
            ],
        )),
    }
    out.join("\n")
}

/// The readout as text for the renderer, in `theme`'s colours.
pub(crate) fn item(text: String, theme: &Theme) -> TextItem {
    item_scaled(text, theme, 1.0)
}

/// [`item`] with its text `scale` times as large (presentation mode: as large as the
/// interface's text there).
pub(crate) fn item_scaled(text: String, theme: &Theme, scale: f32) -> TextItem {
    let [r, g, b, _] = theme.background;
    TextItem {
        text,
        anchor: Anchor::Fraction(CORNER),
        align: [0.0, 0.0],
        size: TextSize::OfView(SIZE * scale),
        colour: theme.joint,
        background: Some([r, g, b, 0.8]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use stewart_kinematics::Scenario;

    #[test]
    fn the_readout_band_is_its_rows_below_the_corner() {
        // 6 rows of 0.027 × 720 px, a quarter row of box below, from 2 % down.
        let share = height_share("a\nb\nc\nd\ne\nf", [1280.0, 720.0]);
        let expected = (0.02 * 720.0 + 0.027 * 720.0 * 6.25) / 720.0;
        assert!((share - expected).abs() < 1e-6, "{share} {expected}");
        // A narrow view sizes text by its width, so the band is a smaller share.
        assert!(height_share("a\nb", [400.0, 800.0]) < height_share("a\nb", [800.0, 800.0]));
    }

    #[test]
    fn the_readout_says_time_pose_and_the_six_values() {
        let s = Scenario::seed();
        let pose = Pose::from_xyz_rpy_deg([0.01, -0.02, 0.85], [1.0, -2.0, 3.0]);
        let text = lines(Lang::En, "seed", &s.geometry, Some(1.5), &pose, None);
        let rows: Vec<&str> = text.lines().collect();
        assert_eq!(rows[0], "seed");
        assert_eq!(rows[1], "t = 1.500 s");
        assert_eq!(rows[2], "x +0.0100  y -0.0200  z +0.8500 m");
        assert_eq!(rows[3], "roll +1.00°  pitch -2.00°  yaw +3.00°");
        let l = s.geometry.leg_lengths(&pose);
        assert_eq!(
            rows[4],
            format!("L1 {:.4}  L2 {:.4}  L3 {:.4} m", l[0], l[1], l[2])
        );
        assert!(rows[5].starts_with("L4 ") && rows[5].ends_with(" m"));
        let servo = Scenario::preset("servo-desk").unwrap_or_else(|e| panic!("{e}"));
        let home = servo.geometry.home_pose();
        let text = lines(Lang::En, "", &servo.geometry, None, &home, None);
        assert!(text.starts_with("manual pose\n"), "{text}");
        assert!(text.contains("θ1 ") && text.ends_with('°'), "{text}");
        // Out of reach: the reason instead of numbers.
        let far = Pose::from_xyz_rpy_deg([0.0, 0.0, 1.0], [0.0; 3]);
        let text = lines(Lang::En, "", &servo.geometry, Some(0.0), &far, None);
        assert!(!text.contains("θ1"), "{text}");
    }

    #[test]
    fn a_frames_values_read_as_the_values_solved_here() {
        // The export hands the readout the values its picture was solved with: the same
        // text, to the last digit, for legs and servos, in reach and out of it.
        let seed = Scenario::seed();
        let servo = Scenario::preset("servo-desk").unwrap_or_else(|e| panic!("{e}"));
        let cases = [
            (
                &seed,
                Pose::from_xyz_rpy_deg([0.01, -0.02, 0.85], [1.0, -2.0, 3.0]),
            ),
            (&servo, servo.geometry.home_pose()),
            (&servo, Pose::from_xyz_rpy_deg([0.0, 0.0, 1.0], [0.0; 3])),
        ];
        for (s, pose) in cases {
            let g = &s.geometry;
            let frame = g.scene_frame(&pose, Vec::new());
            let solved = frame.actuator_values();
            assert_eq!(solved.is_some(), g.actuator_values_at(&pose).is_ok());
            assert_eq!(
                lines(Lang::En, "", g, Some(1.0), &pose, solved),
                lines(Lang::En, "", g, Some(1.0), &pose, None)
            );
        }
    }
}
