//! `stewart cue --input capture.pcap`: a braking-and-turning manoeuvre sent by each game
//! (its packets built here field by field from the game's published layout), captured as
//! tcpdump writes it, gives the poses `stewart cue` gives for the same motion as CSV.

use crate::{parse_csv, stderr, stewart, tempdir, write};

/// Standard gravity, m/s² (the g-load formats).
const G: f64 = 9.80665;

/// The manoeuvre at sample `k` of 60 a second, in the formats' own numbers: braking
/// (forward acceleration, m/s² and g), sliding left (m/s² and g) and turning left
/// (rad/s and °/s), each exactly an `f32`.
pub(crate) struct Moment {
    pub(crate) forward: f32,
    pub(crate) left: f32,
    pub(crate) yaw_rad: f32,
    pub(crate) forward_g: f32,
    pub(crate) left_g: f32,
    pub(crate) yaw_deg: f32,
}

pub(crate) fn moment(k: usize) -> Moment {
    let braking = (60..180).contains(&k);
    let turning = (120..240).contains(&k);
    let pick = |on: bool, v: f32| if on { v } else { 0.0 };
    Moment {
        forward: pick(braking, -6.0),
        left: pick(turning, 3.0),
        yaw_rad: pick(turning, 0.375),
        forward_g: pick(braking, -0.5),
        left_g: pick(turning, 0.25),
        yaw_deg: pick(turning, 20.0),
    }
}

const SAMPLES: usize = 300;

/// A little-endian packet being laid out.
struct Packet(Vec<u8>);

impl Packet {
    fn new(len: usize, magic: &[u8]) -> Self {
        let mut p = vec![0; len];
        p[..magic.len()].copy_from_slice(magic);
        Self(p)
    }
    fn f32(mut self, at: usize, values: &[f32]) -> Self {
        for (k, v) in values.iter().enumerate() {
            self.0[at + 4 * k..at + 4 * k + 4].copy_from_slice(&v.to_le_bytes());
        }
        self
    }
    fn u32(mut self, at: usize, v: u32) -> Self {
        self.0[at..at + 4].copy_from_slice(&v.to_le_bytes());
        self
    }
    fn bytes(mut self, at: usize, b: &[u8]) -> Self {
        self.0[at..at + b.len()].copy_from_slice(b);
        self
    }
}

/// Milliseconds of sample `k` at 60 a second.
pub(crate) fn ms(k: usize) -> u32 {
    ((k as f64) * 1000.0 / 60.0).round() as u32
}

/// Forza Horizon (324 bytes): IsRaceOn, TimestampMS, AccelerationX (right), Y, Z
/// (forward), AngularVelocityX (pitch), Y (yaw, left-handed: a left turn is negative), Z.
pub(crate) fn forza(k: usize) -> Vec<Vec<u8>> {
    let m = moment(k);
    let p = Packet::new(324, &[])
        .u32(0, 1)
        .u32(4, 5_000 + ms(k))
        .f32(20, &[-m.left, 0.0, m.forward])
        .f32(44, &[0.0, -m.yaw_rad, 0.0]);
    vec![p.0]
}

/// F1 24: `Motion` (player car 3's g-forces lateral, longitudinal, vertical) and
/// `Motion Ex` (angular velocity X pitch, Y yaw, Z roll) of frame `k`.
fn f1(k: usize) -> Vec<Vec<u8>> {
    let m = moment(k);
    let time = k as f32 / 60.0;
    let header = |len, id: u8| {
        Packet::new(len, &2024u16.to_le_bytes())
            .bytes(2, &[24, 1, 5, 1, id])
            .bytes(7, &77u64.to_le_bytes())
            .f32(15, &[time])
            .u32(19, k as u32)
            .u32(23, k as u32)
            .bytes(27, &[3, 255])
    };
    let motion = header(1349, 0).f32(29 + 3 * 60 + 36, &[m.left_g, m.forward_g, 0.0]);
    let ex = header(237, 13).f32(173, &[0.0, m.yaw_rad, 0.0]);
    vec![motion.0, ex.0]
}

/// BeamNG MotionSim (88 bytes): `BNG1`, accX (right), accY (forward), accZ at 28; roll,
/// pitch, yaw rates at 64 (as the car gives them: yaw positive to the left).
fn beamng(k: usize) -> Vec<Vec<u8>> {
    let m = moment(k);
    let p = Packet::new(88, b"BNG1")
        .f32(28, &[-m.left, m.forward, 0.0])
        .f32(64, &[0.0, 0.0, -m.yaw_rad]); // yawRate: positive turning right
    vec![p.0]
}

/// Live for Speed OutSim (64 bytes), the car at heading 0 (world = car: X right, Y
/// forward, Z up): Time, AngVel, Heading/Pitch/Roll, Accel.
fn outsim(k: usize) -> Vec<Vec<u8>> {
    let m = moment(k);
    let p = Packet::new(64, &[])
        .u32(0, 90_000 + ms(k))
        .f32(4, &[0.0, 0.0, m.yaw_rad])
        .f32(28, &[-m.left, m.forward, 0.0]);
    vec![p.0]
}

/// An X-Plane `RREF` reply: indices 0–5 are g_nrml, g_axil, g_side (g; axial positive
/// backwards, side positive to the right) and P, Q, R (°/s; R positive to the right).
fn xplane(k: usize) -> Vec<Vec<u8>> {
    let m = moment(k);
    let mut p = b"RREF,".to_vec();
    for (index, value) in [1.0, -m.forward_g, -m.left_g, 0.0, 0.0, -m.yaw_deg]
        .into_iter()
        .enumerate()
    {
        p.extend((index as i32).to_le_bytes());
        p.extend(value.to_le_bytes());
    }
    vec![p]
}

/// The units a format carries its motion in.
#[derive(Clone, Copy)]
enum Units {
    /// m/s² and rad/s.
    Si,
    /// g and rad/s.
    GRad,
    /// g and °/s.
    GDeg,
}

/// The same motion as the studio's CSV: `t` from the format's clock (or the capture
/// time, for formats without one), in our axes and units.
fn csv(time: impl Fn(usize) -> f64, units: Units) -> String {
    let mut text = String::from("t,ax,ay,az,wx,wy,wz\n");
    for k in 0..SAMPLES {
        let m = moment(k);
        let (ax, ay) = match units {
            Units::Si => (f64::from(m.forward), f64::from(m.left)),
            Units::GRad | Units::GDeg => (G * f64::from(m.forward_g), G * f64::from(m.left_g)),
        };
        let wz = match units {
            Units::Si | Units::GRad => f64::from(m.yaw_rad).to_degrees(),
            Units::GDeg => f64::from(m.yaw_deg),
        };
        text.push_str(&format!("{},{ax},{ay},0,0,0,{wz}\n", time(k)));
    }
    text
}

/// A legacy pcap (Ethernet, microseconds) of UDP datagrams to `port`, sample `k`'s sent
/// at 1000.5 s + k/60 (µs).
fn pcap(port: u16, datagrams: impl Fn(usize) -> Vec<Vec<u8>>) -> Vec<u8> {
    pcap_to_ports(|k| datagrams(k).into_iter().map(|d| (port, d)).collect())
}

/// [`pcap`] of datagrams each to its own port.
pub(crate) fn pcap_to_ports(datagrams: impl Fn(usize) -> Vec<(u16, Vec<u8>)>) -> Vec<u8> {
    let mut out = Vec::new();
    for word in [0xa1b2_c3d4u32, 0x0004_0002, 0, 0, 65535, 1] {
        out.extend(word.to_le_bytes());
    }
    for k in 0..SAMPLES {
        let usec = 500_000 + (k as u64 * 1_000_000).div_ceil(60);
        for (port, payload) in datagrams(k) {
            let frame = ethernet_udp(port, &payload);
            out.extend(((1000 + usec / 1_000_000) as u32).to_le_bytes());
            out.extend(((usec % 1_000_000) as u32).to_le_bytes());
            out.extend((frame.len() as u32).to_le_bytes());
            out.extend((frame.len() as u32).to_le_bytes());
            out.extend(frame);
        }
    }
    out
}

/// The capture time of sample `k`, seconds after the first.
fn captured_at(k: usize) -> f64 {
    let usec = 500_000 + (k as u64 * 1_000_000).div_ceil(60);
    (1000.0 + usec as f64 * 1e-6) - 1000.5
}

/// An Ethernet II frame holding an IPv4 header (no options) and a UDP header around
/// `payload`, as the RFCs lay them out (checksums left 0: "not computed" for UDP).
pub(crate) fn ethernet_udp(port: u16, payload: &[u8]) -> Vec<u8> {
    let mut f = vec![2, 0, 0, 0, 0, 2, 2, 0, 0, 0, 0, 1, 0x08, 0x00];
    let total = (20 + 8 + payload.len()) as u16;
    f.extend([0x45, 0]);
    f.extend(total.to_be_bytes());
    f.extend([0, 1, 0, 0, 64, 17, 0, 0]);
    f.extend([192, 168, 1, 20, 192, 168, 1, 10]);
    f.extend(5300u16.to_be_bytes());
    f.extend(port.to_be_bytes());
    f.extend(((8 + payload.len()) as u16).to_be_bytes());
    f.extend([0, 0]);
    f.extend(payload);
    f
}

/// The datagrams a game sends for sample `k`.
type Sends = fn(usize) -> Vec<Vec<u8>>;

/// The pose table `stewart cue` writes for `input`.
fn cue(input: &str) -> Vec<Vec<f64>> {
    let o = stewart(&["cue", "--preset", "seed", "--input", input]);
    assert_eq!(o.status.code(), Some(0), "{input}: {}", stderr(&o));
    let (_, rows) = parse_csv(&String::from_utf8_lossy(&o.stdout));
    rows
}

#[test]
fn every_games_capture_gives_the_poses_of_the_same_motion_as_csv() {
    let dir = tempdir();
    let game_ms = |offset: u32| move |k: usize| f64::from(offset + ms(k)) / 1000.0;
    let f1_time = |k: usize| f64::from(k as f32 / 60.0);
    let cases: [(&str, u16, Sends, String); 5] = [
        // The games' millisecond clocks count from the first datagram (5 s and 90 s here).
        ("forza", 5300, forza, csv(game_ms(0), Units::Si)),
        ("f1", 20777, f1, csv(f1_time, Units::GRad)),
        ("beamng", 4444, beamng, csv(captured_at, Units::Si)),
        ("outsim", 4123, outsim, csv(game_ms(0), Units::Si)),
        ("xplane", 49001, xplane, csv(captured_at, Units::GDeg)),
    ];
    for (game, port, datagrams, table) in cases {
        let capture = dir.path().join(format!("{game}.pcap"));
        std::fs::write(&capture, pcap(port, datagrams)).unwrap_or_else(|e| panic!("{e}"));
        let table = write(dir.path(), &format!("{game}.csv"), &table);
        let (from_capture, from_table) = (cue(&capture.display().to_string()), cue(&table));
        assert_eq!(from_capture.len(), SAMPLES, "{game}");
        assert_eq!(from_capture.len(), from_table.len(), "{game}");
        let worst = (from_capture.iter().flatten())
            .zip(from_table.iter().flatten())
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(worst <= 1e-9, "{game}: {worst}");
        // The manoeuvre moved the platform (a capture read as nothing would also agree).
        let surge = from_capture.iter().map(|r| r[1].abs()).fold(0.0, f64::max);
        assert!(surge > 0.01, "{game}: {surge}");
    }
}

#[test]
fn a_capture_says_what_it_held_and_one_without_motion_is_refused() {
    let dir = tempdir();
    let capture = dir.path().join("forza.pcap");
    std::fs::write(&capture, pcap(5300, forza)).unwrap_or_else(|e| panic!("{e}"));
    let o = stewart(&[
        "cue",
        "--preset",
        "seed",
        "--input",
        &capture.display().to_string(),
    ]);
    let said = stderr(&o);
    assert!(
        said.contains(
            "300 packets, 300 UDP datagrams; telemetry read from port 5300; 300 Forza Horizon"
        ),
        "{said}"
    );
    // A capture of F1's other packets only (Car Telemetry, id 6): no motion, refused,
    // nothing written.
    let telemetry = |k: usize| {
        let p = Packet::new(1352, &2024u16.to_le_bytes())
            .bytes(6, &[6])
            .u32(19, k as u32);
        vec![p.0]
    };
    let none = dir.path().join("none.pcap");
    std::fs::write(&none, pcap(20777, telemetry)).unwrap_or_else(|e| panic!("{e}"));
    let out = dir.path().join("poses.csv");
    let o = stewart(&[
        "cue",
        "--preset",
        "seed",
        "--input",
        &none.display().to_string(),
        "--out",
        &out.display().to_string(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("no vehicle motion in this capture"),
        "{}",
        stderr(&o)
    );
    assert!(stderr(&o).contains("300 F1 24/25"), "{}", stderr(&o));
    assert!(!out.exists());
    // A file that is neither CSV nor a capture's beginning is a CSV error; a damaged
    // capture names the packet and the byte.
    let mut damaged = pcap(5300, forza);
    damaged.truncate(24 + 10);
    damaged.extend([0xff; 16]);
    let bad = dir.path().join("damaged.pcap");
    std::fs::write(&bad, damaged).unwrap_or_else(|e| panic!("{e}"));
    let o = stewart(&[
        "cue",
        "--preset",
        "seed",
        "--input",
        &bad.display().to_string(),
    ]);
    assert_ne!(o.status.code(), Some(0));
    assert!(stderr(&o).contains("damaged.pcap"), "{}", stderr(&o));
}
