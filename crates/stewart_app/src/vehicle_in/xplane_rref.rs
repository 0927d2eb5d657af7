//! Keeping X-Plane sending the datarefs of motion by `RREF` (`stewart_link::vehicle::xplane`
//! lays the requests out): asked at once, asked again every few seconds (X-Plane forgets its
//! subscribers when it restarts or loads a flight), and stopped at the end. X-Plane answers
//! to the address the requests came from, so they go out of the socket that listens.

use std::net::{SocketAddr, ToSocketAddrs, UdpSocket};
use std::time::{Duration, Instant};

use anyhow::{Context as _, Result, anyhow};
use stewart_link::vehicle::xplane::rref_subscriptions;

/// How often the subscriptions are sent again.
pub(crate) const RENEW: Duration = Duration::from_secs(5);

/// The datarefs asked of one X-Plane.
#[derive(Debug)]
pub(crate) struct RrefSubscription {
    to: SocketAddr,
    per_second: i32,
    sent: Option<Instant>,
}

impl RrefSubscription {
    /// Subscriptions to X-Plane at `address` (`HOST:PORT`), `rate_hz` times a second.
    pub(crate) fn new(address: &str, rate_hz: f64) -> Result<Self> {
        let to = address
            .to_socket_addrs()
            .with_context(|| format!("X-Plane's address `{address}` does not resolve"))?
            .next()
            .ok_or_else(|| anyhow!("X-Plane's address `{address}` does not resolve"))?;
        Ok(Self {
            to,
            per_second: rate_hz.round().clamp(1.0, 1000.0) as i32,
            sent: None,
        })
    }

    /// Send the subscriptions from `socket` when they are due. A send that fails (X-Plane
    /// not started yet) is tried again at the next renewal.
    pub(crate) fn keep(&mut self, socket: &UdpSocket, now: Instant) {
        if self.sent.is_some_and(|at| now.duration_since(at) < RENEW) {
            return;
        }
        self.sent = Some(now);
        for request in rref_subscriptions(self.per_second) {
            let _ = socket.send_to(&request, self.to);
        }
    }

    /// Stop X-Plane sending them.
    pub(crate) fn end(&self, socket: &UdpSocket) {
        for request in rref_subscriptions(0) {
            let _ = socket.send_to(&request, self.to);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn x_plane_is_asked_at_once_again_when_due_and_told_to_stop() {
        let x_plane = UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
        let at = x_plane.local_addr().unwrap_or_else(|e| panic!("{e}"));
        let ours = UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
        let mut s = RrefSubscription::new(&at.to_string(), 60.4).unwrap_or_else(|e| panic!("{e}"));
        let start = Instant::now();
        s.keep(&ours, start);
        s.keep(&ours, start + Duration::from_secs(1));
        s.keep(&ours, start + RENEW);
        s.end(&ours);
        let mut got = Vec::new();
        let mut buffer = [0u8; 1024];
        // Loopback has delivered every datagram before `send_to` returned.
        x_plane
            .set_nonblocking(true)
            .unwrap_or_else(|e| panic!("{e}"));
        while let Ok(n) = x_plane.recv(&mut buffer) {
            got.push(buffer[..n].to_vec());
        }
        assert_eq!(got.len(), 3 * 6, "asked twice, stopped once");
        assert!(got.iter().all(|r| r.len() == 413 && &r[..4] == b"RREF"));
        let rate = |r: &Vec<u8>| i32::from_le_bytes([r[5], r[6], r[7], r[8]]);
        assert!(got[..12].iter().all(|r| rate(r) == 60));
        assert!(got[12..].iter().all(|r| rate(r) == 0));
        assert!(RrefSubscription::new("no port here", 60.0).is_err());
    }
}
