//! A recording of vehicle motion loaded into the viewer and the motion cued from it: the
//! scenario's trajectory while that motion is the one shown, cued again whenever the
//! scenario's cueing, geometry or limits change, with the channels the Cueing panel plots.

use std::sync::Arc;

use stewart_kinematics::analysis::cueing::compare::{CueMeasures, FeltSample, felt, measure};
use stewart_kinematics::analysis::cueing::{CuedRecording, VehicleMotion, cue_recording};
use stewart_kinematics::model::cueing_settings::{CueingAlgorithm, CueingSettings};
use stewart_kinematics::{Scenario, model::trajectory::Motion};

use crate::viewer::error::ViewerError;

/// The recording and what the washout made of it for a scenario.
#[derive(Clone, Debug)]
pub(crate) struct VehicleSource {
    /// The file, for messages.
    pub(crate) name: String,
    /// Time and motion of each sample.
    pub(crate) samples: Arc<Vec<(f64, VehicleMotion)>>,
    /// The motion cued from it (the scenario's while the two are equal).
    pub(crate) motion: Motion,
    /// The poses, limiter scales and cues per sample.
    pub(crate) cued: CuedRecording,
    /// Both algorithms side by side, the scenario's first: what each makes felt at
    /// every inner sample, and its measures (the other left out where it cannot cue
    /// this scenario: its failure is not the edit's).
    pub(crate) compared: Vec<Compared>,
}

/// One algorithm's cue of the recording, as the Cueing panel compares them.
#[derive(Clone, Debug)]
pub(crate) struct Compared {
    /// Felt and wanted force and rates at samples `1..n−1`.
    pub(crate) felt: Vec<FeltSample>,
    /// Its measures (errors, stroke used, limiter time).
    pub(crate) measures: CueMeasures,
}

impl Compared {
    fn of(
        scenario: &Scenario,
        settings: &CueingSettings,
        samples: &[(f64, VehicleMotion)],
        cued: &CuedRecording,
    ) -> Self {
        Self {
            felt: felt(&scenario.geometry, settings, samples, &cued.poses),
            measures: measure(&scenario.geometry, settings, samples, cued),
        }
    }
}

impl VehicleSource {
    /// Cue `samples` (from the file `name`) for `scenario`.
    pub(crate) fn new(
        name: &str,
        samples: Arc<Vec<(f64, VehicleMotion)>>,
        scenario: &Scenario,
    ) -> Result<Self, ViewerError> {
        let cued = cue_recording(
            &scenario.geometry,
            &scenario.limits,
            &scenario.checks,
            &scenario.cueing,
            &samples,
        )
        .map_err(|e| ViewerError::from(e).in_file(name))?;
        let times: Vec<f64> = samples.iter().map(|s| s.0).collect();
        let motion = cued.to_motion(&times, name)?;
        // The other algorithm on the same recording, for the comparison.
        let other = CueingSettings {
            algorithm: match scenario.cueing.algorithm {
                CueingAlgorithm::Washout => CueingAlgorithm::Mpc,
                CueingAlgorithm::Mpc => CueingAlgorithm::Washout,
            },
            ..scenario.cueing.clone()
        };
        let mut compared = vec![Compared::of(scenario, &scenario.cueing, &samples, &cued)];
        if let Ok(other_cued) = cue_recording(
            &scenario.geometry,
            &scenario.limits,
            &scenario.checks,
            &other,
            &samples,
        ) {
            compared.push(Compared::of(scenario, &other, &samples, &other_cued));
        }
        Ok(Self {
            name: name.to_owned(),
            samples,
            motion,
            cued,
            compared,
        })
    }

    /// The same recording cued for `scenario` (after an edit of its cueing, geometry or
    /// limits).
    pub(crate) fn recue(&self, scenario: &Scenario) -> Result<Self, ViewerError> {
        Self::new(&self.name, Arc::clone(&self.samples), scenario)
    }

    /// The times of the samples.
    pub(crate) fn times(&self) -> impl Iterator<Item = f64> + '_ {
        self.samples.iter().map(|s| s.0)
    }
}
