//! The Design tool's state: an envelope of poses (a range below and above home for each
//! coordinate, as `stewart design --envelope` takes it), the search run off the UI
//! thread, and its outcome.

use stewart_kinematics::analysis::design::{DesignReport, Envelope, envelope_needs};
use stewart_kinematics::{Geometry, Pose};

use crate::viewer::error::ViewerError;
use crate::viewer::tools::job::Job;

/// The envelope, the search running, the last outcome.
pub(crate) struct DesignTool {
    /// The envelope: for x, y, z (m) and roll, pitch, yaw (°), how far below and above the
    /// home pose it reaches (`[0, 0]`: the coordinate stays at home).
    pub(crate) spans: [[f64; 2]; 6],
    /// The last outcome: the report, or why the envelope was refused.
    pub(crate) result: Option<Result<DesignReport, ViewerError>>,
    job: Job<DesignReport>,
}

/// The envelope's coordinates, as `stewart design --envelope` names them.
pub(crate) const COORDINATES: [&str; 6] = ["x", "y", "z", "roll", "pitch", "yaw"];

impl Default for DesignTool {
    fn default() -> Self {
        Self {
            spans: [
                [-0.1, 0.1],
                [-0.1, 0.1],
                [0.0, 0.0],
                [-10.0, 10.0],
                [-10.0, 10.0],
                [-15.0, 15.0],
            ],
            result: None,
            job: Job::new("design"),
        }
    }
}

impl DesignTool {
    /// The envelope about `home`, or why there is none (no coordinate with a range, or a
    /// range whose lower end is above its upper end).
    pub(crate) fn envelope(&self, home: &Pose) -> Result<Envelope, ViewerError> {
        if let Some((k, [a, b])) = self
            .spans
            .iter()
            .enumerate()
            .find(|(_, [a, b])| !(a.is_finite() && b.is_finite() && a <= b))
        {
            return Err(ViewerError::InvertedRange {
                coordinate: COORDINATES[k],
                lo: *a,
                hi: *b,
            });
        }
        if self.spans.iter().all(|[a, b]| a == b && *a == 0.0) {
            return Err(ViewerError::EmptyEnvelope);
        }
        let h = home.to_coordinates();
        let at_home: [f64; 6] =
            std::array::from_fn(|k| if k < 3 { h[k] } else { h[k].to_degrees() });
        Ok(Envelope {
            lo: std::array::from_fn(|k| at_home[k] + self.spans[k][0]),
            hi: std::array::from_fn(|k| at_home[k] + self.spans[k][1]),
        })
    }

    /// The same envelope in `stewart design --envelope` syntax (±A about home, absolute
    /// A..B otherwise), for the command line.
    pub(crate) fn command_line(&self, home: &Pose) -> String {
        let h = home.to_coordinates();
        let parts: Vec<String> = self
            .spans
            .iter()
            .enumerate()
            .filter(|(_, [a, b])| *a != 0.0 || *b != 0.0)
            .map(|(k, &[a, b])| {
                let centre = if k < 3 { h[k] } else { h[k].to_degrees() };
                if a == -b {
                    format!("{}=±{b}", COORDINATES[k])
                } else {
                    format!("{}={}..{}", COORDINATES[k], centre + a, centre + b)
                }
            })
            .collect();
        parts.join(",")
    }

    /// Start the search for `geometry` on its own thread (a bad envelope is refused at
    /// once, with its reason).
    pub(crate) fn start(&mut self, geometry: &Geometry) {
        let envelope = match self.envelope(&geometry.home_pose()) {
            Ok(e) => e,
            Err(e) => {
                self.result = Some(Err(e));
                self.job.cancel();
                return;
            }
        };
        let geometry = geometry.clone();
        // A search asked for again replaces the one in flight.
        self.job.start(move |worker| {
            worker.send(envelope_needs(&geometry, &envelope));
        });
        self.result = None;
    }

    /// Whether a search runs.
    pub(crate) fn busy(&self) -> bool {
        self.job.busy()
    }

    /// Collect a finished search.
    pub(crate) fn poll(&mut self) {
        if let Some(outcome) = self.job.poll() {
            self.result = Some(outcome.map_err(ViewerError::from));
        }
    }

    /// Wait for the running search (tests).
    #[cfg(test)]
    pub(crate) fn wait(&mut self) {
        if let Some(outcome) = self.job.wait() {
            self.result = Some(outcome.map_err(ViewerError::from));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_envelope_is_the_spans_about_home_and_reads_as_the_command_line_does() {
        let g = Geometry::seed();
        let home = g.home_pose();
        let mut tool = DesignTool::default();
        tool.spans[2] = [-0.1, 0.05];
        let env = tool.envelope(&home).unwrap_or_else(|e| panic!("{e}"));
        let text = tool.command_line(&home);
        let parsed = Envelope::parse(&text, &home).unwrap_or_else(|e| panic!("{text}: {e}"));
        for k in 0..6 {
            assert!((env.lo[k] - parsed.lo[k]).abs() < 1e-12, "{text}: {k}");
            assert!((env.hi[k] - parsed.hi[k]).abs() < 1e-12, "{text}: {k}");
        }
        assert!((env.lo[2] - (g.home_height() - 0.1)).abs() < 1e-12);
        tool.spans = [[0.0; 2]; 6];
        let empty = tool.envelope(&home);
        assert!(
            matches!(empty, Err(ViewerError::EmptyEnvelope)),
            "{empty:?}"
        );
        tool.spans[3] = [5.0, -5.0];
        let inverted = tool.envelope(&home);
        assert!(
            matches!(
                inverted,
                Err(ViewerError::InvertedRange {
                    coordinate: "roll",
                    lo: 5.0,
                    hi: -5.0
                })
            ),
            "{inverted:?}"
        );
        let words = inverted.err().map(|e| e.to_string()).unwrap_or_default();
        assert!(words.starts_with("`roll`: the range 5 .. -5"), "{words}");
    }
}
