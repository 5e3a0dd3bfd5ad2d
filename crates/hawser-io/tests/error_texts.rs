//! No user message shows Rust's debug formatting (`Location { object: … }`, `Some(…)`,
//! `Point(3)`): every variant of the core's error types is built and its message checked,
//! and so is every stored error snapshot of the CLI and the input reader.

use hawser::error::{ModalError, ModelError, SimulationError, StaticsError};
use hawser::linalg::eigen::EigenFailure;
use hawser::system::Location;
use std::path::Path;

/// The first trace of debug formatting in `text`: a type name followed by ` {` or `(`
/// (`Location {`, `Some(`, `Point(`), or `None`.
fn debug_trace(text: &str) -> Option<String> {
    let bytes: Vec<char> = text.chars().collect();
    for (i, c) in bytes.iter().enumerate() {
        let starts_word = i == 0 || !bytes[i - 1].is_alphanumeric() && bytes[i - 1] != '_';
        if !c.is_ascii_uppercase() || !starts_word {
            continue;
        }
        let mut j = i + 1;
        while j < bytes.len() && bytes[j].is_ascii_alphabetic() {
            j += 1;
        }
        let word: String = bytes[i..j].iter().collect();
        let rest: String = bytes[j..bytes.len().min(j + 2)].iter().collect();
        if j - i >= 2 && (rest.starts_with('(') || rest == " {") || word == "None" {
            return Some(bytes[i..bytes.len().min(j + 12)].iter().collect());
        }
    }
    None
}

fn check(message: &str) {
    assert!(
        debug_trace(message).is_none(),
        "debug formatting `{}` in: {message}",
        debug_trace(message).unwrap()
    );
}

/// Every variant (the `match`es fail to compile when a variant is added, so that it is added
/// here too).
#[test]
fn every_error_variant_reads_as_words() {
    let location = Location {
        object: "L1".into(),
        node: 12,
    };
    check(&location.to_string());
    let model = [
        ModelError::Invalid {
            what: "line L1".into(),
            why: "length must be > 0 m".into(),
        },
        ModelError::SchemeCannotStepDg {
            scheme: "three-level",
            line: "L1".into(),
        },
        ModelError::SchemeCannotStepBodies {
            scheme: "three-level",
            body: "buoy".into(),
        },
        ModelError::SchemeCannotStepPinOnBody {
            body: "arm".into(),
            parent: "buoy".into(),
        },
        ModelError::StateLength {
            given: 3,
            expected: 6,
        },
        ModelError::MasslessDgJoint {
            point: "joint".into(),
        },
    ];
    for e in &model {
        match e {
            ModelError::Invalid { .. }
            | ModelError::SchemeCannotStepDg { .. }
            | ModelError::SchemeCannotStepBodies { .. }
            | ModelError::SchemeCannotStepPinOnBody { .. }
            | ModelError::StateLength { .. }
            | ModelError::MasslessDgJoint { .. } => check(&e.to_string()),
        }
    }
    let statics = [
        StaticsError::Unsupported {
            points: "buoy".into(),
            net_force: 1.0e3,
            what: "weight 1.0e3 N".into(),
        },
        StaticsError::NotConverged {
            iterations: 100,
            residual: 1.0,
            tolerance: 1e-6,
            location: format!("{location}"),
            relaxation_residual: 0.5,
            hint: "start the bodies where their lines are taut".into(),
        },
    ];
    for e in &statics {
        match e {
            StaticsError::Unsupported { .. } | StaticsError::NotConverged { .. } => {
                check(&e.to_string())
            }
        }
    }
    let simulation = [
        SimulationError::Diverged {
            time: 1.0,
            object: "L1".into(),
            node: 3,
            reason: "non-finite state".into(),
            stable_step: 1e-3,
        },
        SimulationError::StepTooLarge {
            step: 1e-2,
            limit: 1e-3,
            culprit: "axial stiffness at line L1 node 1".into(),
        },
        SimulationError::Interrupted { time: 2.0 },
        SimulationError::StepUnusable {
            step: 0.0,
            culprit: "axial stiffness at line L1 node 1".into(),
            duration: 10.0,
            steps: f64::INFINITY,
        },
        SimulationError::Observer {
            message: "writing out/timeseries.csv: disk full".into(),
        },
        SimulationError::Coupling {
            what: "point #3 is not a coupled point".into(),
        },
        SimulationError::Checkpoint {
            what: "another model".into(),
        },
        SimulationError::Model(model[0].clone()),
        SimulationError::Statics(statics[1].clone()),
    ];
    for e in &simulation {
        match e {
            SimulationError::Diverged { .. }
            | SimulationError::StepTooLarge { .. }
            | SimulationError::Interrupted { .. }
            | SimulationError::StepUnusable { .. }
            | SimulationError::Observer { .. }
            | SimulationError::Coupling { .. }
            | SimulationError::Checkpoint { .. }
            | SimulationError::Model(_)
            | SimulationError::Statics(_) => check(&e.to_string()),
        }
    }
    let modal = [
        ModalError::Unsupported {
            line: "L1".into(),
            formulation: "dg",
        },
        ModalError::NoDegreesOfFreedom,
        ModalError::PinnedToBody {
            body: "arm".into(),
            parent: "buoy".into(),
        },
        ModalError::MassNotDefinite,
        ModalError::Singular {
            location: "the stiffness matrix".into(),
        },
        ModalError::NotConverged {
            iterations: 40,
            residual: 1e-6,
        },
    ];
    for e in &modal {
        match e {
            ModalError::Unsupported { .. }
            | ModalError::NoDegreesOfFreedom
            | ModalError::PinnedToBody { .. }
            | ModalError::MassNotDefinite
            | ModalError::Singular { .. }
            | ModalError::NotConverged { .. } => check(&e.to_string()),
        }
    }
    for e in [
        EigenFailure::MassNotDefinite,
        EigenFailure::SingularShift,
        EigenFailure::NotConverged {
            iterations: 40,
            residual: 1e-6,
        },
    ] {
        check(&e.to_string());
    }
}

/// The coupling errors a host gets name objects in words.
#[test]
fn coupling_errors_read_as_words() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/moordyn/oc3_lines.txt");
    let (mut loaded, _) = hawser_io::input::load_input(&path, &Default::default()).unwrap();
    hawser_io::moordyn::couple_deck_points(&mut loaded);
    let mut session = hawser::Session::new(loaded.model).unwrap();
    // Wrong lengths, an object that is not there (an error, not a panic), one that is not
    // coupled.
    let errors = [
        session
            .set_coupled(0.1, &[0.0; 2], &[0.0; 2], None)
            .unwrap_err(),
        session.body_reaction(0).unwrap_err(),
        session.point_reaction(99).unwrap_err(),
        session.pin_load(0).unwrap_err(),
        session
            .set_point_kinematics(0, 0.1, Default::default(), Default::default(), None)
            .unwrap_err(),
    ];
    for e in errors {
        eprintln!("{e}");
        check(&e.to_string());
    }
}

/// Every stored error snapshot (the CLI's, the input reader's) reads as words.
#[test]
fn stored_messages_read_as_words() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut n = 0;
    for dir in [
        "crates/hawser-cli/tests/snapshots",
        "crates/hawser-io/tests/snapshots",
    ] {
        for entry in std::fs::read_dir(root.join(dir)).unwrap() {
            let path = entry.unwrap().path();
            let text = std::fs::read_to_string(&path).unwrap();
            // The snapshot's body, after its front matter.
            let body = text.splitn(3, "---").nth(2).unwrap_or(&text);
            if let Some(t) = debug_trace(body) {
                panic!("{}: debug formatting `{t}`", path.display());
            }
            n += 1;
        }
    }
    assert!(n > 100, "{n} snapshots");
}

#[test]
fn the_detector_finds_debug_formatting() {
    for bad in [
        "singular at Location { object: \"L1\", node: 3 }",
        "value Some(3.0)",
        "got None",
        "at Point(3)",
    ] {
        assert!(debug_trace(bad).is_some(), "{bad}");
    }
    for good in [
        "R = R_z(yaw) R_y(pitch)",
        "line `L1` node 12",
        "MoorDyn 2.7.2 (its surge drag is zero)",
        "the OC3 deck",
    ] {
        assert!(debug_trace(good).is_none(), "{good}");
    }
}
