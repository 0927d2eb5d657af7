//! The Design tool's state: an envelope typed as on the command line (`stewart design
//! --envelope`), the search run off the UI thread, and its outcome.

use std::sync::mpsc::{self, Receiver};

use stewart_kinematics::Geometry;
use stewart_kinematics::design::{DesignReport, Envelope, envelope_needs};

/// The envelope typed, the search running, the last outcome.
pub struct DesignTool {
    /// The envelope, `x=±0.1,roll=±10,…`.
    pub text: String,
    /// The last outcome: the report, or why the envelope was refused.
    pub result: Option<Result<DesignReport, String>>,
    running: Option<Receiver<DesignReport>>,
}

impl Default for DesignTool {
    fn default() -> Self {
        Self {
            text: "x=±0.1,y=±0.1,roll=±10,pitch=±10,yaw=±15".to_owned(),
            result: None,
            running: None,
        }
    }
}

impl DesignTool {
    /// Start the search for `geometry` on its own thread (a bad envelope is refused at
    /// once, with its reason).
    pub fn start(&mut self, geometry: &Geometry) {
        let envelope = match Envelope::parse(&self.text, &geometry.home_pose()) {
            Ok(e) => e,
            Err(e) => {
                self.result = Some(Err(e));
                self.running = None;
                return;
            }
        };
        let (done, outcome) = mpsc::channel();
        let geometry = geometry.clone();
        std::thread::spawn(move || {
            let _ = done.send(envelope_needs(&geometry, &envelope));
        });
        self.result = None;
        self.running = Some(outcome);
    }

    /// Whether a search runs.
    pub fn busy(&self) -> bool {
        self.running.is_some()
    }

    /// Collect a finished search.
    pub fn poll(&mut self) {
        if let Some(outcome) = &self.running
            && let Ok(report) = outcome.try_recv()
        {
            self.result = Some(Ok(report));
            self.running = None;
        }
    }

    /// Wait for the running search (tests).
    pub fn wait(&mut self) {
        if let Some(outcome) = self.running.take()
            && let Ok(report) = outcome.recv()
        {
            self.result = Some(Ok(report));
        }
    }
}
