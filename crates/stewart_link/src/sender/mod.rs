//! The real-time sender: a thread that wakes at absolute deadlines (`start + k / rate`, not
//! the UI's frame clock), asks for the target at that time, lets the [`Supervisor`] decide
//! what may be sent, maps it to the wire and sends it. Commands (arm, e-stop, stop) come in
//! through a channel; the status (state, last note, frames, timing) is shared.

use std::sync::mpsc::{self, Receiver, TryRecvError};
use std::sync::{Arc, Mutex, PoisonError};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use thiserror::Error;

use crate::boards::Board;
use crate::channels::ChannelMap;
use crate::frame::{Flags, Frame, FrameDecoder, FrameKind};
use crate::safety::{LinkState, Supervisor};
use crate::target::Target;
use crate::telemetry::{Matcher, Row, TelemetryStats};
use crate::template::Template;
use crate::text;
use crate::transport::Transport;

/// Binary frames, text lines, or a board's own bytes.
#[derive(Clone, Debug, PartialEq)]
pub enum WireFormat {
    /// The 34-byte frame.
    Binary,
    /// The `S,seq,…` line.
    Text,
    /// An output template's bytes ([`crate::template`]): each actuator's value scaled from
    /// its range, sent while the supervisor drives the platform (armed, arming, or on its
    /// way home); nothing while disarmed, as the text line.
    Template(Template),
    /// A board protocol on several ports ([`crate::boards`]): set-points while the
    /// supervisor drives the platform, the board's arming commands when that begins and
    /// its disarming ones when it ends.
    Board(Board),
}

/// What the sender is asked to do.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Command {
    /// Start arming (ramp from the last values).
    Arm,
    /// Emergency stop (a second one on the way home: disarm where the platform is, send
    /// disarmed frames for [`EMERGENCY_TAIL_S`] and end the stream).
    EStop,
    /// Bring the platform to rest as the stop mode says, disarm, and end the stream (a
    /// second one on the way home is an emergency, as a second [`Command::EStop`]).
    Stop,
}

/// How late the wake-ups were, microseconds.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Timing {
    /// Wake-ups measured.
    pub count: u64,
    /// Mean lateness.
    pub mean_us: f64,
    /// 99th percentile (to the histogram's 1 µs bins).
    pub p99_us: f64,
    /// Latest.
    pub max_us: f64,
}

/// The mean, 99th percentile and worst of `n` calls of `call(k)`, each timed alone after
/// an untimed `before(k)`, microseconds: what one tick costs, call by call (the
/// benchmarks' figures).
pub fn time_each(n: usize, mut before: impl FnMut(usize), mut call: impl FnMut(usize)) -> Timing {
    let mut times = Lateness::new();
    for k in 0..n {
        before(k);
        let started = Instant::now();
        call(k);
        times.add(started.elapsed().as_secs_f64() * 1e6);
    }
    times.timing()
}

/// Lateness histogram: 1 µs bins up to 20 ms, the rest in the last bin.
#[derive(Clone, Debug)]
struct Lateness {
    bins: Vec<u64>,
    count: u64,
    sum: f64,
    max: f64,
}

impl Lateness {
    fn new() -> Self {
        Self {
            bins: vec![0; 20_001],
            count: 0,
            sum: 0.0,
            max: 0.0,
        }
    }

    fn add(&mut self, us: f64) {
        let bin = (us.max(0.0) as usize).min(self.bins.len() - 1);
        self.bins[bin] += 1;
        self.count += 1;
        self.sum += us;
        self.max = self.max.max(us);
    }

    fn timing(&self) -> Timing {
        let wanted = (self.count as f64 * 0.99).ceil() as u64;
        let mut seen = 0;
        let mut p99 = 0.0;
        for (k, &n) in self.bins.iter().enumerate() {
            seen += n;
            if seen >= wanted.max(1) {
                p99 = k as f64 + 1.0;
                break;
            }
        }
        Timing {
            count: self.count,
            mean_us: if self.count > 0 {
                self.sum / self.count as f64
            } else {
                0.0
            },
            p99_us: if self.count > 0 { p99 } else { 0.0 },
            max_us: self.max,
        }
    }
}

/// What the sender shows while it runs.
#[derive(Clone, Debug, PartialEq)]
pub struct Status {
    /// The supervisor's state.
    pub state: LinkState,
    /// The latest note (held, limited, disarmed because …).
    pub note: Option<String>,
    /// Frames sent.
    pub frames: u64,
    /// Deadlines passed without a frame because the thread woke after the next one had
    /// passed too (a stalled machine): only the latest is sent, never a burst.
    pub skipped: u64,
    /// Stream time of the last tick, seconds.
    pub time: f64,
    /// Wake-up lateness so far (how long after its deadline each tick woke).
    pub timing: Timing,
    /// Period error so far: how far each interval between two sends was from the period.
    pub period_error: Timing,
    /// How the sender thread is scheduled (real-time where permitted).
    pub scheduling: String,
    /// Telemetry frames the controller sent back.
    pub telemetry_frames: u64,
    /// The telemetry matched to the set-points: answered, unanswered, stale, latency.
    pub telemetry_stats: TelemetryStats,
    /// Seconds since the last telemetry frame, once one has come (a controller that
    /// stopped answering shows here).
    pub telemetry_silent_s: Option<f64>,
    /// The latest of them, with the stream time it came at.
    pub telemetry: Option<(f64, Frame)>,
    /// The last values sent, natural units (where the platform was left, once disarmed).
    pub values: [f64; 6],
    /// A second stop ended the way home: the platform was left where [`Status::values`]
    /// says.
    pub emergency: bool,
}

/// How the stream ended.
#[derive(Clone, Debug, PartialEq)]
pub struct Summary {
    /// The status at the end.
    pub status: Status,
    /// Why it ended early (a write failed, the map refused a value), if it did.
    pub failure: Option<String>,
}

/// The sender's settings.
pub struct SenderConfig {
    /// Ticks per second (10–1000).
    pub rate_hz: f64,
    /// Frames or lines.
    pub format: WireFormat,
    /// Values to wire.
    pub map: ChannelMap,
    /// The safety state machine (starts disarmed).
    pub supervisor: Supervisor,
    /// Arm at the first tick.
    pub arm_at_start: bool,
    /// After this many seconds of stream, stop as [`Command::Stop`] does.
    pub stop_after: Option<f64>,
    /// Where each set-point answered by telemetry goes, with its measured values (a
    /// recorder on another thread; nothing is written on the sender's).
    pub record: Option<mpsc::Sender<Row>>,
    /// Whose clock the ticks follow.
    pub clock: Clock,
}

/// Whose clock the ticks follow.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Clock {
    /// The wall clock: each tick waits for its deadline, and a stalled machine skips
    /// deadlines rather than send late set-points (every live link).
    #[default]
    Wall,
    /// The stream's own clock: every tick in turn, at once, none skipped (a dry run into a
    /// record that nothing reads as it is written: the same ticks as a live stream on an
    /// idle machine, whatever the load).
    Stepped,
}

/// A running sender.
pub struct Sender {
    commands: mpsc::Sender<Command>,
    status: Arc<Mutex<Status>>,
    handle: JoinHandle<Summary>,
}

/// How long disarmed frames follow an emergency stop before the stream ends, seconds.
pub const EMERGENCY_TAIL_S: f64 = 0.25;

/// The lowest and highest rates, hertz.
pub const RATES_HZ: (f64, f64) = (10.0, 1000.0);

/// Why a sender did not start.
#[derive(Debug, Error)]
pub enum SpawnError {
    /// The rate (hertz) is outside [`RATES_HZ`].
    #[error("the rate must be between {lo} and {hi} Hz, got {0}", lo = RATES_HZ.0, hi = RATES_HZ.1)]
    Rate(f64),
    /// The system refused the thread.
    #[error("cannot start the sender thread: {0}")]
    Thread(std::io::Error),
}

impl Sender {
    /// Start the thread. Refuses a rate outside [`RATES_HZ`].
    pub fn spawn(
        config: SenderConfig,
        target: Target,
        transport: Box<dyn Transport>,
    ) -> Result<Sender, SpawnError> {
        let (lo, hi) = RATES_HZ;
        if !(lo..=hi).contains(&config.rate_hz) {
            return Err(SpawnError::Rate(config.rate_hz));
        }
        let (commands, inbox) = mpsc::channel();
        let status = Arc::new(Mutex::new(Status {
            state: LinkState::Disarmed,
            note: None,
            frames: 0,
            skipped: 0,
            time: 0.0,
            timing: Timing::default(),
            period_error: Timing::default(),
            scheduling: String::new(),
            telemetry_frames: 0,
            telemetry: None,
            telemetry_stats: TelemetryStats::default(),
            telemetry_silent_s: None,
            values: *config.supervisor.last(),
            emergency: false,
        }));
        let shared = Arc::clone(&status);
        let handle = std::thread::Builder::new()
            .name("stewart-link".to_owned())
            .spawn(move || run(config, target, transport, &inbox, &shared))
            .map_err(SpawnError::Thread)?;
        Ok(Sender {
            commands,
            status,
            handle,
        })
    }

    /// Send a command (ignored once the stream has ended).
    pub fn command(&self, command: Command) {
        let _ = self.commands.send(command);
    }

    /// The current status.
    pub fn status(&self) -> Status {
        self.status
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .clone()
    }

    /// Whether the stream has ended.
    pub fn finished(&self) -> bool {
        self.handle.is_finished()
    }

    /// Stop (as [`Command::Stop`]) and wait for the end.
    pub fn stop_and_join(self) -> Summary {
        self.command(Command::Stop);
        self.join()
    }

    /// Wait for the stream to end by itself.
    pub fn join(self) -> Summary {
        let status = self.status();
        self.handle.join().unwrap_or_else(|_| Summary {
            status,
            failure: Some("the sender thread failed".to_owned()),
        })
    }
}

/// Telemetry coming back from the controller, decoded as it arrives and matched to the
/// set-points it answers.
#[derive(Default)]
struct Telemetry {
    decoder: FrameDecoder,
    frames: u64,
    latest: Option<(f64, Frame)>,
    last_at: Option<Instant>,
    matcher: Matcher,
    record: Option<mpsc::Sender<Row>>,
}

impl Telemetry {
    /// Read what has come back (never waiting) and keep the latest telemetry frame.
    fn collect(
        &mut self,
        transport: &mut dyn Transport,
        t: f64,
        map: &ChannelMap,
    ) -> Result<(), crate::transport::TransportError> {
        let mut buf = [0u8; 256];
        // A bounded number of reads per tick: a chatty controller cannot stall the sender.
        for _ in 0..8 {
            let n = transport.receive(&mut buf)?;
            if n == 0 {
                break;
            }
            for &b in &buf[..n] {
                if let Some(Ok(frame)) = self.decoder.push(b)
                    && frame.kind == FrameKind::Telemetry
                {
                    let now = Instant::now();
                    self.frames += 1;
                    self.latest = Some((t, frame));
                    self.last_at = Some(now);
                    if let Some(row) = self.matcher.answer(&frame, now, map)
                        && let Some(record) = &self.record
                    {
                        // A recorder that has gone away records nothing more.
                        let _ = record.send(row);
                    }
                }
            }
        }
        Ok(())
    }
}

/// Waits for deadlines: the system sleep until `margin` before the deadline, then a spin.
/// The margin follows how late the system's sleep wakes (it jumps up to 1.5 × the latest
/// oversleep and decays by a thousandth per tick), between 100 µs and a quarter of the
/// period, at most 2 ms: a machine whose sleeps wake late (a virtual machine, a loaded
/// desktop) costs more spinning instead of late set-points.
struct Waiter {
    margin: f64,
    most: f64,
}

impl Waiter {
    const LEAST_S: f64 = 100e-6;

    fn new(period: f64) -> Self {
        let most = (0.25 * period).clamp(Self::LEAST_S, 2e-3);
        Self {
            margin: (4e-4_f64).min(most),
            most,
        }
    }

    fn sleep_until(&mut self, deadline: Instant) {
        let now = Instant::now();
        if let Some(left) = deadline.checked_duration_since(now) {
            let nap = left.as_secs_f64() - self.margin;
            if nap > 0.0 {
                let wake = now + Duration::from_secs_f64(nap);
                std::thread::sleep(Duration::from_secs_f64(nap));
                let late = Instant::now().saturating_duration_since(wake).as_secs_f64();
                self.margin = (self.margin * 0.999)
                    .max(1.5 * late)
                    .clamp(Self::LEAST_S, self.most);
            }
        }
        while Instant::now() < deadline {
            std::hint::spin_loop();
        }
    }
}

/// One stream between its ticks: the target, the supervisor's decisions mapped to the wire,
/// encoded and sent, and what came back. The sender's thread drives it at its deadlines;
/// [`Stream::tick`] is also what the benchmarks time.
pub struct Stream {
    config: SenderConfig,
    target: Target,
    transport: Box<dyn Transport>,
    sequence: u16,
    frames: u64,
    failure: Option<String>,
    note: Option<String>,
    telemetry: Telemetry,
    values: [f64; 6],
    /// A template's frame, written here each tick (no allocation once it has its size).
    bytes: Vec<u8>,
    /// A board protocol's bytes for each port this tick, and whether the boards were last
    /// told the platform is driven.
    board_bytes: Vec<Vec<u8>>,
    board_driven: bool,
    /// Whether the last tick that drove the platform was on the way home.
    board_home_last: bool,
}

impl Stream {
    /// A stream that has sent nothing yet.
    pub fn new(mut config: SenderConfig, target: Target, transport: Box<dyn Transport>) -> Self {
        let values = *config.supervisor.last();
        let telemetry = Telemetry {
            record: config.record.take(),
            ..Telemetry::default()
        };
        Self {
            config,
            target,
            transport,
            sequence: 0,
            frames: 0,
            failure: None,
            note: None,
            telemetry,
            values,
            bytes: Vec::with_capacity(64),
            board_bytes: Vec::new(),
            board_driven: false,
            board_home_last: false,
        }
    }

    /// One tick of a board protocol: the arming commands when the supervisor begins to drive
    /// the platform, its set-points while it does, and the disarming ones only once the
    /// way home has ended there (a hold or an emergency leaves the boards holding where
    /// they are: ODrive's idle would let a loaded rig sink). Every port gets its bytes; the
    /// first failure is the stream's. `None`: nothing was sent as a set-point.
    fn send_to_boards(
        &mut self,
        board: &Board,
        t: f64,
        tick: &crate::safety::Tick,
    ) -> Option<Result<(), crate::transport::TransportError>> {
        let driven = tick.armed || tick.home;
        self.board_bytes.resize(board.ports(), Vec::new());
        self.board_bytes.iter_mut().for_each(Vec::clear);
        if driven && !self.board_driven {
            board.arming(true, &mut self.board_bytes);
        }
        if !driven && self.board_driven && self.board_home_last {
            board.arming(false, &mut self.board_bytes);
        }
        self.board_driven = driven;
        if driven {
            self.board_home_last = tick.home;
            let sv = &self.config.supervisor;
            let (ranges, velocities) = (&sv.limits().range, &sv.motion().velocity);
            board.set_point(&tick.values, velocities, ranges, &mut self.board_bytes);
        }
        let mut first_error = None;
        for (port, bytes) in self.board_bytes.iter().enumerate() {
            if !bytes.is_empty()
                && let Err(e) = self.transport.send_on(port, t, bytes)
            {
                first_error.get_or_insert(e);
            }
        }
        match first_error {
            Some(e) => Some(Err(e)),
            None => driven.then_some(Ok(())),
        }
    }

    /// The supervisor (to arm or stop it).
    pub fn supervisor(&mut self) -> &mut Supervisor {
        &mut self.config.supervisor
    }

    /// Why the stream failed, once it has (it then sends nothing more).
    pub fn failure(&self) -> Option<&str> {
        self.failure.as_deref()
    }

    /// One tick at stream time `t`: the target, the supervisor's decision, the frame (or
    /// line) sent, the telemetry read. Returns whether something was sent. A failure (the
    /// map refused a value, the transport failed) disarms the supervisor with its reason.
    pub fn tick(&mut self, t: f64) -> bool {
        let sv = &mut self.config.supervisor;
        let tick = sv.tick_sample(t, (self.target)(t));
        if tick.note.is_some() {
            self.note = tick.note.clone();
        }
        self.values = tick.values;
        let values = match self.config.map.wire(&tick.values) {
            Ok(values) => values,
            Err(e) => {
                self.fail(format!("{e}; disarmed"));
                return false;
            }
        };
        let frame = Frame {
            kind: FrameKind::SetPoint,
            sequence: self.sequence,
            flags: Flags {
                armed: tick.armed,
                estop: tick.estop,
                home: tick.home,
            },
            unit: self.config.map.output().unit(),
            values,
        };
        let sent = match &self.config.format {
            WireFormat::Binary => Some(self.transport.send(t, &frame.encode())),
            WireFormat::Text => {
                text::line(&frame).map(|line| self.transport.send(t, line.as_bytes()))
            }
            WireFormat::Template(template) => (tick.armed || tick.home).then(|| {
                self.bytes.clear();
                let ranges = &self.config.supervisor.limits().range;
                template.encode(&tick.values, ranges, &mut self.bytes);
                self.transport.send(t, &self.bytes)
            }),
            WireFormat::Board(board) => {
                let board = board.clone();
                self.send_to_boards(&board, t, &tick)
            }
        };
        let delivered = match sent {
            Some(Err(e)) => {
                self.fail(format!("{e}; disarmed"));
                return false;
            }
            Some(Ok(())) => {
                self.telemetry
                    .matcher
                    .sent(self.sequence, t, Instant::now(), tick.values);
                self.frames += 1;
                self.sequence = self.sequence.wrapping_add(1);
                true
            }
            None => false,
        };
        let map = self.config.map;
        if let Err(e) = self.telemetry.collect(self.transport.as_mut(), t, &map) {
            self.fail(format!("{e}; disarmed"));
        }
        delivered
    }

    /// Write the stream's state at time `t` into the shared `status` (the timing figures
    /// apart).
    fn report(&self, status: &mut Status, t: f64, skipped: u64) {
        let sv = &self.config.supervisor;
        status.state = sv.state();
        status.note.clone_from(&self.note);
        status.frames = self.frames;
        status.skipped = skipped;
        status.telemetry_frames = self.telemetry.frames;
        status.telemetry = self.telemetry.latest;
        status.telemetry_stats = self.telemetry.matcher.stats();
        status.telemetry_silent_s = self.telemetry.last_at.map(|at| at.elapsed().as_secs_f64());
        status.time = t;
        status.values = self.values;
        status.emergency = sv.emergency();
    }

    fn fail(&mut self, why: String) {
        self.config.supervisor.fault(why.clone());
        self.failure = Some(why);
    }
}

/// Apply the commands waiting in `inbox` at stream time `t`: arm, emergency stop, or stop
/// (a second stop on the way home is an emergency; a gone commander is a stop).
fn take_commands(inbox: &Receiver<Command>, sv: &mut Supervisor, t: f64, stopping: &mut bool) {
    loop {
        match inbox.try_recv() {
            Ok(Command::Arm) => {
                let from = *sv.last();
                sv.arm(t, from);
            }
            Ok(Command::EStop) => sv.estop(),
            Ok(Command::Stop) => {
                // A second stop is an emergency, also when the first was taken in this
                // same call and has not turned the supervisor homewards yet.
                if *stopping {
                    if matches!(sv.state(), LinkState::Arming | LinkState::Armed) {
                        sv.estop();
                    }
                    if sv.state() == LinkState::Stopping {
                        sv.estop();
                    }
                }
                *stopping = true;
            }
            Err(TryRecvError::Empty) => break,
            // Whoever commanded the stream is gone: stop it.
            Err(TryRecvError::Disconnected) => {
                *stopping = true;
                break;
            }
        }
    }
}

/// The sender's thread: one tick per period from `start`, commands taken between ticks,
/// the shared status updated after each, until the stream has stopped or failed.
fn run(
    config: SenderConfig,
    target: Target,
    transport: Box<dyn Transport>,
    inbox: &Receiver<Command>,
    shared: &Mutex<Status>,
) -> Summary {
    let rate_hz = config.rate_hz;
    let period = 1.0 / rate_hz;
    let arm_at_start = config.arm_at_start;
    let stop_after = config.stop_after;
    let stepped = config.clock == Clock::Stepped;
    let mut stream = Stream::new(config, target, transport);
    let mut waiter = Waiter::new(period);
    let scheduling = if stepped {
        "stepped (no deadlines)".to_owned()
    } else {
        priority::raise()
    };
    shared
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .scheduling
        .clone_from(&scheduling);
    let start = Instant::now();
    let mut lateness = Lateness::new();
    let mut period_error = Lateness::new();
    let mut last_send: Option<Instant> = None;
    // The shared status's timing figures are summed up ten times a second (not every tick).
    let summary_every = ((rate_hz / 10.0).round() as u64).max(1);
    let mut stopping = false;
    let mut k: u64 = 0;
    let mut skipped = 0u64;
    let mut first_tick = true;
    // After an emergency stop: when the disarmed tail ends.
    let mut tail_until: Option<f64> = None;
    loop {
        let mut t = k as f64 * period;
        if !stepped {
            let mut deadline = start + Duration::from_secs_f64(t);
            waiter.sleep_until(deadline);
            // Woken so late that later deadlines have passed too (the machine stalled): a
            // late set-point is a wrong one, so send only for the latest deadline passed, not
            // a burst.
            let behind = (Instant::now()
                .saturating_duration_since(deadline)
                .as_secs_f64()
                / period)
                .floor() as u64;
            if behind > 0 {
                skipped += behind;
                k += behind;
                t = k as f64 * period;
                deadline = start + Duration::from_secs_f64(t);
            }
            lateness.add(
                Instant::now()
                    .saturating_duration_since(deadline)
                    .as_secs_f64()
                    * 1e6,
            );
        }
        let sv = stream.supervisor();
        // Arm on the first tick, whichever deadline that is (a stalled start skips some).
        if std::mem::take(&mut first_tick) && arm_at_start {
            let from = *sv.last();
            sv.arm(t, from);
        }
        take_commands(inbox, sv, t, &mut stopping);
        if stop_after.is_some_and(|d| t >= d) {
            stopping = true;
        }
        if stopping && matches!(sv.state(), LinkState::Arming | LinkState::Armed) {
            sv.estop();
        }
        if stream.tick(t) && !stepped {
            let now = Instant::now();
            if let Some(previous) = last_send {
                let interval = now.saturating_duration_since(previous).as_secs_f64();
                period_error.add((interval - period).abs() * 1e6);
            }
            last_send = Some(now);
        }
        let sv = &stream.config.supervisor;
        if sv.emergency() && tail_until.is_none() {
            tail_until = Some(t + EMERGENCY_TAIL_S);
        }
        let last = stream.failure.is_some()
            || match tail_until {
                Some(end) => t >= end - 1e-9,
                None => stopping && sv.state() == LinkState::Disarmed,
            };
        {
            let mut s = shared.lock().unwrap_or_else(PoisonError::into_inner);
            stream.report(&mut s, t, skipped);
            if last || k.is_multiple_of(summary_every) {
                s.timing = lateness.timing();
                s.period_error = period_error.timing();
            }
        }
        if last {
            break;
        }
        k += 1;
    }
    let status = shared
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
        .clone();
    Summary {
        status,
        failure: stream.failure,
    }
}

mod priority;
#[cfg(test)]
mod tests;
