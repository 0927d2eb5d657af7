//! The live cue's planner thread: with model-predictive cueing, the sender's tick follows
//! the plan and never solves; each solve instant's request goes to this thread, which
//! answers it within the solve interval (`Mpc`'s remote planning). A request that finds
//! another still waiting is dropped, and an instant whose plan has not come goes on with
//! the last plan; so no solve, however long, delays a tick.

use std::sync::mpsc::{Receiver, SyncSender, TrySendError, sync_channel};

use stewart_kinematics::analysis::cueing::Mpc;
use stewart_kinematics::analysis::cueing::mpc::remote::{PlanReply, PlanRequest};

/// The thread and the two ways to it.
pub(crate) struct PlannerThread {
    requests: SyncSender<PlanRequest>,
    replies: Receiver<PlanReply>,
    /// Requests taken by the thread whose replies have not been offered yet.
    pending: usize,
}

impl PlannerThread {
    /// Answer requests with `planner` (a copy of the follower's, planning locally) on a
    /// thread of its own, until this is dropped.
    pub(crate) fn start(mut planner: Mpc) -> std::io::Result<Self> {
        // Room for one: a request finding another still waiting is dropped.
        let (requests, asked) = sync_channel::<PlanRequest>(1);
        let (answered, replies) = sync_channel::<PlanReply>(2);
        std::thread::Builder::new()
            .name("cue planner".to_owned())
            .spawn(move || {
                while let Ok(request) = asked.recv() {
                    let reply = planner.answer(&request);
                    match answered.try_send(reply) {
                        Ok(()) | Err(TrySendError::Full(_)) => {}
                        Err(TrySendError::Disconnected(_)) => break,
                    }
                }
            })?;
        Ok(Self {
            requests,
            replies,
            pending: 0,
        })
    }

    /// Offer `follower` the replies that have come.
    pub(crate) fn receive(&mut self, follower: &mut Mpc) {
        while let Ok(reply) = self.replies.try_recv() {
            self.pending = self.pending.saturating_sub(1);
            follower.offer(&reply);
        }
    }

    /// Send `follower`'s request, if it has one.
    pub(crate) fn send(&mut self, follower: &mut Mpc) {
        if let Some(request) = follower.take_request() {
            // One still waiting: this one is dropped, its instant goes on with the last
            // plan.
            if self.requests.try_send(request).is_ok() {
                self.pending += 1;
            }
        }
    }

    /// Wait for the reply to the request the thread took, if any, and offer it (tests:
    /// the thread's answers without racing it).
    #[cfg(test)]
    pub(crate) fn wait(&mut self, follower: &mut Mpc) -> bool {
        if self.pending == 0 {
            return false;
        }
        match self.replies.recv() {
            Ok(reply) => {
                self.pending -= 1;
                follower.offer(&reply);
                true
            }
            Err(_) => false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use stewart_kinematics::Scenario;
    use stewart_kinematics::analysis::cueing::VehicleMotion;

    #[test]
    fn the_thread_answers_as_the_planner_would_here() {
        let mut s = Scenario::preset("seed").unwrap_or_else(|e| panic!("{e}"));
        s.cueing.algorithm = stewart_kinematics::model::cueing_settings::CueingAlgorithm::Mpc;
        let planner = Mpc::new(&s.geometry, &s.limits, &s.cueing).unwrap_or_else(|_| panic!());
        let mut here = planner.clone();
        let mut thread = PlannerThread::start(planner.clone()).unwrap_or_else(|e| panic!("{e}"));
        let mut follower = planner;
        follower.set_remote(true);
        follower.hold(&VehicleMotion {
            accel: [2.0, 1.0, 0.0],
            rates_deg_s: [0.0, 0.0, 10.0],
        });
        let mut followed = Vec::new();
        for _ in 0..50 {
            followed.push(follower.advance(0.01));
            let request = follower
                .take_request()
                .unwrap_or_else(|| panic!("a request"));
            let expected = here.answer(&request);
            follower.offer(&expected);
            // The thread's answer to the same request, waited for (it is waiting for
            // one: nothing else is asked of it).
            thread
                .requests
                .send(request)
                .unwrap_or_else(|e| panic!("{e}"));
            thread.pending += 1;
            let mut other = follower.clone();
            assert!(thread.wait(&mut other));
            let (a, b) = (follower.clone().advance(0.01), other.advance(0.01));
            assert_eq!(a, b, "the same plan from the thread");
        }
        assert!(followed.iter().any(|p| *p != followed[0]), "it moved");
    }
}
