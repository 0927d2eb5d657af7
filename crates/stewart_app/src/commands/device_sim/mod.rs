//! `stewart device-sim`: a stand-in controller. It listens for UDP datagrams or reads a
//! serial port (a pseudo-terminal in tests), decodes the frames, counts damaged and lost
//! ones and values outside the limits, and records every set-point frame as a CSV row:
//! `t_s,seq,armed,estop,home,unit,v1,…,v6` (`t_s` since the first frame; `unit` the wire
//! code: 0 µm, 1 0.01°, 2 µs of pulse). With `--telemetry` it answers each set-point with a
//! telemetry frame: the set-point's sequence number, and where its simulated actuators are
//! ([`model`]: a first-order lag, a speed limit, a dead band; without them, the values
//! received). `--format text` reads the lines of `link --format text` instead (`S`, `E`,
//! `H`; their unit is `--text-unit`, as the text form does not carry one); `--format
//! template:…` a template's frames (a hobby board's: numbered in the order they come,
//! recorded with unit 3, their numbers 0 to the type's largest, an actuator the template
//! leaves out as 0; bytes that match no frame count as a damaged frame; no telemetry).

use std::io::Write as _;
use std::net::UdpSocket;
use std::process::ExitCode;
use std::time::{Duration, Instant};

use anyhow::{Result, anyhow, bail};
use stewart_link::boards::{Board, BoardReader, BoardRecord, Turns};
use stewart_link::template::TemplateDecoder;
use stewart_link::text::LineDecoder;
use stewart_link::transport::Transport as _;
use stewart_link::transport::{NOTHING_YET, Serial, bytes_read};
use stewart_link::{Flags, Frame, FrameDecoder, FrameKind, ValueUnit};

use crate::cli::{DeviceSimArgs, WireFormatArg, WireUnit};
use crate::output;

pub(crate) mod model;

use model::{ActuatorModel, Actuators};

/// What was received.
#[derive(Default)]
struct Received {
    rows: String,
    frames: u64,
    bad: u64,
    lost: u64,
    /// Frames whose sequence number stepped back (a duplicate, a reordering, a new link).
    out_of_order: u64,
    outside: u64,
    last_sequence: Option<u16>,
}

/// Run the command.
pub(crate) fn run(args: &DeviceSimArgs) -> Result<ExitCode> {
    if let (Some(min), Some(max)) = (args.min, args.max)
        && min > max
    {
        bail!("--min {min} is above --max {max}: no value could be accepted");
    }
    let out = output::destination(args.out.as_deref(), output::NO_INPUTS)?;
    let mut input = Input::open(args)?;
    let _ = writeln!(std::io::stderr(), "device-sim: listening on {}", input.name);
    let started = Instant::now();
    let mut first: Option<Instant> = None;
    let mut last = Instant::now();
    let stop = crate::interrupt::flag();
    let mut buf = [0u8; 2048];
    let mut controller = Controller::new(args);
    loop {
        if stop.load(std::sync::atomic::Ordering::Relaxed)
            || started.elapsed().as_secs_f64() >= args.duration
            || first.is_some() && last.elapsed().as_secs_f64() >= args.idle
        {
            break;
        }
        let n = input.receive(&mut buf)?;
        if n == 0 {
            continue;
        }
        let now = Instant::now();
        let t0 = *first.get_or_insert(now);
        last = now;
        let t = (now - t0).as_secs_f64();
        for reply in controller.read(&buf[..n], t, input.datagrams, args) {
            input.reply(&reply.encode())?;
        }
    }
    let mut tally = controller.tally;
    let rows = std::mem::take(&mut tally.rows);
    output::emit_with(out.as_ref(), |w| w.write_all(rows.as_bytes()))?;
    let _ = writeln!(
        std::io::stderr(),
        "device-sim: {} frames, {} damaged, {} lost, {} out of order, {} values outside the limits",
        tally.frames,
        tally.bad,
        tally.lost,
        tally.out_of_order,
        tally.outside
    );
    Ok(if tally.bad + tally.lost + tally.outside == 0 {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// The stand-in controller: its decoder (a serial line is one stream, frames may span
/// reads; each datagram stands alone), what it received, and its simulated actuators.
struct Controller {
    decoder: WireDecoder,
    tally: Received,
    actuators: Actuators,
    /// Whether the actuators lag, saturate or dead-band (else they are where told).
    modelled: bool,
    /// Whether set-points are answered with telemetry (a board of a template or a board
    /// protocol answers nothing).
    answers: bool,
}

impl Controller {
    fn new(args: &DeviceSimArgs) -> Self {
        let model = ActuatorModel {
            lag_s: args.lag_s,
            speed_max: args.speed_max,
            dead_band: args.dead_band,
        };
        let board = matches!(
            args.format,
            WireFormatArg::Template(_) | WireFormatArg::Smc3 | WireFormatArg::Odrive
        );
        Self {
            decoder: WireDecoder::new(args),
            tally: Received {
                rows: "t_s,seq,armed,estop,home,unit,v1,v2,v3,v4,v5,v6\n".to_owned(),
                ..Received::default()
            },
            actuators: Actuators::new(model),
            modelled: model != ActuatorModel::default(),
            answers: args.telemetry && !board,
        }
    }

    /// The bytes of one read (a datagram when `datagram`) at `t` seconds since the first:
    /// frames recorded and counted, damage counted; the telemetry answers to send.
    fn read(&mut self, bytes: &[u8], t: f64, datagram: bool, args: &DeviceSimArgs) -> Vec<Frame> {
        let mut replies = Vec::new();
        let decoder = &mut self.decoder;
        if datagram {
            // Each datagram stands alone.
            decoder.reset();
        }
        let (skipped_before, commands_before) = (decoder.skipped(), decoder.commands());
        let (mut any, mut damaged) = (false, false);
        for &b in bytes {
            match decoder.push(b) {
                // Another host's telemetry is not a set-point: not recorded, not answered.
                Some(Ok(frame)) if frame.kind == FrameKind::Telemetry => any = true,
                Some(Ok(frame)) => {
                    any = true;
                    record(&mut self.tally, t, &frame, args);
                    let armed = frame.flags.armed && !frame.flags.estop;
                    let measured = self.actuators.frame(t, &frame.values, armed);
                    if self.answers {
                        replies.push(Frame {
                            kind: FrameKind::Telemetry,
                            values: if self.modelled {
                                measured
                            } else {
                                frame.values
                            },
                            ..frame
                        });
                    }
                }
                Some(Err(_)) => {
                    self.tally.bad += 1;
                    damaged = true;
                }
                None => {}
            }
        }
        any |= decoder.commands() > commands_before;
        // Template bytes that matched no frame: a damaged frame (once a read).
        if decoder.skipped() > skipped_before {
            self.tally.bad += 1;
            damaged = true;
        }
        if datagram && !damaged && (!any || decoder.pending()) {
            // A datagram with no frame in it at all, or that ends inside a line, is damaged
            // too (once).
            self.tally.bad += 1;
        }
        replies
    }
}

/// Reads binary frames, text lines or a template's frames, as `--format` says.
enum WireDecoder {
    Binary(FrameDecoder),
    Text(LineDecoder),
    /// A template's frames, numbered here (the bytes carry no sequence).
    Template(TemplateDecoder, u16),
    /// One board of a board protocol (0-based), its ticks numbered here, whether it was
    /// last told the motors are enabled, and how many such commands came.
    Board(BoardReader, usize, u16, bool, u64),
}

impl WireDecoder {
    fn new(args: &DeviceSimArgs) -> Self {
        match &args.format {
            WireFormatArg::Binary => Self::Binary(FrameDecoder::new()),
            WireFormatArg::Text => Self::Text(LineDecoder::new(match args.text_unit {
                WireUnit::Micrometre => ValueUnit::Micrometre,
                WireUnit::Centidegree => ValueUnit::Centidegree,
                WireUnit::Microsecond => ValueUnit::PulseMicrosecond,
            })),
            WireFormatArg::Template(t) => Self::Template(TemplateDecoder::new(t.clone()), 0),
            WireFormatArg::Smc3 => Self::Board(
                BoardReader::new(Board::Smc3),
                usize::from(args.board - 1),
                0,
                false,
                0,
            ),
            WireFormatArg::Odrive => {
                // Reading needs no turns: the lines carry them.
                let turns = Turns {
                    per_unit: [1.0; 6],
                    offset: [0.0; 6],
                };
                Self::Board(
                    BoardReader::new(Board::ODrive(turns)),
                    usize::from(args.board - 1),
                    0,
                    false,
                    0,
                )
            }
        }
    }

    /// Take one byte; a frame, or that one was refused (`Err(())`), when one ends. A
    /// template's frame is a set-point of its numbers (sent only while the platform is
    /// driven: armed); bytes that match no frame are counted by [`WireDecoder::skipped`].
    fn push(&mut self, byte: u8) -> Option<Result<Frame, ()>> {
        match self {
            Self::Binary(d) => d.push(byte).map(|r| r.map_err(drop)),
            Self::Text(d) => d.push(byte).map(|r| r.map_err(drop)),
            Self::Template(d, sequence) => {
                d.push(&[byte]);
                let numbers = d.next_frame()?;
                let frame = Frame {
                    kind: FrameKind::SetPoint,
                    sequence: *sequence,
                    flags: Flags {
                        armed: true,
                        estop: false,
                        home: false,
                    },
                    unit: ValueUnit::Micrometre,
                    values: numbers.map(|n| n.map_or(0, |n| i32::try_from(n).unwrap_or(i32::MAX))),
                };
                *sequence = sequence.wrapping_add(1);
                Some(Ok(frame))
            }
            Self::Board(reader, board, sequence, armed, commands) => {
                reader.push(&[byte]);
                let values = loop {
                    match reader.next_record()? {
                        BoardRecord::Armed(on) => {
                            *armed = on;
                            *commands += 1;
                        }
                        BoardRecord::Unknown => return Some(Err(())),
                        BoardRecord::SetPoint(values) => break values,
                    }
                };
                // SMC3's numbers as they are, ODrive's turns in millionths; in the columns
                // of the actuators this board drives.
                let first = *board * values.len();
                let mut wire = [0i32; 6];
                for (k, v) in values.iter().enumerate() {
                    let n = if values.len() == 3 {
                        *v
                    } else {
                        (v * 1e6).round()
                    };
                    if let Some(slot) = wire.get_mut(first + k) {
                        *slot = n.clamp(f64::from(i32::MIN), f64::from(i32::MAX)) as i32;
                    }
                }
                let frame = Frame {
                    kind: FrameKind::SetPoint,
                    sequence: *sequence,
                    flags: Flags {
                        armed: *armed,
                        estop: false,
                        home: false,
                    },
                    unit: ValueUnit::Micrometre,
                    values: wire,
                };
                *sequence = sequence.wrapping_add(1);
                Some(Ok(frame))
            }
        }
    }

    /// Arming and disarming commands a board got (a datagram of them alone is sound).
    fn commands(&self) -> u64 {
        match self {
            Self::Board(.., commands) => *commands,
            _ => 0,
        }
    }

    /// Bytes of a template stream that matched no frame.
    fn skipped(&self) -> u64 {
        match self {
            Self::Template(d, _) => d.skipped(),
            _ => 0,
        }
    }

    /// Forget a frame or line begun (before each datagram, which stands alone).
    fn reset(&mut self) {
        match self {
            Self::Binary(d) => *d = FrameDecoder::new(),
            Self::Text(d) => d.reset(),
            Self::Template(d, _) => d.reset(),
            Self::Board(reader, ..) => *reader = BoardReader::new(reader.board().clone()),
        }
    }

    /// Whether part of a line or template frame waits for its end (a binary frame cut
    /// short is found by the datagram holding no frame).
    fn pending(&self) -> bool {
        match self {
            Self::Binary(_) => false,
            Self::Text(d) => d.pending(),
            Self::Template(d, _) => d.pending(),
            Self::Board(reader, ..) => reader.pending(),
        }
    }
}

/// Where frames come from.
struct Input {
    source: Source,
    name: String,
    /// Where the last datagram came from (telemetry goes back there).
    peer: Option<std::net::SocketAddr>,
    /// Whether each read is a datagram that stands alone.
    datagrams: bool,
}

enum Source {
    Udp(UdpSocket),
    Serial(Serial),
}

impl Input {
    fn open(args: &DeviceSimArgs) -> Result<Self> {
        match (&args.udp, &args.serial) {
            (Some(address), None) => {
                let socket = UdpSocket::bind(address)
                    .map_err(|e| anyhow!("cannot listen on `{address}`: {e}"))?;
                socket.set_read_timeout(Some(Duration::from_millis(50)))?;
                Ok(Self {
                    name: socket.local_addr()?.to_string(),
                    peer: None,
                    source: Source::Udp(socket),
                    datagrams: true,
                })
            }
            (None, Some(port)) => Ok(Self {
                source: Source::Serial(Serial::open(port, args.baud, Duration::from_millis(50))?),
                name: format!("{port} at {} baud", args.baud),
                peer: None,
                datagrams: false,
            }),
            _ => bail!("give one of --udp HOST:PORT or --serial PORT"),
        }
    }

    /// Send `bytes` back to the host (telemetry).
    fn reply(&mut self, bytes: &[u8]) -> Result<()> {
        match &mut self.source {
            Source::Udp(socket) => {
                if let Some(peer) = self.peer {
                    socket
                        .send_to(bytes, peer)
                        .map_err(|e| anyhow!("answering {peer}: {e}"))?;
                }
            }
            Source::Serial(port) => port.send(0.0, bytes)?,
        }
        Ok(())
    }

    /// Bytes that arrived within 50 ms (0 when none).
    fn receive(&mut self, buf: &mut [u8]) -> Result<usize> {
        match &mut self.source {
            Source::Udp(socket) => {
                let got = socket.recv_from(buf).map(|(n, from)| {
                    self.peer = Some(from);
                    n
                });
                let name = &self.name;
                Ok(bytes_read(got, &NOTHING_YET, || {
                    format!("receiving on {name}")
                })?)
            }
            Source::Serial(port) => Ok(port.read_waiting(buf)?),
        }
    }
}

/// Count and record one good frame.
fn record(tally: &mut Received, t: f64, f: &Frame, args: &DeviceSimArgs) {
    tally.frames += 1;
    if let Some(previous) = tally.last_sequence {
        // Ahead by less than half the circle: the frames skipped were lost; else it stepped
        // back (counted apart, not as 65 535 lost).
        let ahead = f.sequence.wrapping_sub(previous);
        if ahead == 0 || ahead >= 0x8000 {
            tally.out_of_order += 1;
        } else {
            tally.lost += u64::from(ahead - 1);
        }
    }
    tally.last_sequence = Some(f.sequence);
    let outside = |v: &i32| args.min.is_some_and(|m| *v < m) || args.max.is_some_and(|m| *v > m);
    tally.outside += f.values.iter().filter(|v| outside(v)).count() as u64;
    let unit = match (&args.format, f.unit) {
        (WireFormatArg::Template(_), _) => 3,
        (WireFormatArg::Smc3, _) => 4,
        (WireFormatArg::Odrive, _) => 5,
        (_, ValueUnit::Micrometre) => 0,
        (_, ValueUnit::Centidegree) => 1,
        (_, ValueUnit::PulseMicrosecond) => 2,
    };
    let values: Vec<String> = f.values.iter().map(i32::to_string).collect();
    tally.rows.push_str(&format!(
        "{t:.6},{},{},{},{},{unit},{}\n",
        f.sequence,
        u8::from(f.flags.armed),
        u8::from(f.flags.estop),
        u8::from(f.flags.home),
        values.join(",")
    ));
}
