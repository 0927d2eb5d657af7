//! `stewart settings` and `--set KEY=VALUE`.

use crate::{parse_csv, stderr, stdout, stewart};

#[test]
fn settings_lists_every_key_with_value_unit_and_default() {
    let o = stewart(&["settings", "--preset", "circle"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    let row = |key: &str| {
        text.lines()
            .find(|l| l.split_whitespace().next() == Some(key))
            .unwrap_or_else(|| panic!("no row for {key} in\n{text}"))
            .split_whitespace()
            .map(str::to_owned)
            .collect::<Vec<_>>()
    };
    assert_eq!(row("geometry.base_angles_deg[0]")[1], "10");
    assert_eq!(row("trajectory.radius_m")[1..3], ["0.15", "m"]);
    // Why a key has no value here, by what it belongs to.
    assert_eq!(
        row("trajectory.x.amplitude_m")[1..3],
        ["(another", "trajectory"]
    );
    assert_eq!(row("limits.servo_speed_max_deg_s")[1..3], ["(the", "other"]);
    assert_eq!(row("limits.leg_speed_max_m_s")[1], "off");
    // The accepted range (what files, --set and sliders may hold), before the default: a
    // radius is positive (above 0, which is itself refused).
    let radius = row("geometry.base_radius");
    assert_eq!(
        radius[radius.len() - 5..radius.len() - 1],
        [">", "0", "..", "1000"]
    );
    let samples = row("trajectory.samples");
    assert_eq!(
        samples[samples.len() - 4..samples.len() - 1],
        ["2", "..", "1e7"]
    );
    assert_eq!(
        row("checks.jump_floor_m").last().map(String::as_str),
        Some("1e-4")
    );
}

#[test]
fn set_changes_the_scenario_for_every_command() {
    // The seed with x and y still and two samples over 5 s: the platform stays on the axis.
    let o = stewart(&[
        "solve",
        "--set",
        "trajectory.x.amplitude_m=0",
        "--set",
        "trajectory.y.amplitude_m=0",
        "--set",
        "trajectory.duration_s=5",
        "--set",
        "trajectory.samples=2",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (_, rows) = parse_csv(&stdout(&o));
    assert_eq!(rows.len(), 2);
    assert_eq!(rows[1][0], 5.0);
    assert_eq!((rows[1][1], rows[1][2]), (0.0, 0.0));
    // A leg minimum above every leg makes `check` find stroke problems.
    let o = stewart(&[
        "check",
        "--preset",
        "paired",
        "--set",
        "geometry.leg_min=1.2",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    assert!(stdout(&o).contains("min"), "{}", stdout(&o));
}

#[test]
fn a_refused_setting_is_one_clear_error() {
    for (args, expected) in [
        (
            vec!["solve", "--set", "geometry.base_radius=-1"],
            "error: --set: `geometry.base_radius` = -1 refused: -1 is outside the accepted range above 0 … 1000 m",
        ),
        (
            vec!["check", "--set", "cueing.mpc_horizon_steps=41"],
            "error: --set: `cueing.mpc_horizon_steps` = 41 refused: 41 is outside the accepted range 2 … 40",
        ),
        (
            vec!["check", "--set", "cueing.tilt=maybe"],
            "error: --set: `cueing.tilt` = maybe refused: it is a switch: true or false (on or off, 1 or 0)",
        ),
        (
            vec![
                "solve",
                "--preset",
                "seed",
                "--set",
                "trajectory.radius_m=0.1",
            ],
            "error: --set: `trajectory.radius_m` does not apply to a `sinusoid` trajectory",
        ),
        (
            vec!["check", "--set", "geometry.radius=1"],
            "error: --set: unknown setting `geometry.radius` (`stewart settings` lists every key)",
        ),
        (
            vec!["solve", "--set", "trajectory.samples=nan"],
            "error: --set: `trajectory.samples` = nan refused: it must be a finite number",
        ),
    ] {
        let o = stewart(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert_eq!(stderr(&o).trim_end(), expected, "{args:?}");
        assert!(o.stdout.is_empty(), "{args:?}");
    }
}

#[test]
fn as_coordinates_writes_the_same_platform_with_every_joint_a_point() {
    let dir = crate::tempdir();
    let file = dir.path().join("paired-xyz.toml");
    let file = file.to_string_lossy().into_owned();
    let o = stewart(&[
        "settings",
        "--preset",
        "paired",
        "--as-coordinates",
        "--out",
        &file,
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&file).unwrap_or_else(|e| panic!("{e}"));
    assert!(text.contains("base_joints_m = [\n  ["), "{text}");
    assert!(text.contains("platform_joints_m = [\n  ["), "{text}");
    assert!(
        !text.contains("base_radius") && !text.contains("angles_deg"),
        "{text}"
    );
    // The same legs over the whole motion, to the last bit of the printed numbers.
    let a = stewart(&["solve", "--preset", "paired"]);
    let b = stewart(&["solve", "--scenario", &file]);
    assert!(b.status.success(), "{}", stderr(&b));
    let (_, rows_a) = parse_csv(&stdout(&a));
    let (_, rows_b) = parse_csv(&stdout(&b));
    assert_eq!(rows_a.len(), rows_b.len());
    for (x, y) in rows_a.iter().zip(&rows_b) {
        for (u, v) in x.iter().zip(y) {
            assert!((u - v).abs() < 1e-14, "{x:?} vs {y:?}");
        }
    }
    // Its table says where the circle keys went.
    let o = stewart(&["settings", "--scenario", &file]);
    let table = stdout(&o);
    let radius = table
        .lines()
        .find(|l| l.starts_with("geometry.base_radius "))
        .unwrap_or_else(|| panic!("{table}"));
    assert!(radius.contains("(joints as coordinates)"), "{radius}");
    assert!(
        table.contains("geometry.platform_joints_m[5][2]"),
        "{table}"
    );
    // One coordinate changed on the command line moves that joint only.
    let moved = stewart(&[
        "solve",
        "--scenario",
        &file,
        "--set",
        "geometry.base_joints_m[2][1]=0.45",
    ]);
    assert!(moved.status.success(), "{}", stderr(&moved));
    let (header, rows_m) = parse_csv(&stdout(&moved));
    let leg = |name: &str| header.iter().position(|h| h == name).unwrap_or(0);
    assert_ne!(rows_m[0][leg("L3")], rows_b[0][leg("L3")]);
    assert_eq!(rows_m[0][leg("L1")], rows_b[0][leg("L1")]);
    // --out needs --as-coordinates.
    let o = stewart(&["settings", "--preset", "seed", "--out", &file]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
}

/// One switch rule everywhere (words, or a number equal to 1 or 0), refusals quoting the
/// value as typed, `--set`s taken in any order, and a UDP address that cannot be one
/// refused where it is written.
#[test]
fn switches_quotes_orders_and_addresses_read_the_same_everywhere() {
    for set in [
        "link.reversed.1=1.0",
        "cueing.tilt=1.0",
        "cueing.tilt=00",
        "link.baud=115200.0",
        "link.actuator.1=1.0",
    ] {
        let o = stewart(&["settings", "--set", set]);
        assert_eq!(o.status.code(), Some(0), "{set}: {}", stderr(&o));
    }
    for (set, said) in [
        (
            "cueing.tilt=3.0",
            "`cueing.tilt` = 3.0 refused: it is a switch: true or false",
        ),
        (
            "link.reversed.1=3.0",
            "`3.0` is not a switch: true or false",
        ),
        (
            "geometry.base_radius=2e3",
            "`geometry.base_radius` = 2e3 refused",
        ),
        (
            "link.address=1.2.3.4:99999",
            "`99999` is not a port number 1 to 65535",
        ),
        ("link.address=nothost", "`nothost` is not an address"),
        ("link.address=[::1]", "it has no `:PORT`"),
        ("link.address=udp:1.2.3.4:99", "write HOST:PORT alone"),
        ("link.address=[127.0.0.1]:9", "is not an IPv6 address"),
        ("link.address=[::1]]:9", "is not an IPv6 address"),
    ] {
        let o = stewart(&["settings", "--set", set]);
        assert_eq!(o.status.code(), Some(2), "{set}");
        assert!(stderr(&o).contains(said), "{set}: {}", stderr(&o));
    }
    // The template format and its template, in either order.
    for order in [
        ["link.format=template", "link.template={a1:u8}"],
        ["link.template={a1:u8}", "link.format=template"],
    ] {
        let o = stewart(&["settings", "--set", order[0], "--set", order[1]]);
        assert_eq!(o.status.code(), Some(0), "{order:?}: {}", stderr(&o));
        assert!(stdout(&o).contains("{a1:u8}"), "{order:?}");
    }
}
