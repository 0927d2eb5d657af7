//! A local UDP peer for the set-points a benchmark streams: it takes them on its own
//! thread so the sender's socket never backs up. Shared by the link's and the app's
//! benchmarks (the app's include this file by its path).

use std::net::UdpSocket;

/// The address (`127.0.0.1:PORT`) of a new peer that reads and drops every datagram.
pub fn drained_peer() -> String {
    let peer = UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
    let address = peer.local_addr().unwrap_or_else(|e| panic!("{e}"));
    std::thread::spawn(move || {
        let mut buf = [0u8; 64];
        while peer.recv(&mut buf).is_ok() {}
    });
    address.to_string()
}
