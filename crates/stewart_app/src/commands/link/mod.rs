//! `stewart link`: stream the trajectory's set-points to a controller through the safety
//! supervisor, or record what would be sent (a dry run). The scenario's `[link]` table
//! says where and how; the options override it.

use std::io::{IsTerminal as _, Write as _};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use anyhow::{Result, anyhow, bail};
use stewart_kinematics::model::link_settings::{LinkSettings, LinkTransport, Word as _};
use stewart_link::sender::{Clock, Command, Sender, SenderConfig, Status, WireFormat};
use stewart_link::telemetry::STALE_AFTER_S;
use stewart_link::transport::{Record, Transport, list_ports};

use crate::cli::{LinkArgs, WireFormatArg};
use crate::link_plan::LinkPlan;
use crate::vehicle_in::live_cue::LiveCue;
use crate::vehicle_in::xplane_rref::RrefSubscription;
use crate::{output, source};

mod record;

/// Run the command.
pub(crate) fn run(args: &LinkArgs) -> Result<ExitCode> {
    if args.list_ports {
        return print_ports();
    }
    if args.bench {
        return bench(args);
    }
    let mut scenario = source::load(&args.scenario)?;
    scenario.link = settings(&scenario.link, args)?;
    let plan = LinkPlan::new(&scenario)?;
    // The outputs checked before anything listens, opens or sends: never a file the
    // scenario reads, never a folder.
    let inputs = source::inputs(&args.scenario, &scenario);
    check_outputs(args, &inputs)?;
    // Live vehicle motion, when asked: listening before anything is opened or sent.
    let live = listen(args, &scenario)?;
    let (transport, staged) = open_transport(&plan, args, &inputs)?;
    let stream_for = match (args.duration, args.repeat || live.is_some()) {
        (Some(d), _) => Some(d),
        (None, false) => Some(plan.span.1),
        (None, true) => None,
    };
    let described = transport.describe();
    let mut config = plan.sender_config(true, stream_for);
    if args.instant {
        if stream_for.is_none() {
            bail!("--instant with --loop needs --duration: the stream would never end");
        }
        config.clock = Clock::Stepped;
    }
    let recorder = start_recorder(args, &plan, &mut config, &inputs)?;
    let (target, cue_counts) = match live {
        Some(live) => {
            let counts = live.counts();
            (plan.cue_target(live), Some(counts))
        }
        None => {
            plan_arming(&plan, args.repeat, &mut config);
            (plan.trajectory_target(args.repeat), None)
        }
    };
    let clock = config.clock;
    let sender = Sender::spawn(config, target, transport)?;
    let stops_seen = supervise(&sender, stream_for);
    let summary = sender.join();
    if PIPE_CLOSED.load(std::sync::atomic::Ordering::Relaxed) {
        return Ok(ExitCode::SUCCESS);
    }
    let s = &summary.status;
    print_summary(s, &described, scenario.link.rate_hz, clock);
    if let Some(counts) = cue_counts {
        let _ = writeln!(std::io::stderr(), "link: {}", counts.words());
    }
    if let Some(recorder) = recorder {
        let rows = recorder.finish()?;
        if rows == 0 {
            let _ = writeln!(
                std::io::stderr(),
                "link: no telemetry answered the set-points: the record holds its header only"
            );
        }
    }
    if let Some(failure) = summary.failure {
        // A record that could not be finished is not left behind (the staged file goes).
        bail!("the link stopped: {failure}");
    }
    // The record of a stream that ended (also by e-stop) is whole: put it in place.
    if let Some((destination, path)) = staged {
        destination.deliver(path)?;
    }
    if s.emergency {
        let _ = writeln!(std::io::stderr(), "{}", left_where(&plan, &s.values));
        return Ok(ExitCode::from(2));
    }
    if stops_seen > 0 {
        bail!("stopped by the user (e-stop): the platform was brought home and disarmed");
    }
    Ok(ExitCode::SUCCESS)
}

/// The live vehicle motion `--cue` asks for, listening (and X-Plane asked to send it, with
/// `--xplane`).
fn listen(args: &LinkArgs, scenario: &stewart_kinematics::Scenario) -> Result<Option<LiveCue>> {
    let mut live = args
        .cue
        .as_deref()
        .map(|source| LiveCue::bind(source, scenario))
        .transpose()?;
    if let Some(live) = &live
        && let Ok(at) = live.local_addr()
    {
        let _ = writeln!(
            std::io::stderr(),
            "link: cueing from vehicle motion on udp:{at}"
        );
    }
    if let (Some(live), Some(xplane)) = (live.as_mut(), args.xplane.as_deref()) {
        live.subscribe_xplane(RrefSubscription::new(xplane, scenario.link.rate_hz)?);
    }
    Ok(live)
}

/// `--out` and `--record` checked: never a file the scenario reads (`inputs`), never a
/// folder.
fn check_outputs(args: &LinkArgs, inputs: &[(&str, std::path::PathBuf)]) -> Result<()> {
    for path in [args.out.as_deref(), args.record.as_deref()]
        .into_iter()
        .flatten()
    {
        if path.as_os_str() != "-" {
            output::Destination::new(path, inputs)?.require_file()?;
        }
    }
    Ok(())
}

/// Plan the first arming against the motion's start and say, before anything is sent,
/// when it will take longer than the ramp asked (the limits need it for the distance to
/// the motion's first pose and its speed there).
fn plan_arming(plan: &LinkPlan, repeat: bool, config: &mut SenderConfig) {
    let asked = plan.settings.ramp_s;
    let takes = match plan.planned_first_ramp(repeat) {
        Some(len) => {
            config.supervisor.plan_first_ramp(len);
            len
        }
        // No plan: the motion's start is out of reach (the supervisor holds and says why)
        // or no ramp up to ten minutes keeps the limits there.
        None => {
            let _ = writeln!(
                std::io::stderr(),
                "link: the ramp into the motion's start could not be planned within the limits: arming toward it as toward a motion not known in advance (the ramp's own motion within a quarter of each limit)"
            );
            return;
        }
    };
    if takes > asked + 1e-9 {
        let _ = writeln!(
            std::io::stderr(),
            "link: arming will take {takes:.2} s, longer than the {asked} s asked: the ramp into the motion's start, with its speed there, must stay within the speed, acceleration and jerk limits"
        );
    }
}

/// The `--record` file of what the controller answered, when asked for: refused when it is
/// the `--out` file too; its rows go to the sender through `config`.
fn start_recorder(
    args: &LinkArgs,
    plan: &LinkPlan,
    config: &mut SenderConfig,
    inputs: &[(&'static str, std::path::PathBuf)],
) -> Result<Option<record::Recorder>> {
    let Some(path) = args.record.as_deref() else {
        return Ok(None);
    };
    let mut inputs = inputs.to_vec();
    if let Some(out) = args.out.as_deref() {
        // Also when neither exists yet: the two records would overwrite each other.
        let same = |p: &std::path::Path| std::path::absolute(p).ok();
        if same(out).is_some() && same(out) == same(path) {
            bail!(
                "--record and --out name the same file `{}`: give each its own",
                path.display()
            );
        }
        inputs.push(("the dry run's record", out.to_path_buf()));
    }
    let destination = output::destination(Some(path), &inputs)?
        .ok_or_else(|| anyhow!("--record needs a file name"))?;
    let unit = plan.geometry.quantity().ascii_unit;
    let (rows, recorder) = record::Recorder::start(destination, unit)?;
    config.record = Some(rows);
    Ok(Some(recorder))
}

/// Watch the stream until it ends, showing progress: a line kept up to date on a terminal,
/// else (a log) a line at each change of state, at each new note and once a second. Ctrl-C is the e-stop:
/// stop at once, return home at the safe speed, disarm; a second one on the way home is
/// an emergency stop: disarm where the platform is. Returns the Ctrl-Cs seen.
fn supervise(sender: &Sender, stream_for: Option<f64>) -> u32 {
    let stops_before = crate::interrupt::count();
    let mut stops_seen = 0;
    let progress = std::io::stderr().is_terminal();
    let mut shown = Instant::now();
    let mut logged = (None, None);
    while !sender.finished() {
        // Every stop counts, however close together: two within one poll are two.
        let stops = crate::interrupt::count() - stops_before;
        while stops_seen < stops {
            if stops_seen == 0 {
                sender.command(Command::EStop);
                sender.command(Command::Stop);
            } else {
                sender.command(Command::EStop);
            }
            stops_seen += 1;
        }
        if progress && shown.elapsed() >= Duration::from_millis(200) {
            shown = Instant::now();
            let _ = write!(
                std::io::stderr(),
                "\r{}\x1b[K",
                progress_line(&sender.status(), stream_for)
            );
        } else if !progress {
            // A log (a file, a pipe): a line at each change of state, at a new kind of
            // note (at most five a second) and once a second.
            let status = sender.status();
            let since = shown.elapsed();
            let kind = status.note.as_deref().map(note_kind);
            let new_note = kind.is_some() && kind != logged.1;
            if logged.0 != Some(status.state)
                || new_note && since >= Duration::from_millis(200)
                || since >= Duration::from_secs(1)
            {
                shown = Instant::now();
                let _ = writeln!(std::io::stderr(), "{}", progress_line(&status, stream_for));
                logged = (Some(status.state), kind);
            }
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    if progress {
        let _ = write!(std::io::stderr(), "\r\x1b[K");
    }
    stops_seen
}

/// The stream's figures on standard error: frames, timing, the last note, and what the
/// controller answered.
fn print_summary(s: &Status, described: &str, rate_hz: f64, clock: Clock) {
    let timing = &s.timing;
    let timed = match clock {
        Clock::Stepped => "; stepped on the stream's own clock, not timed".to_owned(),
        Clock::Wall => format!(
            "; period error mean {:.0} µs, p99 {:.0} µs, max {:.0} µs; wake-up lateness mean {:.0} µs, p99 {:.0} µs, max {:.0} µs",
            s.period_error.mean_us,
            s.period_error.p99_us,
            s.period_error.max_us,
            timing.mean_us,
            timing.p99_us,
            timing.max_us,
        ),
    };
    let skipped = match s.skipped {
        0 => String::new(),
        n => format!(
            "; {n} deadlines skipped (the machine stalled: only the latest set-point is sent, never a burst)"
        ),
    };
    let _ = writeln!(
        std::io::stderr(),
        "link: {} frames to {described} over {:.2} s at {} Hz{timed}{skipped}{}",
        s.frames,
        s.time,
        rate_hz,
        s.note
            .as_ref()
            .map(|n| format!("; last note: {n}"))
            .unwrap_or_default()
    );
    if let Some((t, frame)) = &s.telemetry {
        let _ = writeln!(
            std::io::stderr(),
            "link: {} telemetry frames from the controller; the last at {t:.2} s: {}",
            s.telemetry_frames,
            frame.in_words()
        );
        let _ = writeln!(std::io::stderr(), "{}", telemetry_summary(s));
    }
}

/// The line after an emergency stop: where the platform was left, as a pose (forward
/// kinematics of the values, from home) and as the actuator values themselves.
fn left_where(plan: &LinkPlan, values: &[f64; 6]) -> String {
    let (pose, actuators) = plan.left_at(values);
    format!(
        "link: emergency stop (a second stop on the way home): disarmed where the platform was, not at home; left at {pose}; {actuators}"
    )
}

/// The telemetry matched to the set-points, in words: answered, unanswered and stale
/// counts, the round trip, and a controller that fell silent before the end.
fn telemetry_summary(s: &Status) -> String {
    let st = &s.telemetry_stats;
    let silent = s
        .telemetry_silent_s
        .filter(|&quiet| quiet > STALE_AFTER_S)
        .map(|quiet| format!("; nothing came for the last {quiet:.2} s of the stream (stale)"))
        .unwrap_or_default();
    format!(
        "link: telemetry answered {} set-points ({} unanswered, {} stale); round trip mean {:.2} ms, max {:.2} ms{silent}",
        st.answered,
        st.unanswered,
        st.stale,
        st.latency_mean_s * 1e3,
        st.latency_max_s * 1e3
    )
}

/// The progress line: state, stream time, frames, lateness so far.
fn progress_line(s: &Status, total: Option<f64>) -> String {
    let of = total.map(|d| format!(" / {d:.1}")).unwrap_or_default();
    format!(
        "link: {:<9} {:7.2}{of} s  {} frames  p99 {:.0} µs{}",
        format!("{:?}", s.state).to_uppercase(),
        s.time,
        s.frames,
        s.timing.p99_us,
        s.note
            .as_ref()
            .map(|n| format!("  ({n})"))
            .unwrap_or_default()
    )
}

/// A note without its figures: notes that differ only in them (the value that would go
/// out of range, growing each tick) are one kind, logged once.
fn note_kind(note: &str) -> String {
    note.chars().filter(|c| !c.is_ascii_digit()).collect()
}

/// `--bench`: the scenario streamed over UDP loopback to a receiver thread at each rate;
/// one table row per rate.
fn bench(args: &LinkArgs) -> Result<ExitCode> {
    let scenario = source::load(&args.scenario)?;
    let rates = args.rate.map_or_else(|| vec![500.0, 1000.0], |r| vec![r]);
    let seconds = args.duration.unwrap_or(10.0);
    let mut table = String::from(
        "rate_hz,seconds,frames,received,skipped,period_error_mean_us,period_error_p99_us,period_error_max_us,lateness_mean_us,lateness_p99_us,lateness_max_us,scheduling\n",
    );
    for rate in rates {
        let receiver = std::net::UdpSocket::bind("127.0.0.1:0")?;
        receiver.set_read_timeout(Some(Duration::from_millis(200)))?;
        let address = receiver.local_addr()?.to_string();
        let counter = std::thread::spawn(move || {
            let mut buf = [0u8; 256];
            let mut n = 0u64;
            while receiver.recv(&mut buf).is_ok() {
                n += 1;
            }
            n
        });
        let mut s = scenario.clone();
        s.link.transport = LinkTransport::Udp;
        s.link.address = Some(address);
        s.link.rate_hz = rate;
        let plan = LinkPlan::new(&s)?;
        let sender = Sender::spawn(
            plan.sender_config(true, Some(seconds)),
            plan.trajectory_target(true),
            plan.open_device()?,
        )?;
        let summary = sender.join();
        let received = counter
            .join()
            .map_err(|_| anyhow!("the receiver thread failed"))?;
        if let Some(failure) = summary.failure {
            bail!("the benchmark stream stopped: {failure}");
        }
        let st = &summary.status;
        let (p, l) = (&st.period_error, &st.timing);
        table.push_str(&format!(
            "{rate},{:.2},{},{received},{},{:.1},{:.0},{:.0},{:.1},{:.0},{:.0},{}\n",
            st.time,
            st.frames,
            st.skipped,
            p.mean_us,
            p.p99_us,
            p.max_us,
            l.mean_us,
            l.p99_us,
            l.max_us,
            st.scheduling
        ));
    }
    output::stdout(table.as_bytes())?;
    Ok(ExitCode::SUCCESS)
}

/// `--list-ports`: the serial ports the system offers, one per line.
fn print_ports() -> Result<ExitCode> {
    let ports = list_ports()?;
    let mut text = String::new();
    for p in &ports {
        text.push_str(&format!("{}\t{}\n", p.name, p.kind));
    }
    output::stdout(text.as_bytes())?;
    if ports.is_empty() {
        let _ = writeln!(std::io::stderr(), "link: no serial ports found");
    }
    Ok(ExitCode::SUCCESS)
}

/// The scenario's `[link]` with the options laid over it (checked as `--set link.…` is).
fn settings(base: &LinkSettings, args: &LinkArgs) -> Result<LinkSettings> {
    let mut link = base.clone();
    let rate = args.rate.map(|r| r.to_string());
    let baud = args.baud.map(|b| b.to_string());
    let ramp = args.ramp.map(|r| r.to_string());
    let overrides = [
        ("transport", args.transport.map(|t| t.word().to_owned())),
        ("port", args.port.clone()),
        ("address", args.address.clone()),
        ("port2", args.port2.clone()),
        ("port3", args.port3.clone()),
        ("address2", args.address2.clone()),
        ("address3", args.address3.clone()),
        ("baud", baud),
        ("rate_hz", rate),
        ("format", args.format.as_ref().map(WireFormatArg::setting)),
        ("ramp_s", ramp),
    ];
    for (key, value) in overrides {
        if let Some(value) = value {
            link.set_text(key, &value)
                .map_err(|p| anyhow!("`{}` = {value}: {}", p.key, p.reason))?;
        }
    }
    if args.dry_run {
        if args.transport.is_some_and(|t| t != LinkTransport::File) {
            bail!("--dry-run sends nothing: leave out `--transport`, or drop --dry-run");
        }
        link.transport = LinkTransport::File;
    }
    if args.instant && link.transport != LinkTransport::File {
        bail!(
            "--instant is for a dry run: a {} link keeps real time (add --dry-run)",
            link.transport.word()
        );
    }
    Ok(link)
}

/// A dry-run record being written beside its destination, put in place when the stream
/// has ended.
type Staged = Option<(output::Destination, tempfile::TempPath)>;

/// The transport the settings ask for (and, for a dry run into a regular file, the staged
/// file to deliver at the end).
fn open_transport(
    plan: &LinkPlan,
    args: &LinkArgs,
    inputs: &[(&'static str, std::path::PathBuf)],
) -> Result<(Box<dyn Transport>, Staged)> {
    if plan.settings.transport != LinkTransport::File {
        if args.out.is_some() {
            bail!(
                "--out records a dry run; a {} link sends to the device instead",
                plan.settings.transport.word()
            );
        }
        return Ok((plan.open_device()?, None));
    }
    // The record never lands on an input, and a regular file is written whole or not at all.
    // A template's bytes are recorded as they would go to the port; frames and lines, a
    // line each with its time.
    fn record<W: std::io::Write + Send + 'static>(
        plan: &LinkPlan,
        out: W,
        name: String,
    ) -> Box<dyn Transport> {
        match plan.format {
            WireFormat::Template(_) => Box::new(Record::raw(out, name)),
            _ => Box::new(Record::new(out, name)),
        }
    }
    let Some(destination) = output::destination(args.out.as_deref(), inputs)? else {
        let stdout = QuietPipe(std::io::stdout());
        return Ok((record(plan, stdout, "standard output".to_owned()), None));
    };
    destination.require_file()?;
    let name = destination.shown().display().to_string();
    if destination.kind() == output::Kind::Special {
        let device = std::fs::OpenOptions::new()
            .write(true)
            .open(destination.real())
            .map_err(|e| anyhow!("cannot write `{name}`: {e}"))?;
        return Ok((record(plan, device, name), None));
    }
    let (file, path) = destination.staged_file(".partial")?.into_parts();
    Ok((record(plan, file, name), Some((destination, path))))
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
