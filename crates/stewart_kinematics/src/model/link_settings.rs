//! The `[link]` table of a scenario: how set-points reach a real platform — the transport
//! (serial port, UDP peer, or a dry-run file), its rate and wire format, the channel map
//! (which actuator on which channel, scaled, offset, mirrored) and the arming and stopping
//! behaviour. Plain data, checked here; the link itself (`stewart_link`) turns it into
//! frames.
//!
//! ```toml
//! [link]
//! transport = "serial"       # serial | udp | file
//! port = "/dev/ttyUSB0"      # serial
//! baud = 115200
//! address = "192.168.1.20:9000"  # udp
//! rate_hz = 100              # 10 … 1000
//! format = "binary"          # binary | text
//! output = "native"          # native (µm or 0.01°) | pulse (servo pulse µs)
//! pulse_zero_us = 1500       # pulse at 0°
//! pulse_us_per_deg = 10      # pulse change per degree
//! ramp_s = 2                 # arming ramp
//! stop = "home"              # hold | home
//! actuator = [1, 2, 3, 4, 5, 6]   # channel k carries actuator actuator[k]
//! scale = [1, 1, 1, 1, 1, 1]
//! offset = [0, 0, 0, 0, 0, 0]     # natural units (m or °)
//! reversed = [false, false, false, false, false, false]
//! ```

use serde::{Deserialize, Serialize};

/// Where set-points go.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LinkTransport {
    /// A serial port (`port`, `baud`).
    Serial,
    /// UDP datagrams to `address`.
    Udp,
    /// A dry-run record of what would be sent.
    #[default]
    File,
}

/// Binary frames, text lines, or a board's own bytes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LinkFormat {
    /// The 34-byte frame with CRC.
    #[default]
    Binary,
    /// `S,seq,v1,…,v6` lines.
    Text,
    /// The bytes of `link.template` (`<255><255>{a1:u16be}…`: FlyPT Mover's and SimTools'
    /// output strings).
    Template,
    /// SMC3 (the Arduino DC-motor sketch): two boards of three motors, on `port` and
    /// `port2` (or `address`, `address2`).
    Smc3,
    /// ODrive's ASCII protocol: three two-axis boards on `port`, `port2`, `port3` (or the
    /// addresses), positions in turns (`turns_per_unit`, `turns_offset`).
    Odrive,
}

/// The unit of the values on the wire.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LinkOutput {
    /// Leg lengths in micrometres, servo angles in hundredths of a degree.
    #[default]
    Native,
    /// Servo pulse widths in microseconds (`pulse_zero_us`, `pulse_us_per_deg`); servos only.
    Pulse,
}

/// What an e-stop or the end of a stream does.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LinkStop {
    /// Stop where it is, braking within the limits.
    Hold,
    /// Return home at a tenth of the speed limit.
    #[default]
    Home,
}

/// The `[link]` table.
#[derive(Clone, Debug, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields, default)]
pub struct LinkSettings {
    /// Where set-points go.
    pub transport: LinkTransport,
    /// The serial port (`/dev/ttyUSB0`, `COM3`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub port: Option<String>,
    /// The serial line speed, bits per second.
    pub baud: u32,
    /// The UDP peer, `host:port`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub address: Option<String>,
    /// The second board's serial port (SMC3, ODrive).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub port2: Option<String>,
    /// The third board's serial port (ODrive).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub port3: Option<String>,
    /// The second board's UDP peer.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub address2: Option<String>,
    /// The third board's UDP peer.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub address3: Option<String>,
    /// Set-points per second.
    pub rate_hz: f64,
    /// Frames, lines, or a template's bytes.
    pub format: LinkFormat,
    /// The output template of `format = "template"`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub template: Option<String>,
    /// The unit on the wire.
    pub output: LinkOutput,
    /// Servo pulse at 0°, µs.
    pub pulse_zero_us: f64,
    /// Servo pulse change per degree, µs (negative turns the other way).
    pub pulse_us_per_deg: f64,
    /// Seconds of the arming ramp.
    pub ramp_s: f64,
    /// What a stop does.
    pub stop: LinkStop,
    /// Channel k carries actuator `actuator[k]` (1–6), each actuator on one channel.
    #[serde(deserialize_with = "crate::ground::text::exactly")]
    pub actuator: [u8; 6],
    /// Per channel: multiplies the value (after reversal).
    #[serde(deserialize_with = "crate::ground::text::exactly")]
    pub scale: [f64; 6],
    /// Per channel: added after scaling, in the value's natural unit (m or °).
    #[serde(deserialize_with = "crate::ground::text::exactly")]
    pub offset: [f64; 6],
    /// Per channel: mirror the value.
    #[serde(deserialize_with = "crate::ground::text::exactly")]
    pub reversed: [bool; 6],
    /// Per actuator, for ODrive: motor turns per metre of leg (or per degree of servo).
    #[serde(deserialize_with = "crate::ground::text::exactly")]
    pub turns_per_unit: [f64; 6],
    /// Per actuator, for ODrive: motor turns where the value is zero.
    #[serde(deserialize_with = "crate::ground::text::exactly")]
    pub turns_offset: [f64; 6],
}

impl Default for LinkSettings {
    fn default() -> Self {
        Self {
            transport: LinkTransport::File,
            port: None,
            baud: 115_200,
            address: None,
            port2: None,
            port3: None,
            address2: None,
            address3: None,
            rate_hz: 100.0,
            format: LinkFormat::Binary,
            template: None,
            output: LinkOutput::Native,
            pulse_zero_us: 1500.0,
            pulse_us_per_deg: 10.0,
            ramp_s: 2.0,
            stop: LinkStop::Home,
            actuator: [1, 2, 3, 4, 5, 6],
            scale: [1.0; 6],
            offset: [0.0; 6],
            reversed: [false; 6],
            turns_per_unit: [1.0; 6],
            turns_offset: [0.0; 6],
        }
    }
}

/// The lowest and highest set-point rates, hertz.
pub const RATES_HZ: (f64, f64) = (10.0, 1000.0);
/// The fastest serial line accepted, bits per second.
pub const MAX_BAUD: u32 = 12_000_000;
/// The longest arming ramp, seconds.
pub const MAX_RAMP_S: f64 = 600.0;

/// A `[link]` value refused: the key (`link.rate_hz`, `link.scale[2]`) and why.
#[derive(Clone, Debug, PartialEq)]
pub struct LinkProblem {
    /// The key, as `--set` and the file name it (array items as `link.scale[2]`).
    pub key: String,
    /// Why.
    pub reason: String,
}

/// The scenario key of the output template (where a refusal of it is placed).
pub const TEMPLATE_KEY: &str = "link.template";

/// A whole number however written (`115200`, `115200.0`, `1.152e5`), as every whole-number
/// setting takes it; `None` for a fraction, a sign below zero or more than `u32` holds.
fn whole(text: &str) -> Option<u32> {
    let v = text.trim().parse::<f64>().ok()?;
    (v.fract() == 0.0 && (0.0..=f64::from(u32::MAX)).contains(&v)).then_some(v as u32)
}

/// Why `address` is no UDP address `HOST:PORT` (a name or an IP, `[…]` around IPv6, a
/// port 1 to 65535), or `None` when it is one. Whether the host exists is only known when
/// the link opens it.
fn address_problem(address: &str) -> Option<String> {
    let not = |why: String| {
        Some(format!(
            "`{address}` is not an address like 192.168.1.20:9000 or localhost:9000: {why}"
        ))
    };
    let Some((host, port)) = address
        .trim()
        .rsplit_once(':')
        .filter(|(_, p)| !p.ends_with(']'))
    else {
        return not("it has no `:PORT`".to_owned());
    };
    // One pair of brackets at most, around the whole host.
    let inside = host.strip_prefix('[').and_then(|h| h.strip_suffix(']'));
    let bracketed = inside.is_some();
    let host = inside.unwrap_or(host);
    if host.is_empty() || host.contains(char::is_whitespace) {
        return not("it names no host".to_owned());
    }
    // `udp:1.2.3.4:99`: a scheme, or an IPv6 address outside its brackets; between
    // brackets goes an IPv6 address and nothing else.
    if (host.contains(':') || host.contains(['[', ']'])) && !bracketed {
        return not("write HOST:PORT alone (an IPv6 address between [ ])".to_owned());
    }
    if bracketed && host.parse::<std::net::Ipv6Addr>().is_err() {
        return not(format!("`{host}` between [ ] is not an IPv6 address"));
    }
    match port.parse::<u16>() {
        Ok(0) => not("port 0 names no peer".to_owned()),
        Ok(_) => None,
        Err(_) => not(format!("`{port}` is not a port number 1 to 65535")),
    }
}

/// The template the template format starts from: six 16-bit values between two 0xFF bytes
/// and a line end.
pub const STARTING_TEMPLATE: &str =
    "<255><255>{a1:u16be}{a2:u16be}{a3:u16be}{a4:u16be}{a5:u16be}{a6:u16be}<10><13>";

/// A template as written after `=` (in `--set`) or `template:` (in `--format`): its
/// leading spaces dropped and its end kept, as a space may be a byte the board reads.
/// The one rule for every place a template is written: `--set`, `--format`, a scenario
/// file's quoted string and the viewer's Link panel.
pub fn template_text(written: &str) -> &str {
    written.trim_start()
}

/// The template of a format written as `template:…` (see [`template_text`]), or `None`
/// for any other format word.
pub fn template_of_format(written: &str) -> Option<&str> {
    written
        .trim_start()
        .strip_prefix("template:")
        .map(template_text)
}

/// Why a key is not a `[link]` setting.
const UNKNOWN_KEY: &str = "unknown link setting (`stewart settings` lists every key)";

/// `value` as a finite number, or why not.
fn finite(value: &str) -> Result<f64, String> {
    value
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| format!("`{value}` is not a finite number"))
}

/// A problem with `key`, for `reason`.
fn bad(key: String, reason: String) -> Option<LinkProblem> {
    Some(LinkProblem { key, reason })
}

impl LinkSettings {
    /// The first value that cannot work, if any: a rate outside 10–1000 Hz, a baud rate of 0,
    /// an empty port or address, NaN or infinite numbers, a zero scale or pulse step, a pulse
    /// output without sensible pulse numbers, an actuator outside 1–6 or carried twice.
    pub fn problem(&self) -> Option<LinkProblem> {
        self.transport_problem()
            .or_else(|| self.text_problem())
            .or_else(|| self.output_problem())
            .or_else(|| self.channel_problem())
    }

    /// The rate, the baud and the template the format needs.
    fn transport_problem(&self) -> Option<LinkProblem> {
        let (lo, hi) = RATES_HZ;
        if !(lo..=hi).contains(&self.rate_hz) {
            return bad(
                "link.rate_hz".into(),
                format!("must be between {lo} and {hi} Hz, got {}", self.rate_hz),
            );
        }
        if !(1..=MAX_BAUD).contains(&self.baud) {
            return bad(
                "link.baud".into(),
                format!("must be between 1 and {MAX_BAUD}, got {}", self.baud),
            );
        }
        if self.format == LinkFormat::Template && self.template.is_none() {
            return bad(
                "link.template".into(),
                "the template format needs a template, such as \"<255><255>{a1:u16be}…{a6:u16be}\""
                    .into(),
            );
        }
        None
    }

    /// Ports, addresses and the template: not empty, addresses well formed.
    fn text_problem(&self) -> Option<LinkProblem> {
        for (key, text) in [
            ("port", &self.port),
            ("address", &self.address),
            ("port2", &self.port2),
            ("port3", &self.port3),
            ("address2", &self.address2),
            ("address3", &self.address3),
            ("template", &self.template),
        ] {
            if text.as_ref().is_some_and(|t| t.trim().is_empty()) {
                return bad(format!("link.{key}"), "must not be empty".into());
            }
        }
        for (key, text) in [
            ("address", &self.address),
            ("address2", &self.address2),
            ("address3", &self.address3),
        ] {
            if let Some(reason) = text.as_deref().and_then(address_problem) {
                return bad(format!("link.{key}"), reason);
            }
        }
        None
    }

    /// The ramp and the pulse output's numbers.
    fn output_problem(&self) -> Option<LinkProblem> {
        if !(0.0..=MAX_RAMP_S).contains(&self.ramp_s) {
            return bad(
                "link.ramp_s".into(),
                format!("must be between 0 and {MAX_RAMP_S} s, got {}", self.ramp_s),
            );
        }
        if !(0.0..=1e5).contains(&self.pulse_zero_us) {
            return bad(
                "link.pulse_zero_us".into(),
                format!(
                    "must be between 0 and 100000 µs, got {}",
                    self.pulse_zero_us
                ),
            );
        }
        if !(self.pulse_us_per_deg.is_finite()
            && self.pulse_us_per_deg != 0.0
            && self.pulse_us_per_deg.abs() <= 1e4)
        {
            return bad(
                "link.pulse_us_per_deg".into(),
                format!(
                    "must be a non-zero number of at most 10000 µs per degree, got {}",
                    self.pulse_us_per_deg
                ),
            );
        }
        None
    }

    /// Each channel: its actuator (one channel each), scale, offset and turns.
    fn channel_problem(&self) -> Option<LinkProblem> {
        for k in 0..6 {
            let a = self.actuator[k];
            if !(1..=6).contains(&a) {
                return bad(
                    format!("link.actuator[{k}]"),
                    format!("actuators are numbered 1 to 6, got {a}"),
                );
            }
            if let Some(first) = self.actuator[..k].iter().position(|&b| b == a) {
                return bad(
                    format!("link.actuator[{k}]"),
                    format!(
                        "channels {} and {} both carry actuator {a}: each actuator needs its own channel",
                        first + 1,
                        k + 1
                    ),
                );
            }
            let s = self.scale[k];
            if !(s.is_finite() && s != 0.0 && s.abs() <= 1e6) {
                return bad(
                    format!("link.scale[{k}]"),
                    format!("must be a non-zero number of size at most 1e6, got {s}"),
                );
            }
            let o = self.offset[k];
            if !(o.is_finite() && o.abs() <= 1e6) {
                return bad(
                    format!("link.offset[{k}]"),
                    format!("must be a number of size at most 1e6, got {o}"),
                );
            }
            let per = self.turns_per_unit[k];
            if !(per.is_finite() && per != 0.0 && per.abs() <= 1e6) {
                return bad(
                    format!("link.turns_per_unit[{k}]"),
                    format!("must be a non-zero number of size at most 1e6, got {per}"),
                );
            }
            let at_zero = self.turns_offset[k];
            if !(at_zero.is_finite() && at_zero.abs() <= 1e6) {
                return bad(
                    format!("link.turns_offset[{k}]"),
                    format!("must be a number of size at most 1e6, got {at_zero}"),
                );
            }
        }
        None
    }

    /// Change one key from its text (what `--set link.KEY=VALUE` does): `transport`,
    /// `port`, `address` (`off` removes them), `baud`, `rate_hz`, `format`, `output`,
    /// `pulse_zero_us`, `pulse_us_per_deg`, `ramp_s`, `stop`, and per channel
    /// `actuator.K`, `scale.K`, `offset.K`, `reversed.K` (K from 1 to 6). A refused value
    /// leaves the settings unchanged.
    pub fn set_text(&mut self, key: &str, value: &str) -> Result<(), LinkProblem> {
        let refuse = |reason: String| LinkProblem {
            key: format!("link.{key}"),
            reason,
        };
        let mut edited = self.clone();
        match key.split_once('.') {
            Some((name, k)) => {
                let k = k
                    .parse::<usize>()
                    .ok()
                    .filter(|k| (1..=6).contains(k))
                    .ok_or_else(|| refuse(format!("channels are numbered 1 to 6, got `{k}`")))?;
                edited.set_channel_text(name, k - 1, value.trim())
            }
            None => edited.set_table_text(key, value),
        }
        .map_err(refuse)?;
        if let Some(p) = edited.problem() {
            return Err(refuse(p.reason));
        }
        *self = edited;
        Ok(())
    }

    /// One table-wide key of [`LinkSettings::set_text`], unchecked: why `raw` cannot be
    /// read, else `Ok`. A template's text keeps its end (see [`template_text`]); every
    /// other value is trimmed.
    fn set_table_text(&mut self, name: &str, raw: &str) -> Result<(), String> {
        let value = raw.trim();
        match name {
            "transport" => {
                self.transport = choice(value)?;
            }
            "port" | "address" | "port2" | "port3" | "address2" | "address3" => {
                let text = (!value.eq_ignore_ascii_case("off")).then(|| value.to_owned());
                *match name {
                    "port" => &mut self.port,
                    "port2" => &mut self.port2,
                    "port3" => &mut self.port3,
                    "address" => &mut self.address,
                    "address2" => &mut self.address2,
                    _ => &mut self.address3,
                } = text;
            }
            "baud" => {
                self.baud = whole(value)
                    .ok_or_else(|| format!("`{value}` is not a whole number of bits per second"))?;
            }
            "rate_hz" => self.rate_hz = finite(value)?,
            "format" => match template_of_format(raw) {
                // `template:<255>…` sets both.
                Some(template) => {
                    self.format = LinkFormat::Template;
                    self.template = Some(template.to_owned());
                }
                None => {
                    self.format = choice(value)?;
                    // The template format starts from a board's usual frame until a
                    // template is given (in either order of `--set`).
                    if self.format == LinkFormat::Template && self.template.is_none() {
                        self.template = Some(STARTING_TEMPLATE.to_owned());
                    }
                }
            },
            "template" => {
                self.template =
                    (!value.eq_ignore_ascii_case("off")).then(|| template_text(raw).to_owned());
            }
            "output" => {
                self.output = choice(value)?;
            }
            "pulse_zero_us" => self.pulse_zero_us = finite(value)?,
            "pulse_us_per_deg" => self.pulse_us_per_deg = finite(value)?,
            "ramp_s" => self.ramp_s = finite(value)?,
            "stop" => self.stop = choice(value)?,
            _ => return Err(UNKNOWN_KEY.to_owned()),
        }
        Ok(())
    }

    /// One channel's key of [`LinkSettings::set_text`] (`k` from 0), unchecked.
    fn set_channel_text(&mut self, name: &str, k: usize, value: &str) -> Result<(), String> {
        match name {
            "actuator" => {
                self.actuator[k] = whole(value)
                    .and_then(|n| u8::try_from(n).ok())
                    .ok_or_else(|| format!("`{value}` is not an actuator number 1 to 6"))?;
            }
            "scale" => self.scale[k] = finite(value)?,
            "turns_per_unit" => self.turns_per_unit[k] = finite(value)?,
            "turns_offset" => self.turns_offset[k] = finite(value)?,
            "offset" => self.offset[k] = finite(value)?,
            "reversed" => {
                // As every switch takes it: true or false, on or off, 1 or 0.
                self.reversed[k] = super::switch::read(value).ok_or_else(|| {
                    format!("`{value}` is not a switch: {}", super::switch::ACCEPTS)
                })?;
            }
            _ => return Err(UNKNOWN_KEY.to_owned()),
        }
        Ok(())
    }

    /// Every key `set_text` takes with its current value, for `stewart settings`.
    pub fn entries(&self) -> Vec<(String, String)> {
        let mut rows = vec![
            ("transport".to_owned(), self.transport.word().to_owned()),
            (
                "port".to_owned(),
                self.port.clone().unwrap_or_else(|| "off".into()),
            ),
            ("baud".to_owned(), self.baud.to_string()),
            (
                "address".to_owned(),
                self.address.clone().unwrap_or_else(|| "off".into()),
            ),
            (
                "port2".to_owned(),
                self.port2.clone().unwrap_or_else(|| "off".into()),
            ),
            (
                "port3".to_owned(),
                self.port3.clone().unwrap_or_else(|| "off".into()),
            ),
            (
                "address2".to_owned(),
                self.address2.clone().unwrap_or_else(|| "off".into()),
            ),
            (
                "address3".to_owned(),
                self.address3.clone().unwrap_or_else(|| "off".into()),
            ),
            ("rate_hz".to_owned(), self.rate_hz.to_string()),
            ("format".to_owned(), self.format.word().to_owned()),
            (
                "template".to_owned(),
                self.template.clone().unwrap_or_else(|| "off".into()),
            ),
            ("output".to_owned(), self.output.word().to_owned()),
            ("pulse_zero_us".to_owned(), self.pulse_zero_us.to_string()),
            (
                "pulse_us_per_deg".to_owned(),
                self.pulse_us_per_deg.to_string(),
            ),
            ("ramp_s".to_owned(), self.ramp_s.to_string()),
            ("stop".to_owned(), self.stop.word().to_owned()),
        ];
        for k in 0..6 {
            rows.push((format!("actuator.{}", k + 1), self.actuator[k].to_string()));
            rows.push((format!("scale.{}", k + 1), self.scale[k].to_string()));
            rows.push((format!("offset.{}", k + 1), self.offset[k].to_string()));
            rows.push((format!("reversed.{}", k + 1), self.reversed[k].to_string()));
            rows.push((
                format!("turns_per_unit.{}", k + 1),
                self.turns_per_unit[k].to_string(),
            ));
            rows.push((
                format!("turns_offset.{}", k + 1),
                self.turns_offset[k].to_string(),
            ));
        }
        rows.into_iter()
            .map(|(k, v)| (format!("link.{k}"), v))
            .collect()
    }
}

/// A choice written as a word in files, on the command line and in the viewer.
pub trait Word: Sized + Copy + PartialEq + 'static {
    /// Every choice with its word.
    const WORDS: &'static [(Self, &'static str)];

    /// The word for this choice.
    fn word(self) -> &'static str {
        Self::WORDS
            .iter()
            .find(|(v, _)| *v == self)
            .map_or("", |(_, w)| w)
    }

    /// The choice a word names (any case).
    fn from_word(text: &str) -> Option<Self> {
        Self::WORDS
            .iter()
            .find(|(_, w)| w.eq_ignore_ascii_case(text.trim()))
            .map(|(v, _)| *v)
    }

    /// The words, for messages: `serial, udp, file`.
    fn choices() -> String {
        Self::WORDS
            .iter()
            .map(|(_, w)| *w)
            .collect::<Vec<_>>()
            .join(", ")
    }
}

impl Word for LinkTransport {
    const WORDS: &'static [(Self, &'static str)] = &[
        (LinkTransport::Serial, "serial"),
        (LinkTransport::Udp, "udp"),
        (LinkTransport::File, "file"),
    ];
}

impl Word for LinkFormat {
    const WORDS: &'static [(Self, &'static str)] = &[
        (LinkFormat::Binary, "binary"),
        (LinkFormat::Text, "text"),
        (LinkFormat::Template, "template"),
        (LinkFormat::Smc3, "smc3"),
        (LinkFormat::Odrive, "odrive"),
    ];
}

impl Word for LinkOutput {
    const WORDS: &'static [(Self, &'static str)] =
        &[(LinkOutput::Native, "native"), (LinkOutput::Pulse, "pulse")];
}

impl Word for LinkStop {
    const WORDS: &'static [(Self, &'static str)] =
        &[(LinkStop::Hold, "hold"), (LinkStop::Home, "home")];
}

/// The choice `value` names, or why not.
fn choice<T: Word>(value: &str) -> Result<T, String> {
    T::from_word(value).ok_or_else(|| format!("`{value}` is not one of {}", T::choices()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_sound_and_every_entry_can_be_set_back() {
        let d = LinkSettings::default();
        assert_eq!(d.problem(), None);
        let mut copy = d.clone();
        for (key, value) in d.entries() {
            let key = key.strip_prefix("link.").unwrap_or_default().to_owned();
            copy.set_text(&key, &value)
                .unwrap_or_else(|p| panic!("{key}={value}: {}", p.reason));
        }
        assert_eq!(copy, d);
        assert!(
            d.entries()
                .iter()
                .any(|(k, v)| k == "link.transport" && v == "file")
        );
    }

    #[test]
    fn set_text_changes_one_key_and_refuses_bad_values_without_change() {
        let mut s = LinkSettings::default();
        s.set_text("transport", "UDP")
            .unwrap_or_else(|p| panic!("{}", p.reason));
        s.set_text("address", "127.0.0.1:9000")
            .unwrap_or_else(|p| panic!("{}", p.reason));
        s.set_text("reversed.3", "true")
            .unwrap_or_else(|p| panic!("{}", p.reason));
        s.set_text("actuator.1", "2").err().map_or_else(
            || panic!("a duplicate actuator was accepted"),
            |p| {
                assert_eq!(p.key, "link.actuator.1");
                assert!(
                    p.reason.contains("channels 1 and 2 both carry actuator 2"),
                    "{}",
                    p.reason
                );
            },
        );
        assert_eq!(s.transport, LinkTransport::Udp);
        assert_eq!(s.address.as_deref(), Some("127.0.0.1:9000"));
        assert_eq!(s.reversed, [false, false, true, false, false, false]);
        // A switch takes the words every switch takes.
        s.set_text("reversed.5", "ON")
            .unwrap_or_else(|p| panic!("{}", p.reason));
        s.set_text("reversed.5", "0")
            .unwrap_or_else(|p| panic!("{}", p.reason));
        assert_eq!(s.reversed, [false, false, true, false, false, false]);
        assert_eq!(s.actuator, [1, 2, 3, 4, 5, 6]);
        let before = s.clone();
        for (key, value, words) in [
            ("rate_hz", "0", "between 10 and 1000"),
            ("rate_hz", "1001", "between 10 and 1000"),
            ("rate_hz", "NaN", "not a finite number"),
            ("baud", "0", "between 1 and"),
            ("baud", "-5", "not a whole number"),
            ("scale.2", "0", "non-zero"),
            ("offset.7", "1", "numbered 1 to 6"),
            ("transport", "tcp", "not one of serial, udp, file"),
            ("port", " ", "must not be empty"),
            ("pulse_us_per_deg", "0", "non-zero"),
            ("ramp_s", "-1", "between 0 and"),
            ("colour", "red", "unknown link setting"),
            ("reversed.1", "maybe", "not a switch: true or false"),
        ] {
            let p = s
                .set_text(key, value)
                .err()
                .unwrap_or_else(|| panic!("{key}={value} was accepted"));
            assert!(p.reason.contains(words), "{key}={value}: {}", p.reason);
            assert_eq!(p.key, format!("link.{key}"));
        }
        assert_eq!(s, before);
    }
}
