//! The decoders against datagrams the games themselves sent (`../shared/real-telemetry/`,
//! read in place: its README says where each came from), each checked against its own
//! physics — in a steady turn `ay = wz·vx`, a car parked on a slope reads `a ≈ 0`, a car
//! in free fall `|a| ≈ g`, and along a drive `a = dv/dt + ω × v` — rather than against the
//! layouts we read them by.
//!
//! The recordings live beside the repository, not in it. Where they are absent (a clone
//! on its own) these tests say so on standard error and pass; `STEWART_REAL_TELEMETRY`
//! names another folder holding them.

use std::path::PathBuf;

use stewart_link::vehicle::capture;
use stewart_link::vehicle::intake::{Intake, Intaken};
use stewart_link::vehicle::replay::replay;
use stewart_link::vehicle::timeline::PushOutcome;
use stewart_link::vehicle::{
    GRAVITY, Reading, VehicleDecoder, VehicleError, VehicleFormat, VehicleSample,
};

/// The folder of the recordings, when it is there.
fn folder() -> Option<PathBuf> {
    let folder = std::env::var_os("STEWART_REAL_TELEMETRY")
        .map(PathBuf::from)
        .unwrap_or_else(|| {
            PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared/real-telemetry")
        });
    if folder.join("README.md").is_file() {
        Some(folder)
    } else {
        eprintln!(
            "real telemetry not found at {}: these checks were not run",
            folder.display()
        );
        None
    }
}

/// The bytes of a recording (`None`: the folder is absent).
fn real(path: &str) -> Option<Vec<u8>> {
    let file = folder()?.join(path);
    Some(std::fs::read(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display())))
}

fn sample(reading: &Result<Reading, VehicleError>) -> VehicleSample {
    match reading {
        Ok(Reading::Sample(s)) => *s,
        other => panic!("not a sample: {other:?}"),
    }
}

fn f32_at(bytes: &[u8], at: usize) -> f64 {
    f64::from(f32::from_le_bytes([
        bytes[at],
        bytes[at + 1],
        bytes[at + 2],
        bytes[at + 3],
    ]))
}

fn norm(v: [f64; 3]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// A BeamNG MotionSim packet and its speed (the world velocity at byte 16).
fn beamng(name: &str) -> Option<(VehicleSample, f64)> {
    let bytes = real(&format!("beamng/beamng_motionsim_{name}.bin"))?;
    let decoded = VehicleDecoder::new().decode(&bytes);
    assert_eq!(decoded.format, Some(VehicleFormat::BeamNg));
    let speed = norm([16, 20, 24].map(|at| f32_at(&bytes, at)));
    Some((sample(&decoded.reading), speed))
}

#[test]
fn beamng_turning_right_reads_a_right_yaw_and_a_push_to_the_right() {
    let Some((s, speed)) = beamng("horizontal") else {
        return;
    };
    // Turning right at 13.2 m/s: the acceleration is to the right (ay < 0), the yaw to the
    // right (wz < 0), and a steady turn has ay = wz·vx in any right-handed frame.
    let wz = s.rates_deg_s[2].to_radians();
    assert!(s.accel[1] < -7.0 && wz < -0.5, "{s:?}");
    let centripetal = wz * speed;
    assert!(
        (s.accel[1] - centripetal).abs() < 0.1 * centripetal.abs(),
        "ay {} against wz·v {centripetal}",
        s.accel[1]
    );
}

#[test]
fn beamng_braking_pitches_the_nose_down_and_parked_cars_feel_nothing() {
    let Some((braking, _)) = beamng("forward") else {
        return;
    };
    // Braking at 1.1 g: ax < 0, and the nose going down is a positive rate about our y
    // (left).
    assert!(braking.accel[0] < -10.0, "{braking:?}");
    assert!(braking.rates_deg_s[1] > 2.0, "{braking:?}");
    // Parked on slopes of 52° and 28°: gravity is not in the acceleration.
    for name in ["pitch", "roll"] {
        let Some((parked, speed)) = beamng(name) else {
            return;
        };
        assert!(
            speed < 0.01 && norm(parked.accel) < 0.05,
            "{name}: {parked:?}"
        );
    }
    // Falling freely: the kinematic acceleration is gravity's.
    let Some((falling, _)) = beamng("vertical") else {
        return;
    };
    assert!(
        (norm(falling.accel) - GRAVITY).abs() < 0.5,
        "{falling:?}: |a| = {}",
        norm(falling.accel)
    );
}

#[test]
fn beamngs_loopback_capture_gives_the_five_packets() {
    let Some(bytes) = real("beamng/beamng_motionsim_loopback_all5.pcap") else {
        return;
    };
    let capture = capture::read(bytes.as_slice()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(capture.datagrams.len(), 5);
    let r = replay(&capture.datagrams, None, Intake::STALL_S);
    assert_eq!(r.port, Some(4444));
    assert_eq!(r.samples.len(), 5);
    // Clockless: each at its capture time, 0.1 s apart.
    for (k, (timed, _)) in r.samples.iter().enumerate() {
        assert!((timed.t - 0.1 * k as f64).abs() < 1e-9, "{k}: {}", timed.t);
    }
    let Some((horizontal, _)) = beamng("horizontal") else {
        return;
    };
    assert!(r.samples.iter().any(|(t, _)| t.sample == horizontal));
}

/// The FH5 recording's 600 datagrams of 324 bytes.
fn fh5() -> Option<Vec<Vec<u8>>> {
    let bytes = real("forza/fh5_debugpacketstream.bin")?;
    assert_eq!(bytes.len(), 600 * 324);
    Some(bytes.chunks(324).map(<[u8]>::to_vec).collect())
}

#[test]
fn every_forza_horizon_datagram_with_new_motion_is_kept() {
    let Some(datagrams) = fh5() else {
        return;
    };
    let mut intake = Intake::default();
    let mut times = Vec::new();
    for (k, d) in datagrams.iter().enumerate() {
        let (format, what, placed) = intake.take(d, k as f64 / 80.0);
        assert_eq!(format, Some(VehicleFormat::ForzaHorizon));
        assert!(
            matches!(
                what,
                Intaken::Sample(PushOutcome::Placed | PushOutcome::Held)
            ),
            "{k}: {what:?}"
        );
        times.extend(placed.iter().map(|p| p.t));
    }
    intake.finish();
    let tally = intake.tally();
    // 127 repeat the stamp before with new motion: none is dropped, none is a repeat.
    assert_eq!((tally.placed, tally.repeats, tally.stale), (600, 0, 0));
    assert_eq!(tally.unplaced, 0);
    assert!(times.windows(2).all(|w| w[1] > w[0]), "times go forward");
    // The capture of the same datagrams gives the same samples.
    let Some(pcap) = real("forza/fh5_debugpacketstream.pcap") else {
        return;
    };
    let capture = capture::read(pcap.as_slice()).unwrap_or_else(|e| panic!("{e}"));
    let r = replay(&capture.datagrams, None, Intake::STALL_S);
    assert_eq!(r.samples.len(), 600);
    for (k, ((timed, packet), t)) in r.samples.iter().zip(&times).enumerate() {
        assert_eq!(timed.t, *t, "{k}");
        assert_eq!(*packet, k + 1);
    }
}

#[test]
fn forza_horizons_motion_obeys_its_own_velocity() {
    // Along the drive a = dv/dt + ω × v in the car's frame. With the decoded acceleration
    // and rates (ours) and the game's velocity turned into our axes the same way, the
    // residual is far smaller than with the rates reversed, and smaller with the repeated
    // stamps placed between their neighbours than at their stamps.
    let Some(datagrams) = fh5() else {
        return;
    };
    let mut intake = Intake::default();
    let mut rows = Vec::new();
    let mut pending = Vec::new();
    for d in &datagrams {
        let [vx_right, vy_up, vz_forward] = [32, 36, 40].map(|at| f32_at(d, at));
        let stamp = f64::from(u32::from_le_bytes([d[4], d[5], d[6], d[7]])) / 1000.0;
        pending.push(([vz_forward, -vx_right, vy_up], stamp));
        let (_, _, placed) = intake.take(d, 0.0);
        for timed in placed.iter() {
            let (v, stamp) = pending.remove(0);
            rows.push((timed.t, stamp, timed.sample, v));
        }
    }
    let residual = |reverse: bool, at_stamp: bool| {
        let mut r: Vec<f64> = (1..rows.len() - 1)
            .filter_map(|k| {
                let time = |j: usize| if at_stamp { rows[j].1 } else { rows[j].0 };
                let dt = time(k + 1) - time(k - 1);
                if dt <= 0.0 {
                    return None;
                }
                let (_, _, s, v) = rows[k];
                let dv: [f64; 3] =
                    std::array::from_fn(|i| (rows[k + 1].3[i] - rows[k - 1].3[i]) / dt);
                let sign = if reverse { -1.0 } else { 1.0 };
                let w = s.rates_deg_s.map(|r| sign * r.to_radians());
                let wv = cross(w, v);
                Some(norm(std::array::from_fn(|i| s.accel[i] - dv[i] - wv[i])))
            })
            .collect();
        r.sort_by(f64::total_cmp);
        r[r.len() / 2]
    };
    let (ours, reversed, at_stamps) = (
        residual(false, false),
        residual(true, false),
        residual(false, true),
    );
    assert!(
        ours < 0.3 * reversed,
        "median residual {ours} against {reversed} reversed"
    );
    assert!(
        ours < 0.8 * at_stamps,
        "median residual {ours} against {at_stamps} at the stamps"
    );
}

#[test]
fn forza_motorsport_accelerating_reads_forwards_without_gravity() {
    for path in [
        "forza/fm2023_issue_sled232.bin",
        "forza/fm2023_issue_317_of_331_bytes.bin",
    ] {
        let Some(mut bytes) = real(path) else {
            return;
        };
        // The 317 bytes that survive, padded to the 331 of the form.
        bytes.resize(if bytes.len() > 232 { 331 } else { 232 }, 0);
        let s = sample(&VehicleDecoder::new().decode(&bytes).reading);
        // AccelerationZ +8.08 forward at 13.5 m/s, AccelerationY −0.18: no gravity.
        assert!((s.accel[0] - 8.08).abs() < 0.01, "{path}: {s:?}");
        assert!(s.accel[2].abs() < 0.5, "{path}: {s:?}");
    }
}

/// The F1 recording's Motion packets' cars: position, forward and right (world), speed
/// and lateral g.
fn f1_cars(bytes: &[u8]) -> Vec<([f64; 3], [f64; 3], f64, f64)> {
    (0..22)
        .map(|k| {
            let at = 29 + 60 * k;
            let unit = |from: usize| -> [f64; 3] {
                std::array::from_fn(|i| {
                    let o = from + 2 * i;
                    f64::from(i16::from_le_bytes([bytes[o], bytes[o + 1]])) / 32767.0
                })
            };
            let p = [0, 4, 8].map(|o| f32_at(bytes, at + o));
            let v = [12, 16, 20].map(|o| f32_at(bytes, at + o));
            let forward = unit(at + 24);
            (p, forward, norm(v), f32_at(bytes, at + 36))
        })
        .collect()
}

#[test]
fn f1_lateral_g_is_positive_to_the_left_by_the_tracks_own_curvature() {
    let Some(bytes) = real("f1/f1_2024_motion_1.bin") else {
        return;
    };
    // The world is right-handed with Y up: each car's right is its forward × up (the 20
    // cars of the session; the last two blocks are empty).
    for k in 0..20 {
        let at = 29 + 60 * k + 24;
        let read = |o: usize| f64::from(i16::from_le_bytes([bytes[o], bytes[o + 1]])) / 32767.0;
        let (f, r) = (
            [read(at), read(at + 2), read(at + 4)],
            [read(at + 6), read(at + 8), read(at + 10)],
        );
        let f_up = cross(f, [0.0, 1.0, 0.0]);
        let along = (0..3).map(|i| f_up[i] * r[i]).sum::<f64>() / norm(f_up);
        assert!(along > 0.95, "car {k}: {f:?} × up against {r:?}");
    }
    // A car with another just ahead on its line (within 2 m sideways, 2 to 50 m ahead):
    // the road's turn between them, v²κ (κ > 0 turning left about +Y), has the sign of
    // the lateral g.
    let cars = f1_cars(&bytes);
    let mut checked = 0;
    for (a, (p, f, speed, lateral)) in cars.iter().enumerate() {
        let right = cross(*f, [0.0, 1.0, 0.0]);
        let ahead = cars
            .iter()
            .enumerate()
            .filter(|(b, _)| *b != a)
            .find_map(|(_, (q, g, ..))| {
                let d: [f64; 3] = std::array::from_fn(|i| q[i] - p[i]);
                let along = d[0] * f[0] + d[2] * f[2];
                let aside = d[0] * right[0] + d[2] * right[2];
                ((2.0..50.0).contains(&along) && aside.abs() < 2.0)
                    .then(|| (along, cross(*f, *g)[1]))
            });
        let Some((along, turn)) = ahead else { continue };
        let centripetal_g = speed * speed * turn / along / GRAVITY;
        if centripetal_g.abs() < 0.05 || lateral.abs() < 0.05 {
            continue;
        }
        assert!(
            centripetal_g * lateral > 0.0,
            "car {a}: v²κ {centripetal_g} g, lateral {lateral} g"
        );
        checked += 1;
    }
    assert!(checked >= 3, "{checked} cars checked");
}

#[test]
fn f1_24s_joined_pair_is_one_sample_and_real_halves_of_two_frames_none() {
    let Some(joined) = real("f1/f1_2024_joined_pair.pcap") else {
        return;
    };
    let capture = capture::read(joined.as_slice()).unwrap_or_else(|e| panic!("{e}"));
    let r = replay(&capture.datagrams, None, Intake::STALL_S);
    assert_eq!(r.samples.len(), 1);
    let s = r.samples[0].0.sample;
    // The player's car 19: lateral −1.221 g (to the right), longitudinal +0.543 g.
    assert!((s.accel[1] + 1.221 * GRAVITY).abs() < 0.01, "{s:?}");
    assert!((s.accel[0] - 0.543 * GRAVITY).abs() < 0.01, "{s:?}");
    assert!((s.t.unwrap_or_default() - 129.6377).abs() < 1e-3, "{s:?}");
    let Some(unpaired) = real("f1/f1_2024_real_unpaired.pcap") else {
        return;
    };
    let capture = capture::read(unpaired.as_slice()).unwrap_or_else(|e| panic!("{e}"));
    let r = replay(&capture.datagrams, None, Intake::STALL_S);
    assert!(r.samples.is_empty());
    assert_eq!((r.tally.of(VehicleFormat::F1), r.tally.refused), (2, 0));
}

#[test]
fn f1_25s_packets_are_read_and_other_years_refused_naming_the_setting() {
    let Some(motion) = real("f1/f1_2025_motion_1.bin") else {
        return;
    };
    let Some(ex) = real("f1/f1_2025_motionEx_1.bin") else {
        return;
    };
    let mut d = VehicleDecoder::new();
    // A spectator's Motion (player car 255): the game at rest for us, not an error.
    assert_eq!(d.decode(&motion).reading, Ok(Reading::Idle));
    // The 273-byte Motion Ex of 2025: read (the first half of a pair).
    let decoded = d.decode(&ex);
    assert_eq!(
        (decoded.format, decoded.reading),
        (Some(VehicleFormat::F1), Ok(Reading::Ignored))
    );
    let Some(others) = real("f1/f1_2022_2023_2025_motion.pcap") else {
        return;
    };
    let capture = capture::read(others.as_slice()).unwrap_or_else(|e| panic!("{e}"));
    let mut d = VehicleDecoder::new();
    let mut refused = Vec::new();
    for datagram in &capture.datagrams {
        if let Err(e) = d.decode(&datagram.payload).reading {
            refused.push(e.to_string());
        }
    }
    // 2022's Motion, 2023's Motion and two Motion Ex: refused; 2025's (a spectator's) not.
    assert_eq!(refused.len(), 4, "{refused:?}");
    for said in &refused {
        assert!(
            said.contains("UDP Format") && said.contains("2025"),
            "{said}"
        );
    }
    for year in ["2022", "2023"] {
        let Some(bytes) = real(&format!("f1/f1_{year}_motion_1.bin")) else {
            return;
        };
        let year: u16 = year.parse().unwrap_or_default();
        assert_eq!(
            VehicleDecoder::new().decode(&bytes).reading,
            Err(VehicleError::F1Format(year))
        );
    }
}
