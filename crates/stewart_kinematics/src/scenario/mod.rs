//! x
pub struct Scenario; pub struct ScenarioError;
