use super::*;

#[test]
fn udp_reaches_a_local_peer_and_bad_addresses_are_named() {
    let peer = UdpSocket::bind("127.0.0.1:0").unwrap_or_else(|e| panic!("{e}"));
    let address = peer
        .local_addr()
        .unwrap_or_else(|e| panic!("{e}"))
        .to_string();
    let mut udp = Udp::connect(&address).unwrap_or_else(|e| panic!("{e}"));
    udp.send(0.0, &[1, 2, 3]).unwrap_or_else(|e| panic!("{e}"));
    let mut buf = [0u8; 64];
    let n = peer.recv(&mut buf).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(&buf[..n], &[1, 2, 3]);
    assert_eq!(udp.describe(), format!("UDP {address}"));
    for bad in [
        "nowhere",
        "1.2.3.4",
        "1.2.3.4:99999",
        "host:port",
        "127.0.0.1:0",
    ] {
        let e = Udp::connect(bad)
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default();
        assert!(e.starts_with(&format!("`{bad}` is not an address")), "{e}");
    }
}

#[test]
fn a_dry_run_records_frames_in_hex_and_lines_as_they_are() {
    let mut r = Record::new(Vec::new(), "memory");
    r.send(0.5, &[0xA5, 0x5A, 0x01])
        .unwrap_or_else(|e| panic!("{e}"));
    r.send(0.51, b"S,1,1,2,3,4,5,6\n")
        .unwrap_or_else(|e| panic!("{e}"));
    let text = String::from_utf8(r.into_inner()).unwrap_or_default();
    assert_eq!(text, "0.500000\tA5 5A 01\n0.510000\tS,1,1,2,3,4,5,6\n");
}
