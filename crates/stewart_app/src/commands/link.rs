//! `stewart link`: stream the trajectory's set-points to a controller through the safety
//! supervisor, or record what would be sent (a dry run).

use std::io::Write as _;
use std::process::ExitCode;
use std::time::Duration;

use anyhow::{Result, anyhow, bail};
use stewart_kinematics::{Geometry, Scenario, bounds};
use stewart_link::channels::{ChannelMap, Output};
use stewart_link::safety::{ActuatorLimits, StopMode, Supervisor};
use stewart_link::sender::{Command, Format, Sender, SenderConfig, Target};
use stewart_link::transport::{Record, Transport, Udp};

use crate::cli::{LinkArgs, LinkFormat, LinkTransport};
use crate::{output, source};

/// Run the command.
pub fn run(args: &LinkArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let (transport, staged) = open_transport(args)?;
    let geometry = scenario.geometry.clone();
    let home = actuator_values(&geometry, &geometry.home_pose())
        .map_err(|why| anyhow!("the home pose of `{}`: {why}", scenario.name))?;
    let duration = scenario.motion.sampling.duration();
    let stream_for = match (args.duration, args.repeat) {
        (Some(d), _) => Some(d),
        (None, false) => Some(duration),
        (None, true) => None,
    };
    let config = SenderConfig {
        rate_hz: args.rate,
        format: match args.format {
            LinkFormat::Binary => Format::Binary,
            LinkFormat::Text => Format::Text,
        },
        map: ChannelMap::identity(if geometry.rotary().is_some() {
            Output::ServoCentidegree
        } else {
            Output::LegMicrometre
        }),
        supervisor: supervisor(&scenario, home, args.ramp),
        arm_at_start: true,
        stop_after: stream_for,
    };
    let described = transport.describe();
    let sender =
        Sender::spawn(config, target(&scenario, args.repeat), transport).map_err(|e| anyhow!(e))?;
    // Ctrl-C is the e-stop: stop at once, return home at the safe speed, disarm.
    let stop = crate::interrupt::flag();
    let mut stopped_by_user = false;
    while !sender.finished() {
        if stop.load(std::sync::atomic::Ordering::Relaxed) && !stopped_by_user {
            sender.command(Command::EStop);
            sender.command(Command::Stop);
            stopped_by_user = true;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let summary = sender.join();
    if PIPE_CLOSED.load(std::sync::atomic::Ordering::Relaxed) {
        return Ok(ExitCode::SUCCESS);
    }
    let s = &summary.status;
    let timing = &s.timing;
    let _ = writeln!(
        std::io::stderr(),
        "link: {} frames to {described} over {:.2} s at {} Hz; wake-up lateness mean {:.0} µs, p99 {:.0} µs, max {:.0} µs{}",
        s.frames,
        s.time,
        args.rate,
        timing.mean_us,
        timing.p99_us,
        timing.max_us,
        s.note
            .as_ref()
            .map(|n| format!("; last note: {n}"))
            .unwrap_or_default()
    );
    if let Some(failure) = summary.failure {
        // A record that could not be finished is not left behind (the staged file goes).
        bail!("the link stopped: {failure}");
    }
    // The record of a stream that ended (also by e-stop) is whole: put it in place.
    if let Some((destination, path)) = staged {
        destination.deliver(path)?;
    }
    if stopped_by_user {
        bail!("stopped by the user (e-stop): the platform was brought home and disarmed");
    }
    Ok(ExitCode::SUCCESS)
}

/// A dry-run record being written beside its destination, put in place when the stream
/// has ended.
type Staged = Option<(output::Destination, tempfile::TempPath)>;

/// The transport the arguments ask for (and, for a dry run into a regular file, the staged
/// file to deliver at the end).
fn open_transport(args: &LinkArgs) -> Result<(Box<dyn Transport>, Staged)> {
    let kind = match (args.dry_run, args.transport) {
        (true, None | Some(LinkTransport::File)) => LinkTransport::File,
        (true, Some(LinkTransport::Udp)) => {
            bail!("--dry-run sends nothing: leave out `--transport udp`, or drop --dry-run")
        }
        (false, Some(kind)) => kind,
        (false, None) => bail!(
            "choose where to send: --dry-run (a record of what would be sent), or --transport udp --address HOST:PORT"
        ),
    };
    if kind == LinkTransport::Udp {
        let address = args
            .address
            .as_deref()
            .ok_or_else(|| anyhow!("--transport udp needs --address HOST:PORT"))?;
        return Ok((Box::new(Udp::connect(address)?), None));
    }
    // The record never lands on an input, and a regular file is written whole or not at all.
    let inputs = source::inputs(&args.scenario);
    let Some(destination) = output::destination(args.out.as_deref(), &inputs)? else {
        let stdout = Record::new(QuietPipe(std::io::stdout()), "standard output");
        return Ok((Box::new(stdout), None));
    };
    destination.require_file()?;
    let name = destination.shown().display().to_string();
    if destination.kind() == output::Kind::Special {
        let device = std::fs::OpenOptions::new()
            .write(true)
            .open(destination.real())
            .map_err(|e| anyhow!("cannot write `{name}`: {e}"))?;
        return Ok((Box::new(Record::new(device, name)), None));
    }
    let (file, path) = destination.staged_file(".partial")?.into_parts();
    Ok((Box::new(Record::new(file, name)), Some((destination, path))))
}

/// Standard output for a dry run: a reader that closed the pipe (`| head`) ends the stream;
/// `run` then ends quietly, as every command does on a closed pipe.
struct QuietPipe(std::io::Stdout);

/// Set when the dry run's reader closed the pipe.
static PIPE_CLOSED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

impl std::io::Write for QuietPipe {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0.write(buf).inspect_err(note_closed)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.0.flush().inspect_err(note_closed)
    }
}

fn note_closed(e: &std::io::Error) {
    if e.kind() == std::io::ErrorKind::BrokenPipe {
        PIPE_CLOSED.store(true, std::sync::atomic::Ordering::Relaxed);
    }
}

/// The quantity the link sends for `pose`: leg lengths (m) or servo angles (°).
fn actuator_values(g: &Geometry, pose: &stewart_kinematics::Pose) -> Result<[f64; 6], String> {
    match g.servo_angles(pose) {
        None => Ok(g.leg_lengths(pose)),
        Some(Ok(angles)) => Ok(angles.map(|a| a.degrees())),
        Some(Err(e)) => Err(e.to_string()),
    }
}

/// The trajectory as a target of stream time (from the sampling's start; wrapping with
/// `repeat`, else holding its last pose).
fn target(scenario: &Scenario, repeat: bool) -> Target {
    let geometry = scenario.geometry.clone();
    let trajectory = scenario.motion.trajectory.clone();
    let start = scenario.motion.sampling.start();
    let duration = scenario.motion.sampling.duration();
    Box::new(move |t| {
        let local = if repeat {
            t.rem_euclid(duration)
        } else {
            t.min(duration)
        };
        actuator_values(&geometry, &trajectory.pose_at(start + local))
    })
}

/// The supervisor for the scenario's limits: the stroke or servo range (or the accepted
/// range of any length or angle when none is set), the leg or servo rate limits, a ramp of
/// `ramp` seconds, and a stop that returns home at a tenth of the speed limit (or 5 % of
/// the range per second).
fn supervisor(scenario: &Scenario, home: [f64; 6], ramp: f64) -> Supervisor {
    let g = &scenario.geometry;
    let l = &scenario.limits;
    let [lo, hi] = g.quantity_limits();
    let (range, speed, accel) = if g.rotary().is_some() {
        (
            (lo.unwrap_or(-180.0), hi.unwrap_or(180.0)),
            l.servo_speed_max,
            l.servo_accel_max,
        )
    } else {
        (
            (lo.unwrap_or(0.0), hi.unwrap_or(bounds::LENGTH_M)),
            l.leg_speed_max,
            l.leg_accel_max,
        )
    };
    let home_speed = speed.map_or(0.05 * (range.1 - range.0).min(1000.0), |s| 0.1 * s);
    Supervisor::new(
        ActuatorLimits {
            range: [range; 6],
            speed,
            accel,
        },
        ramp,
        StopMode::Home { speed: home_speed },
        home,
    )
}
