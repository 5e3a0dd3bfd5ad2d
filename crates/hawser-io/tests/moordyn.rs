//! MoorDyn v2 deck import: conventions converted, conversion round trip through TOML, and the
//! error for every kind of bad deck (file, line, column name, expected form).

use hawser::analysis::Channel;
use hawser::model::{MassMatrix, PointKind, TimeStep};
use hawser::physics::material::AxialDamping;
use hawser::physics::seabed::{ContactDamping, FrictionLaw};
use hawser_io::moordyn::{self, ConvertOptions};
use std::path::{Path, PathBuf};

fn deck_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/moordyn")
}

fn deck_text(name: &str) -> String {
    std::fs::read_to_string(deck_dir().join(name)).expect("deck present")
}

const DECKS: [&str; 6] = [
    "oc3_lines.txt",
    "WD0050_Chain.txt",
    "WD0200_Chain.txt",
    "WD0600_Chain.txt",
    "buoy_oc3.txt",
    "rod_hanging.txt",
];

/// Parses deck text as if it were `deck.txt` beside the shared decks.
fn parse(text: &str) -> Result<moordyn::LoadedDeck, String> {
    moordyn::parse(
        &deck_dir().join("deck.txt"),
        text,
        &ConvertOptions::default(),
    )
    .map_err(|e| {
        e.to_string()
            .replace(&deck_dir().display().to_string(), "<decks>")
    })
}

fn error_of(text: &str) -> String {
    match parse(text) {
        Ok(_) => panic!("the deck should be refused"),
        Err(e) => e,
    }
}

/// Replaces one exact piece of a deck (which must be present).
fn mutate(name: &str, from: &str, to: &str) -> String {
    let t = deck_text(name);
    assert!(t.contains(from), "`{from}` not in {name}");
    t.replacen(from, to, 1)
}

#[test]
fn every_deck_is_recognised_by_content_and_reads() {
    for name in DECKS {
        let text = deck_text(name);
        assert!(moordyn::looks_like_deck(&text), "{name}");
        let d = parse(&text).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(!d.loaded.model.lines.is_empty());
    }
    // A hawser scenario is not mistaken for a deck.
    let toml = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/catenary_mooring.toml"),
    )
    .unwrap();
    assert!(!moordyn::looks_like_deck(&toml));
}

#[test]
fn oc3_conventions_are_converted() {
    let d = parse(&deck_text("oc3_lines.txt")).unwrap();
    let m = &d.loaded.model;
    let t = &m.line_types[0];
    assert_eq!(t.diameter, 0.09);
    assert_eq!(t.mass_per_length, 77.7066);
    // CdAx on π·d becomes C_dt on d.
    match &t.drag {
        hawser::physics::hydrodynamics::DragModel::Morison { normal, tangential } => {
            assert_eq!(*normal, 1.6);
            assert!((tangential - 0.1 * std::f64::consts::PI).abs() < 1e-15);
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(t.axial_damping, AxialDamping::Ratio(0.8));
    assert_eq!(t.normal_added_mass, 1.0);
    assert_eq!(t.tangential_added_mass, 0.0);
    assert_eq!(m.environment.depth, 320.0);
    assert_eq!(m.environment.water_density, 1025.0);
    assert_eq!(m.environment.gravity, 9.80665);
    assert_eq!(m.environment.seabed.stiffness, 3.0e6);
    assert_eq!(m.environment.seabed.damping, ContactDamping::PerArea(3.0e5));
    assert_eq!(m.settings.time_step, TimeStep::Fixed(0.002));
    // MoorDyn's lines are lumped-mass.
    for l in &m.lines {
        assert_eq!(l.mass_matrix, MassMatrix::Lumped);
        assert_eq!(l.sections[0].elements, 20);
        assert_eq!(l.sections[0].length, 902.2);
    }
    let fixed = m
        .points
        .iter()
        .filter(|p| matches!(p.kind, PointKind::Fixed))
        .count();
    let prescribed = m
        .points
        .iter()
        .filter(|p| matches!(p.kind, PointKind::Prescribed(_)))
        .count();
    assert_eq!((fixed, prescribed), (3, 3));
    // OUTPUTS keep their names and mean MoorDyn's |Fnet| of the end node.
    let outs: Vec<_> = d
        .loaded
        .model
        .outputs
        .iter()
        .filter(|c| c.label.is_some())
        .collect();
    assert_eq!(outs.len(), 3);
    for (i, o) in outs.iter().enumerate() {
        assert_eq!(
            o.label.as_deref(),
            Some(format!("FairTen{}", i + 1).as_str())
        );
        assert_eq!(
            o.channel,
            Channel::EndNodeForce {
                line: i,
                end_b: true
            }
        );
    }
}

#[test]
fn chain_decks_get_moordyns_friction_and_cfl_step() {
    let d = parse(&deck_text("WD0050_Chain.txt")).unwrap();
    let m = &d.loaded.model;
    let s = &m.environment.seabed;
    assert_eq!(s.friction_coefficient, 0.5);
    assert_eq!(
        s.friction_law,
        FrictionLaw::Viscous {
            damping: 200.0,
            static_scale: 1.0
        }
    );
    assert_eq!(s.stiffness, 1.0e5);
    assert_eq!(s.damping, ContactDamping::PerArea(1.0e4));
    assert_eq!(m.settings.time_step, TimeStep::Auto);
    // The options hawser does not use are reported, by name, with their line.
    let said = |word: &str| d.notes.iter().any(|n| n.message.contains(word));
    for word in [
        "CFL",
        "fileIC",
        "dtIC",
        "TmaxIC",
        "threshIC",
        "writeLog",
        "disableOutTime",
    ] {
        assert!(said(word), "no note on {word}: {:#?}", d.notes);
    }
    assert!(
        d.notes
            .iter()
            .all(|n| n.line > 0 || n.message.contains("duration"))
    );
}

#[test]
fn conversion_round_trips_through_toml() {
    for name in DECKS {
        let d = parse(&deck_text(name)).unwrap();
        let text = moordyn::to_toml(&d, Path::new(name));
        let back = hawser_io::scenario::parse(&deck_dir().join("converted.toml"), &text)
            .unwrap_or_else(|e| panic!("{name}: converted TOML does not read back:\n{e}\n{text}"));
        assert_eq!(
            format!("{:?}", back.model),
            format!("{:?}", d.loaded.model),
            "{name}: the converted scenario is not the same model"
        );
        assert_eq!(back.model.outputs, d.loaded.model.outputs, "{name}");
    }
}

#[test]
fn tabs_blank_lines_and_missing_unit_rows_are_accepted() {
    let original = parse(&deck_text("oc3_lines.txt")).unwrap();
    let forgiving = deck_text("oc3_lines.txt")
        .replace("     ", "\t")
        .replace("1     main", "\n1\tmain")
        .replace("(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2)    (-)    (-)    (-)     (-)\n", "");
    let d = parse(&forgiving).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        format!("{:?}", d.loaded.model),
        format!("{:?}", original.loaded.model)
    );
}

#[test]
fn negative_length_is_a_multiple_of_the_span() {
    let text = mutate("WD0050_Chain.txt", "410       41", "-1.05     41");
    let d = parse(&text).unwrap();
    let span = (400.0f64.powi(2) + 50.0f64.powi(2)).sqrt();
    assert!((d.loaded.model.lines[0].sections[0].length - 1.05 * span).abs() < 1e-9);
}

#[test]
fn unknown_option_is_reported_not_fatal() {
    let text = mutate(
        "oc3_lines.txt",
        "320           WtrDpth",
        "320           WtrDpth\n5             FooBar",
    );
    let d = parse(&text).unwrap();
    assert!(d.notes.iter().any(|n| n.message.contains("FooBar")));
}

#[test]
fn output_channel_names() {
    use hawser_io::moordyn::convert::output_channel;
    let seg = |l: &str| (l == "L1").then_some(20);
    // B1 free, B2 coupled.
    let body = |b: &str| match b {
        "B1" => Some(true),
        "B2" => Some(false),
        _ => None,
    };
    let ok = |n: &str| output_channel(n, seg, body).unwrap();
    assert_eq!(ok("FairTen1"), "L1.end_b.node_force");
    assert_eq!(ok("anchten1"), "L1.end_a.node_force");
    assert_eq!(ok("L1N5PX"), "L1.node5.x");
    assert_eq!(ok("Line1Node5VZ"), "L1.node5.vz");
    assert_eq!(ok("L1N10T"), "L1.node10.tension");
    assert_eq!(ok("L1N20T"), "L1.end_b.node_force");
    assert_eq!(ok("L1NBT"), "L1.end_b.node_force");
    assert_eq!(ok("L1NAPZ"), "L1.node0.z");
    assert_eq!(ok("P4FX"), "P4.fx");
    assert_eq!(ok("Point4PZ"), "P4.z");
    assert_eq!(ok("Body1PX"), "B1.x");
    assert_eq!(ok("B1RY"), "B1.pitch");
    assert_eq!(ok("b1rvz"), "B1.wz");
    assert_eq!(ok("Body2FX"), "B2.fx");
    assert_eq!(ok("B2MZ"), "B2.mz");
    for bad in [
        "L2N1T", "L1N21T", "L1N5AX", "Con3FX", "R1PX", "FairTen", "Foo", "B1FX", "B3PX", "B1AX",
    ] {
        assert!(output_channel(bad, seg, body).is_err(), "{bad}");
    }
}

#[test]
fn coupled_points_follow_a_vessel_motion() {
    let options = ConvertOptions {
        duration: None,
        vessel_motion: Some(deck_dir().join("ZZP1_A1.txt")),
    };
    let d = moordyn::parse(
        &deck_dir().join("WD0200_Chain.txt"),
        &deck_text("WD0200_Chain.txt"),
        &options,
    )
    .unwrap();
    let m = &d.loaded.model;
    // 30 s of motion after the shift of its first row (t = −10 s) to t = 0.
    assert_eq!(m.settings.duration, 30.0);
    let PointKind::Prescribed(motion) = &m.points[1].kind else {
        panic!("the vessel point is prescribed");
    };
    // ZZP1: z = 2 sin(2π t/10) on the file's clock; t = 2.5 s there is t = 12.5 s here.
    let (r, _, _) = motion.kinematics(12.5);
    assert!((r.z - 2.0).abs() < 1e-9, "{r}");
    assert!(r.x.abs() < 1e-12 && r.y.abs() < 1e-12);
}

// ---- bodies ---------------------------------------------------------------------------------

/// OC3 with its fairleads as the points of a coupled body (MoorDyn's own `example/body.txt`
/// form), the body at `pose` (X0 Y0 Z0 r0 p0 y0) and the points at `points` in its axes.
fn oc3_on_a_body(pose: &str, points: [[f64; 3]; 3]) -> String {
    let mut t = mutate(
        "oc3_lines.txt",
        "---------------------- POINT PROPERTIES",
        &format!(
            "---------------------- BODIES ----\nID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca*\n\
             (#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)\n\
             1 Coupled {pose} 0 0 0 0 0 0\n---------------------- POINT PROPERTIES"
        ),
    );
    for (id, [x, y, z]) in [4, 5, 6].into_iter().zip(points) {
        let row = t
            .lines()
            .find(|l| l.starts_with(&format!("{id}     Coupled")))
            .unwrap()
            .to_string();
        t = t.replacen(&row, &format!("{id} Body1 {x} {y} {z} 0 0 0 0"), 1);
    }
    t
}

fn static_fairlead_tensions(d: &moordyn::LoadedDeck) -> Vec<f64> {
    let system = hawser::system::System::new(&d.loaded.model).unwrap();
    let sol = hawser::statics::solve(&system, None, &Default::default()).unwrap();
    let mut ws = system.workspace();
    hawser::statics::evaluate(&system, &sol.state, &mut ws);
    (0..3)
        .map(|l| system.end_force(&ws, l, true).norm())
        .collect()
}

/// A coupled body carrying OC3's fairleads gives OC3's tensions: at z = −70 with its points at
/// z = 0 (MoorDyn's example), and turned 120° in yaw with the points turned back, which
/// permutes nothing (the same global fairleads).
#[test]
fn coupled_body_carries_its_points() {
    let oc3 = static_fairlead_tensions(&parse(&deck_text("oc3_lines.txt")).unwrap());
    let fair = [[5.2, 0.0, -70.0], [-2.6, 4.5, -70.0], [-2.6, -4.5, -70.0]];
    let lifted = fair.map(|[x, y, _]| [x, y, 0.0]);
    let d = parse(&oc3_on_a_body("0 0 -70 0 0 0", lifted)).unwrap();
    let b = &d.loaded.model.bodies[0];
    assert_eq!(b.name, "B1");
    assert_eq!(b.kind, hawser::model::BodyKind::Coupled);
    assert!(
        d.loaded.model.points[3..6]
            .iter()
            .all(|p| matches!(p.kind, PointKind::Body { body: 0, .. }))
    );
    // The points in the axes of a body yawed by 120°: R_z(−120°) applied to the fairleads.
    let (s, c) = (-120f64).to_radians().sin_cos();
    let turned = fair.map(|[x, y, z]| [c * x - s * y, s * x + c * y, z]);
    let yawed = parse(&oc3_on_a_body("0 0 0 0 0 120", turned)).unwrap();
    for d in [d, yawed] {
        let t = static_fairlead_tensions(&d);
        for (a, b) in t.iter().zip(&oc3) {
            // The same fairleads to round-off of the turned coordinates.
            assert!(((a - b) / b).abs() < 1e-9, "{a} vs {b}");
        }
    }
}

/// MoorDyn turns a body by R = R_x(r0) R_y(p0) R_z(y0); the converted body has the same
/// rotation.
#[test]
fn body_orientation_is_moordyns_rotation() {
    let text = mutate(
        "buoy_oc3.txt",
        "-60    0     0     0 ",
        "-60    10    20    30",
    );
    let d = parse(&text).unwrap();
    let q = d.loaded.model.bodies[0].orientation;
    use hawser::math::{Quat, Vec3};
    let [r, p, y] = [10f64, 20.0, 30.0].map(f64::to_radians);
    let moordyn = Quat::from_axis_angle(&Vec3::x_axis(), r)
        * Quat::from_axis_angle(&Vec3::y_axis(), p)
        * Quat::from_axis_angle(&Vec3::z_axis(), y);
    assert!(q.angle_to(&moordyn) < 1e-12, "{}", q.angle_to(&moordyn));
    assert!(
        d.notes
            .iter()
            .any(|n| n.message.contains("R = R_x R_y R_z"))
    );
}

/// The buoy's MoorDyn values in hawser's keys, and the mass and volume of points on a free
/// body folded into it: two points of 1000 kg and 2 m³ at (4, 0, −10) and (0, 3, 0) in body
/// axes, checked against the hand sums.
#[test]
fn free_body_physics_and_point_masses() {
    let d = parse(&deck_text("buoy_oc3.txt")).unwrap();
    let b = &d.loaded.model.bodies[0];
    assert_eq!(b.kind, hawser::model::BodyKind::Free);
    assert_eq!(b.mass, 180e3);
    assert_eq!(b.centre_of_gravity, hawser::math::Vec3::new(0.0, 0.0, -2.0));
    assert_eq!(b.centre_of_buoyancy, b.centre_of_gravity);
    assert_eq!(b.hydrodynamic_centre, Some(hawser::math::Vec3::zeros()));
    assert_eq!(b.drag_speed, hawser::model::DragSpeed::Magnitude);
    assert_eq!(
        b.displacement,
        hawser::model::Displacement::Submerged { volume: 339.3 }
    );
    let rho_v = 1025.0 * 339.3;
    assert_eq!(
        b.added_mass.as_slice(),
        &[rho_v, rho_v, 0.5 * rho_v, 0.0, 0.0, 0.0]
    );
    assert_eq!(
        b.quadratic_drag.as_slice(),
        &[72.0, 72.0, 72.0, 3888.0, 3888.0, 3888.0]
    );
    let text = mutate(
        "buoy_oc3.txt",
        "4     Body1     5.2     0.0     -10.0   0      0",
        "4     Body1     5.2     0.0     -10.0   0      0       0      0\n\
         9     Body1     4.0     0.0     -10.0   1000   2",
    );
    let text = text.replacen(
        "8     Coupled   -400.0  0.0      0.0    0      0       0      0",
        "8     Coupled   -400.0  0.0      0.0    0      0       0      0\n\
         10    Body1     0.0     3.0      0.0   1000   2       0      0",
        1,
    );
    // Renumber: MoorDyn needs sequential IDs, hawser does not; the lines name points 1–8.
    let d = parse(&text).unwrap();
    let b = &d.loaded.model.bodies[0];
    let m = 180e3 + 2000.0;
    assert_eq!(b.mass, m);
    use hawser::math::Vec3;
    let cg = (Vec3::new(0.0, 0.0, -2.0) * 180e3
        + Vec3::new(4.0, 0.0, -10.0) * 1000.0
        + Vec3::new(0.0, 3.0, 0.0) * 1000.0)
        / m;
    assert!((b.centre_of_gravity - cg).norm() < 1e-12);
    // Inertia about the combined centre of gravity by parallel axes.
    let parallel = |r: Vec3, mass: f64| {
        let d = r - cg;
        (hawser::math::Mat3::identity() * d.norm_squared() - d * d.transpose()) * mass
    };
    let expected = hawser::math::Mat3::from_diagonal(&Vec3::new(2.565e6, 2.565e6, 8.1e5))
        + parallel(Vec3::new(0.0, 0.0, -2.0), 180e3)
        + parallel(Vec3::new(4.0, 0.0, -10.0), 1000.0)
        + parallel(Vec3::new(0.0, 3.0, 0.0), 1000.0);
    assert!((b.inertia - expected).abs().max() < 1e-6 * expected.abs().max());
    let v = 339.3 + 4.0;
    assert_eq!(
        b.displacement,
        hawser::model::Displacement::Submerged { volume: v }
    );
    let cb = (Vec3::new(0.0, 0.0, -2.0) * 339.3
        + Vec3::new(4.0, 0.0, -10.0) * 2.0
        + Vec3::new(0.0, 3.0, 0.0) * 2.0)
        / v;
    assert!((b.centre_of_buoyancy - cb).norm() < 1e-12);
    // The added mass stays the body's own ρ V Ca, at the origin.
    assert_eq!(b.added_mass[0], rho_v);
    assert!(
        d.notes
            .iter()
            .any(|n| n.message.contains("folded") || n.message.contains("part of the body"))
    );
}

/// A coupled body at the vessel origin rides on `--vessel-motion`: a prescribed body whose
/// pose is the file's.
#[test]
fn coupled_body_follows_a_vessel_motion() {
    let text = oc3_on_a_body(
        "0 0 0 0 0 0",
        [[5.2, 0.0, -70.0], [-2.6, 4.5, -70.0], [-2.6, -4.5, -70.0]],
    );
    let options = ConvertOptions {
        duration: None,
        vessel_motion: Some(deck_dir().join("ZZP1_A1.txt")),
    };
    let d = moordyn::parse(&deck_dir().join("deck.txt"), &text, &options).unwrap();
    let hawser::model::BodyKind::Prescribed(motion) = &d.loaded.model.bodies[0].kind else {
        panic!("the coupled body rides on the vessel motion");
    };
    // ZZP1: z = 2 sin(2π t/10) on the file's clock, shifted by 10 s.
    let k = motion.kinematics(12.5);
    assert!((k.position.z - 2.0).abs() < 1e-9, "{}", k.position);
    // Away from the vessel origin it is refused.
    let moved = oc3_on_a_body(
        "0 0 -70 0 0 0",
        [[5.2, 0.0, 0.0], [-2.6, 4.5, 0.0], [-2.6, -4.5, 0.0]],
    );
    let e = moordyn::parse(&deck_dir().join("deck.txt"), &moved, &options).unwrap_err();
    assert!(e.to_string().contains("not at the vessel origin"), "{e}");
}

/// A free rod is a free body `R1` at end A with one member; its mass w·L sits at mid-length
/// with a solid cylinder's inertia (MoorDyn's lumped nodes with its inertia correction); the
/// lines attach to the points `R1A` and `R1B` at its ends. On a body (`Body1`) the same rod is
/// a member of that body, its mass and inertia folded in.
#[test]
fn rods_are_members_of_bodies() {
    let d = parse(&deck_text("rod_hanging.txt")).unwrap();
    let m = &d.loaded.model;
    let b = &m.bodies[0];
    assert_eq!(b.name, "R1");
    assert_eq!(b.kind, hawser::model::BodyKind::Free);
    use hawser::math::{Mat3, Vec3};
    assert_eq!(b.position, Vec3::new(-10.0, 0.0, -75.0));
    let (mass, r, l) = (77.7066 * 20.0, 0.125, 20.0);
    assert!((b.mass - mass).abs() < 1e-9);
    assert_eq!(b.centre_of_gravity, Vec3::new(10.0, 0.0, 0.0));
    let across = mass * (l * l / 12.0 + r * r / 4.0);
    let expected = Mat3::from_diagonal(&Vec3::new(0.5 * mass * r * r, across, across));
    assert!((b.inertia - expected).abs().max() < 1e-9 * across);
    let member = &b.members[0];
    assert_eq!(
        (member.end_a, member.end_b),
        (Vec3::zeros(), Vec3::new(20.0, 0.0, 0.0))
    );
    assert_eq!((member.diameter, member.segments), (0.25, 4));
    assert_eq!(
        [
            member.normal_drag,
            member.normal_added_mass,
            member.end_drag,
            member.end_added_mass
        ],
        [1.6, 1.0, 1.6, 1.0]
    );
    let names: Vec<&str> = m.points.iter().map(|p| p.name.as_str()).collect();
    assert!(names.contains(&"R1A") && names.contains(&"R1B"));
    let hawser::model::LineEnd::Point(end_b) = m.lines[1].end_b;
    assert_eq!(m.points[end_b].name, "R1B");

    // The same rod on a free body at (−10, 0, −75): a member from (0, 0, 0) to (20, 0, 0).
    let text = mutate(
        "rod_hanging.txt",
        "---------------------- RODS",
        "---------------------- BODIES ----\nID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG I Volume CdA Ca\n\
         1 Free -10 0 -75 0 0 0 1000 0 10 0 0 0\n---------------------- RODS",
    )
    .replacen("1    rod       Free        -10   0     -75   10    0     -75", "1    rod       Body1        0   0       0   20    0       0", 1);
    let d = parse(&text).unwrap();
    let b = &d.loaded.model.bodies[0];
    assert_eq!(b.name, "B1");
    assert!((b.mass - (1000.0 + mass)).abs() < 1e-9);
    let cg = Vec3::new(10.0, 0.0, 0.0) * mass / (1000.0 + mass);
    assert!((b.centre_of_gravity - cg).norm() < 1e-12);
    assert_eq!(b.members.len(), 1);
    assert_eq!(d.loaded.model.bodies.len(), 1);
}

// ---- bad decks: every error names the file, line, column and the expected form ----------

macro_rules! bad_deck {
    ($name:ident, $deck:expr, $from:expr, $to:expr) => {
        #[test]
        fn $name() {
            insta::assert_snapshot!(error_of(&mutate($deck, $from, $to)));
        }
    };
}

bad_deck!(
    missing_column,
    "oc3_lines.txt",
    "main       0.09    77.7066    384.243E6  -0.8        0          1.6    1.0    0.1     0.0",
    "main       0.09    77.7066    384.243E6  -0.8        0          1.6    1.0    0.1"
);
bad_deck!(
    non_numeric_value,
    "oc3_lines.txt",
    "main       0.09",
    "main       0.O9"
);
bad_deck!(
    ea_neither_number_nor_file,
    "oc3_lines.txt",
    "384.243E6",
    "384.243E6x"
);
bad_deck!(
    unknown_line_type,
    "oc3_lines.txt",
    "2     main",
    "2     mian"
);
bad_deck!(
    unknown_point,
    "oc3_lines.txt",
    "3     main       3        6",
    "3     main       3        9"
);
bad_deck!(
    missing_closing_line,
    "oc3_lines.txt",
    "------------------------- need this line -------------------------------------- ",
    ""
);
bad_deck!(
    coupled_pinned_body_without_mass,
    "oc3_lines.txt",
    "---------------------- POINT PROPERTIES",
    "---------------------- BODIES ----\nID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca*\n(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)\n1 CoupledPinned 0 0 0 0 0 0 0 0 0 0 0 0\n---------------------- POINT PROPERTIES"
);
bad_deck!(
    body_cda_of_four_values,
    "buoy_oc3.txt",
    "72|3888",
    "72|3888|1|2"
);
bad_deck!(free_body_without_mass, "buoy_oc3.txt", "180e3 ", "0     ");
bad_deck!(
    drag_on_a_point_of_a_free_body,
    "buoy_oc3.txt",
    "5     Body1     -2.6    4.5     -10.0   0      0       0      0",
    "5     Body1     -2.6    4.5     -10.0   0      0       2.5    0"
);
bad_deck!(
    attached_to_a_missing_rod,
    "oc3_lines.txt",
    "1     main       1        4",
    "1     main       1        R1B"
);
bad_deck!(
    rod_pinned_on_a_missing_body,
    "rod_hanging.txt",
    "1    rod       Free       ",
    "1    rod       Body1Pinned"
);
bad_deck!(
    zero_length_rod_refused,
    "rod_hanging.txt",
    "-75  4       -",
    "-75  0       -"
);
bad_deck!(
    unknown_rod_type,
    "rod_hanging.txt",
    "1    rod       Free",
    "1    bar       Free"
);
bad_deck!(
    point_on_a_missing_body,
    "oc3_lines.txt",
    "4     Coupled",
    "4     Body1  "
);
bad_deck!(
    unknown_point_type,
    "oc3_lines.txt",
    "5     Coupled",
    "5     Floater"
);
bad_deck!(
    viv_refused,
    "oc3_lines.txt",
    "0.1     0.0\n",
    "0.1     0.0   0.8\n"
);
bad_deck!(
    unknown_output,
    "oc3_lines.txt",
    "FairTen2",
    "FairTen2 L1N5AX"
);
bad_deck!(
    waves_refused,
    "oc3_lines.txt",
    "320           WtrDpth       water depth (m)",
    "320           WtrDpth       water depth (m)\n1             WaveKin"
);
bad_deck!(
    negative_diameter_in_deck_words,
    "oc3_lines.txt",
    "main       0.09",
    "main       -0.09"
);
bad_deck!(
    zero_segments,
    "oc3_lines.txt",
    "902.2     20      p\n2",
    "902.2     0       p\n2"
);
bad_deck!(
    fractional_segments,
    "oc3_lines.txt",
    "902.2     20      p\n2",
    "902.2     20.5    p\n2"
);

#[test]
fn no_lines_section() {
    let t = deck_text("oc3_lines.txt");
    let start = t.find("---------------------- LINES").unwrap();
    let end = t.find("---------------------- OPTIONS").unwrap();
    let text = format!("{}{}", &t[..start], &t[end..]);
    insta::assert_snapshot!(error_of(&text));
}

/// A `Pinned` rod becomes a rigid cylinder body pinned at end A where it is (its origin),
/// turning freely, with the free rod's mass and inertia; `CoupledPinned` the same on a coupled
/// pin (three coupled degrees of freedom).
#[test]
fn pinned_rods_convert_to_pinned_bodies() {
    use hawser::model::{BodyKind, Pin};
    for (word, pin) in [("Pinned", Pin::Fixed), ("CpldPin", Pin::Coupled)] {
        let text = mutate(
            "rod_hanging.txt",
            "1    rod       Free  ",
            &format!("1    rod       {word:<6}"),
        );
        let deck = parse(&text).unwrap_or_else(|e| panic!("{e}"));
        let body = &deck.loaded.model.bodies[0];
        assert_eq!(body.kind, BodyKind::Pinned(pin));
        assert_eq!(body.position, hawser::math::Vec3::new(-10.0, 0.0, -75.0));
        // The free rod's mass: w L = 77.7066 kg/m × 20 m.
        assert!((body.mass - 77.7066 * 20.0).abs() < 1e-9, "{}", body.mass);
        assert!(deck.scenario.bodies[0].pin.is_some());
    }
}

/// A `Body1Pinned` rod becomes a body `R1` pinned to body `B1` at end A (the point
/// (Xa, Ya, Za) in `B1`'s axes, its origin there at t = 0), with the free rod's mass, its
/// member from its origin to end B; the scenario says `pin = "body"`, `pin_body = "B1"`.
#[test]
fn rod_pinned_on_a_body_converts_to_a_pin_on_the_body() {
    use hawser::math::Vec3;
    use hawser::model::{BodyKind, Pin};
    let text = deck_text("buoy_pinned_rod.txt");
    let deck = parse(&text).unwrap_or_else(|e| panic!("{e}"));
    let bodies = &deck.loaded.model.bodies;
    let rod = bodies.iter().position(|b| b.name == "R1").unwrap();
    let buoy = bodies.iter().position(|b| b.name == "B1").unwrap();
    assert_eq!(
        bodies[rod].kind,
        BodyKind::Pinned(Pin::Body {
            body: buoy,
            point: Vec3::new(0.0, 0.0, -5.0)
        })
    );
    assert_eq!(bodies[rod].position, Vec3::new(0.0, 0.0, -65.0));
    assert!(
        (bodies[rod].mass - 400.0 * 10.0).abs() < 1e-9,
        "{}",
        bodies[rod].mass
    );
    let toml = toml::to_string(&deck.scenario).unwrap();
    assert!(
        toml.contains("pin = \"body\"") && toml.contains("pin_body = \"B1\""),
        "{toml}"
    );
}

/// The `Body1Pinned` rod of `buoy_pinned_rod.txt` on a buoy made `Fixed`, run from the
/// deck's geometry: with the pin still, MoorDyn 2.7.2's pinned-rod equations (moment about
/// end A of the rod's weight, buoyancy, drag and added mass) are the exact ones, so the
/// two codes must agree. Both start the rod along B − A, 36.87° from the vertical (MoorDyn
/// reports end B at atan(6/13) = 24.78° before its first step: `Rod::setup`'s placeholder
/// orientation, which its state, the identity quaternion about q0 = B − A, replaces), and
/// it swings through the vertical under its wet weight. MoorDyn's inclinations (end B from
/// end A in the x-z plane) by `scripts/moordyn_pinned_rod.py --no-ic --fixed-buoy`; within
/// 1e-3° (measured 9e-6° every 0.1 s over 20 s; 1 % more inertia about the pin moves the
/// 2 s value by 0.08°).
#[test]
fn rod_pinned_on_a_fixed_body_swings_as_in_moordyn() {
    use hawser::math::Vec3;
    use hawser::model::InitialCondition;
    let text = mutate(
        "buoy_pinned_rod.txt",
        "1    Free         0    0  -60",
        "1    Fixed        0    0  -60",
    );
    let mut deck = parse(&text).unwrap_or_else(|e| panic!("{e}"));
    deck.loaded.model.settings.initial_condition = InitialCondition::AsDefined;
    let rod = deck
        .loaded
        .model
        .bodies
        .iter()
        .position(|b| b.name == "R1")
        .unwrap();
    let mut session = hawser::Session::new(deck.loaded.model.clone()).unwrap();
    let inclination = |session: &mut hawser::Session| {
        let k = *session.view().unwrap().body(rod);
        // The rod's member runs from its origin (end A) to end B − A = (6, 0, −8) m.
        let b = k.orientation * Vec3::new(6.0, 0.0, -8.0);
        b.x.atan2(-b.z).to_degrees()
    };
    let start = inclination(&mut session);
    // The deck's end B − A, atan(6/8) = 36.87° from the vertical.
    assert!(
        (start - 6.0_f64.atan2(8.0).to_degrees()).abs() < 1e-9,
        "{start}"
    );
    for (t, moordyn) in [
        (1.0, 29.874394),
        (2.0, 16.849225),
        (5.0, -7.490847),
        (10.0, 4.881685),
        (20.0, 2.549767),
    ] {
        session.advance_to(t).unwrap();
        let hawser = inclination(&mut session);
        eprintln!("t = {t} s: rod inclination hawser {hawser:.6}°, MoorDyn 2.7.2 {moordyn:.6}°");
        assert!(
            (hawser - moordyn).abs() < 1e-3,
            "t = {t} s: {hawser} vs {moordyn}"
        );
    }
}

/// A deck with a `CoupledPinned` body (OC3's buoy with its origin held by the host, 60 m
/// down, its rotations free) converts to a pinned body on a coupled pin, solves its statics
/// (the rotations only: the body tilts under the vessel chain's pull) and runs coupled: 3
/// coupled degrees of freedom for the pin and 3 for the vessel point, as MoorDyn counts them.
/// At the static start the force on the pin balances the body's own static load and the
/// lines' (the pin takes what the body does not: wet weight (buoyant) and line pull), within
/// 1e-3 of the buoyancy (the statics' acceptance), and the moment about the pin of those
/// loads is small against the lines' moments (1e-3). After 1 s held still, the run is finite,
/// the pin has not moved, and the pitch and the force on the pin (through the coupled forces)
/// agree with MoorDyn 2.7.2's.
#[test]
fn coupled_pinned_body_converts_and_runs() {
    use hawser::model::{BodyKind, Pin};
    let text = mutate(
        "buoy_oc3.txt",
        "1    Free         0    0  -60",
        "1    CoupledPinned 0   0  -60",
    );
    let mut deck = parse(&text).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        deck.loaded.model.bodies[0].kind,
        BodyKind::Pinned(Pin::Coupled)
    );
    let toml = toml::to_string(&deck.scenario).unwrap();
    assert!(
        toml.contains("type = \"pinned\"") && toml.contains("pin = \"coupled\""),
        "{toml}"
    );
    moordyn::couple_deck_points(&mut deck.loaded);
    let model = deck.loaded.model.clone();
    let mut session = hawser::Session::new(model.clone()).unwrap();
    assert_eq!(session.coupled_dofs(), 6);
    let view = session.view().unwrap();
    let k = *view.body(0);
    assert!((k.position - hawser::math::Vec3::new(0.0, 0.0, -60.0)).norm() < 1e-12);
    let tilt = k.orientation.angle();
    let lines = view.body_line_load(0);
    let own = model.bodies[0].loads(&k, &model.environment, 0.0);
    let pin = view.pin_load(0).unwrap();
    let balance = own.force + hawser::math::Vec3::new(lines[0], lines[1], lines[2]);
    let moment = own.moment + hawser::math::Vec3::new(lines[3], lines[4], lines[5]);
    let buoyancy = 1025.0 * 339.3 * model.environment.gravity;
    let line_moment = hawser::math::Vec3::new(lines[3], lines[4], lines[5]).norm();
    eprintln!(
        "coupled pinned buoy: tilt {:.4} deg, pin load {pin:?}, own + lines {balance:?}, \
         moment about the pin {:.3e} of the lines' {line_moment:.3e} N·m",
        tilt.to_degrees(),
        moment.norm()
    );
    assert!(tilt > 1e-3, "the vessel chain tilts the buoy");
    assert!((pin - balance).norm() < 1e-3 * buoyancy);
    assert!(moment.norm() < 1e-3 * line_moment);
    let x0 = [0.0, 0.0, -60.0, -400.0, 0.0, 0.0];
    let mut forces = [0.0; 6];
    for k in 1..=10 {
        let t1 = 0.1 * k as f64;
        session.set_coupled(t1, &x0, &[0.0; 6], None).unwrap();
        session.advance_to(t1).unwrap();
        session.coupled_forces(&mut forces).unwrap();
    }
    assert!(forces.iter().all(|f| f.is_finite()));
    let p = session.view().unwrap().body(0).position;
    assert!((p - hawser::math::Vec3::new(0.0, 0.0, -60.0)).norm() < 1e-12);
    // MoorDyn 2.7.2 on the same deck and host at t = 1 s (scripts/moordyn_pinned.py): pitch
    // 8.49929°, force on the pin (−321462.55, 0, −37941.70) N. Within 0.01° and 1e-3 of the
    // buoyancy ρ V g = 3.4 MN (the level at which the two codes' line discretisations agree
    // on static tensions, 0.2 % of the lines' pull; measured 4e-5° and 6.3 N).
    let moordyn_force = hawser::math::Vec3::new(-321462.55, 0.0, -37941.70);
    let pitch = session.view().unwrap().body(0).orientation.euler_angles().1;
    let pin = hawser::math::Vec3::new(forces[0], forces[1], forces[2]);
    eprintln!(
        "at 1 s: hawser pitch {:.5} deg, pin force {pin:?}; MoorDyn 2.7.2 8.49929 deg, \
         {moordyn_force:?}: difference {:.3} N",
        pitch.to_degrees(),
        (pin - moordyn_force).norm()
    );
    assert!((pitch.to_degrees() - 8.49929).abs() < 0.01);
    assert!((pin - moordyn_force).norm() < 1e-3 * buoyancy);
}
