//! The Objective Motion Cueing Test in the viewer: on request, off the UI thread, the test
//! of the cueing settings shown on the platform shown (`analysis::cueing::omct`), kept with
//! what it was run for.

use stewart_kinematics::Geometry;
use stewart_kinematics::analysis::cueing::omct::{OmctOptions, OmctReport, omct};
use stewart_kinematics::model::cueing_settings::CueingSettings;
use stewart_kinematics::model::limits::Limits;

use super::job::Job;

/// What a test was run for.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct OmctKey {
    /// The platform.
    pub(crate) geometry: Geometry,
    /// Its limits.
    pub(crate) limits: Limits,
    /// The cueing tested.
    pub(crate) cueing: CueingSettings,
}

/// A finished test.
#[derive(Clone, Debug)]
pub(crate) struct OmctOutcome {
    /// What it was for.
    pub(crate) key: OmctKey,
    /// The report, or why there is none.
    pub(crate) report: Result<OmctReport, String>,
}

/// The tool: its job and its newest result.
pub(crate) struct OmctTool {
    job: Job<OmctOutcome>,
    /// The newest finished test.
    pub(crate) latest: Option<OmctOutcome>,
}

impl Default for OmctTool {
    fn default() -> Self {
        Self {
            job: Job::new("motion cueing test"),
            latest: None,
        }
    }
}

impl OmctTool {
    /// Test the cueing of `key` at the twelve frequencies (a test in flight is cancelled).
    pub(crate) fn start(&mut self, key: OmctKey) {
        self.job.start(move |worker| {
            let cancel = worker.cancel_flag();
            let stop = move || cancel.load(std::sync::atomic::Ordering::Relaxed);
            let report = omct(
                &key.geometry,
                &key.limits,
                &key.cueing,
                &OmctOptions::default(),
                &stop,
            )
            .map_err(|e| e.to_string());
            if !worker.cancelled() {
                worker.send(OmctOutcome { key, report });
            }
        });
    }

    /// Take a finished test. Never blocks.
    pub(crate) fn poll(&mut self) {
        if let Some(Ok(outcome)) = self.job.poll() {
            self.latest = Some(outcome);
        }
    }

    /// Whether a test is running.
    pub(crate) fn busy(&self) -> bool {
        self.job.busy()
    }

    /// Wait until the test asked for has finished (tests).
    #[cfg(test)]
    pub(crate) fn wait(&mut self) {
        if let Some(Ok(outcome)) = self.job.wait() {
            self.latest = Some(outcome);
        }
    }
}
