//! Where the bytes go: a serial port, a UDP peer, or a dry-run record of exactly what
//! would be sent.

#[cfg(feature = "serial")]
mod serial;

#[cfg(feature = "serial")]
pub use serial::{PortInfo, Serial, list_ports, max_rate_hz};

use std::io::Write;
use std::net::{SocketAddr, ToSocketAddrs, UdpSocket};

use thiserror::Error;

/// Why a transport could not be opened or used.
#[derive(Debug, Error)]
pub enum TransportError {
    /// The address is not `host:port`.
    #[error("`{address}` is not an address like 192.168.1.20:9000 or localhost:9000: {reason}")]
    Address {
        /// What was given.
        address: String,
        /// Why it did not resolve.
        reason: String,
    },
    /// A setting cannot work (a baud rate of 0).
    #[error("{0}")]
    Setting(String),
    /// The operating system refused.
    #[error("{what}: {cause}")]
    Io {
        /// What was being done.
        what: String,
        /// The system's words (part of the message, not a separate cause: said once).
        cause: std::io::Error,
    },
}

/// A read's outcome as a byte count: what came, 0 when nothing came in time (or when the
/// error is one of `nothing_yet`), else the error with what was being done.
pub fn bytes_read(
    read: std::io::Result<usize>,
    nothing_yet: &[std::io::ErrorKind],
    what: impl FnOnce() -> String,
) -> Result<usize, TransportError> {
    match read {
        Ok(n) => Ok(n),
        Err(e) if nothing_yet.contains(&e.kind()) => Ok(0),
        Err(cause) => Err(TransportError::Io {
            what: what(),
            cause,
        }),
    }
}

/// The errors that mean "nothing has come yet" for a read that does not wait (or waits
/// with a timeout).
pub const NOTHING_YET: [std::io::ErrorKind; 2] =
    [std::io::ErrorKind::WouldBlock, std::io::ErrorKind::TimedOut];

/// A way to send frames or lines.
pub trait Transport: Send {
    /// Send one frame (or one text line) sampled at `t` seconds since the stream began.
    fn send(&mut self, t: f64, bytes: &[u8]) -> Result<(), TransportError>;
    /// What it sends to, for messages.
    fn describe(&self) -> String;

    /// Bytes that have come back (telemetry), without waiting; `Ok(0)` when none (and for
    /// transports that carry nothing back).
    fn receive(&mut self, _buf: &mut [u8]) -> Result<usize, TransportError> {
        Ok(0)
    }

    /// Send to port `port` of a transport with several (a board protocol's boards, each on
    /// its own serial port); a transport of one port takes port 0 only.
    fn send_on(&mut self, port: usize, t: f64, bytes: &[u8]) -> Result<(), TransportError> {
        if port == 0 {
            self.send(t, bytes)
        } else {
            Err(TransportError::Setting(format!(
                "{} is one port; the board protocol sends to {} (give --port2, --port3)",
                self.describe(),
                port + 1
            )))
        }
    }
}

/// Several transports, one a board: port k is the k-th.
pub struct Ports(pub Vec<Box<dyn Transport>>);

impl Transport for Ports {
    fn send(&mut self, t: f64, bytes: &[u8]) -> Result<(), TransportError> {
        self.send_on(0, t, bytes)
    }

    fn send_on(&mut self, port: usize, t: f64, bytes: &[u8]) -> Result<(), TransportError> {
        let count = self.0.len();
        let transport = self
            .0
            .get_mut(port)
            .ok_or_else(|| TransportError::Setting(format!("port {} of {count}", port + 1)))?;
        transport.send(t, bytes)
    }

    fn describe(&self) -> String {
        let each: Vec<String> = self.0.iter().map(|p| p.describe()).collect();
        each.join(" and ")
    }

    fn receive(&mut self, buf: &mut [u8]) -> Result<usize, TransportError> {
        match self.0.first_mut() {
            Some(first) => first.receive(buf),
            None => Ok(0),
        }
    }
}

/// UDP datagrams to one peer, one frame per datagram.
pub struct Udp {
    socket: UdpSocket,
    peer: SocketAddr,
}

impl Udp {
    /// A socket on an ephemeral local port, aimed at `address` (`host:port`).
    pub fn connect(address: &str) -> Result<Self, TransportError> {
        let bad = |reason: String| TransportError::Address {
            address: address.to_owned(),
            reason,
        };
        let peer = address
            .to_socket_addrs()
            .map_err(|e| bad(e.to_string()))?
            .next()
            .ok_or_else(|| bad("it names no address".to_owned()))?;
        if peer.port() == 0 {
            return Err(bad("port 0 names no peer".to_owned()));
        }
        let local: SocketAddr = if peer.is_ipv4() {
            ([0, 0, 0, 0], 0).into()
        } else {
            ([0u16; 8], 0).into()
        };
        let io = |what: &str| {
            let what = format!("{what} {peer}");
            move |cause| TransportError::Io { what, cause }
        };
        let socket = UdpSocket::bind(local).map_err(io("cannot open a UDP socket for"))?;
        socket.connect(peer).map_err(io("cannot aim UDP at"))?;
        socket
            .set_nonblocking(true)
            .map_err(io("cannot set up UDP to"))?;
        Ok(Self { socket, peer })
    }
}

impl Transport for Udp {
    fn send(&mut self, _t: f64, bytes: &[u8]) -> Result<(), TransportError> {
        self.socket
            .send(bytes)
            .map(|_| ())
            .map_err(|cause| TransportError::Io {
                what: format!("sending to {}", self.peer),
                cause,
            })
    }

    fn describe(&self) -> String {
        format!("UDP {}", self.peer)
    }

    fn receive(&mut self, buf: &mut [u8]) -> Result<usize, TransportError> {
        let got = self.socket.recv(buf);
        // A peer that is not listening answers a datagram with "connection refused", which
        // the system reports on the next call on the socket, this one: it is the send's.
        let what = match &got {
            Err(e) if e.kind() == std::io::ErrorKind::ConnectionRefused => "sending to",
            _ => "receiving from",
        };
        bytes_read(got, &[std::io::ErrorKind::WouldBlock], || {
            format!("{what} {}", self.peer)
        })
    }
}

/// A dry run: each frame as a line `t_s <TAB> bytes in hex` (or the text line itself,
/// after the time), into any writer (a file, standard output); or, [`Record::raw`], the
/// bytes exactly as they would go to the port.
pub struct Record<W: Write + Send> {
    out: W,
    name: String,
    raw: bool,
}

impl<W: Write + Send> Record<W> {
    /// Record into `out`, called `name` in messages.
    pub fn new(out: W, name: impl Into<String>) -> Self {
        Self {
            out,
            name: name.into(),
            raw: false,
        }
    }

    /// Write the bytes into `out` as they are, nothing added (a board's own bytes, to
    /// compare with what it expects).
    pub fn raw(out: W, name: impl Into<String>) -> Self {
        Self {
            raw: true,
            ..Self::new(out, name)
        }
    }

    /// The writer back (to flush or inspect it).
    pub fn into_inner(self) -> W {
        self.out
    }
}

impl<W: Write + Send> Transport for Record<W> {
    fn send(&mut self, t: f64, bytes: &[u8]) -> Result<(), TransportError> {
        let failed = |cause, name: &str| TransportError::Io {
            what: format!("writing the dry run to {name}"),
            cause,
        };
        if self.raw {
            return (self.out.write_all(bytes))
                .and_then(|()| self.out.flush())
                .map_err(|cause| failed(cause, &self.name));
        }
        let body = if bytes.ends_with(b"\n") && bytes.is_ascii() {
            String::from_utf8_lossy(bytes).trim_end().to_owned()
        } else {
            bytes
                .iter()
                .map(|b| format!("{b:02X}"))
                .collect::<Vec<_>>()
                .join(" ")
        };
        writeln!(self.out, "{t:.6}\t{body}")
            .and_then(|()| self.out.flush())
            .map_err(|cause| failed(cause, &self.name))
    }

    fn describe(&self) -> String {
        format!("dry run into {}", self.name)
    }

    /// A board's port: its lines (or bytes in hex) after the time and `port k`; raw, the
    /// bytes as they are.
    fn send_on(&mut self, port: usize, t: f64, bytes: &[u8]) -> Result<(), TransportError> {
        if self.raw {
            return self.send(t, bytes);
        }
        let text = String::from_utf8_lossy(bytes);
        let lines: Vec<String> = if bytes.is_ascii() && bytes.ends_with(b"\n") {
            text.lines().map(str::to_owned).collect()
        } else {
            vec![
                bytes
                    .iter()
                    .map(|b| format!("{b:02X}"))
                    .collect::<Vec<_>>()
                    .join(" "),
            ]
        };
        for line in lines {
            writeln!(self.out, "{t:.6}\tport {}\t{line}", port + 1).map_err(|cause| {
                TransportError::Io {
                    what: format!("writing the dry run to {}", self.name),
                    cause,
                }
            })?;
        }
        self.out.flush().map_err(|cause| TransportError::Io {
            what: format!("writing the dry run to {}", self.name),
            cause,
        })
    }
}

#[cfg(test)]
mod tests;
