//! From a scenario to the link's parts: the channel map, the safety supervisor, the wire
//! format and the transport. The command line (`stewart link`) and the viewer's link
//! panel build their senders here, so both send the same thing for the same scenario.

use anyhow::{Result, anyhow, bail};
use stewart_kinematics::Scenario;
use stewart_kinematics::model::actuator::ActuatorKind;
use stewart_kinematics::model::link_settings;
use stewart_kinematics::model::link_settings::Word as _;
use stewart_kinematics::model::link_settings::{
    LinkFormat, LinkOutput, LinkSettings, LinkStop, LinkTransport,
};
use stewart_link::boards::{Board, Turns};
use stewart_link::channels::{ChannelMap, Output, OutputChannel};
use stewart_link::frame::FRAME_LEN;
use stewart_link::safety::{ActuatorLimits, StopMode, Supervisor};
use stewart_link::sender::WireFormat;
use stewart_link::template::Template;
use stewart_link::transport::{Ports, Serial, Transport, Udp, max_rate_hz};

/// How long a serial write may block before the link counts the device as gone.
const SERIAL_WRITE_TIMEOUT: std::time::Duration = std::time::Duration::from_millis(200);

/// The actuator values at the home pose.
pub(crate) fn home_values(scenario: &Scenario) -> Result<[f64; 6]> {
    let g = &scenario.geometry;
    g.actuator_values_at(&g.home_pose())
        .map_err(|why| anyhow!("the home pose of `{}`: {why}", scenario.name))
}

/// The channel map of `[link]`: leg lengths in µm or servo angles in 0.01° (`native`), or
/// servo pulses (`pulse`, servos only).
pub(crate) fn channel_map(scenario: &Scenario) -> Result<ChannelMap> {
    let link = &scenario.link;
    let output = match (link.output, scenario.geometry.actuator().kind()) {
        (LinkOutput::Native, ActuatorKind::Linear) => Output::LegMicrometre,
        (LinkOutput::Native, ActuatorKind::Rotary) => Output::ServoCentidegree,
        (LinkOutput::Pulse, ActuatorKind::Rotary) => Output::ServoPulse {
            zero_us: link.pulse_zero_us,
            us_per_degree: link.pulse_us_per_deg,
        },
        (LinkOutput::Pulse, ActuatorKind::Linear) => {
            bail!(
                "`link.output = pulse` drives hobby servos; a platform with linear legs sends `native` (µm)"
            )
        }
    };
    let channels = std::array::from_fn(|k| OutputChannel {
        source: usize::from(link.actuator[k]).saturating_sub(1),
        scale: link.scale[k],
        offset: link.offset[k],
        reversed: link.reversed[k],
    });
    ChannelMap::new(channels, output).map_err(|e| anyhow!("[link] {e}"))
}

/// Why the scenario's template (its `link.template`, whether or not it is the format in
/// use) is no template: `(key, reason)` for a scenario loader to place at its line, so a
/// bad template is refused where it is written, not first when a link starts.
pub(crate) fn template_problem(scenario: &Scenario) -> Option<(String, String)> {
    let text = scenario.link.template.as_deref()?;
    Template::parse(text)
        .err()
        .map(|e| (link_settings::TEMPLATE_KEY.to_owned(), e.to_string()))
}

/// The wire format of `[link]` (a template parsed, or refused at its column).
pub(crate) fn format(link: &LinkSettings) -> Result<WireFormat> {
    Ok(match link.format {
        LinkFormat::Binary => WireFormat::Binary,
        LinkFormat::Text => WireFormat::Text,
        LinkFormat::Template => {
            let text = link.template.as_deref().unwrap_or_default();
            WireFormat::Template(Template::parse(text).map_err(|e| anyhow!("link.template: {e}"))?)
        }
        LinkFormat::Smc3 => WireFormat::Board(Board::Smc3),
        LinkFormat::Odrive => WireFormat::Board(Board::ODrive(Turns {
            per_unit: link.turns_per_unit,
            offset: link.turns_offset,
        })),
    })
}

/// A board's own bytes (a template, SMC3, ODrive) scale each actuator from the stroke (or
/// servo range) and name the actuators themselves: refused, naming what to set, when the
/// scenario sets no range (the accepted range of any length, 0–1000 m, would send every
/// leg to the bottom), or when `[link]` asks for a channel map these formats do not apply
/// (another order, reversal, scale, offset, servo pulses).
pub(crate) fn check_board_format(scenario: &Scenario) -> Result<()> {
    let link = &scenario.link;
    let board = !matches!(link.format, LinkFormat::Binary | LinkFormat::Text);
    if !board {
        return Ok(());
    }
    let format = link.format.word();
    let [lo, hi] = scenario.geometry.quantity_limits();
    if lo.is_none() || hi.is_none() {
        let (min, max) = match scenario.geometry.actuator().kind() {
            // Quoted as the keys are written (and not taken for words of the catalogues).
            ActuatorKind::Linear => ("`geometry.leg_min`", "`geometry.leg_max`"),
            ActuatorKind::Rotary => ("`actuator.servo_min_deg`", "`actuator.servo_max_deg`"),
        };
        bail!(
            "`link.format = {format}` scales each actuator from its range: set both {min} and {max}"
        );
    }
    let default = LinkSettings::default();
    let mapped = [
        ("`link.actuator`", link.actuator != default.actuator),
        ("`link.reversed`", link.reversed != default.reversed),
        ("`link.scale`", link.scale != default.scale),
        ("`link.offset`", link.offset != default.offset),
        ("`link.output`", link.output != default.output),
    ];
    if let Some((key, _)) = mapped.iter().find(|(_, set)| *set) {
        bail!(
            "`link.format = {format}` sends each actuator as the board reads it and applies no channel map: leave {key} at its default (reverse or reorder on the board; ODrive: a negative `link.turns_per_unit`)"
        );
    }
    Ok(())
}

/// The most bytes one set-point takes on the wire in `format`.
pub(crate) fn frame_bytes(format: &WireFormat) -> usize {
    match format {
        WireFormat::Binary => FRAME_LEN,
        // The longest text line: `S,65535,` and six signed 11-character values.
        WireFormat::Text => 8 + 6 * 12,
        WireFormat::Template(t) => t.max_len(),
        WireFormat::Board(b) => b.max_frame_bytes(),
    }
}

/// The supervisor for the scenario's limits: the stroke or servo range (or the accepted
/// range of any length or angle when none is set), the leg or servo rate limits, the ramp
/// of `[link]`, and a stop that holds or returns home at a tenth of the speed limit (or
/// 5 % of the range per second when no limit is set).
pub(crate) fn supervisor(scenario: &Scenario, home: [f64; 6]) -> Supervisor {
    let g = &scenario.geometry;
    let l = &scenario.limits;
    let range = actuator_range(scenario);
    let [speed, accel, jerk] = g.actuator_rate_limits(l);
    let stop = match scenario.link.stop {
        LinkStop::Hold => StopMode::Hold,
        LinkStop::Home => StopMode::Home {
            speed: speed.map_or(0.05 * (range.1 - range.0).min(1000.0), |s| 0.1 * s),
        },
    };
    Supervisor::new(
        ActuatorLimits {
            range: [range; 6],
            speed,
            accel,
            jerk,
        },
        scenario.link.ramp_s,
        stop,
        home,
    )
}

/// The range every actuator is kept in: the stroke or servo range, or the accepted range
/// of any length or angle where the scenario sets none (a template scales from it).
pub(crate) fn actuator_range(scenario: &Scenario) -> (f64, f64) {
    let g = &scenario.geometry;
    let [lo, hi] = g.quantity_limits();
    let widest = g.quantity().widest;
    (lo.unwrap_or(widest.0), hi.unwrap_or(widest.1))
}

/// Open the serial port or UDP peer `[link]` names — a board protocol's ports, one a
/// board — (a `file` transport is the caller's: the command line records into a file, the
/// viewer into its panel).
pub(crate) fn open_device(link: &LinkSettings) -> Result<Box<dyn Transport>> {
    let boards = match format(link)? {
        WireFormat::Board(board) => board.ports(),
        _ => 1,
    };
    if boards == 1 {
        return open_one(link, link.port.as_deref(), link.address.as_deref());
    }
    let ports = [&link.port, &link.port2, &link.port3];
    let addresses = [&link.address, &link.address2, &link.address3];
    let mut opened: Vec<Box<dyn Transport>> = Vec::new();
    for k in 0..boards {
        let named = match link.transport {
            LinkTransport::Serial => ports[k].is_some(),
            _ => addresses[k].is_some(),
        };
        if k > 0 && !named {
            let n = k + 1;
            bail!(
                "`link.format = {}` drives {boards} boards: give board {n}'s port too (--port{n} or `link.port{n}`; over UDP --address{n})",
                link.format.word()
            );
        }
        opened.push(open_one(
            link,
            ports[k].as_deref(),
            addresses[k].as_deref(),
        )?);
    }
    Ok(Box::new(Ports(opened)))
}

/// Open one serial port or UDP peer.
fn open_one(
    link: &LinkSettings,
    port: Option<&str>,
    address: Option<&str>,
) -> Result<Box<dyn Transport>> {
    match link.transport {
        LinkTransport::Udp => {
            let address = address.ok_or_else(|| {
                anyhow!(
                    "the UDP transport needs an address (`--address HOST:PORT` or `link.address`)"
                )
            })?;
            Ok(Box::new(Udp::connect(address)?))
        }
        LinkTransport::Serial => {
            let port = port
                .ok_or_else(|| anyhow!("the serial transport needs a port (`--port /dev/ttyUSB0` or `link.port`; `stewart link --list-ports` lists them)"))?;
            let bytes = frame_bytes(&format(link)?);
            let most = max_rate_hz(link.baud, bytes);
            if link.rate_hz > most {
                bail!(
                    "{} Hz does not fit {port} at {} baud: each set-point takes {bytes} bytes, so at most {:.0} Hz; raise `link.baud` (--baud) or lower the rate",
                    link.rate_hz,
                    link.baud,
                    most.floor()
                );
            }
            Ok(Box::new(Serial::open(
                port,
                link.baud,
                SERIAL_WRITE_TIMEOUT,
            )?))
        }
        LinkTransport::File => bail!("a dry run records what would be sent; it opens no device"),
    }
}
