//! The certified workspace in the viewer: on request, off the UI thread, the volume
//! bracket and the classed boxes of positions at the workspace panel's orientation
//! (`analysis::certified::workspace`), kept with what they were computed for.

use stewart_kinematics::analysis::certified::workspace::{
    CertifiedWorkspace, WorkspaceRequest, certified_workspace,
};
use stewart_kinematics::model::limits::Limits;
use stewart_kinematics::{Angle, Geometry, Pose};

use super::job::Job;

/// The boxes a viewer certification may classify (a few seconds at most).
const BOXES: usize = 3_000_000;
/// Boxes narrower than this share of the platform's size are not split further.
const WIDTH_SHARE: f64 = 0.01;

/// What a certification was computed for.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct CertifiedKey {
    /// The platform.
    pub(crate) geometry: Geometry,
    /// Its cone and clearance limits.
    pub(crate) limits: Limits,
    /// Roll, pitch, yaw.
    pub(crate) orientation: [Angle; 3],
}

/// A finished certification.
#[derive(Clone, Debug)]
pub(crate) struct CertifiedOutcome {
    /// What it was for.
    pub(crate) key: CertifiedKey,
    /// The bracket and the boxes; `None` for legs without both stroke limits.
    pub(crate) workspace: Option<CertifiedWorkspace>,
    /// The width boxes stop at, metres.
    pub(crate) width: f64,
}

/// The tool: its job and its newest result.
pub(crate) struct CertifiedTool {
    job: Job<CertifiedOutcome>,
    /// The newest finished certification.
    pub(crate) latest: Option<CertifiedOutcome>,
}

impl Default for CertifiedTool {
    fn default() -> Self {
        Self {
            job: Job::new("certified workspace"),
            latest: None,
        }
    }
}

impl CertifiedTool {
    /// Certify the workspace for `key` (a certification in flight is cancelled).
    pub(crate) fn start(&mut self, key: CertifiedKey) {
        self.job.start(move |worker| {
            let cancel = worker.cancel_flag();
            let stop = move || cancel.load(std::sync::atomic::Ordering::Relaxed);
            let [roll, pitch, yaw] = key.orientation;
            let orientation = Pose::new(key.geometry.home_pose().position, roll, pitch, yaw);
            let width = WIDTH_SHARE * key.geometry.characteristic_length();
            let request = WorkspaceRequest {
                orientation: &orientation,
                boundary_width: width,
                budget: BOXES,
                stop: &stop,
            };
            let workspace = certified_workspace(&key.geometry, &key.limits, &request);
            if !worker.cancelled() {
                worker.send(CertifiedOutcome {
                    key,
                    workspace,
                    width,
                });
            }
        });
    }

    /// Take a finished certification. Never blocks.
    pub(crate) fn poll(&mut self) {
        if let Some(Ok(outcome)) = self.job.poll() {
            self.latest = Some(outcome);
        }
    }

    /// Whether a certification is running.
    pub(crate) fn busy(&self) -> bool {
        self.job.busy()
    }

    /// Wait until the certification asked for has finished (tests).
    #[cfg(test)]
    pub(crate) fn wait(&mut self) {
        if let Some(Ok(outcome)) = self.job.wait() {
            self.latest = Some(outcome);
        }
    }
}
