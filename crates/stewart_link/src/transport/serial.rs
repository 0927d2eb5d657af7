//! A serial port (a USB-serial adapter, a microcontroller's virtual COM port).

use std::io::Write;
use std::time::Duration;

use super::{Transport, TransportError};

/// The system's words for a serial port error.
fn system_error(e: serialport::Error) -> std::io::Error {
    e.into()
}

/// The bits on the line per byte: start, eight data bits, stop (8N1).
const BITS_PER_BYTE: f64 = 10.0;

/// Frames or lines written to a serial port, 8N1, no flow control.
pub struct Serial {
    port: Box<dyn serialport::SerialPort>,
    name: String,
}

/// One port the system offers, for `--list-ports`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PortInfo {
    /// What to pass as `--port` (`/dev/ttyUSB0`, `COM3`).
    pub name: String,
    /// What is behind it, in words (`USB 2341:0043 Arduino Uno`, `PCI`, `Bluetooth`).
    pub kind: String,
}

/// The ports the system offers, sorted by name.
pub fn list_ports() -> Result<Vec<PortInfo>, TransportError> {
    let ports = serialport::available_ports().map_err(|e| TransportError::Io {
        what: "listing the serial ports".to_owned(),
        cause: system_error(e),
    })?;
    let mut list: Vec<PortInfo> = ports
        .into_iter()
        .map(|p| PortInfo {
            name: p.port_name,
            kind: match p.port_type {
                serialport::SerialPortType::UsbPort(usb) => {
                    let words: Vec<String> = [usb.manufacturer, usb.product, usb.serial_number]
                        .into_iter()
                        .flatten()
                        .collect();
                    format!("USB {:04x}:{:04x} {}", usb.vid, usb.pid, words.join(" "))
                        .trim_end()
                        .to_owned()
                }
                serialport::SerialPortType::PciPort => "PCI".to_owned(),
                serialport::SerialPortType::BluetoothPort => "Bluetooth".to_owned(),
                serialport::SerialPortType::Unknown => "unknown".to_owned(),
            },
        })
        .collect();
    list.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(list)
}

/// The most frames per second `baud` carries for frames of `bytes` bytes (8N1).
pub fn max_rate_hz(baud: u32, bytes: usize) -> f64 {
    f64::from(baud) / (BITS_PER_BYTE * bytes.max(1) as f64)
}

impl Serial {
    /// Open `port` at `baud` (8N1). A write that cannot finish within `timeout` is an
    /// error (the device stopped reading, the cable is gone); a read waits that long.
    pub fn open(port: &str, baud: u32, timeout: Duration) -> Result<Self, TransportError> {
        if baud == 0 {
            return Err(TransportError::Setting(format!(
                "the baud rate of {port} must be above 0"
            )));
        }
        let opened = serialport::new(port, baud)
            .timeout(timeout)
            .open()
            .map_err(|e| TransportError::Io {
                what: format!("cannot open the serial port {port}"),
                cause: system_error(e),
            })?;
        Ok(Self {
            port: opened,
            name: format!("{port} at {baud} baud"),
        })
    }

    /// Read what has arrived (telemetry, or frames for a stand-in device) into `buf`,
    /// waiting at most the port's timeout; `Ok(0)` when nothing came.
    pub fn read_waiting(&mut self, buf: &mut [u8]) -> Result<usize, TransportError> {
        use std::io::Read as _;
        super::bytes_read(self.port.read(buf), &super::NOTHING_YET, || {
            format!("reading from {}", self.name)
        })
    }
}

impl Transport for Serial {
    fn send(&mut self, _t: f64, bytes: &[u8]) -> Result<(), TransportError> {
        self.port
            .write_all(bytes)
            .map_err(|cause| TransportError::Io {
                what: format!("writing to {}", self.name),
                cause,
            })
    }

    fn describe(&self) -> String {
        format!("serial {}", self.name)
    }

    fn receive(&mut self, buf: &mut [u8]) -> Result<usize, TransportError> {
        let waiting = self.port.bytes_to_read().map_err(|e| TransportError::Io {
            what: format!("reading from {}", self.name),
            cause: system_error(e),
        })? as usize;
        if waiting == 0 {
            return Ok(0);
        }
        let n = waiting.min(buf.len());
        self.read_waiting(&mut buf[..n])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_line_rate_limits_the_frame_rate() {
        // 115200 baud, 34-byte frames: 340 bits each, 338.8 frames per second.
        assert!((max_rate_hz(115_200, 34) - 115_200.0 / 340.0).abs() < 1e-9);
        assert!((max_rate_hz(1_000_000, 34) - 1e6 / 340.0).abs() < 1e-9);
    }

    #[test]
    fn a_missing_port_is_named() {
        let e = Serial::open("/dev/no-such-port", 115_200, Duration::from_millis(10))
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default();
        assert!(
            e.starts_with("cannot open the serial port /dev/no-such-port"),
            "{e}"
        );
        let e = Serial::open("/dev/null", 0, Duration::from_millis(10))
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default();
        assert!(e.contains("baud rate"), "{e}");
    }
}
