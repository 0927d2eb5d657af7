//! Live motion cueing for the link: vehicle motion arriving as UDP datagrams (the studio's
//! generic text or `f32`, X-Plane, Forza, F1 24 and 25, BeamNG.drive, Live for Speed:
//! `stewart_link::vehicle`) made into the pose the link follows, tick by tick, through the
//! scenario's washout and limiter.
//!
//! Each sample steps the washout at its own time (the sender's clock; X-Plane's, which
//! has none, at its arrival), exactly as `stewart cue` steps a recording, so a recording
//! played live gives the poses `stewart cue` writes for it. A datagram that cannot be
//! read, or a sample older than the last, is counted and dropped. When nothing arrives for
//! `[cueing] stall_s`, or the game says it is in its menus or paused, the input is taken
//! as a vehicle at rest and the cue fades to neutral over `fade_s`; samples that come
//! back fade it in again.

use std::net::UdpSocket;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use anyhow::{Context as _, Result, bail};
use stewart_kinematics::analysis::cueing::{Cueing, VehicleMotion, home_conditioning};
use stewart_kinematics::{Pose, Scenario};
use stewart_link::vehicle::VehicleFormat;
use stewart_link::vehicle::intake::{Intake, Intaken};
use stewart_link::vehicle::timeline::{PushOutcome, Step, Timed};

use crate::vehicle_in::xplane_rref::RrefSubscription;

pub mod measure;
mod planner;

/// The largest datagram read (X-Plane sends up to a few hundred bytes).
const DATAGRAM: usize = 65_536;

/// The most datagrams one tick reads: the work per tick is bounded, so a flood on the
/// port cannot delay the sender's deadlines (what is left waits for the next ticks, or the
/// system drops it when the socket's buffer is full). Reading also stops once a fifth of
/// the tick's period is spent (at least [`MIN_READ_BUDGET`]): 64 a tick is 6 400 samples a
/// second at 100 Hz (640 at the lowest rate, 10 Hz), far above what a simulator sends
/// (X-Plane at most 99 a second, games a few hundred).
pub(crate) const MAX_DATAGRAMS_PER_TICK: usize = 64;

/// The least time a tick may spend reading (the first tick, or very fast ticks).
pub(crate) const MIN_READ_BUDGET: std::time::Duration = std::time::Duration::from_micros(100);

/// Seconds of the trace kept for the viewer's live plots.
pub(crate) const TRACE_S: f64 = 10.0;

/// One sample of the trace: stream time, the vehicle's specific force (m/s²), the one the
/// platform makes felt, and the tilt of roll and pitch (degrees).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct TracePoint {
    /// Stream time, seconds.
    pub(crate) t: f64,
    /// The vehicle's specific force, x, y, z.
    pub(crate) vehicle: [f64; 3],
    /// The specific force the platform makes felt, x, y, z.
    pub(crate) platform: [f64; 3],
    /// Roll and pitch tilt, degrees.
    pub(crate) tilt_deg: [f64; 2],
}

/// What the input brought, for the link's summary and the viewer (shared with the
/// sender's thread).
#[derive(Debug, Default)]
pub(crate) struct CueCounts {
    /// Samples used.
    pub(crate) received: AtomicU64,
    /// Datagrams that could not be read, or came out of order.
    pub(crate) malformed: AtomicU64,
    /// Times the input stalled.
    pub(crate) stalls: AtomicU64,
    /// The last [`TRACE_S`] of samples, oldest first.
    pub(crate) trace: std::sync::Mutex<std::collections::VecDeque<TracePoint>>,
    /// The formats that arrived in the last whole second (`None`: datagrams not
    /// recognised), with their datagrams a second.
    pub(crate) arriving: std::sync::Mutex<Vec<(Option<VehicleFormat>, f64)>>,
}

impl CueCounts {
    /// Samples used, dropped, and stalls so far.
    pub(crate) fn numbers(&self) -> [u64; 3] {
        [&self.received, &self.malformed, &self.stalls].map(|n| n.load(Ordering::Relaxed))
    }

    /// The formats arriving, with their rates: `[(Some(VehicleFormat::F1), 120.0)]`.
    pub(crate) fn arriving(&self) -> Vec<(Option<VehicleFormat>, f64)> {
        self.arriving
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .clone()
    }

    /// One line for the link's summary.
    pub(crate) fn words(&self) -> String {
        format!(
            "cue: {} samples in, {} malformed or out of order dropped, {} stalls",
            self.received.load(Ordering::Relaxed),
            self.malformed.load(Ordering::Relaxed),
            self.stalls.load(Ordering::Relaxed)
        )
    }
}

impl Drop for LiveCue {
    fn drop(&mut self) {
        if let Some(x) = &self.input.xplane {
            x.end(&self.input.socket);
        }
    }
}

/// The last two samples of the input: the straight line through them, extrapolated ahead
/// of the last, and drawn to the next.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Prediction {
    /// The last sample: its time and motion.
    last: Option<(f64, VehicleMotion)>,
    /// The input's rate of change between the last two samples, per second.
    slope: VehicleMotion,
}

impl Prediction {
    /// A sample at `time`.
    fn sampled(&mut self, time: f64, motion: VehicleMotion) {
        self.slope = match self.last {
            Some((before, m)) if time > before => {
                let per = |a: f64, b: f64| (a - b) / (time - before);
                VehicleMotion {
                    accel: std::array::from_fn(|k| per(motion.accel[k], m.accel[k])),
                    rates_deg_s: std::array::from_fn(|k| {
                        per(motion.rates_deg_s[k], m.rates_deg_s[k])
                    }),
                }
            }
            _ => VehicleMotion::default(),
        };
        self.last = Some((time, motion));
    }

    /// The input held over the `ahead` seconds after the last sample: the line's value
    /// half-way (the middle of a line holds its integrals exactly).
    fn midpoint(&self, ahead: f64) -> VehicleMotion {
        let Some((_, m)) = self.last else {
            return VehicleMotion::default();
        };
        let at = |v: f64, s: f64| v + s * 0.5 * ahead;
        VehicleMotion {
            accel: std::array::from_fn(|k| at(m.accel[k], self.slope.accel[k])),
            rates_deg_s: std::array::from_fn(|k| at(m.rates_deg_s[k], self.slope.rates_deg_s[k])),
        }
    }

    /// The input held from the last sample to `next`: their middle.
    fn middle_to(&self, next: &VehicleMotion) -> VehicleMotion {
        let Some((_, m)) = self.last else {
            return *next;
        };
        VehicleMotion {
            accel: std::array::from_fn(|k| 0.5 * (m.accel[k] + next.accel[k])),
            rates_deg_s: std::array::from_fn(|k| 0.5 * (m.rates_deg_s[k] + next.rates_deg_s[k])),
        }
    }
}

/// The live input and the cueing it feeds.
pub struct LiveCue {
    input: UdpInput,
    reported: Reported,
    liveness: Liveness,
    cueing: Cueing,
    /// The pose to follow.
    pose: Pose,
    /// The last two samples, for the look ahead (`None`: `input_prediction_s` is 0).
    prediction: Option<Prediction>,
    /// How far ahead of the last sample a tick looks, seconds.
    prediction_s: f64,
    /// The model-predictive planner's thread (`None` for the washout).
    planner: Option<planner::PlannerThread>,
}

/// Where the vehicle's motion comes in: the socket, its buffer, and what reads the
/// datagrams.
struct UdpInput {
    socket: UdpSocket,
    buffer: Vec<u8>,
    /// Reads the datagrams of every format (pairs F1's halves, unwraps games' clocks) and
    /// places their samples on the time line (restarted after a stall).
    intake: Intake,
    /// X-Plane asked for its datarefs of motion, when it is.
    xplane: Option<RrefSubscription>,
}

/// What is reported of the input: the counts shared with the interface, and the datagrams
/// per format (`None`: not recognised) in this second's window, published as rates each
/// second of stream time.
struct Reported {
    counts: Arc<CueCounts>,
    window: Vec<(Option<VehicleFormat>, u32)>,
    window_start: Option<f64>,
}

/// Whether the input is alive: when it last came, a stall or the game's menus, and how
/// a quiet input fades.
struct Liveness {
    /// Stream time of the last sample used.
    last_arrival: Option<f64>,
    /// Stream time of the last tick.
    last_tick: Option<f64>,
    stalled: bool,
    /// The game says it is in its menus or paused (until its next sample).
    idle: bool,
    /// `stall_s` and `fade_s`.
    stall_s: f64,
    fade_s: f64,
}

impl Reported {
    /// One more datagram of `format` in this second's window.
    fn count_format(&mut self, format: Option<VehicleFormat>) {
        match self.window.iter_mut().find(|(f, _)| *f == format) {
            Some((_, count)) => *count += 1,
            None => self.window.push((format, 1)),
        }
    }

    /// Once a second of stream time has passed, publish the window's rates and start the
    /// next.
    fn publish_rates(&mut self, t: f64) {
        let start = *self.window_start.get_or_insert(t);
        let elapsed = t - start;
        if elapsed < 1.0 {
            return;
        }
        let rates = self
            .window
            .drain(..)
            .map(|(format, n)| (format, f64::from(n) / elapsed))
            .collect();
        *self
            .counts
            .arriving
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner) = rates;
        self.window_start = Some(t);
    }
}

impl LiveCue {
    /// Listen at `source` (`udp:HOST:PORT`) for vehicle motion, cued by `scenario`'s
    /// `[cueing]` table within its limits.
    pub fn bind(source: &str, scenario: &Scenario) -> Result<Self> {
        let Some(address) = source.strip_prefix("udp:") else {
            bail!("--cue takes udp:HOST:PORT (such as udp:0.0.0.0:4123), got `{source}`");
        };
        let mut cueing = Cueing::new(&scenario.geometry, &scenario.limits, &scenario.cueing)
            .and_then(|c| {
                let checks = &scenario.checks;
                home_conditioning(&scenario.geometry, checks, &scenario.cueing).map(|()| c)
            })
            .map_err(|e| anyhow::anyhow!("scenario `{}`: {e}", scenario.name))?;
        // The planner solves on a thread of its own; the tick only follows its plans.
        let planner = match cueing.mpc_mut() {
            Some(follower) => {
                let thread = planner::PlannerThread::start(follower.clone())
                    .context("cannot start the cueing planner's thread")?;
                follower.set_remote(true);
                Some(thread)
            }
            None => None,
        };
        let socket =
            UdpSocket::bind(address).with_context(|| format!("cannot listen at `{address}`"))?;
        socket
            .set_nonblocking(true)
            .context("cannot make the cue socket non-blocking")?;
        Ok(Self {
            input: UdpInput {
                socket,
                buffer: vec![0; DATAGRAM],
                intake: Intake::new(scenario.cueing.stall_s),
                xplane: None,
            },
            reported: Reported {
                counts: Arc::default(),
                window: Vec::new(),
                window_start: None,
            },
            liveness: Liveness {
                last_arrival: None,
                last_tick: None,
                stalled: false,
                idle: false,
                stall_s: scenario.cueing.stall_s,
                fade_s: scenario.cueing.fade_s,
            },
            cueing,
            pose: scenario.geometry.home_pose(),
            prediction: (scenario.cueing.input_prediction_s > 0.0).then(Prediction::default),
            prediction_s: scenario.cueing.input_prediction_s,
            planner,
        })
    }

    /// Ask X-Plane for its datarefs of motion (`RREF`) while listening: at once, renewed
    /// every few seconds, stopped when this input is dropped.
    pub(crate) fn subscribe_xplane(&mut self, subscription: RrefSubscription) {
        self.input.xplane = Some(subscription);
    }

    /// Where it listens.
    pub fn local_addr(&self) -> Result<std::net::SocketAddr> {
        Ok(self.input.socket.local_addr()?)
    }

    /// Samples taken so far.
    pub fn samples_taken(&self) -> u64 {
        self.reported.counts.received.load(Ordering::Relaxed)
    }

    /// The counts, shared.
    pub(crate) fn counts(&self) -> Arc<CueCounts> {
        Arc::clone(&self.reported.counts)
    }

    /// The pose to follow at stream time `t`: the datagrams waiting are read, at most
    /// [`MAX_DATAGRAMS_PER_TICK`] and a fifth of the time since the last tick, and each
    /// sample steps the washout; a stalled input fades the cue.
    pub fn tick(&mut self, t: f64) -> Pose {
        let dt = self
            .liveness
            .last_tick
            .map_or(0.0, |last| (t - last).max(0.0));
        self.liveness.last_tick = Some(t);
        if let Some(x) = self.input.xplane.as_mut() {
            x.keep(&self.input.socket, std::time::Instant::now());
        }
        // Until nothing more is waiting (or an ICMP error from a previous send), or the
        // tick's share of datagrams or of time is used.
        let budget = std::time::Duration::from_secs_f64(0.2 * dt).max(MIN_READ_BUDGET);
        let started = std::time::Instant::now();
        for k in 0..MAX_DATAGRAMS_PER_TICK {
            if k > 0 && started.elapsed() > budget {
                break;
            }
            let Ok(n) = self.input.socket.recv(&mut self.input.buffer) else {
                break;
            };
            let buffer = std::mem::take(&mut self.input.buffer);
            self.receive(&buffer[..n], t);
            self.input.buffer = buffer;
        }
        self.settle(t, dt)
    }

    /// One datagram arriving at stream time `t`, decoded and taken (what [`LiveCue::tick`]
    /// does with each datagram it reads; public for measurements that feed it directly).
    pub fn receive(&mut self, bytes: &[u8], t: f64) {
        let (format, what, placed) = self.input.intake.take(bytes, t);
        self.reported.count_format(format);
        match what {
            // The game's menus or pause: as if the input had stalled.
            Intaken::Idle => self.liveness.idle = true,
            Intaken::Refused(_) | Intaken::Sample(PushOutcome::Stale) => {
                self.reported
                    .counts
                    .malformed
                    .fetch_add(1, Ordering::Relaxed);
            }
            // A true repeat carries nothing new; a held sample comes with the next stamp.
            Intaken::Ignored | Intaken::Sample(_) => {}
        }
        for timed in placed.iter() {
            self.take(timed, t);
        }
    }

    /// After a tick's datagrams (`dt` after the last tick): the rates published, a stall or
    /// a menu faded, and the pose to follow — the last sample's, or, with
    /// `input_prediction_s`, where the washout goes with the input extrapolated that far
    /// beyond it.
    pub fn settle(&mut self, t: f64, dt: f64) -> Pose {
        self.reported.publish_rates(t);
        let quiet = self.liveness.idle
            || self
                .liveness
                .last_arrival
                .is_none_or(|at| t - at > self.liveness.stall_s);
        if quiet && self.liveness.last_arrival.is_some() {
            self.stall(dt);
        } else if !quiet && self.cueing.fade() < 1.0 {
            self.cueing
                .set_fade(self.cueing.fade() + dt / self.liveness.fade_s);
        }
        match (&self.prediction, self.liveness.last_arrival) {
            (Some(p), Some(arrived)) if !quiet => {
                let ahead = (t - arrived).clamp(0.0, self.prediction_s);
                self.cueing.preview(ahead, &p.midpoint(ahead))
            }
            _ => self.pose,
        }
    }

    /// Step the washout to the placed sample's time and hold its motion.
    fn take(&mut self, timed: &Timed, now: f64) {
        let h = match timed.step {
            Step::First | Step::Same => 0.0,
            Step::By(h) => h,
        };
        let sample = timed.sample;
        let motion = VehicleMotion {
            accel: sample.accel,
            rates_deg_s: sample.rates_deg_s,
        };
        // Predicting, the input between two samples is taken as the straight line between
        // them (its middle held: exact for the integrals of a line), as the look ahead
        // extrapolated it.
        if let Some(p) = &mut self.prediction {
            if h > 0.0 {
                self.cueing.hold(&p.middle_to(&motion));
            }
            p.sampled(timed.t, motion);
        }
        self.pose = self.advance(h);
        self.cueing.hold(&motion);
        self.ask();
        let cue = self.cueing.cue();
        let mut trace = (self.reported.counts)
            .trace
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        trace.push_back(TracePoint {
            t: now,
            vehicle: sample.accel,
            platform: cue.specific_force(),
            tilt_deg: cue.tilt.map(f64::to_degrees),
        });
        while trace.front().is_some_and(|p| now - p.t > TRACE_S) {
            trace.pop_front();
        }
        drop(trace);
        self.liveness.last_arrival = Some(now);
        self.liveness.stalled = false;
        self.liveness.idle = false;
        self.reported
            .counts
            .received
            .fetch_add(1, Ordering::Relaxed);
    }

    /// No sample for a while: a vehicle at rest, the cue fading to neutral; once there,
    /// the washout is at rest too.
    fn stall(&mut self, dt: f64) {
        if !self.liveness.stalled {
            self.liveness.stalled = true;
            self.reported.counts.stalls.fetch_add(1, Ordering::Relaxed);
            self.cueing.hold(&VehicleMotion::default());
            // The intake starts a new stretch of the sender's clock itself at the next
            // datagram (by the same stall time), as a replayed capture does.
            if let Some(p) = &mut self.prediction {
                *p = Prediction::default();
            }
        }
        let fade = self.cueing.fade() - dt / self.liveness.fade_s;
        self.cueing.set_fade(fade);
        self.pose = self.advance(dt);
        self.ask();
        // Faded out: at rest (the planner brings the platform home first; its pose is not
        // scaled by the fade, so it is reset only there, never with a jump).
        if fade <= 0.0 && self.cueing.settled() {
            self.cueing.reset();
            self.cueing.set_fade(1.0);
            self.pose = self.advance(0.0);
        }
    }

    /// The cueing advanced `h` seconds; with the planner, the replies that came offered
    /// first.
    fn advance(&mut self, h: f64) -> Pose {
        if let (Some(planner), Some(follower)) = (&mut self.planner, self.cueing.mpc_mut()) {
            planner.receive(follower);
        }
        self.cueing.advance(h)
    }

    /// With the planner, its request for the next solve instant sent (with the motion held
    /// now).
    fn ask(&mut self) {
        if let (Some(planner), Some(follower)) = (&mut self.planner, self.cueing.mpc_mut()) {
            planner.send(follower);
        }
    }

    /// Wait for the planner's reply to the request it took, if any (tests: the thread's
    /// answers in time, whatever its pace).
    #[cfg(test)]
    fn wait_for_plan(&mut self) {
        if let (Some(planner), Some(follower)) = (&mut self.planner, self.cueing.mpc_mut()) {
            planner.wait(follower);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use stewart_kinematics::analysis::cueing::cue_recording;

    fn send(to: std::net::SocketAddr, text: &str) {
        let s = UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
        s.send_to(text.as_bytes(), to)
            .unwrap_or_else(|e| panic!("{e}"));
    }

    /// A live input on a free loopback port for `scenario`, and where it listens.
    fn listening(scenario: &Scenario) -> (LiveCue, std::net::SocketAddr) {
        let live = LiveCue::bind("udp:127.0.0.1:0", scenario).unwrap_or_else(|e| panic!("{e}"));
        let at = live.local_addr().unwrap_or_else(|e| panic!("{e}"));
        (live, at)
    }

    /// Wait until the socket has something to read (loopback delivers at once, almost).
    fn settle() {
        std::thread::sleep(std::time::Duration::from_millis(20));
    }

    #[test]
    fn a_live_planner_keeps_the_limits_whatever_its_thread_does_and_fades_home() {
        // Model-predictive cueing, live: the tick follows plans from the planner's thread
        // (answered when they come: this test does not wait for them, so whatever the
        // thread's pace) and every pose is within the limits; silence fades it home.
        let mut scenario = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
        scenario.cueing.algorithm =
            stewart_kinematics::model::cueing_settings::CueingAlgorithm::Mpc;
        let (mut live, at) = listening(&scenario);
        for k in 0..200 {
            let t = 0.01 * f64::from(k);
            let sign = if (k / 40) % 2 == 0 { 1.0 } else { -1.0 };
            send(
                at,
                &format!("{t},{},{},0,0,0,{}\n", 9.0 * sign, -6.0 * sign, 40.0 * sign),
            );
            settle();
            let pose = live.tick(t);
            assert!(
                stewart_kinematics::analysis::workspace::pose_within_limits(
                    &scenario.geometry,
                    &scenario.limits,
                    &pose
                ),
                "sample {k}"
            );
        }
        // Silence: the cue fades, the planner (each of its replies waited for now) brings
        // the platform home without a jump, and there it is reset.
        let home = scenario.geometry.home_pose();
        let mut t = 2.0;
        let mut last = live.tick(t);
        while last != home {
            t += 0.01;
            live.wait_for_plan();
            let pose = live.tick(t);
            assert!(stewart_kinematics::analysis::workspace::pose_within_limits(
                &scenario.geometry,
                &scenario.limits,
                &pose
            ));
            assert!(
                (pose.position - last.position).norm() < 0.01,
                "a jump at {t}"
            );
            last = pose;
            assert!(t < 60.0, "not home after {t} s: {last:?}");
        }
    }

    #[test]
    fn live_samples_give_the_poses_of_the_recording_and_a_stall_fades_to_neutral() {
        let scenario = Scenario::seed();
        let (mut live, at) = listening(&scenario);
        let samples: Vec<(f64, VehicleMotion)> = (0..50)
            .map(|k| {
                let t = 10.0 + 0.02 * f64::from(k);
                let motion = VehicleMotion {
                    accel: [if k > 5 { -4.0 } else { 0.0 }, 1.0, 0.5],
                    rates_deg_s: [0.0, 3.0, if k > 20 { 15.0 } else { 0.0 }],
                };
                (t, motion)
            })
            .collect();
        let expected = cue_recording(
            &scenario.geometry,
            &scenario.limits,
            &scenario.checks,
            &scenario.cueing,
            &samples,
        )
        .unwrap_or_else(|e| panic!("{e}"));
        for (k, (t, m)) in samples.iter().enumerate() {
            let [ax, ay, az] = m.accel;
            let [wx, wy, wz] = m.rates_deg_s;
            send(at, &format!("{t},{ax},{ay},{az},{wx},{wy},{wz}\n"));
            if k == 10 {
                send(at, "garbage");
                send(at, &format!("{},0,0,0,0,0,0", t - 1.0));
            }
            settle();
            let pose = live.tick(0.02 * k as f64);
            assert_eq!(pose, expected.poses[k], "sample {k}");
        }
        let counts = live.counts();
        assert_eq!(counts.received.load(Ordering::Relaxed), 50);
        assert_eq!(counts.malformed.load(Ordering::Relaxed), 2);
        // Silence: after the stall time the cue fades, and within the fade it is home.
        let home = scenario.geometry.home_pose();
        let mut t = 1.0;
        let mut last = live.tick(t);
        assert_ne!(last, home);
        let c = &scenario.cueing;
        while t < 1.0 + c.stall_s + c.fade_s + 0.1 {
            t += 0.01;
            let pose = live.tick(t);
            // No jumps on the way.
            assert!((pose.position - last.position).norm() < 0.01);
            last = pose;
        }
        assert_eq!(last, home);
        assert_eq!(counts.stalls.load(Ordering::Relaxed), 1);
        assert!(
            counts
                .words()
                .starts_with("cue: 50 samples in, 2 malformed")
        );
    }

    #[test]
    fn a_flood_is_read_a_bounded_share_per_tick_and_a_burst_loses_nothing() {
        // 200 samples at once (loopback delivers each before `send_to` returns): each
        // tick takes at least one and at most its share, and after enough ticks the pose
        // is the one the whole recording gives.
        let scenario = Scenario::seed();
        let (mut live, at) = listening(&scenario);
        let samples: Vec<(f64, VehicleMotion)> = (0..200)
            .map(|k| {
                let motion = VehicleMotion {
                    accel: [-3.0, 0.5, 0.0],
                    rates_deg_s: [0.0, 0.0, 10.0],
                };
                (0.01 * f64::from(k), motion)
            })
            .collect();
        let sender = UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
        for (t, m) in &samples {
            let [ax, ay, az] = m.accel;
            let [wx, wy, wz] = m.rates_deg_s;
            let line = format!("{t},{ax},{ay},{az},{wx},{wy},{wz}");
            sender
                .send_to(line.as_bytes(), at)
                .unwrap_or_else(|e| panic!("{e}"));
        }
        let counts = live.counts();
        let mut pose = live.tick(0.0);
        let first = counts.received.load(Ordering::Relaxed);
        assert!(
            (1..=MAX_DATAGRAMS_PER_TICK as u64).contains(&first),
            "{first}"
        );
        let mut ticks: u32 = 1;
        while counts.received.load(Ordering::Relaxed) < 200 {
            let before = counts.received.load(Ordering::Relaxed);
            pose = live.tick(0.001 * f64::from(ticks));
            let took = counts.received.load(Ordering::Relaxed) - before;
            assert!(
                (1..=MAX_DATAGRAMS_PER_TICK as u64).contains(&took),
                "{took}"
            );
            ticks += 1;
        }
        let expected = cue_recording(
            &scenario.geometry,
            &scenario.limits,
            &scenario.checks,
            &scenario.cueing,
            &samples,
        )
        .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(pose, expected.poses[199]);
        assert!(ticks as usize >= 200 / MAX_DATAGRAMS_PER_TICK, "{ticks}");
        assert_eq!(counts.malformed.load(Ordering::Relaxed), 0);
    }

    /// A Forza *Sled* packet (232 bytes, Turn 10's layout): race on or not, its clock, and
    /// a forward acceleration (local Z).
    fn forza(race_on: bool, ms: u32, forward: f32) -> Vec<u8> {
        let mut p = vec![0u8; 232];
        p[0..4].copy_from_slice(&i32::from(race_on).to_le_bytes());
        p[4..8].copy_from_slice(&ms.to_le_bytes());
        p[28..32].copy_from_slice(&forward.to_le_bytes());
        p
    }

    #[test]
    fn a_game_in_its_menus_fades_the_cue_to_neutral_at_once() {
        // Forza braking hard, then its menus (IsRaceOn = 0) arriving as often as before:
        // not a stall by silence, yet the cue fades to home within the fade time, and the
        // next race sample fades it in again.
        let scenario = Scenario::seed();
        let (mut live, at) = listening(&scenario);
        let sender = UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
        let home = scenario.geometry.home_pose();
        let mut t = 0.0;
        for k in 0..30u32 {
            sender
                .send_to(&forza(true, 1000 + 20 * k, -8.0), at)
                .unwrap_or_else(|e| panic!("{e}"));
            settle();
            t += 0.02;
            live.tick(t);
        }
        let braking = live.tick(t);
        assert_ne!(braking, home);
        let c = &scenario.cueing;
        let fade_ends = t + c.fade_s + 0.05;
        while t < fade_ends {
            sender
                .send_to(&forza(false, 0, 0.0), at)
                .unwrap_or_else(|e| panic!("{e}"));
            settle();
            t += 0.02;
            live.tick(t);
        }
        assert_eq!(live.tick(t), home);
        // The Link panel's "arriving": Forza's form at its rate, one a tick of 20 ms.
        let arriving = live.counts().arriving();
        assert!(
            matches!(arriving[..], [(Some(VehicleFormat::ForzaSled), rate)] if (rate - 50.0).abs() < 0.5),
            "{arriving:?}"
        );
        assert_eq!(live.counts().stalls.load(Ordering::Relaxed), 1);
        assert_eq!(live.counts().malformed.load(Ordering::Relaxed), 0);
        sender
            .send_to(&forza(true, 5000, -8.0), at)
            .unwrap_or_else(|e| panic!("{e}"));
        settle();
        live.tick(t + 0.02);
        assert_eq!(live.counts().received.load(Ordering::Relaxed), 31);
    }

    #[test]
    fn predicting_the_input_takes_out_the_lag_of_a_slow_input() {
        // A 1 Hz manoeuvre sent at 60 Hz lags the same one at 1 kHz by about a sample
        // (half of it the hold of each sample, half the platform stepping from one to the
        // next); looking 1/60 s ahead takes nearly all of it out.
        use measure::{lag, surge};
        let held = lag(60.0, 1.0, 0.0);
        let predicted = lag(60.0, 1.0, 1.0 / 60.0);
        assert!((0.012..0.022).contains(&held), "{held}");
        assert!(predicted.abs() < 0.003, "{predicted}");
        // And the platform no longer steps at each sample: its largest move in a tick.
        let largest_step = |trace: Vec<(f64, f64)>| {
            (trace.windows(2))
                .map(|w| (w[1].1 - w[0].1).abs())
                .fold(0.0, f64::max)
        };
        let stepped = largest_step(surge(60.0, 1.0, 0.0, 5.0));
        let smooth = largest_step(surge(60.0, 1.0, 1.0 / 60.0, 5.0));
        assert!(smooth * 5.0 < stepped, "{smooth} against {stepped}");
    }

    #[test]
    fn a_source_that_is_not_udp_is_refused() {
        let e = LiveCue::bind("tcp:1.2.3.4:5", &Scenario::seed())
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default();
        assert!(e.contains("udp:HOST:PORT"), "{e}");
    }
}
