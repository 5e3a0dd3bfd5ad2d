//! A MoorDyn FAILURE row that lists several lines (tests/data/moordyn/joined_failure.txt): two
//! slack 45 m chains from fixed points 80 m apart meet at a fixed point P3, whose row
//! `1 3 1,2 2.0 0` releases both line ends at 2 s. As in MoorDyn (MoorDyn2.cpp `detachLines`)
//! the two ends move onto ONE new massless free point at P3's place and velocity, so the
//! chains stay joined and fall together as one 90 m chain.

use hawser::Session;
use hawser::math::{Real, Vec3, get3};
use hawser::model::{End, LineFailure};
use hawser_io::moordyn::{self, ConvertOptions};
use hawser_io::scenario;
use std::path::Path;

fn deck() -> moordyn::LoadedDeck {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/moordyn/joined_failure.txt");
    let text = std::fs::read_to_string(&path).unwrap();
    moordyn::parse(&path, &text, &ConvertOptions::default()).unwrap()
}

/// The joined free point's position [m] in the session's current state.
fn joint(s: &Session) -> Vec3 {
    let system = s.system();
    let p = system
        .points
        .iter()
        .position(|p| p.name == "L1.end_b.released")
        .expect("the failure's free point");
    let o = system.layout.point_offset[p].unwrap();
    get3(&s.state()[o..], 0)
}

/// The row maps to one failure of both ends (L1's end B, L2's end A, both at P3) with the
/// time trigger, as a `[[failures]]` table that reads back to the same model.
#[test]
fn the_row_maps_to_one_joined_failure() {
    let d = deck();
    assert_eq!(
        d.loaded.model.failures,
        vec![LineFailure {
            line: 0,
            end: End::B,
            joined: vec![(1, End::A)],
            time: Some(2.0),
            tension: None,
        }]
    );
    let toml = moordyn::to_toml(&d, Path::new("joined_failure.txt"));
    assert!(
        toml.contains(
            "[[failures]]\npoint = \"P3\"\nlines = [\n    \"L1\",\n    \"L2\",\n]\ntime = 2.0"
        ),
        "{toml}"
    );
    let again = scenario::parse(Path::new("joined_failure.toml"), &toml).unwrap();
    assert_eq!(again.model.failures, d.loaded.model.failures);
}

/// MoorDyn 2.7.2's joined point, from the deck's post-release twin (scripts/moordyn_joined.py:
/// P3 a free massless point, no initial-condition solve, so the chains start from their
/// catenaries as at the release; 0.05 s coupling steps, dtM 0.5 ms): its depth [m] at these
/// times after the release [s], and L1's tension at the joint [N].
const MOORDYN: [(Real, Real, Real); 5] = [
    (1.0, -23.5114, 1991.21),
    (2.0, -27.9746, 3670.09),
    (3.0, -31.4732, 3937.96),
    (5.0, -37.0701, 7355.00),
    (10.0, -38.2589, 8310.85),
];

/// After the release the two ends are one point: both lines' end nodes sit on it, the fixed
/// point P3 carries nothing, and the joint falls as MoorDyn's does, within 1 % of the 18.3 m
/// fall (0.18 m: the two lumped-mass discretisations are the same, 15 segments a line; what
/// differs is the time scheme, RK4 at hawser's stable step against MoorDyn's RK2 at 0.5 ms,
/// and the catenary MoorDyn starts from against hawser's statics; measured: 0.164, 0.063,
/// 0.043, 0.044, 0.007 m). L1's tension at the joint within 1 % of MoorDyn's from 2 s after
/// the release (measured 0.6, 0.1, 0.7, 0.05 %); at 1 s, while the joint still accelerates
/// downward, it is 12 % above MoorDyn's (2224 N against 1991 N), not held. After
/// 40 s at rest the joint is where the statics of the two chains joined by a massless free
/// point put it (1 % of the fall), and the two lines' forces on it balance (their sum below
/// 1e-3 of either, the residual of a massless point's equation at rest).
#[test]
fn the_joined_ends_fall_together_as_moordyn_s() {
    let d = deck();
    let mut m = d.loaded.model.clone();
    m.settings.duration = 42.0;
    let mut s = Session::new(m.clone()).unwrap();
    let start = joint(&s);
    s.advance_to(2.0).unwrap();
    let events = s.failure_events();
    assert_eq!(events.len(), 1);
    assert_eq!(events[0].release.time, 2.0);
    assert_eq!(events[0].joined, vec![("L2".to_string(), End::A)]);
    {
        let j = joint(&s);
        let v = s.view().unwrap();
        assert_eq!(j, start);
        let first = v.line_samples(0).last().unwrap().position;
        let second = v.line_samples(1).next().unwrap().position;
        assert!((first - j).norm() < 1e-12 && (second - j).norm() < 1e-12);
    }
    let fall = 38.2589 - 20.0;
    for (after, z, tension) in MOORDYN {
        s.advance_to(2.0 + after).unwrap();
        let j = joint(&s);
        let v = s.view().unwrap();
        let t = v.system.end_force(v.workspace, 0, true).norm();
        eprintln!(
            "{after} s after: joint z {:.4} m (MoorDyn {z}), L1 tension at the joint {t:.1} N \
             (MoorDyn {tension})",
            j.z
        );
        assert!(j.x.abs() < 1e-6 && j.y.abs() < 1e-9, "{j:?}");
        assert!((j.z - z).abs() < 0.01 * fall, "{after} s: {} vs {z}", j.z);
        if after >= 2.0 {
            assert!(
                (t / tension - 1.0).abs() < 0.01,
                "{after} s: {t} N vs {tension} N"
            );
        }
    }
    s.run().unwrap();
    let end = joint(&s);
    // The statics of the system after the release: P3 a massless free point.
    let mut twin = m.clone();
    twin.failures.clear();
    let p3 = twin.points.iter().position(|p| p.name == "P3").unwrap();
    twin.points[p3].kind = hawser::model::PointKind::Free {
        mass: 0.0,
        volume: 0.0,
        drag_area: 0.0,
        added_mass_coefficient: 0.0,
        force: Vec3::zeros(),
    };
    let system = hawser::system::System::new(&twin).unwrap();
    let eq = hawser::statics::solve(&system, None, &Default::default()).unwrap();
    let o = system.layout.point_offset[p3].unwrap();
    let target = get3(&eq.state[o..], 0);
    eprintln!("at {} s: joint {end:?}, statics {target:?}", s.time());
    assert!((end - target).norm() < 0.01 * fall, "{end:?} vs {target:?}");
    let v = s.view().unwrap();
    let a = v.system.end_force(v.workspace, 0, true);
    let b = v.system.end_force(v.workspace, 1, false);
    eprintln!("forces on the joint {a:?} + {b:?}");
    assert!((a + b).norm() < 1e-3 * a.norm(), "{a:?} + {b:?}");
}
