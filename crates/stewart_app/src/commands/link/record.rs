//! `stewart link --record FILE.csv`: each set-point the controller answered, commanded and
//! measured side by side, written on a thread of its own (never on the sender's) into a
//! staged file that is put in place when the stream has ended.
//!
//! Columns: `t_s` (the set-point's stream time), `seq`, `cmd1 … cmd6`, `meas1 … meas6` in the
//! actuators' natural unit (metres for legs, degrees for servos, named in the header), and
//! `latency_ms`, the round trip from sending the set-point to its answer.

use std::io::Write as _;
use std::sync::mpsc;
use std::thread::JoinHandle;

use anyhow::{Result, anyhow};
use stewart_link::telemetry::Row;

use crate::output::Destination;

/// A recorder running on its thread.
pub(crate) struct Recorder {
    destination: Destination,
    writer: JoinHandle<std::io::Result<(tempfile::TempPath, u64)>>,
}

impl Recorder {
    /// Start recording into `destination` (a file); rows come through the returned sender.
    /// `unit` names the natural unit in the header (`m` or `deg`).
    pub(crate) fn start(destination: Destination, unit: &str) -> Result<(mpsc::Sender<Row>, Self)> {
        destination.require_file()?;
        let (file, path) = destination.staged_file(".partial")?.into_parts();
        let (rows, inbox) = mpsc::channel::<Row>();
        let header = header(unit);
        let writer = std::thread::Builder::new()
            .name("stewart-link-record".to_owned())
            .spawn(move || {
                let mut out = std::io::BufWriter::new(file);
                out.write_all(header.as_bytes())?;
                let mut count = 0;
                for row in inbox {
                    out.write_all(line(&row).as_bytes())?;
                    count += 1;
                }
                out.flush()?;
                Ok((path, count))
            })
            .map_err(|e| anyhow!("cannot start the recorder: {e}"))?;
        Ok((
            rows,
            Self {
                destination,
                writer,
            },
        ))
    }

    /// Wait for the last row (the sender has ended) and put the record in place. Returns
    /// how many rows it holds.
    pub(crate) fn finish(self) -> Result<u64> {
        let name = self.destination.shown().display().to_string();
        let (path, count) = self
            .writer
            .join()
            .map_err(|_| anyhow!("the recorder of `{name}` failed"))?
            .map_err(|e| anyhow!("cannot write `{name}`: {e}"))?;
        self.destination.deliver(path)?;
        Ok(count)
    }
}

/// The header line for values in `unit`.
fn header(unit: &str) -> String {
    let names =
        |what: &str| -> Vec<String> { (1..=6).map(|k| format!("{what}{k}_{unit}")).collect() };
    format!(
        "t_s,seq,{},{},latency_ms\n",
        names("cmd").join(","),
        names("meas").join(",")
    )
}

/// One row as a CSV line (values to the nanometre or the microdegree and beyond).
fn line(row: &Row) -> String {
    let values = |v: &[f64; 6]| -> String {
        v.iter()
            .map(|x| format!("{x:.9}"))
            .collect::<Vec<_>>()
            .join(",")
    };
    format!(
        "{:.6},{},{},{},{:.3}\n",
        row.time,
        row.sequence,
        values(&row.commanded),
        values(&row.measured),
        row.latency_s * 1e3
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_row_is_one_line_under_its_header() {
        let h = header("m");
        assert!(h.starts_with("t_s,seq,cmd1_m,"));
        assert!(h.ends_with(",meas6_m,latency_ms\n"));
        let row = Row {
            time: 1.25,
            sequence: 7,
            commanded: [1.0; 6],
            measured: [0.999_999_5; 6],
            latency_s: 0.0012345,
        };
        let l = line(&row);
        assert!(l.starts_with("1.250000,7,1.000000000,"), "{l}");
        assert!(
            l.ends_with(",0.999999500,1.234\n") || l.ends_with(",0.999999500,1.235\n"),
            "{l}"
        );
        assert_eq!(l.split(',').count(), h.split(',').count());
    }
}
