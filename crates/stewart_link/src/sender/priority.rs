//! The sender thread's scheduling: real-time (first-in-first-out) where the system permits
//! it, so that a busy machine (the viewer rendering on every core) does not delay the
//! set-points; otherwise the highest normal priority.

use thread_priority::{ThreadPriority, ThreadPriorityValue};

/// The real-time priority asked for (1–99 on Linux): above ordinary work, below the
/// kernel's own real-time threads.
const REALTIME_PRIORITY: u8 = 50;

/// Raise the calling thread's priority; returns how it is now scheduled, in words.
pub fn raise() -> String {
    #[cfg(unix)]
    {
        use thread_priority::unix::{
            RealtimeThreadSchedulePolicy, ThreadSchedulePolicy, set_thread_priority_and_policy,
            thread_native_id,
        };
        if let Ok(value) = ThreadPriorityValue::try_from(REALTIME_PRIORITY)
            && set_thread_priority_and_policy(
                thread_native_id(),
                ThreadPriority::Crossplatform(value),
                ThreadSchedulePolicy::Realtime(RealtimeThreadSchedulePolicy::Fifo),
            )
            .is_ok()
        {
            return format!("real-time (FIFO {REALTIME_PRIORITY})");
        }
    }
    match thread_priority::set_current_thread_priority(ThreadPriority::Max) {
        Ok(()) => "highest normal priority (real-time not permitted)".to_owned(),
        Err(e) => format!("normal priority (could not raise it: {e:?})"),
    }
}
