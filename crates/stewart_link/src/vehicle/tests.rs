//! Every format's packets are built here field by field at the offsets of its published
//! layout (not by an encoder of ours), and decoded back to the numbers put in, in our axes.

use super::xplane::{RREF_DATAREFS, rref_request, rref_subscriptions, xplane_datagram};
use super::*;
use proptest::prelude::*;

/// A zeroed packet of `len` bytes with `magic` at its start.
fn packet(len: usize, magic: &[u8]) -> Vec<u8> {
    let mut p = vec![0u8; len];
    p[..magic.len()].copy_from_slice(magic);
    p
}

fn put_f32(p: &mut [u8], at: usize, v: f32) {
    p[at..at + 4].copy_from_slice(&v.to_le_bytes());
}

fn put_u32(p: &mut [u8], at: usize, v: u32) {
    p[at..at + 4].copy_from_slice(&v.to_le_bytes());
}

fn put_f32s(p: &mut [u8], at: usize, values: &[f32]) {
    for (k, v) in values.iter().enumerate() {
        put_f32(p, at + 4 * k, *v);
    }
}

fn sample_of(d: &Decoded) -> VehicleSample {
    match d.reading {
        Ok(Reading::Sample(s)) => s,
        ref other => panic!("not a sample: {other:?}"),
    }
}

fn close(a: [f64; 3], b: [f64; 3], tolerance: f64) -> bool {
    a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= tolerance)
}

#[test]
fn the_generic_forms_decode_to_the_same_motion() {
    let text = decode(b"1.25,-3.5,0.5,1,10,-20,30\n").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        text,
        VehicleSample {
            t: Some(1.25),
            accel: [-3.5, 0.5, 1.0],
            rates_deg_s: [10.0, -20.0, 30.0],
        }
    );
    let spaced = decode(b"1.25 -3.5\t0.5 1 10 -20 30").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(spaced, text);
    let binary: Vec<u8> = [1.25f32, -3.5, 0.5, 1.0, 10.0, -20.0, 30.0]
        .iter()
        .flat_map(|v| v.to_le_bytes())
        .collect();
    assert_eq!(decode(&binary), Ok(text));
    let mut d = VehicleDecoder::new();
    assert_eq!(d.decode(&binary).format, Some(VehicleFormat::Binary));
    assert_eq!(d.decode(b"1,0,0,0,0,0,0").format, Some(VehicleFormat::Text));
    // A text line of a binary format's length is still text.
    let line = format!("{:<63}\n", "1,2,3,4,5,6,7");
    assert_eq!(line.len(), outsim::CLASSIC_BYTES);
    assert_eq!(d.decode(line.as_bytes()).format, Some(VehicleFormat::Text));
}

#[test]
fn x_plane_data_g_loads_and_body_rates_become_our_axes() {
    // Braking at 0.5 g (g_axil positive backwards, as `faxil_plug_acf` pushes: +0.5), 0.2 g
    // to the right (g_side positive to the right, as `fside_plug_acf`), 1.3 g pulling up;
    // rolling right, pitching up and yawing right at 0.1, 0.2, 0.3 rad/s.
    let bytes = xplane_datagram([1.3, 0.5, 0.2], [0.2, 0.1, 0.3]);
    assert_eq!(bytes.len(), 5 + 2 * 36);
    let s = decode(&bytes).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.t, None);
    let g = GRAVITY;
    assert!(close(s.accel, [-0.5 * g, -0.2 * g, 0.3 * g], 1e-5));
    let deg = f64::to_degrees;
    assert!(close(s.rates_deg_s, [deg(0.1), -deg(0.2), -deg(0.3)], 1e-4));
}

#[test]
fn an_x_plane_take_off_roll_reads_forwards() {
    // Accelerating down the runway at 0.3 g: the total force pushes the aircraft forwards,
    // against `faxil_plug_acf`'s positive (backwards), so g_axil = −0.3; level, 1 g normal.
    let s = decode(&xplane_datagram([1.0, -0.3, 0.0], [0.0; 3])).unwrap_or_else(|e| panic!("{e}"));
    assert!((s.accel[0] - 0.3 * GRAVITY).abs() < 1e-5, "{s:?}");
    assert!(s.accel[1].abs() < 1e-9 && s.accel[2].abs() < 1e-9, "{s:?}");
}

#[test]
fn x_plane_rref_replies_give_the_same_motion_as_data() {
    // The reply: "RREF", the byte X-Plane 11 and 12 put there (','), then (index, value)
    // pairs in any order; another client's index (9) is not read.
    let mut reply = b"RREF,".to_vec();
    let values: [(i32, f32); 7] = [
        (2, 0.2),
        (9, 123.0),
        (0, 1.3),
        (1, 0.5),
        (5, 0.3f32.to_degrees()),
        (3, 0.1f32.to_degrees()),
        (4, 0.2f32.to_degrees()),
    ];
    for (index, value) in values {
        reply.extend(index.to_le_bytes());
        reply.extend(value.to_le_bytes());
    }
    let mut d = VehicleDecoder::new();
    let decoded = d.decode(&reply);
    assert_eq!(decoded.format, Some(VehicleFormat::XPlaneRref));
    let from_rref = sample_of(&decoded);
    let from_data = decode(&xplane_datagram([1.3, 0.5, 0.2], [0.2, 0.1, 0.3]))
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(close(from_rref.accel, from_data.accel, 1e-5));
    assert!(close(from_rref.rates_deg_s, from_data.rates_deg_s, 1e-4));
    // Without R (index 5): refused; a length that is not pairs: refused.
    let short = &reply[..reply.len() - 24];
    assert!(matches!(
        d.decode(short).reading,
        Err(VehicleError::XPlaneMissing("RREF", _))
    ));
    assert!(matches!(
        d.decode(&reply[..reply.len() - 3]).reading,
        Err(VehicleError::Length {
            format: VehicleFormat::XPlaneRref,
            ..
        })
    ));
}

#[test]
fn an_rref_request_is_laid_out_as_x_plane_reads_it() {
    let r = rref_request(60, 3, "sim/flightmodel/position/P");
    assert_eq!(r.len(), 413);
    assert_eq!(&r[..5], b"RREF\0");
    assert_eq!(r[5..9], 60i32.to_le_bytes());
    assert_eq!(r[9..13], 3i32.to_le_bytes());
    assert_eq!(&r[13..39], b"sim/flightmodel/position/P");
    assert!(r[39..].iter().all(|&b| b == 0));
    let all = rref_subscriptions(0);
    assert_eq!(all.len(), RREF_DATAREFS.len());
    assert!(all.iter().all(|r| r[5..9] == [0; 4]), "0 a second stops");
    assert_eq!(all[5][9..13], 5i32.to_le_bytes());
}

/// A Forza packet of `len` bytes: race on, `ms`, and the Sled fields given (local X
/// right, Y up, Z forward; rad/s).
fn forza(len: usize, ms: u32, accel: [f32; 3], velocity: [f32; 3], omega: [f32; 3]) -> Vec<u8> {
    let mut p = packet(len, &[]);
    put_u32(&mut p, 0, 1); // IsRaceOn
    put_u32(&mut p, 4, ms); // TimestampMS
    put_f32s(&mut p, 20, &accel); // AccelerationX, Y, Z
    put_f32s(&mut p, 32, &velocity); // VelocityX, Y, Z
    put_f32s(&mut p, 44, &omega); // AngularVelocityX (pitch), Y (yaw), Z (roll)
    p
}

#[test]
fn forza_packets_of_every_length_give_the_sled_motion_in_our_axes() {
    for (len, format) in [
        (232, VehicleFormat::ForzaSled),
        (311, VehicleFormat::ForzaDash),
        (324, VehicleFormat::ForzaHorizon),
        (331, VehicleFormat::ForzaMotorsport2023),
    ] {
        let p = forza(len, 1500, [1.0, 2.0, -3.0], [0.0; 3], [0.1, 0.2, 0.3]);
        let decoded = VehicleDecoder::new().decode(&p);
        assert_eq!(decoded.format, Some(format));
        let s = sample_of(&decoded);
        assert_eq!(s.t, Some(0.0)); // the first reading

        // x = Z (forward), y = −X (left), z = Y (up).
        assert!(close(s.accel, [-3.0, -1.0, 2.0], 1e-6), "{len}: {s:?}");
        // (wx, wy, wz) = (−ωZ, ωX, −ωY), °/s.
        let deg = |r: f64| r.to_degrees();
        assert!(
            close(s.rates_deg_s, [-deg(0.3), deg(0.1), -deg(0.2)], 1e-4),
            "{len}: {s:?}"
        );
    }
}

#[test]
fn forzas_left_handed_rates_are_settled_by_its_own_turning_car() {
    // A car at 20 m/s forward (local Z) turning left at 0.5 rad/s has its centripetal
    // acceleration of 10 m/s² to its left (−X). In Forza's own frame a = ω × v, so
    // ω × (0, 0, 20) = (20 ωY, −20 ωX, 0) = (−10, 0, 0): ωY = −0.5.
    let (v, w) = (20.0f32, 0.5f32);
    let p = forza(232, 0, [-v * w, 0.0, 0.0], [0.0, 0.0, v], [0.0, -w, 0.0]);
    let s = sample_of(&VehicleDecoder::new().decode(&p));
    // Ours: a left turn is a positive yaw rate, the acceleration to the left, and
    // a = ω × v holds in our right-handed axes too: ay = wz·vx.
    assert!(s.rates_deg_s[2] > 0.0 && s.accel[1] > 0.0, "{s:?}");
    let wz = s.rates_deg_s[2].to_radians();
    assert!((s.accel[1] - wz * f64::from(v)).abs() < 1e-5, "{s:?}");
    // Pitching: nose down is positive about our y (left) and about Forza's X (right):
    // the nose (Z) moving down is ω × Z = (ωX, 0, 0) × (0, 0, 1) = (0, −ωX, 0), down.
    let p = forza(232, 0, [0.0; 3], [0.0; 3], [0.4, 0.0, 0.0]);
    let s = sample_of(&VehicleDecoder::new().decode(&p));
    assert!(
        (s.rates_deg_s[1] - 0.4f64.to_degrees()).abs() < 1e-4,
        "{s:?}"
    );
}

#[test]
fn forza_menus_read_as_idle_and_its_clock_unwraps() {
    let mut d = VehicleDecoder::new();
    let mut menus = forza(324, 10, [5.0; 3], [0.0; 3], [0.0; 3]);
    put_u32(&mut menus, 0, 0);
    assert_eq!(d.decode(&menus).reading, Ok(Reading::Idle));
    // Times count from the first reading, exactly.
    let before = sample_of(&d.decode(&forza(232, u32::MAX - 5, [0.0; 3], [0.0; 3], [0.0; 3])));
    assert_eq!(before.t, Some(0.0));
    let after = sample_of(&d.decode(&forza(232, 11, [0.0; 3], [0.0; 3], [0.0; 3])));
    assert_eq!(after.t, Some(0.017));
    // A clock going back a little is not a wrap: the receiver sees an older sample.
    let back = sample_of(&d.decode(&forza(232, 5, [0.0; 3], [0.0; 3], [0.0; 3])));
    assert!(back.t < after.t);
    // Nor is a restart from the middle of the range.
    d.decode(&forza(232, u32::MAX / 2, [0.0; 3], [0.0; 3], [0.0; 3]));
    let restarted = sample_of(&d.decode(&forza(232, 3, [0.0; 3], [0.0; 3], [0.0; 3])));
    assert_eq!(restarted.t, Some(0.009));
    // Readings sent to fool it (top, bottom, top, …) add laps only up to a bound, and a
    // time beyond the tables' bound is refused by name, never a panic or an infinity.
    for _ in 0..1000 {
        d.decode(&forza(232, u32::MAX, [0.0; 3], [0.0; 3], [0.0; 3]));
        d.decode(&forza(232, 0, [0.0; 3], [0.0; 3], [0.0; 3]));
    }
    let last = d.decode(&forza(232, 1, [0.0; 3], [0.0; 3], [0.0; 3]));
    assert!(
        matches!(last.reading, Err(VehicleError::Value { name: "t", value }) if value.is_finite()),
        "{last:?}"
    );
}

#[test]
fn a_forza_clock_near_its_wrap_gives_the_times_of_one_far_from_it() {
    // The same 16 ms ticks, once from 1 s and once across the counter's wrap: the times
    // (counted from the first reading) are equal bit for bit.
    let starts = [1000u32, u32::MAX - 40];
    let times: Vec<Vec<f64>> = starts
        .iter()
        .map(|&start| {
            let mut d = VehicleDecoder::new();
            (0..10u32)
                .map(|k| {
                    let ms = start.wrapping_add(16 * k);
                    sample_of(&d.decode(&forza(232, ms, [0.0; 3], [0.0; 3], [0.0; 3])))
                        .t
                        .unwrap_or(f64::NAN)
                })
                .collect()
        })
        .collect();
    assert_eq!(times[0], times[1]);
    assert_eq!(times[0][9], 0.144);
}

/// An F1 24 packet: its header (format, id, session, time, frame, player car) and room
/// for `len` bytes in all.
fn f1(len: usize, format: u16, id: u8, time: f32, frame: u32, player: u8) -> Vec<u8> {
    let mut p = packet(len, &format.to_le_bytes());
    p[2] = 24; // gameYear
    p[5] = 1; // packetVersion
    p[6] = id; // packetId
    p[7..15].copy_from_slice(&0x0123_4567_89ab_cdefu64.to_le_bytes()); // sessionUID
    put_f32(&mut p, 15, time); // sessionTime
    put_u32(&mut p, 19, frame); // frameIdentifier
    put_u32(&mut p, 23, frame); // overallFrameIdentifier
    p[27] = player; // playerCarIndex
    p[28] = 255; // secondaryPlayerCarIndex
    p
}

/// `Motion` with the player's (car 5) g-forces, another car's different.
fn f1_motion(time: f32, frame: u32, g: [f32; 3]) -> Vec<u8> {
    let mut p = f1(1349, 2024, 0, time, frame, 5);
    put_f32s(&mut p, 29 + 60 * 4 + 36, &[9.0, 9.0, 9.0]);
    put_f32s(&mut p, 29 + 60 * 5 + 36, &g); // gForceLateral, Longitudinal, Vertical
    p
}

/// `Motion Ex` with the angular velocity (X pitch, Y yaw, Z roll; rad/s).
fn f1_motion_ex(time: f32, frame: u32, omega: [f32; 3]) -> Vec<u8> {
    let mut p = f1(237, 2024, 13, time, frame, 5);
    put_f32s(&mut p, 161, &[30.0, 0.0, 0.0]); // localVelocity, not read
    put_f32s(&mut p, 173, &omega);
    p
}

#[test]
fn f1_motion_and_motion_ex_of_one_frame_make_one_sample() {
    let mut d = VehicleDecoder::new();
    let motion = f1_motion(12.5, 700, [0.5, -1.2, 0.1]);
    let ex = f1_motion_ex(12.5, 700, [0.01, 0.2, -0.05]);
    let first = d.decode(&motion);
    assert_eq!(first.format, Some(VehicleFormat::F1));
    assert_eq!(first.reading, Ok(Reading::Ignored));
    let s = sample_of(&d.decode(&ex));
    assert_eq!(s.t, Some(12.5));
    let g = GRAVITY;
    assert!(close(s.accel, [-1.2 * g, 0.5 * g, 0.1 * g], 1e-5), "{s:?}");
    let deg = f64::to_degrees;
    assert!(
        close(s.rates_deg_s, [deg(-0.05), deg(0.01), deg(0.2)], 1e-4),
        "{s:?}"
    );
    // The other order pairs too; halves of different frames do not.
    assert_eq!(
        d.decode(&f1_motion_ex(12.6, 701, [0.0; 3])).reading,
        Ok(Reading::Ignored)
    );
    assert_eq!(
        d.decode(&f1_motion(12.7, 702, [0.0; 3])).reading,
        Ok(Reading::Ignored)
    );
    let pair = sample_of(&d.decode(&f1_motion_ex(12.7, 702, [0.0; 3])));
    assert_eq!(pair.t, Some(f64::from(12.7f32)));
    // Paused, the game sends its last frame again: idle, not a sample older than the last.
    d.decode(&f1_motion(12.7, 702, [0.0; 3]));
    assert_eq!(
        d.decode(&f1_motion_ex(12.7, 702, [0.0; 3])).reading,
        Ok(Reading::Idle)
    );
    // Other packets (a Car Telemetry, id 6) are nothing to use, and no error.
    let telemetry = d.decode(&f1(1352, 2024, 6, 12.8, 703, 5));
    assert_eq!(telemetry.format, Some(VehicleFormat::F1));
    assert_eq!(telemetry.reading, Ok(Reading::Ignored));
}

#[test]
fn every_format_has_its_place_in_the_list() {
    for (k, format) in VehicleFormat::ALL.iter().enumerate() {
        assert_eq!(format.index(), k);
    }
    // Exhaustive: a new format fails to build here until it is listed, and then fails
    // until `ALL` holds it (the tally counts by its place there).
    let listed = |format: VehicleFormat| match format {
        VehicleFormat::Text
        | VehicleFormat::Binary
        | VehicleFormat::XPlaneData
        | VehicleFormat::XPlaneRref
        | VehicleFormat::ForzaSled
        | VehicleFormat::ForzaDash
        | VehicleFormat::ForzaHorizon
        | VehicleFormat::ForzaMotorsport2023
        | VehicleFormat::F1
        | VehicleFormat::BeamNg
        | VehicleFormat::OutGauge
        | VehicleFormat::OutSim
        | VehicleFormat::OutSimPack => VehicleFormat::ALL.contains(&format),
    };
    assert!(VehicleFormat::ALL.iter().all(|&f| listed(f)));
    let last = VehicleFormat::OutSimPack;
    assert!(listed(last) && last.index() + 1 == VehicleFormat::ALL.len());
}

#[test]
fn f1_25_packets_pair_as_f1_24_ones_and_a_spectator_is_idle() {
    let year = |mut p: Vec<u8>| {
        p[..2].copy_from_slice(&2025u16.to_le_bytes());
        p
    };
    let mut d = VehicleDecoder::new();
    let motion = year(f1_motion(3.0, 9, [0.5, -1.2, 0.1]));
    let mut ex = year(f1_motion_ex(3.0, 9, [0.01, 0.2, -0.05]));
    // The 2025 Motion Ex is 273 bytes; the 2024 length is refused in the 2025 format.
    assert!(matches!(
        d.decode(&ex).reading,
        Err(VehicleError::Length { got: 237, .. })
    ));
    ex.resize(273, 0);
    assert_eq!(d.decode(&motion).reading, Ok(Reading::Ignored));
    let s = sample_of(&d.decode(&ex));
    assert!(
        close(
            s.accel,
            [-1.2 * GRAVITY, 0.5 * GRAVITY, 0.1 * GRAVITY],
            1e-5
        ),
        "{s:?}"
    );
    let mut spectating = year(f1_motion(3.1, 10, [0.0; 3]));
    spectating[27] = 255;
    assert_eq!(d.decode(&spectating).reading, Ok(Reading::Idle));
    // Another year names the setting to change.
    let old = f1(1349, 2023, 0, 1.0, 1, 0);
    let said = d
        .decode(&old)
        .reading
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert!(
        said.contains("UDP Format") && said.contains("2025"),
        "{said}"
    );
}

#[test]
fn f1_packets_of_other_years_lengths_or_cars_are_refused() {
    let mut d = VehicleDecoder::new();
    let old = f1(1349, 2023, 0, 1.0, 1, 0);
    assert_eq!(d.decode(&old).reading, Err(VehicleError::F1Format(2023)));
    let short = f1(1300, 2024, 0, 1.0, 1, 0);
    assert!(matches!(
        d.decode(&short).reading,
        Err(VehicleError::Length {
            format: VehicleFormat::F1,
            got: 1300,
            ..
        })
    ));
    let nobody = f1(1349, 2024, 0, 1.0, 1, 22);
    assert_eq!(d.decode(&nobody).reading, Err(VehicleError::F1Car(22)));
    let mut nan = f1_motion(1.0, 2, [0.0; 3]);
    put_f32(&mut nan, 29 + 60 * 5 + 40, f32::NAN);
    assert_eq!(d.decode(&nan).reading, Ok(Reading::Ignored));
    assert!(matches!(
        d.decode(&f1_motion_ex(1.0, 2, [0.0; 3])).reading,
        Err(VehicleError::Value { name: "ax", .. })
    ));
}

#[test]
fn beamng_motion_sim_becomes_our_axes_and_outgauge_is_told_apart() {
    let mut p = packet(88, b"BNG1");
    put_f32s(&mut p, 4, &[100.0, 200.0, 3.0]); // position, not read
    put_f32s(&mut p, 28, &[1.5, -4.0, 0.25]); // accX (right), accY (forward), accZ (up)
    put_f32s(&mut p, 64, &[0.1, 0.2, 0.3]); // roll, pitch, yaw rates (as the car gives them)
    let mut d = VehicleDecoder::new();
    let decoded = d.decode(&p);
    assert_eq!(decoded.format, Some(VehicleFormat::BeamNg));
    let s = sample_of(&decoded);
    assert_eq!(s.t, None);
    assert!(close(s.accel, [-4.0, -1.5, 0.25], 1e-6), "{s:?}");
    let deg = f64::to_degrees;
    assert!(close(s.rates_deg_s, [deg(0.1), -deg(0.2), -deg(0.3)], 1e-4));
    assert!(matches!(
        d.decode(&p[..87]).reading,
        Err(VehicleError::Length {
            format: VehicleFormat::BeamNg,
            ..
        })
    ));
    for len in [92, 96] {
        let mut gauge = packet(len, &[]);
        gauge[4..8].copy_from_slice(b"beam");
        let decoded = d.decode(&gauge);
        assert_eq!(decoded.format, Some(VehicleFormat::OutGauge));
        assert_eq!(decoded.reading, Ok(Reading::Ignored));
    }
}

#[test]
fn outsim_world_vectors_are_turned_into_the_car() {
    // Heading +90° (anticlockwise from above): the car faces world −X and its right (X)
    // has turned to world +Y. Speeding up along −X at 2 m/s², sliding towards world −Y
    // (its left) at 1 m/s², yawing anticlockwise (left) at 0.3 rad/s about world Z.
    let heading = std::f32::consts::FRAC_PI_2;
    for (len, magic, base) in [
        (64, &b""[..], 0),
        (68, &b""[..], 0),
        (272, &b"LFST"[..], 8),
        (280, &b"LFST"[..], 8),
    ] {
        let mut p = packet(len, magic);
        put_u32(&mut p, base, 4321); // Time, ms
        put_f32s(&mut p, base + 4, &[0.0, 0.0, 0.3]); // AngVel (world)
        put_f32s(&mut p, base + 16, &[heading, 0.0, 0.0]); // Heading, Pitch, Roll
        put_f32s(&mut p, base + 28, &[-2.0, -1.0, 0.0]); // Accel (world)
        let decoded = VehicleDecoder::new().decode(&p);
        let format = if magic.is_empty() {
            VehicleFormat::OutSim
        } else {
            VehicleFormat::OutSimPack
        };
        assert_eq!(decoded.format, Some(format), "{len}");
        let s = sample_of(&decoded);
        assert_eq!(s.t, Some(0.0)); // the first reading of its clock
        assert!(close(s.accel, [2.0, 1.0, 0.0], 1e-6), "{len}: {s:?}");
        assert!(close(s.rates_deg_s, [0.0, 0.0, 0.3f64.to_degrees()], 1e-4));
    }
    let mut odd = packet(100, b"LFST");
    odd[99] = 1;
    assert!(matches!(
        VehicleDecoder::new().decode(&odd).reading,
        Err(VehicleError::Length {
            format: VehicleFormat::OutSimPack,
            ..
        })
    ));
}

#[test]
fn the_car_frame_is_the_inverse_of_heading_then_pitch_then_roll() {
    // Build the car's axes in the world by turning them (roll about Y, then pitch about X,
    // then heading about Z — the rotation Rz Rx Ry applied to each axis) and check that
    // each comes back as its own unit vector.
    let (h, p, r) = (0.7f64, -0.3f64, 0.45f64);
    let turn = |v: [f64; 3]| {
        let [x, y, z] = v;
        let [x, z] = [r.cos() * x + r.sin() * z, -r.sin() * x + r.cos() * z];
        let [y, z] = [p.cos() * y - p.sin() * z, p.sin() * y + p.cos() * z];
        [h.cos() * x - h.sin() * y, h.sin() * x + h.cos() * y, z]
    };
    for (k, axis) in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]
        .into_iter()
        .enumerate()
    {
        let back = outsim::car_frame(turn(axis), h, p, r);
        assert!(close(back, axis, 1e-12), "{k}: {back:?}");
    }
}

#[test]
fn malformed_datagrams_are_refused_with_the_reason() {
    assert!(matches!(decode(b"1,2,3"), Err(VehicleError::Text(_))));
    assert!(matches!(
        decode(b"1,2,3,4,5,6,x"),
        Err(VehicleError::Text(_))
    ));
    assert!(matches!(
        decode(b"1,NaN,0,0,0,0,0"),
        Err(VehicleError::Value { name: "ax", .. })
    ));
    assert!(matches!(
        decode(b"1,0,0,0,0,0,1e300"),
        Err(VehicleError::Value { name: "wz", .. })
    ));
    assert!(matches!(
        decode(b"DATA*123"),
        Err(VehicleError::Length {
            format: VehicleFormat::XPlaneData,
            got: 8,
            ..
        })
    ));
    let only_header = &xplane_datagram([1.0, 0.0, 0.0], [0.0; 3])[..5];
    assert!(matches!(
        decode(only_header),
        Err(VehicleError::XPlaneMissing("DATA", _))
    ));
    assert_eq!(decode(&[0xff, 0x00, 0x13]), Err(VehicleError::Unknown(3)));
    let nan: Vec<u8> = [0.0f32, f32::NAN, 0.0, 0.0, 0.0, 0.0, 0.0]
        .iter()
        .flat_map(|v| v.to_le_bytes())
        .collect();
    assert!(matches!(
        decode(&nan),
        Err(VehicleError::Value { name: "ax", .. })
    ));
    let mut inf = forza(331, 1, [0.0; 3], [0.0; 3], [0.0; 3]);
    put_f32(&mut inf, 52, f32::INFINITY);
    assert!(matches!(
        decode(&inf),
        Err(VehicleError::Value { name: "wx", .. })
    ));
}

/// Magics and lengths that steer the decoder into each format.
fn steered(selector: u8, mut body: Vec<u8>) -> Vec<u8> {
    let heads: [&[u8]; 6] = [
        &b"DATA*"[..],
        &b"RREF,"[..],
        &b"BNG1"[..],
        &b"LFST"[..],
        &[0xe8, 0x07],
        &[1, 0, 0, 0],
    ];
    let lengths = [
        28, 64, 68, 88, 92, 96, 232, 237, 272, 280, 311, 324, 331, 1349,
    ];
    let head = heads[usize::from(selector) % heads.len()];
    if selector & 0x80 != 0 {
        body.resize(lengths[usize::from(selector) % lengths.len()], 0);
    }
    let n = head.len().min(body.len());
    body[..n].copy_from_slice(&head[..n]);
    body
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Any bytes: a format or none, a reading or a refusal — never a panic, and no sample
    /// with a number that is not finite.
    #[test]
    fn any_bytes_decode_without_a_panic(selector in any::<u8>(), body in proptest::collection::vec(any::<u8>(), 0..1500)) {
        let mut d = VehicleDecoder::new();
        for bytes in [body.clone(), steered(selector, body)] {
            let decoded = d.decode(&bytes);
            if let Ok(Reading::Sample(s)) = decoded.reading {
                let numbers = s.accel.iter().chain(&s.rates_deg_s).chain(s.t.as_ref());
                prop_assert!(numbers.into_iter().all(|v| v.is_finite()));
            }
        }
    }
}
