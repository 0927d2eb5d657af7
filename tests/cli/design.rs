//! `stewart design`: the stroke a motion envelope needs.

use crate::{stderr, stdout, stewart};

#[test]
fn the_envelope_gives_the_stroke_it_needs_and_whether_it_fits() {
    let o = stewart(&[
        "design",
        "--envelope",
        "x=±0.1,y=±0.1,z=0.7..0.9,roll=±10,pitch=±10,yaw=±15",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    for leg in 1..=6 {
        assert!(text.contains(&format!("  L{leg}  ")), "{text}");
    }
    assert!(
        text.contains("Needed leg range: 0.6551 .. 1.3520 m"),
        "{text}"
    );
    assert!(text.contains("does not fit the scenario's limits (0.55 m .. 1.3 m)"));
    // Widened limits: it fits.
    let o = stewart(&[
        "design",
        "--set",
        "geometry.leg_max=1.4",
        "--envelope",
        "x=±0.1,y=±0.1,z=0.7..0.9,roll=±10,pitch=±10,yaw=±15",
        "--format",
        "json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let json: serde_json::Value =
        serde_json::from_str(&stdout(&o)).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(json["fits"], serde_json::Value::Bool(true));
    assert_eq!(json["actuators"].as_array().map(Vec::len), Some(6));
    let hi = json["needed"][1]["value"].as_f64().unwrap_or(0.0);
    assert!((hi - 1.352).abs() < 1e-3, "{hi}");
}

#[test]
fn a_servo_platform_gets_its_angle_range() {
    let o = stewart(&[
        "design",
        "--preset",
        "servo-desk",
        "--envelope",
        "x=±0.01,roll=±5,yaw=±8",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    assert!(
        text.contains("  S1  ") && text.contains("Needed servo range:"),
        "{text}"
    );
    assert!(text.contains("°"));
}

#[test]
fn a_bad_envelope_is_one_clear_error() {
    for (envelope, words) in [
        ("", "the envelope is empty"),
        ("z=0.9..0.7", "inverted"),
        ("x=NaN", "not a finite number"),
        ("roll=±inf", "not a finite number"),
        ("q=1", "`q` is not a coordinate"),
        ("x=1,x=1", "given twice"),
    ] {
        let o = stewart(&["design", "--envelope", envelope]);
        assert_eq!(o.status.code(), Some(2), "{envelope}");
        let err = stderr(&o);
        assert!(err.contains(words), "{envelope}: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(stdout(&o).is_empty());
    }
}
