//! Planning elsewhere: a live stream at 1 kHz cannot wait for a solve inside its tick, so
//! the planner that follows the plan hands each solve to another (on its own thread)
//! one solve interval ahead.
//!
//! At each solve instant `tᵢ` the follower asks for the plan that starts at `tᵢ₊₁`: the
//! state then is known exactly (the plan is followed exactly until then), the vehicle's
//! motion is the one known at `tᵢ`. When the answer has come by `tᵢ₊₁` it is adopted
//! there, seamlessly; when it has not (or found no plan), the current plan goes on — it
//! ends at rest within the limits — and the next one is asked for. The poses still pass
//! the exact check before they are given. Requests and answers are plain values: no
//! allocation on either side.

use super::Mpc;
use crate::model::cueing_settings::MAX_HORIZON_STEPS;

/// The most steps of a horizon.
const STEPS: usize = MAX_HORIZON_STEPS as usize;

/// A plan asked for: the state at the instant it will start and what is wanted then.
#[derive(Clone, Copy, Debug)]
pub struct PlanRequest {
    /// Which solve instant (from 1).
    pub id: u64,
    /// The follower's epoch when asked: a stop or reset since makes the reply stale.
    epoch: u64,
    s: [f64; 6],
    v: [f64; 6],
    a: [f64; 6],
    wanted: [[f64; 6]; STEPS],
    wanted_end: [[f64; 6]; STEPS],
    fade: f64,
    tilt_now: Option<[f64; 2]>,
    /// The vestibular organs' states then.
    sensed: [[f64; 3]; 6],
}

/// A plan made for a request.
#[derive(Clone, Copy, Debug)]
pub struct PlanReply {
    /// The request's id.
    pub id: u64,
    epoch: u64,
    /// Whether a plan within the limits was found.
    pub found: bool,
    plan: [f64; 6 * STEPS],
    active: usize,
}

impl Mpc {
    /// Plan elsewhere (`true`): from now on [`Mpc::advance`] never solves; at each solve
    /// instant it adopts the reply offered for it, if any, and leaves a request for the
    /// next ([`Mpc::take_request`]).
    pub fn set_remote(&mut self, remote: bool) {
        self.remote.on = remote;
    }

    /// The request left at the last solve instant, if not taken yet, with the vehicle's
    /// motion held now (a sample taken since the instant is in it).
    pub fn take_request(&mut self) -> Option<PlanRequest> {
        let mut request = self.remote.request.take()?;
        let steps = self.problem.layout.steps;
        request.wanted[..steps].copy_from_slice(&self.wanted.mean);
        request.wanted_end[..steps].copy_from_slice(&self.wanted.at_end);
        request.fade = self.wanted.fade;
        request.tilt_now = self.wanted.tilt_now;
        Some(request)
    }

    /// Offer a reply: it is adopted at its solve instant if it is the one asked for then.
    pub fn offer(&mut self, reply: &PlanReply) {
        self.remote.reply = Some(*reply);
    }

    /// Plan for `request` (on the planner that answers), from its state.
    pub fn answer(&mut self, request: &PlanRequest) -> PlanReply {
        let steps = self.problem.layout.steps;
        self.plant.s = request.s;
        self.plant.v = request.v;
        self.wanted.mean.copy_from_slice(&request.wanted[..steps]);
        self.wanted
            .at_end
            .copy_from_slice(&request.wanted_end[..steps]);
        self.wanted.fade = request.fade;
        self.wanted.tilt_now = request.tilt_now;
        if let Some(s) = &mut self.sensed {
            s.states = request.sensed;
        }
        let found = self.plan_from(request.a);
        let mut plan = [0.0; 6 * STEPS];
        plan[..self.plan.accelerations.len()].copy_from_slice(&self.plan.accelerations);
        PlanReply {
            id: request.id,
            epoch: request.epoch,
            found,
            plan,
            active: self.counts.active,
        }
    }

    /// At a solve instant, planning elsewhere: adopt the reply for this instant, or go on
    /// with the plan; then ask for the plan of the next instant.
    pub(super) fn remote_instant(&mut self) {
        self.remote.instant += 1;
        match self.remote.reply.take() {
            Some(r) if r.id == self.remote.instant && r.epoch == self.remote.epoch && r.found => {
                let n = self.plan.accelerations.len();
                self.plan.accelerations.copy_from_slice(&r.plan[..n]);
                self.plan.age = 0.0;
                self.counts.active = r.active;
                self.counts.solves += 1;
            }
            Some(r) if r.id == self.remote.instant && r.epoch == self.remote.epoch => {
                self.counts.solves += 1;
                self.counts.failed += 1;
            }
            _ => self.counts.late += 1,
        }
        self.sense(self.input_at(self.plan.age));
        let every = self.problem.settings.mpc_solve_interval_s;
        let (s, v, age) = self.integrate(self.plant.s, self.plant.v, self.plan.age, every);
        let mut request = PlanRequest {
            id: self.remote.instant + 1,
            epoch: self.remote.epoch,
            s,
            v,
            a: self.input_at(age),
            wanted: [[0.0; 6]; STEPS],
            wanted_end: [[0.0; 6]; STEPS],
            fade: self.wanted.fade,
            tilt_now: self.wanted.tilt_now,
            sensed: self.sensed.as_ref().map_or([[0.0; 3]; 6], |v| v.next()),
        };
        let steps = self.problem.layout.steps;
        request.wanted[..steps].copy_from_slice(&self.wanted.mean);
        request.wanted_end[..steps].copy_from_slice(&self.wanted.at_end);
        self.remote.request = Some(request);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::cueing::VehicleMotion;
    use crate::io::scenario::Scenario;
    use crate::model::cueing_settings::{CueingAlgorithm, CueingSettings};

    fn planners() -> (Mpc, Mpc) {
        let s = Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}"));
        let settings = CueingSettings {
            algorithm: CueingAlgorithm::Mpc,
            mpc_tilt_weight: 0.0,
            ..s.cueing.clone()
        };
        let mpc = Mpc::new(&s.geometry, &s.limits, &settings).unwrap_or_else(|_| panic!());
        let mut follower = mpc.clone();
        follower.set_remote(true);
        (follower, mpc)
    }

    #[test]
    fn answered_at_once_the_remote_plan_reaches_the_same_steady_state() {
        let (mut follower, mut answering) = planners();
        let (mut local, _) = planners();
        local.set_remote(false);
        let force = VehicleMotion {
            accel: [1.5, -1.0, 0.0],
            rates_deg_s: [0.0; 3],
        };
        follower.hold(&force);
        local.hold(&force);
        for _ in 0..3000 {
            follower.advance(0.01);
            local.advance(0.01);
            if let Some(request) = follower.take_request() {
                let reply = answering.answer(&request);
                follower.offer(&reply);
            }
        }
        let (f, l) = (
            follower.cue().specific_force(),
            local.cue().specific_force(),
        );
        for i in 0..3 {
            assert!((f[i] - l[i]).abs() < 1e-6, "{f:?} vs {l:?}");
        }
        let counts = follower.counts();
        assert_eq!(counts.late, 1, "only the first instant, before any request");
        assert_eq!(follower.counts().stops, 0);
    }

    #[test]
    fn unanswered_the_plan_goes_on_to_rest_within_the_limits() {
        let (mut follower, mut answering) = planners();
        follower.hold(&VehicleMotion {
            accel: [3.0, 0.0, 0.0],
            rates_deg_s: [0.0; 3],
        });
        // Answered for half a second: the platform moves.
        for _ in 0..50 {
            follower.advance(0.01);
            if let Some(request) = follower.take_request() {
                follower.offer(&answering.answer(&request));
            }
        }
        assert!(follower.plant.v.iter().any(|v| v.abs() > 1e-3));
        // Then the answers stop: the last plan is followed to rest.
        for _ in 0..300 {
            let pose = follower.advance(0.01);
            assert!(crate::analysis::workspace::pose_within_limits(
                &follower.problem.geometry,
                &follower.problem.limits,
                &pose
            ));
        }
        assert!(
            follower.plant.v.iter().all(|v| v.abs() < 1e-12),
            "{:?}",
            follower.plant.v
        );
        assert!(follower.counts().late >= 300);
    }

    #[test]
    fn a_reply_asked_for_before_a_reset_is_not_adopted() {
        let (mut follower, mut answering) = planners();
        follower.hold(&VehicleMotion {
            accel: [3.0, 0.0, 0.0],
            rates_deg_s: [0.0; 3],
        });
        follower.advance(0.01);
        let request = follower
            .take_request()
            .unwrap_or_else(|| panic!("a request"));
        let reply = answering.answer(&request);
        // Reset (or an exact-check stop) while the plan was on its way: dropped.
        follower.reset();
        follower.offer(&reply);
        let late = follower.counts().late;
        follower.advance(0.01);
        assert_eq!(follower.counts().late, late + 1);
        assert!(follower.plan.accelerations.iter().all(|u| *u == 0.0));
    }
}
