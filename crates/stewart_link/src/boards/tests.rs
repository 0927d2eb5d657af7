//! Boards' bytes against frames computed by hand, and read back.

use super::*;
use proptest::prelude::*;

const RANGES: [(f64, f64); 6] = [(0.5, 0.7); 6];

fn ports(board: &Board) -> Vec<Vec<u8>> {
    vec![Vec::new(); board.ports()]
}

#[test]
fn smc3_frames_for_0_512_and_1023_are_the_bytes_computed_by_hand() {
    // 0.5 m → 0; 0.6 m → 511.5 → 512 (0x0200); 0.7 m → 1023 (0x03FF); board 2 the same.
    let values = [0.5, 0.6, 0.7, 0.7, 0.5, 0.6];
    let mut out = ports(&Board::Smc3);
    Board::Smc3.set_point(&values, &[0.0; 6], &RANGES, &mut out);
    assert_eq!(
        out[0],
        b"[A\x00\x00][B\x02\x00][C\x03\xff]".to_vec(),
        "board 1: motors A, B, C"
    );
    assert_eq!(out[1], b"[A\x03\xff][B\x00\x00][C\x02\x00]".to_vec());
    let mut armed = ports(&Board::Smc3);
    Board::Smc3.arming(true, &mut armed);
    assert_eq!(armed, [b"[ena]".to_vec(), b"[ena]".to_vec()]);
    let mut disarmed = ports(&Board::Smc3);
    Board::Smc3.arming(false, &mut disarmed);
    assert!(disarmed.iter().all(Vec::is_empty), "SMC3 has no disable");
}

#[test]
fn odrive_lines_carry_turns_and_their_velocity_feed_forward() {
    // 10 turns per metre of leg, −6 turns at zero: 0.6 m is 0 turns; 0.65 m at 0.2 m/s
    // is 0.5 turns at 2 turns/s.
    let turns = Turns {
        per_unit: [10.0; 6],
        offset: [-6.0; 6],
    };
    let board = Board::ODrive(turns);
    let values = [0.6, 0.65, 0.6, 0.6, 0.6, 0.55];
    let velocities = [0.0, 0.2, 0.0, 0.0, 0.0, -0.1];
    let mut out = ports(&board);
    board.set_point(&values, &velocities, &RANGES, &mut out);
    assert_eq!(
        String::from_utf8_lossy(&out[0]),
        "p 0 0.000000 0.000000 0\np 1 0.500000 2.000000 0\n"
    );
    assert_eq!(
        String::from_utf8_lossy(&out[2]),
        "p 0 0.000000 0.000000 0\np 1 -0.500000 -1.000000 0\n"
    );
    let mut armed = ports(&board);
    board.arming(true, &mut armed);
    let closed = "w axis0.requested_state 8\nw axis1.requested_state 8\n";
    assert!(armed.iter().all(|b| b == closed.as_bytes()));
    let mut idle = ports(&board);
    board.arming(false, &mut idle);
    assert!(idle[1].starts_with(b"w axis0.requested_state 1\n"));
}

#[test]
fn a_boards_stream_reads_back_a_record_a_tick() {
    let mut out = ports(&Board::Smc3);
    Board::Smc3.arming(true, &mut out);
    Board::Smc3.set_point(
        &[0.5, 0.6, 0.7, 0.6, 0.6, 0.6],
        &[0.0; 6],
        &RANGES,
        &mut out,
    );
    let mut r = BoardReader::new(Board::Smc3);
    // Joined one byte late, then the rest in pieces.
    let mut stream = vec![0x7f];
    stream.extend(&out[0]);
    for piece in stream.chunks(3) {
        r.push(piece);
    }
    let mut got = Vec::new();
    while let Some(record) = r.next_record() {
        got.push(record);
    }
    assert_eq!(
        got,
        [
            BoardRecord::Unknown,
            BoardRecord::Armed(true),
            BoardRecord::SetPoint(vec![0.0, 512.0, 1023.0]),
        ]
    );
    let board = Board::ODrive(Turns {
        per_unit: [1.0; 6],
        offset: [0.0; 6],
    });
    let mut out = ports(&board);
    board.set_point(
        &[0.25, -0.5, 0.0, 0.0, 0.0, 0.0],
        &[0.0; 6],
        &RANGES,
        &mut out,
    );
    board.arming(false, &mut out);
    let mut r = BoardReader::new(board);
    r.push(&out[0]);
    assert_eq!(
        r.next_record(),
        Some(BoardRecord::SetPoint(vec![0.25, -0.5]))
    );
    assert_eq!(r.next_record(), Some(BoardRecord::Armed(false)));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    /// Any bytes read without a panic, for both protocols.
    #[test]
    fn any_bytes_read_without_a_panic(bytes in proptest::collection::vec(any::<u8>(), 0..600)) {
        for board in [Board::Smc3, Board::ODrive(Turns { per_unit: [1.0; 6], offset: [0.0; 6] })] {
            let mut r = BoardReader::new(board);
            r.push(&bytes);
            while r.next_record().is_some() {}
        }
    }
}
