//! A recording of vehicle motion as CSV (`t, ax, ay, az, wx, wy, wz`: s, m/s² in the
//! vehicle's frame with gravity excluded, °/s), read for `stewart cue` and the viewer,
//! each value checked against its bounds with the line at fault named.

use std::io::Read;

use anyhow::Result;
use stewart_kinematics::analysis::cueing::VehicleMotion;
use stewart_kinematics::ground::bounds::symmetric;
use stewart_kinematics::io::table::NumericTable;
use stewart_link::vehicle::COLUMN_BOUNDS;

/// The columns, in order (those of `COLUMN_BOUNDS`).
pub(crate) const VEHICLE_COLUMNS: [&str; 7] = ["t", "ax", "ay", "az", "wx", "wy", "wz"];

/// A recording: the table as read (for its lines) and its samples.
pub(crate) struct VehicleTable {
    /// The table, for the line of each sample.
    pub(crate) table: NumericTable,
    /// Time and motion of each row.
    pub(crate) samples: Vec<(f64, VehicleMotion)>,
}

/// Read a recording from `input` (named `name` in errors).
pub(crate) fn read(input: &mut dyn Read, name: &str) -> Result<VehicleTable> {
    let table = NumericTable::read(input, name, &VEHICLE_COLUMNS, &[])?;
    // The one range rule of vehicle motion, as a game's datagrams are read.
    for (column, bound, unit) in COLUMN_BOUNDS {
        table.check_range(column, &symmetric(bound), unit)?;
    }
    let samples = table
        .rows()
        .map(|r| {
            let motion = VehicleMotion {
                accel: [r[1], r[2], r[3]],
                rates_deg_s: [r[4], r[5], r[6]],
            };
            (r[0], motion)
        })
        .collect();
    Ok(VehicleTable { table, samples })
}

/// Whether a CSV's header line names vehicle motion (its acceleration and rate columns)
/// rather than poses.
pub(crate) fn is_vehicle_header(first_line: &str) -> bool {
    let columns: Vec<&str> = first_line.split(',').map(str::trim).collect();
    ["ax", "wx"].iter().all(|c| columns.contains(c))
}
