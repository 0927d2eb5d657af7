//! The channel map: which actuator value goes out on which of the six channels, and how it
//! is scaled, offset and mirrored on the way — and for servos driven by pulse width, the
//! pulse at 0° and per degree.
//!
//! Values come in their natural units (leg lengths in metres, servo angles in degrees).
//! Channel `k` sends `v = ±values[source] · scale + offset` (minus when `reversed`), then
//! in the link's unit: micrometres, hundredths of a degree, or
//! `zero_us + us_per_degree · v` microseconds of pulse.

use thiserror::Error;

use crate::frame::ValueUnit;

/// One output channel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OutputChannel {
    /// The actuator (0–5) whose value this channel carries.
    pub source: usize,
    /// Multiplies the value (after reversal).
    pub scale: f64,
    /// Added after scaling, in the value's natural unit.
    pub offset: f64,
    /// Mirror the value (a servo mounted the other way round).
    pub reversed: bool,
}

impl OutputChannel {
    /// Actuator `source` as it is.
    pub fn straight(source: usize) -> Self {
        Self {
            source,
            scale: 1.0,
            offset: 0.0,
            reversed: false,
        }
    }
}

/// What the six channels carry on the wire.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Output {
    /// Leg lengths, micrometres.
    LegMicrometre,
    /// Servo angles, hundredths of a degree.
    ServoCentidegree,
    /// Servo pulse widths, microseconds: `zero_us` at 0°, `us_per_degree` more per degree.
    ServoPulse {
        /// Pulse width at 0°, µs (1500 for most hobby servos).
        zero_us: f64,
        /// Change of pulse width per degree, µs (about 10 for hobby servos; negative to turn the other way).
        us_per_degree: f64,
    },
}

impl Output {
    /// The unit of the frame's values.
    pub fn unit(self) -> ValueUnit {
        match self {
            Output::LegMicrometre => ValueUnit::Micrometre,
            Output::ServoCentidegree => ValueUnit::Centidegree,
            Output::ServoPulse { .. } => ValueUnit::PulseMicrosecond,
        }
    }
}

/// A checked channel map.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChannelMap {
    channels: [OutputChannel; 6],
    output: Output,
}

/// Why a channel map or a value was refused.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum ChannelError {
    /// A source outside 0–5 (written 1–6 for people).
    #[error("channel {channel} takes actuator {source_number}, but actuators are numbered 1 to 6")]
    Source {
        /// Channel number, from 1.
        channel: usize,
        /// The actuator number given, from 1.
        source_number: usize,
    },
    /// Two channels carry the same actuator (and so another actuator is carried by none).
    #[error(
        "channels {first} and {second} both carry actuator {actuator}: each actuator needs its own channel"
    )]
    Duplicate {
        /// The first channel, from 1.
        first: usize,
        /// The second channel, from 1.
        second: usize,
        /// The actuator, from 1.
        actuator: usize,
    },
    /// A scale, offset or pulse number that is not finite, or a zero scale.
    #[error("channel {channel}: `{field}` must be a finite number{nonzero}, got {value}")]
    Number {
        /// Channel number, from 1 (0 for the pulse settings shared by all).
        channel: usize,
        /// The field.
        field: &'static str,
        /// ", not zero" where zero is refused.
        nonzero: &'static str,
        /// The value given.
        value: f64,
    },
    /// A value that does not fit the wire's integers (or is not a number).
    #[error("channel {channel}: {value} does not fit the link's {unit} integers")]
    Overflow {
        /// Channel number, from 1.
        channel: usize,
        /// The value in the link's unit before rounding.
        value: f64,
        /// The unit's name.
        unit: &'static str,
    },
}

impl ChannelMap {
    /// A checked map: every actuator on exactly one channel, finite non-zero scales, finite
    /// offsets and pulse settings.
    pub fn new(channels: [OutputChannel; 6], output: Output) -> Result<Self, ChannelError> {
        for (k, c) in channels.iter().enumerate() {
            if c.source > 5 {
                return Err(ChannelError::Source {
                    channel: k + 1,
                    source_number: c.source + 1,
                });
            }
            if let Some(first) = channels[..k].iter().position(|d| d.source == c.source) {
                return Err(ChannelError::Duplicate {
                    first: first + 1,
                    second: k + 1,
                    actuator: c.source + 1,
                });
            }
            for (field, value, nonzero) in [("scale", c.scale, true), ("offset", c.offset, false)] {
                if !value.is_finite() || (nonzero && value == 0.0) {
                    return Err(ChannelError::Number {
                        channel: k + 1,
                        field,
                        nonzero: if nonzero { ", not zero" } else { "" },
                        value,
                    });
                }
            }
        }
        if let Output::ServoPulse {
            zero_us,
            us_per_degree,
        } = output
        {
            for (field, value, nonzero) in [
                ("pulse_zero_us", zero_us, false),
                ("pulse_us_per_deg", us_per_degree, true),
            ] {
                if !value.is_finite() || (nonzero && value == 0.0) {
                    return Err(ChannelError::Number {
                        channel: 0,
                        field,
                        nonzero: if nonzero { ", not zero" } else { "" },
                        value,
                    });
                }
            }
        }
        Ok(Self { channels, output })
    }

    /// Actuator `k` on channel `k`, unscaled.
    pub fn identity(output: Output) -> Self {
        Self {
            channels: std::array::from_fn(OutputChannel::straight),
            output,
        }
    }

    /// The channels.
    pub fn channels(&self) -> &[OutputChannel; 6] {
        &self.channels
    }

    /// What the channels carry.
    pub fn output(&self) -> Output {
        self.output
    }

    /// The six wire integers for actuator `values` in their natural units.
    pub fn wire(&self, values: &[f64; 6]) -> Result<[i32; 6], ChannelError> {
        let unit = self.output.unit();
        let mut out = [0; 6];
        for (k, c) in self.channels.iter().enumerate() {
            let sign = if c.reversed { -1.0 } else { 1.0 };
            let v = sign * values[c.source] * c.scale + c.offset;
            let natural = match self.output {
                Output::ServoPulse {
                    zero_us,
                    us_per_degree,
                } => zero_us + us_per_degree * v,
                _ => v,
            };
            out[k] = unit.to_fixed(natural).ok_or(ChannelError::Overflow {
                channel: k + 1,
                value: natural * unit.per_natural_unit(),
                unit: match unit {
                    ValueUnit::Micrometre => "micrometre",
                    ValueUnit::Centidegree => "centidegree",
                    ValueUnit::PulseMicrosecond => "microsecond",
                },
            })?;
        }
        Ok(out)
    }

    /// The actuator values, natural units, that `wire` integers stand for: [`ChannelMap::wire`]
    /// undone (to the wire's rounding), for the values a controller reports back.
    pub fn natural(&self, wire: &[i32; 6]) -> [f64; 6] {
        let unit = self.output.unit();
        let mut out = [0.0; 6];
        for (k, c) in self.channels.iter().enumerate() {
            let natural = f64::from(wire[k]) / unit.per_natural_unit();
            let v = match self.output {
                Output::ServoPulse {
                    zero_us,
                    us_per_degree,
                } => (natural - zero_us) / us_per_degree,
                _ => natural,
            };
            let sign = if c.reversed { -1.0 } else { 1.0 };
            out[c.source] = sign * (v - c.offset) / c.scale;
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_are_routed_scaled_mirrored_and_converted() {
        let legs = ChannelMap::identity(Output::LegMicrometre);
        assert_eq!(
            legs.wire(&[0.5, 0.6, 0.7, 0.8, 0.9, 1.0]),
            Ok([500_000, 600_000, 700_000, 800_000, 900_000, 1_000_000])
        );
        // Channel 1 carries servo 2 mirrored, channel 2 servo 1 with a 2° offset; pulses
        // of 1500 µs at 0° and 10 µs per degree.
        let mut channels = std::array::from_fn(OutputChannel::straight);
        channels[0] = OutputChannel {
            source: 1,
            reversed: true,
            ..OutputChannel::straight(1)
        };
        channels[1] = OutputChannel {
            offset: 2.0,
            ..OutputChannel::straight(0)
        };
        let map = ChannelMap::new(
            channels,
            Output::ServoPulse {
                zero_us: 1500.0,
                us_per_degree: 10.0,
            },
        )
        .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(map.output().unit(), ValueUnit::PulseMicrosecond);
        let angles = [10.0, 20.0, -30.0, 0.0, 45.5, -90.0];
        assert_eq!(map.wire(&angles), Ok([1300, 1620, 1200, 1500, 1955, 600]));
        let deg = ChannelMap::identity(Output::ServoCentidegree);
        assert_eq!(deg.wire(&angles), Ok([1000, 2000, -3000, 0, 4550, -9000]));
        // A value the wire cannot carry is refused, naming the channel.
        let e = legs.wire(&[0.5, 0.5, 5000.0, 0.5, 0.5, 0.5]).unwrap_err();
        assert!(e.to_string().starts_with("channel 3: "), "{e}");
        assert!(legs.wire(&[f64::NAN; 6]).is_err());
    }

    #[test]
    fn a_map_with_two_channels_for_one_actuator_is_refused() {
        let mut channels = std::array::from_fn(OutputChannel::straight);
        channels[4].source = 1;
        assert_eq!(
            ChannelMap::new(channels, Output::LegMicrometre)
                .unwrap_err()
                .to_string(),
            "channels 2 and 5 both carry actuator 2: each actuator needs its own channel"
        );
        let mut channels = std::array::from_fn(OutputChannel::straight);
        channels[3].scale = 0.0;
        assert!(
            ChannelMap::new(channels, Output::LegMicrometre)
                .unwrap_err()
                .to_string()
                .contains("`scale` must be a finite number, not zero")
        );
        let e = ChannelMap::new(
            std::array::from_fn(OutputChannel::straight),
            Output::ServoPulse {
                zero_us: 1500.0,
                us_per_degree: f64::INFINITY,
            },
        )
        .unwrap_err();
        assert!(e.to_string().contains("pulse_us_per_deg"), "{e}");
        let mut channels = std::array::from_fn(OutputChannel::straight);
        channels[0].source = 6;
        assert!(ChannelMap::new(channels, Output::LegMicrometre).is_err());
    }

    #[test]
    fn the_wire_read_back_gives_the_values_to_its_rounding() {
        let mut channels = std::array::from_fn(OutputChannel::straight);
        channels[0] = OutputChannel {
            source: 3,
            reversed: true,
            scale: 1.5,
            offset: -2.0,
        };
        channels[3] = OutputChannel::straight(0);
        let values = [12.345, -7.5, 0.0, 33.3, -45.0, 8.125];
        for output in [
            Output::ServoCentidegree,
            Output::ServoPulse {
                zero_us: 1500.0,
                us_per_degree: -10.0,
            },
        ] {
            let map = ChannelMap::new(channels, output).unwrap_or_else(|e| panic!("{e}"));
            let wire = map.wire(&values).unwrap_or_else(|e| panic!("{e}"));
            let back = map.natural(&wire);
            for (a, b) in back.iter().zip(&values) {
                assert!((a - b).abs() < 0.1, "{output:?}: {back:?} vs {values:?}");
            }
        }
        let legs = ChannelMap::identity(Output::LegMicrometre);
        assert_eq!(legs.natural(&[1_000_000, 0, -5, 1, 2, 3])[0], 1.0);
        assert_eq!(legs.natural(&[1_000_000, 0, -5, 1, 2, 3])[2], -5e-6);
    }
}
