//! Undo and redo of scenario edits (Ctrl+Z, Ctrl+Shift+Z or Ctrl+Y): every change that
//! goes through the state's one edit path, and every scenario loaded, is a step. The
//! edits of one gesture (a slider dragged while the button is held) make a single step.

use stewart_kinematics::Scenario;

/// Steps kept; the oldest go first.
pub(crate) const DEPTH: usize = 200;

/// The scenarios before the present one, and those undone.
#[derive(Debug, Default)]
pub(crate) struct Undo {
    past: Vec<Scenario>,
    future: Vec<Scenario>,
    /// An edit gesture is under way: further edits join its step.
    open: bool,
}

impl Undo {
    /// The scenario is about to change from `before`: start a step (unless one gesture's
    /// step is open) and forget what was undone.
    pub(crate) fn record(&mut self, before: &Scenario) {
        if !self.open {
            if self.past.len() == DEPTH {
                self.past.remove(0);
            }
            self.past.push(before.clone());
            self.open = true;
        }
        self.future.clear();
    }

    /// The gesture ended (no button held): the next edit starts a new step.
    pub(crate) fn seal(&mut self) {
        self.open = false;
    }

    /// The scenario before `present`, if any (`present` can be redone).
    pub(crate) fn undo(&mut self, present: &Scenario) -> Option<Scenario> {
        self.open = false;
        let before = self.past.pop()?;
        self.future.push(present.clone());
        Some(before)
    }

    /// The scenario undone last, if any (`present` can be undone again).
    pub(crate) fn redo(&mut self, present: &Scenario) -> Option<Scenario> {
        self.open = false;
        let after = self.future.pop()?;
        self.past.push(present.clone());
        Some(after)
    }

    /// Whether there is a step to undo.
    pub(crate) fn can_undo(&self) -> bool {
        !self.past.is_empty()
    }

    /// Whether there is a step to redo.
    pub(crate) fn can_redo(&self) -> bool {
        !self.future.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn named(name: &str) -> Scenario {
        let mut s = Scenario::seed();
        s.name = name.to_owned();
        s
    }

    #[test]
    fn steps_undo_and_redo_in_order_and_a_gesture_is_one_step() {
        let mut u = Undo::default();
        let (a, b, c) = (named("a"), named("b"), named("c"));
        u.record(&a);
        u.seal();
        // One drag: two edits, one step.
        u.record(&b);
        u.record(&named("b2"));
        u.seal();
        assert_eq!(u.undo(&c).map(|s| s.name), Some("b".to_owned()));
        assert_eq!(u.undo(&b).map(|s| s.name), Some("a".to_owned()));
        assert!(u.undo(&a).is_none());
        assert_eq!(u.redo(&a).map(|s| s.name), Some("b".to_owned()));
        assert_eq!(u.redo(&b).map(|s| s.name), Some("c".to_owned()));
        assert!(!u.can_redo());
        // A new edit after an undo forgets the redo.
        u.undo(&c);
        u.record(&b);
        assert!(!u.can_redo());
    }

    #[test]
    fn only_the_last_steps_are_kept() {
        let mut u = Undo::default();
        for k in 0..DEPTH + 5 {
            u.record(&named(&k.to_string()));
            u.seal();
        }
        let mut oldest = String::new();
        let present = named("now");
        while let Some(s) = u.undo(&present) {
            oldest = s.name;
        }
        assert_eq!(oldest, "5");
    }
}
