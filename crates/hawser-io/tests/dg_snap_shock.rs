//! The dg shock sensor (`shock_filter`, docs/dg.md "Shock sensor") on an undamped snap: the
//! snapping cable at 1.27 Hz (`examples/snapping_cable_127.toml`, no axial damping), peak top
//! tension of the first large snap (4.3 ≤ t ≤ 4.8 s, ≈ 600 N), sampled every 0.1 ms as in
//! BENCHMARKS.md (`cargo run --release -p hawser-io --example dg_report -- cost snap-shock`).
//!
//! Run in release mode: `cargo test --release -p hawser-io --test dg_snap_shock` (about 30 s).

use hawser::analysis::Channel;
use hawser::math::Real;
use hawser::model::{Formulation, Model, Scheme, TimeStep};
use hawser::simulation::{Observer, Simulation};
use hawser::validation::signal::peak;
use hawser::validation::swinging_cable::with_discretisation;
use hawser::{System, statics};
use rayon::prelude::*;
use std::path::PathBuf;

fn load(file: &str) -> Model {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(file);
    hawser_io::scenario::load(&path).unwrap().model
}

struct Probe {
    time: Vec<Real>,
    value: Vec<Real>,
}

impl Observer for Probe {
    fn sample(
        &mut self,
        view: &hawser::session::View<'_>,
    ) -> Result<(), hawser::session::ObserverError> {
        let (system, time, ws) = (view.system, view.time, view.workspace);
        self.time.push(time);
        self.value.push(
            Channel::EndTension {
                line: 0,
                end_b: false,
            }
            .value(system, ws),
        );
        Ok(())
    }
}

/// Peak top tension [N] of the first large snap on `elements` dg elements of order `order`.
fn snap_peak(elements: usize, order: usize, shock: Real) -> Real {
    let mut m = with_discretisation(
        &load("snapping_cable_127.toml"),
        Formulation::Dg,
        elements,
        order,
    );
    m.lines[0].shock_filter = shock;
    m.settings.duration = 4.8;
    m.settings.output_interval = 1e-4;
    m.settings.scheme = Scheme::SspRk3;
    m.settings.time_step = TimeStep::Auto;
    let system = System::new(&m).unwrap();
    let y0 = statics::solve(&system, None, &Default::default())
        .unwrap()
        .state;
    let mut sim = Simulation::new(&system, &m.settings, y0).unwrap();
    let mut p = Probe {
        time: Vec::new(),
        value: Vec::new(),
    };
    sim.run(m.settings.duration, &mut p).unwrap();
    peak(&p.time, &p.value, 4.3, 4.8).unwrap().1
}

/// With the sensor (c_s = 0.25) the undamped snap peak settles: 604.7 and 605.8 N on 10 and 20
/// elements of P = 4 (0.18 % apart; asserted within 0.3 %) and 607.8 N on 10 of P = 6, all
/// within 0.28 % of their mean (asserted within 0.5 %) and within 1 % of `fe` on 160 elements
/// (602.6 N). Without it (the modal filter alone) the same meshes give 601.8, 597.7 and
/// 609.3 N: the P = 4 pair 0.68 % apart and P = 6 1.1 % from their mean, so this test fails
/// without the sensor.
#[test]
fn shock_sensor_settles_the_undamped_snap_peak() {
    // Three independent runs, spread over the cores.
    let all: Vec<Real> = [(10, 4), (20, 4), (10, 6)]
        .par_iter()
        .map(|&(elements, order)| snap_peak(elements, order, 0.25))
        .collect();
    let p4 = [all[0], all[1]];
    let mean = all.iter().sum::<Real>() / 3.0;
    eprintln!("peaks P4 N10, N20, P6 N10: {all:?} N, mean {mean:.2} N");
    assert!(
        (p4[1] - p4[0]).abs() < 3e-3 * mean,
        "P = 4: {:.2} N on 10 elements, {:.2} N on 20",
        p4[0],
        p4[1]
    );
    for &v in &all {
        assert!(
            (v / mean - 1.0).abs() < 5e-3,
            "{v:.2} N against mean {mean:.2} N"
        );
    }
    assert!((mean / 602.6 - 1.0).abs() < 1e-2, "mean {mean:.2} N");
}
