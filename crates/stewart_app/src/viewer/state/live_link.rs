//! The viewer's link to hardware: a sender (its own thread, absolute deadlines) built from
//! the scenario's `[link]` table, sampling what the viewer shows — the trajectory at the
//! playback time, extrapolated on the sender's clock between frames, or the manual
//! (teleoperated) pose. The UI only says what drives the platform; it never paces the
//! stream. Dropping the link stops the stream first (e-stop, then home or hold as the
//! table says, then disarmed).

use std::collections::VecDeque;
use std::io::Write;
use std::sync::{Arc, Mutex, PoisonError, mpsc};

use stewart_kinematics::model::link_settings::LinkTransport;
use stewart_kinematics::{Pose, Scenario};
use stewart_link::sender::{Command, Sender, Status};
use stewart_link::telemetry::Row;
use stewart_link::transport::{Record, Transport};

use crate::i18n::Lang;
use crate::link_plan::{AskedPose, Drive, Followed, LinkPlan};
use crate::vehicle_in::live_cue::{CueCounts, LiveCue};
use crate::viewer::error::ViewerError;

/// Lines of a dry run kept for the panel.
const RECENT_LINES: usize = 8;
/// Seconds of tracking error kept for the panel's plot.
pub(crate) const TRACKING_WINDOW_S: f64 = 10.0;
/// Playback further than this from the sender's extrapolation (a seek, a pause) re-anchors
/// the sender's clock, seconds.
const RESYNC_S: f64 = 0.05;

/// A running stream.
struct Running {
    sender: Sender,
    source: Arc<Mutex<Followed>>,
    described: String,
    stopping: bool,
    /// What the stream was built from (for where an emergency stop left the platform).
    plan: LinkPlan,
    /// With live vehicle motion as the source: what it brought.
    cue: Option<Arc<CueCounts>>,
    /// The set-points the controller answered, as they come.
    answered: mpsc::Receiver<Row>,
    /// With live vehicle motion as the source: the pose it asked for last.
    asked: Option<AskedPose>,
}

/// Where the commanded pose shown comes from when the values sent give none by forward
/// kinematics (a singular layout such as the seed's, or values on their way home).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum CommandedFrom {
    /// Forward kinematics of the values sent (or the cue's pose, which gives them exactly).
    Values,
    /// The pose the live cue asked for; the values sent are still on their way to it (a
    /// ramp, a hold).
    Asked,
    /// The last pose the values sent gave; the newest give none.
    LastGood,
}

/// The link panel's state: the stream when connected, the outcome of the last one.
#[derive(Default)]
pub(crate) struct LiveLink {
    running: Option<Running>,
    /// The outcome of the last connect or stream (shown until the next).
    pub(crate) status: crate::viewer::error::ActionStatus,
    /// The last lines of a dry run (newest last).
    recent: Arc<Mutex<VecDeque<String>>>,
    /// The language of the status messages (the viewer's).
    pub(crate) lang: Lang,
    /// The tracking error of the answered set-points, oldest first: stream time and
    /// measured minus commanded per actuator (natural units), the last
    /// [`TRACKING_WINDOW_S`].
    tracking: VecDeque<(f64, [f64; 6])>,
    /// The pose the controller's measured values give (forward kinematics), while
    /// telemetry comes.
    measured_pose: Option<Pose>,
    /// The values sent last and the pose they give (forward kinematics), while the stream
    /// drives the platform (arming, armed, stopping).
    commanded: Option<(Pose, [f64; 6])>,
    /// How that pose was found.
    pub(crate) commanded_from: Option<CommandedFrom>,
    /// Follow live vehicle motion arriving at this UDP address (`HOST:PORT`) through the
    /// scenario's washout, instead of what the viewer shows.
    pub(crate) cue_input: Option<String>,
}

/// A dry run's writer: keeps the last whole lines for the panel (a line may come in
/// several writes).
struct RecentLines {
    lines: Arc<Mutex<VecDeque<String>>>,
    partial: Vec<u8>,
}

impl Write for RecentLines {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.partial.extend_from_slice(buf);
        while let Some(end) = self.partial.iter().position(|&b| b == b'\n') {
            let line: Vec<u8> = self.partial.drain(..=end).collect();
            let mut lines = self.lines.lock().unwrap_or_else(PoisonError::into_inner);
            if lines.len() == RECENT_LINES {
                lines.pop_front();
            }
            lines.push_back(String::from_utf8_lossy(&line).trim_end().to_owned());
        }
        Ok(buf.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

impl LiveLink {
    /// Start streaming (disarmed until [`LiveLink::arm`]) to where `[link]` says, driven by
    /// `drive`. A transport that cannot open is shown in the status; nothing is sent.
    pub(crate) fn connect(&mut self, scenario: &Scenario, drive: Drive, looping: bool) {
        self.disconnect_now();
        self.status = Some(self.start(scenario, drive, looping));
    }

    fn start(
        &mut self,
        scenario: &Scenario,
        drive: Drive,
        looping: bool,
    ) -> Result<String, ViewerError> {
        let fail = |e: anyhow::Error| ViewerError::Link(Arc::new(e));
        let plan = LinkPlan::new(scenario).map_err(fail)?;
        let transport: Box<dyn Transport> = if scenario.link.transport == LinkTransport::File {
            self.recent
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .clear();
            Box::new(Record::new(
                RecentLines {
                    lines: Arc::clone(&self.recent),
                    partial: Vec::new(),
                },
                "this panel",
            ))
        } else {
            plan.open_device().map_err(fail)?
        };
        let mut config = plan.sender_config(false, None);
        let (answers, answered) = mpsc::channel();
        config.record = Some(answers);
        self.tracking.clear();
        self.measured_pose = None;
        self.commanded = None;
        let source = plan.followed(looping, drive);
        let mut asked_pose = None;
        let (target, cue): (stewart_link::target::Target, _) = match &self.cue_input {
            Some(address) => {
                let live = LiveCue::bind(&format!("udp:{address}"), scenario).map_err(fail)?;
                let counts = live.counts();
                let asked = AskedPose::default();
                asked_pose = Some(Arc::clone(&asked));
                (plan.cue_target_telling(live, Some(asked)), Some(counts))
            }
            None => (LinkPlan::followed_target(Arc::clone(&source)), None),
        };
        // Where the frames go, in the reader's words (a UDP address reads the same in both).
        let described = match scenario.link.transport {
            LinkTransport::File => self.lang.tr("link.dry_run_here").to_owned(),
            LinkTransport::Serial => self.lang.fmt(
                "link.serial_port",
                &[("port", &scenario.link.port.clone().unwrap_or_default())],
            ),
            LinkTransport::Udp => transport.describe(),
        };
        let sender = Sender::spawn(config, target, transport)
            .map_err(|e| ViewerError::LinkSpawn(Arc::new(e)))?;
        self.running = Some(Running {
            sender,
            source,
            described: described.clone(),
            stopping: false,
            plan,
            answered,
            cue,
            asked: asked_pose,
        });
        Ok(self.lang.fmt(
            "link.connected",
            &[("to", &described), ("rate", &scenario.link.rate_hz)],
        ))
    }

    /// With live vehicle motion as the source: what it brought (counts, recent trace).
    pub(crate) fn cue(&self) -> Option<&CueCounts> {
        self.running.as_ref().and_then(|r| r.cue.as_deref())
    }

    /// Whether a stream runs (also while it stops).
    pub(crate) fn connected(&self) -> bool {
        self.running.is_some()
    }

    /// Whether the stream is being stopped (after Disconnect).
    pub(crate) fn stopping(&self) -> bool {
        self.running.as_ref().is_some_and(|r| r.stopping)
    }

    /// What the stream goes to, when connected.
    pub(crate) fn described(&self) -> Option<&str> {
        self.running.as_ref().map(|r| r.described.as_str())
    }

    /// The sender's status, when connected.
    pub(crate) fn sender_status(&self) -> Option<Status> {
        self.running.as_ref().map(|r| r.sender.status())
    }

    /// The last lines of a dry run, oldest first.
    pub(crate) fn recent_lines(&self) -> Vec<String> {
        self.recent
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .iter()
            .cloned()
            .collect()
    }

    /// Ramp from where the platform is to the target, then follow it.
    pub(crate) fn arm(&self) {
        if let Some(r) = &self.running {
            r.sender.command(Command::Arm);
        }
    }

    /// Emergency stop: at once; then hold or home as `[link]` says, and disarm.
    pub(crate) fn estop(&self) {
        if let Some(r) = &self.running {
            r.sender.command(Command::EStop);
        }
    }

    /// Stop the stream (e-stop, home or hold, disarm, end) without waiting; [`LiveLink::poll`]
    /// collects the end. Pressed again while the platform is on its way home, an emergency
    /// stop: disarm where it is.
    pub(crate) fn disconnect(&mut self) {
        if let Some(r) = &mut self.running {
            r.sender.command(Command::EStop);
            if !r.stopping {
                r.sender.command(Command::Stop);
            }
            r.stopping = true;
        }
    }

    /// Stop the stream and wait for its end (closing the window): a stream already stopping
    /// goes on home.
    pub(crate) fn disconnect_now(&mut self) {
        if !self.stopping() {
            self.disconnect();
        }
        if let Some(r) = self.running.take() {
            self.status = Some(outcome(self.lang, r));
        }
    }

    /// Tell the sender what drives the platform now (called every frame). While playing,
    /// the sender keeps its own clock; it is re-anchored only when playback jumped
    /// (seek, pause, speed change).
    pub(crate) fn follow(&self, drive: Drive, looping: bool) {
        let Some(r) = &self.running else {
            return;
        };
        let mut s = r.source.lock().unwrap_or_else(PoisonError::into_inner);
        s.looping = looping;
        let resync = match (s.drive, drive) {
            (
                Drive::Playing {
                    time,
                    anchor,
                    speed,
                },
                Drive::Playing {
                    time: now,
                    speed: new_speed,
                    ..
                },
            ) => {
                let predicted = time + anchor.elapsed().as_secs_f64() * speed;
                let gap = if looping && s.duration > 0.0 {
                    let d = (predicted - now).rem_euclid(s.duration);
                    d.min(s.duration - d)
                } else {
                    (predicted.clamp(0.0, s.duration) - now).abs()
                };
                speed != new_speed || gap > RESYNC_S
            }
            _ => true,
        };
        if resync {
            s.drive = drive;
        }
    }

    /// The tracking error of the last [`TRACKING_WINDOW_S`]: stream time and measured minus
    /// commanded per actuator, oldest first.
    pub(crate) fn tracking(&self) -> &VecDeque<(f64, [f64; 6])> {
        &self.tracking
    }

    /// The platform as the controller measured it, while connected and answered.
    pub(crate) fn measured_pose(&self) -> Option<Pose> {
        self.running.as_ref().and(self.measured_pose)
    }

    /// The platform as the values sent command it, while the stream drives it (arming,
    /// armed, on its way home): what goes to the hardware, whatever the source.
    pub(crate) fn commanded_pose(&self) -> Option<Pose> {
        self.commanded().map(|(pose, _)| pose)
    }

    /// The values sent last (natural units) and the pose they give, while the stream drives
    /// the platform.
    pub(crate) fn commanded(&self) -> Option<(Pose, [f64; 6])> {
        self.running.as_ref().and(self.commanded)
    }

    /// Whether the platform follows live vehicle motion now (the stream drives it, and the
    /// source is the cue input, not what the viewer plays).
    pub(crate) fn cueing_live(&self) -> bool {
        self.commanded.is_some() && self.cue().is_some()
    }

    /// The commanded pose from the values sent last (forward kinematics from the last
    /// commanded pose, or home); none while disarmed (nothing is driven). Where forward
    /// kinematics finds none (a singular layout): following the viewer, none (the pose it
    /// plays is the one asked for); following a live cue, the pose the cue asked for, else
    /// the last good one, said by [`LiveLink::commanded_from`], never the pose the viewer
    /// plays behind the stream.
    fn take_commanded(&mut self) {
        let Some(r) = &self.running else {
            self.commanded = None;
            self.commanded_from = None;
            return;
        };
        let status = r.sender.status();
        if status.state == stewart_link::safety::LinkState::Disarmed || status.frames == 0 {
            self.commanded = None;
            self.commanded_from = None;
            return;
        }
        let geometry = &r.plan.geometry;
        let near = self
            .commanded
            .map_or_else(|| geometry.home_pose(), |(pose, _)| pose);
        let values = status.values;
        let found = match geometry.pose_from_actuator_values(&values, &near) {
            Ok(pose) => Some((pose, CommandedFrom::Values)),
            // Following the viewer: the pose it plays is the one asked for (shown as such).
            Err(_) if r.asked.is_none() => None,
            Err(_) => {
                let asked = (r.asked.as_ref())
                    .and_then(|cell| *cell.lock().unwrap_or_else(PoisonError::into_inner));
                match (asked, self.commanded) {
                    (Some(pose), _) => {
                        let gives = geometry.actuator_values_at(&pose).ok();
                        let reached = gives.is_some_and(|g| {
                            g.iter().zip(&values).all(|(a, b)| (a - b).abs() <= 1e-6)
                        });
                        let from = if reached {
                            CommandedFrom::Values
                        } else {
                            CommandedFrom::Asked
                        };
                        Some((pose, from))
                    }
                    (None, Some((last, _))) => Some((last, CommandedFrom::LastGood)),
                    (None, None) => None,
                }
            }
        };
        self.commanded = found.map(|(pose, _)| (pose, values));
        self.commanded_from = found.map(|(_, from)| from);
    }

    /// Take in the answered set-points: the tracking error, and the measured pose from the
    /// newest (forward kinematics from the last measured pose, or home).
    fn take_answers(&mut self) {
        let Some(r) = &self.running else {
            return;
        };
        let mut newest = None;
        for row in r.answered.try_iter() {
            let error = std::array::from_fn(|k| row.measured[k] - row.commanded[k]);
            self.tracking.push_back((row.time, error));
            newest = Some(row);
        }
        let Some(row) = newest else {
            return;
        };
        while self
            .tracking
            .front()
            .is_some_and(|(t, _)| *t < row.time - TRACKING_WINDOW_S)
        {
            self.tracking.pop_front();
        }
        let geometry = &r.plan.geometry;
        let near = self.measured_pose.unwrap_or_else(|| geometry.home_pose());
        self.measured_pose = geometry
            .pose_from_actuator_values(&row.measured, &near)
            .ok();
    }

    /// Collect a stream that ended (stopped, or failed: a lost port, a write error).
    pub(crate) fn poll(&mut self) {
        self.take_answers();
        self.take_commanded();
        if self.running.as_ref().is_some_and(|r| r.sender.finished())
            && let Some(r) = self.running.take()
        {
            self.status = Some(outcome(self.lang, r));
        }
    }
}

/// The words for how a stream ended.
fn outcome(lang: Lang, running: Running) -> Result<String, ViewerError> {
    let Running {
        sender,
        described,
        plan,
        ..
    } = running;
    let summary = sender.join();
    if summary.status.emergency {
        let (pose, values) = plan.left_at(&summary.status.values);
        return Err(ViewerError::LinkEmergency {
            to: described,
            pose,
            values,
        });
    }
    match summary.failure {
        Some(why) => Err(ViewerError::LinkStopped { to: described, why }),
        None => Ok(lang.fmt(
            "link.disconnected",
            &[("to", &described), ("frames", &summary.status.frames)],
        )),
    }
}

impl Drop for LiveLink {
    fn drop(&mut self) {
        self.disconnect_now();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Instant;
    use stewart_link::safety::LinkState;

    fn wait_for(link: &LiveLink, what: impl Fn(&Status) -> bool) -> Status {
        let started = Instant::now();
        loop {
            let s = link
                .sender_status()
                .unwrap_or_else(|| panic!("not connected"));
            if what(&s) {
                return s;
            }
            assert!(started.elapsed().as_secs() < 10, "waited in vain: {s:?}");
            std::thread::sleep(std::time::Duration::from_millis(5));
        }
    }

    #[test]
    fn a_dry_run_arms_follows_the_manual_pose_stops_on_estop_and_disconnects_disarmed() {
        let mut scenario = Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}"));
        scenario.link.ramp_s = 0.05;
        scenario.link.rate_hz = 200.0;
        let home = scenario.geometry.home_pose();
        let mut link = LiveLink::default();
        link.connect(&scenario, Drive::Still(home), true);
        assert!(link.connected(), "{:?}", link.status);
        wait_for(&link, |s| s.frames >= 3 && s.state == LinkState::Disarmed);
        link.arm();
        wait_for(&link, |s| s.state == LinkState::Armed);
        let mut raised = home;
        raised.position.z += 0.05;
        link.follow(Drive::Still(raised), true);
        // The last dry-run line carries the raised pose's legs (µm) once it has got there.
        let want = scenario.geometry.leg_lengths(&raised)[0] * 1e6;
        let started = Instant::now();
        loop {
            let last = link.recent_lines().last().cloned().unwrap_or_default();
            let first_value = last
                .split_whitespace()
                .skip(1)
                .collect::<Vec<_>>()
                .get(8..12)
                .map(|b| {
                    let bytes: Vec<u8> = b
                        .iter()
                        .map(|h| u8::from_str_radix(h, 16).unwrap_or(0))
                        .collect();
                    f64::from(i32::from_le_bytes([bytes[0], bytes[1], bytes[2], bytes[3]]))
                })
                .unwrap_or(0.0);
            if (first_value - want).abs() <= 1.0 {
                break;
            }
            assert!(
                started.elapsed().as_secs() < 10,
                "never reached {want}: {last}"
            );
            std::thread::sleep(std::time::Duration::from_millis(5));
        }
        link.estop();
        wait_for(&link, |s| s.state == LinkState::Disarmed);
        link.disconnect();
        let started = Instant::now();
        while link.connected() {
            link.poll();
            assert!(started.elapsed().as_secs() < 10);
            std::thread::sleep(std::time::Duration::from_millis(5));
        }
        let ended = (link.status.clone())
            .map(|s| s.map_err(|e| e.to_string()))
            .unwrap_or_else(|| Err("no status".into()));
        assert!(
            ended.as_ref().is_ok_and(|m| m.contains("ended disarmed")),
            "{ended:?}"
        );
    }

    #[test]
    fn a_device_that_cannot_open_is_said_and_nothing_runs() {
        let mut scenario = Scenario::seed();
        scenario.link.transport = LinkTransport::Serial;
        scenario.link.port = Some("/dev/no-such-port".into());
        let mut link = LiveLink::default();
        link.connect(&scenario, Drive::Still(scenario.geometry.home_pose()), true);
        assert!(!link.connected());
        let e = link.status.clone().and_then(Result::err);
        assert!(matches!(e, Some(ViewerError::Link(_))), "{e:?}");
        let e = e.map(|e| e.to_string()).unwrap_or_default();
        assert!(
            e.contains("cannot open the serial port /dev/no-such-port"),
            "{e}"
        );
    }
}
