//! What the viewer derives from its scenario: the plotted samples, the traced path, the
//! layout the geometry controls show, and the pre-flight report. Rebuilt only through
//! [`Derived::rebuild`] (the state's one edit path calls it), so it never falls out of
//! step; the report is computed off the UI thread, newest request first.

use crate::viewer::tools::job::Job;
use nalgebra::Vector3;
use stewart_kinematics::analysis::dynamics;
use stewart_kinematics::analysis::sound_layout;
use stewart_kinematics::analysis::sound_layout::SoundLayout;
use stewart_kinematics::{
    CheckReport, Scenario, analysis::checks::check_motion, model::layout::Layout,
};

/// Most samples the plot and the traced path hold (a trajectory may have ten million:
/// the check uses them all, the picture needs far fewer).
pub(crate) const PLOT_SAMPLES: usize = 20_000;

/// The plot's and path's samples, the layout, and the report.
pub(crate) struct Derived {
    /// Sample times (at most [`PLOT_SAMPLES`], both ends kept), seconds.
    pub(crate) times: Vec<f64>,
    /// Leg lengths (m) or servo angles (°, NaN out of reach) at those times.
    pub(crate) lengths: Vec<[f64; 6]>,
    /// Platform-centre positions at those times, for the traced path.
    pub(crate) centres: Vec<Vector3<f64>>,
    /// The named layout of the joint angles, `None` when they follow none.
    pub(crate) layout: Option<Layout>,
    /// Whether some plotted value lies beyond a stroke or servo limit.
    pub(crate) beyond_limits: bool,
    /// The actuator efforts (N or N·m, with the legs' parts and friction) at those
    /// times, when the scenario has a payload; NaN where none is determined.
    pub(crate) efforts: Option<Vec<[f64; 6]>>,
    /// The nearest layout that is not architecturally singular, once asked for (it is
    /// searched only when the report finds the geometry singular).
    sound_layout: Option<Option<SoundLayout>>,
    report: ReportWorker,
}

impl Derived {
    /// Everything for `scenario` (the report is started, not waited for).
    pub(crate) fn new(scenario: &Scenario) -> Self {
        let mut d = Self {
            times: Vec::new(),
            lengths: Vec::new(),
            centres: Vec::new(),
            layout: None,
            beyond_limits: false,
            efforts: None,
            sound_layout: None,
            report: ReportWorker::default(),
        };
        d.rebuild(scenario);
        d
    }

    /// Recompute after `scenario` changed: the thinned samples now, the report in the
    /// background (a request made while one runs replaces any waiting one).
    pub(crate) fn rebuild(&mut self, scenario: &Scenario) {
        let params = scenario.geometry.params();
        self.layout = match (params.base.circle(), params.platform.circle()) {
            (Some((_, base)), Some((_, platform))) => Layout::recognise(base, platform),
            _ => None,
        };
        self.sound_layout = None;
        let sampling = scenario.motion.sampling;
        let n = sampling.len();
        let m = n.min(PLOT_SAMPLES);
        let index = |i: usize| {
            if m == n {
                i
            } else {
                ((i as f64) * (n - 1) as f64 / (m - 1) as f64).round() as usize
            }
        };
        let g = &scenario.geometry;
        self.times = (0..m).map(|i| scenario.motion.time(index(i))).collect();
        let poses: Vec<_> = self
            .times
            .iter()
            .map(|&t| scenario.motion.trajectory.pose_at(t))
            .collect();
        self.lengths = g.actuator_values(&poses);
        let [min, max] = g.quantity_limits();
        self.beyond_limits = self
            .lengths
            .iter()
            .flatten()
            .any(|&v| min.is_some_and(|m| v < m) || max.is_some_and(|m| v > m));
        self.centres = poses.iter().map(|p| g.platform_centre(p)).collect();
        self.efforts = scenario.payload.map(|payload| {
            let samples = stewart_kinematics::model::trajectory::Samples {
                times: self.times.clone(),
                poses,
            };
            dynamics::motion_states(&samples)
                .iter()
                .map(|state| {
                    dynamics::inverse_dynamics(g, state, &payload, &scenario.dynamics)
                        .unwrap_or([f64::NAN; 6])
                })
                .collect()
        });
        self.report.request(scenario.clone());
    }

    /// The nearest paired layout of `scenario`'s geometry that is not architecturally
    /// singular (searched on the first call after an edit, then kept).
    pub(crate) fn sound_layout(&mut self, scenario: &Scenario) -> Option<&SoundLayout> {
        self.sound_layout
            .get_or_insert_with(|| sound_layout::nearest_sound_layout(&scenario.geometry))
            .as_ref()
    }

    /// The latest finished report of the current scenario, if it is in.
    pub(crate) fn report(&self) -> Option<&CheckReport> {
        self.report.current.as_ref()
    }

    /// Whether a report is being computed (or waits to be).
    pub(crate) fn report_pending(&self) -> bool {
        self.report.job.busy()
    }

    /// Collect a finished report and start the waiting request; never blocks.
    pub(crate) fn poll(&mut self) {
        self.report.poll(false);
    }

    /// Block until the report of the current scenario is in (screenshots and tests).
    pub(crate) fn wait_for_report(&mut self) {
        while self.report_pending() {
            self.report.poll(true);
        }
    }
}

/// The pre-flight check on a background job: the newest scenario's report only.
struct ReportWorker {
    /// The report of the scenario as it is now (`None` while the first is computed, or
    /// after an edit until the new one is in).
    current: Option<CheckReport>,
    job: Job<CheckReport>,
}

impl Default for ReportWorker {
    fn default() -> Self {
        Self {
            current: None,
            job: Job::new("check"),
        }
    }
}

impl ReportWorker {
    fn request(&mut self, scenario: Scenario) {
        self.current = None;
        self.job.start(move |worker| {
            let samples = scenario.motion.samples_judged(scenario.link.rate_hz);
            worker.send(check_motion(
                &scenario.geometry,
                &scenario.limits,
                &samples,
                &scenario.checks,
            ));
        });
    }

    fn poll(&mut self, block: bool) {
        let outcome = if block {
            self.job.wait()
        } else {
            self.job.poll()
        };
        if let Some(Ok(report)) = outcome {
            self.current = Some(report);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_trajectories_are_thinned_for_the_plot_but_keep_their_ends() {
        let mut s = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
        stewart_kinematics::io::settings::apply_all(&mut s, ["trajectory.samples=30000"])
            .unwrap_or_else(|e| panic!("{e}"));
        let mut d = Derived::new(&s);
        assert_eq!(d.times.len(), PLOT_SAMPLES);
        assert_eq!(d.times.first(), Some(&s.motion.sampling.start()));
        assert_eq!(d.times.last(), Some(&s.motion.sampling.time(29_999)));
        d.wait_for_report();
        assert_eq!(d.report().map(|r| r.samples), Some(30_000));
    }

    #[test]
    fn only_the_report_of_the_newest_scenario_is_kept() {
        let seed = Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}"));
        let paired = Scenario::preset("paired").unwrap_or_else(|e| panic!("{e}"));
        let mut d = Derived::new(&seed);
        d.rebuild(&paired);
        d.rebuild(&seed);
        d.rebuild(&paired);
        d.wait_for_report();
        assert!(!d.report_pending());
        assert!(d.report().is_some_and(|r| !r.architecture.singular));
    }
}
