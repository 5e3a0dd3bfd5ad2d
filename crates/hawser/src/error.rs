//! Error types. They carry the numbers a user needs to act on them.

use crate::math::Real;

/// A model that cannot be simulated.
#[derive(Debug, thiserror::Error, Clone, PartialEq)]
pub enum ModelError {
    /// A value or reference is out of range.
    #[error("{what}: {why}")]
    Invalid {
        /// What is wrong (the item and key).
        what: String,
        /// Why, with the expected range and unit.
        why: String,
    },
    /// A `dg` line in a run whose scheme integrates second-order equations in positions only.
    #[error(
        "line {line}: uses `dg`, a first-order system in q and v, which the {scheme} scheme \
         (for second-order equations in positions) cannot step: use scheme = \"ssp-rk3\" (the \
         DG paper's) or \"rk4\""
    )]
    SchemeCannotStepDg {
        /// The scheme's name as in the scenario key (`three-level`).
        scheme: &'static str,
        /// The first `dg` line's name.
        line: String,
    },
    /// A free rigid body in a run whose scheme does not integrate rigid bodies.
    #[error(
        "body {body}: is free: the {scheme} scheme does not integrate rigid bodies; use \
         scheme = \"rk4\" or \"ssp-rk3\""
    )]
    SchemeCannotStepBodies {
        /// The scheme's name as in the scenario key (`three-level`).
        scheme: &'static str,
        /// The first free body's name.
        body: String,
    },
    /// A body pinned to another body in a generalized-α run: the scheme enforces the pin's
    /// acceleration constraint with the parent's kinematics of its force evaluation (at
    /// t_{n+1−α_f}) rather than at t_{n+1}, and converges at first order only (measured in
    /// `crates/hawser/tests/body_pins.rs`), so it is refused until that is mended.
    #[error(
        "body {body}: is pinned to body {parent}, which the generalized-alpha scheme steps at \
         first order only; use scheme = \"rk4\" or \"ssp-rk3\""
    )]
    SchemeCannotStepPinOnBody {
        /// The pinned body's name.
        body: String,
        /// The parent body's name.
        parent: String,
    },
    /// A state vector given to a session has the wrong length.
    #[error("the initial state: has {given} entries where the model's state has {expected}")]
    StateLength {
        /// Entries given.
        given: usize,
        /// Entries of the model's state.
        expected: usize,
    },
    /// A massless free point where only `dg` lines meet: nothing carries its inertia.
    #[error(
        "point {point}: is a massless free point joining dg lines, whose ends carry no mass: \
         give it a mass (a massless point at the end of a single dg line is that line's free end)"
    )]
    MasslessDgJoint {
        /// The point's name.
        point: String,
    },
}

/// A time integration that cannot go on.
#[derive(Debug, thiserror::Error, Clone, PartialEq)]
pub enum SimulationError {
    /// The state became non-finite or non-physical.
    #[error(
        "the simulation diverged at t = {time:.6} s on {object} node {node} ({reason}); \
         the stable time step estimate is {stable_step:.3e} s; \
         hint: reduce the time step (or use time_step = \"auto\"), refine or check the line properties"
    )]
    Diverged {
        /// Simulated time [s] of the last good state.
        time: Real,
        /// Line or point name.
        object: String,
        /// Node index along the line (0 at end A); 0 for a point.
        node: usize,
        /// What went wrong.
        reason: String,
        /// Stable step estimate [s].
        stable_step: Real,
    },
    /// A user time step above the stability limit.
    #[error(
        "time_step = {step:.4e} s exceeds the stability limit {limit:.4e} s set by {culprit}; \
         hint: use time_step = \"auto\" or a step ≤ {limit:.4e} s"
    )]
    StepTooLarge {
        /// The requested step [s].
        step: Real,
        /// The limit [s].
        limit: Real,
        /// Which element or point sets it.
        culprit: String,
    },
    /// A time step with which the run cannot end: zero, not finite, or needing more than
    /// [`MAX_STEPS`](crate::session::MAX_STEPS) steps for the duration.
    #[error(
        "the time step {step:.4e} s (set by {culprit}) cannot run the {duration} s duration: it \
         needs {steps:.3e} steps; hint: check the property that sets the step (a friction \
         velocity, damping or stiffness far outside the physical range?), or give a \
         time_step"
    )]
    StepUnusable {
        /// The step [s].
        step: Real,
        /// What sets it.
        culprit: String,
        /// The run's duration [s].
        duration: Real,
        /// The steps the duration needs (infinite for a zero step).
        steps: Real,
    },
    /// The run was stopped from outside (SIGINT, SIGTERM, a host's interrupt flag) between
    /// two steps.
    #[error("the run was interrupted at t = {time:.6} s")]
    Interrupted {
        /// Simulated time of the last completed step [s].
        time: Real,
    },
    /// An observer (a result writer) failed; the message names the file.
    #[error("{message}")]
    Observer {
        /// What failed.
        message: String,
    },
    /// A coupling host's call that cannot be taken (an object that is not coupled, arrays of
    /// the wrong length, a time in the past, non-finite kinematics).
    #[error("coupling: {what}")]
    Coupling {
        /// What is wrong, with the numbers.
        what: String,
    },
    /// A checkpoint that cannot be restored (another model, another format version, damaged).
    #[error("checkpoint: {what}")]
    Checkpoint {
        /// Why.
        what: String,
    },
    /// The model is invalid.
    #[error(transparent)]
    Model(#[from] ModelError),
    /// The initial statics failed.
    #[error("initial statics: {0}")]
    Statics(#[from] StaticsError),
}

/// A static solve that failed.
#[derive(Debug, thiserror::Error, Clone, PartialEq)]
pub enum StaticsError {
    /// Free points and lines held by no fixed or prescribed point, under a net load.
    #[error(
        "no static equilibrium exists: {points} are held by no fixed or prescribed point and carry \
         a net static force of {net_force:.4e} N ({what}); hint: attach them to an anchor or a \
         prescribed point, or balance their weight with buoyancy"
    )]
    Unsupported {
        /// Names of the free points of the unsupported group.
        points: String,
        /// Magnitude of the group's net static force [N].
        net_force: Real,
        /// What that force is made of.
        what: String,
    },
    /// Newton and the dynamic-relaxation fallback both failed to converge.
    #[error(
        "no static equilibrium found: Newton stopped after {iterations} iterations with residual \
         {residual:.3e} N (tolerance {tolerance:.3e} N) at {location}; dynamic relaxation reached \
         {relaxation_residual:.3e} N; hint: {hint}"
    )]
    NotConverged {
        /// Newton iterations done.
        iterations: usize,
        /// Largest nodal force imbalance after Newton [N].
        residual: Real,
        /// Tolerance [N].
        tolerance: Real,
        /// Where the largest imbalance is.
        location: String,
        /// Largest imbalance after dynamic relaxation [N].
        relaxation_residual: Real,
        /// What to try.
        hint: String,
    },
}

/// A modal analysis that failed.
#[derive(Debug, thiserror::Error, Clone, PartialEq)]
pub enum ModalError {
    /// A line's unknowns are not linearised (`dg`: modal coefficients).
    #[error(
        "line `{line}` uses the `{formulation}` formulation, whose modal coefficients are not \
         linearised; hint: compute the modes of the model's hermite twin \
         (hawser::analysis::modes::modal_twin: the same sections in cubic elements, as `hawser \
         modes` does), or give the line `formulation = \"hermite\"`, which keeps its bending"
    )]
    Unsupported {
        /// Line name.
        line: String,
        /// Formulation name.
        formulation: &'static str,
    },
    /// A body pinned to a point of another body: its translations follow the parent's
    /// rotations, a constraint the linearisation does not carry.
    #[error(
        "body `{body}` is pinned to body `{parent}`, and the modal analysis holds a pinned \
         body's origin still (its pin's motion is given), which a pin on a moving body is not; \
         hint: run the dynamics, or pin `{body}` to a fixed point to compute the modes"
    )]
    PinnedToBody {
        /// Body name.
        body: String,
        /// The parent body's name.
        parent: String,
    },
    /// Nothing can move: every line end is fixed or prescribed and no line has interior nodes.
    #[error(
        "the system has no degrees of freedom (no interior line nodes, free points or free \
         bodies); hint: give the lines more than one element"
    )]
    NoDegreesOfFreedom,
    /// The mass matrix is not positive definite (a massless free point outside the water
    /// with no line mass, or a non-physical added mass).
    #[error(
        "the mass matrix is not positive definite; hint: give massless free points a mass or \
         use the shift-invert method"
    )]
    MassNotDefinite,
    /// The stiffness is singular at every shift tried.
    #[error(
        "{location} is singular: some degrees of freedom have no stiffness (a slack line or an \
         unloaded joint); hint: check the static state, or give a shift below zero"
    )]
    Singular {
        /// Where.
        location: String,
    },
    /// The eigen solver did not converge.
    #[error(
        "the eigen solver did not converge after {iterations} iterations (relative residual \
         {residual:.2e}); hint: ask for fewer modes or use the dense method"
    )]
    NotConverged {
        /// Iterations done.
        iterations: usize,
        /// Largest relative residual of the wanted modes.
        residual: Real,
    },
}

impl std::fmt::Display for crate::system::Location {
    /// `line L1, node 12`, or the name of a point or body (node 0).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.node == 0 {
            write!(f, "`{}`", self.object)
        } else {
            write!(f, "`{}` node {}", self.object, self.node)
        }
    }
}

/// The message of a caught panic's payload (`std::panic::catch_unwind`'s `Err`): the text
/// given to `panic!`, or "a panic without a message" for any other payload. The hosts that
/// turn a panic into an error (the C ABI, the Python runner, `hawser sweep`) report it with
/// this text.
pub fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "a panic without a message".into())
}

#[cfg(test)]
mod tests {
    use super::panic_message;

    #[test]
    fn panic_message_reads_str_and_string_payloads() {
        let s = std::panic::catch_unwind(|| panic!("static text")).unwrap_err();
        assert_eq!(panic_message(s.as_ref()), "static text");
        let n = 3;
        let f = std::panic::catch_unwind(|| panic!("formatted {n}")).unwrap_err();
        assert_eq!(panic_message(f.as_ref()), "formatted 3");
        let o = std::panic::catch_unwind(|| std::panic::panic_any(7_u8)).unwrap_err();
        assert_eq!(panic_message(o.as_ref()), "a panic without a message");
    }
}
