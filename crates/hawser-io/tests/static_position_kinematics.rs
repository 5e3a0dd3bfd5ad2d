//! Wave kinematics at the static position against direct summation on the OC3 mooring
//! (examples/oc3_surge.toml: three 902.2 m chains of 20 `fe` elements in 320 m of water,
//! fairleads in a 2 m, 10 s surge) in a JONSWAP sea, Hs 6 m, Tp 10 s, γ 3.3, 200 components
//! (seed 1, 0.5–5 × 1/Tp, Wheeler stretching, the default 20 s ramp), lumped mass, RK4.
//!
//! The target (docs/waves.md, "Kinematics at the static position"): the standard deviation
//! and the maximum of every fairlead tension (MoorDyn's FairTen, the end node force) within
//! 0.5 % of direct summation. The test runs the first 60 s (direct summation of 200
//! components at 120 Gauss points costs ~200× still water, 3.5 ms per step); the ignored
//! test runs the 600 s record and prints the errors over its first 60 s and over all of it,
//! which docs/waves.md records (they agree: the short record is representative).
//!
//! On OC3 the waves barely reach the lines (the fairleads are 70 m deep, where the peak
//! component is at e^{−k_p 70} = 6 % of its surface value): they change the fairlead tension's
//! standard deviation by ~1e-5 and its maximum by ~1e-4 of themselves, so the 0.5 % target
//! alone could not catch a wrong field. The test therefore also compares the wave-induced
//! tension ΔT = T − T_still (same surge, same steps) between the two methods.

use hawser::analysis::Channel;
use hawser::math::Real;
use hawser::model::{Model, TimeStep};
use hawser::physics::static_kinematics::WaveKinematicsMethod;
use hawser::physics::waves::{IrregularSea, SeaState, Spectrum, Stretching, WaveSpec, Waves};
use hawser::simulation::{Observer, Simulation};
use hawser::statics::{StaticOptions, solve};
use hawser::system::System;
use std::f64::consts::PI;
use std::path::Path;

/// Relative tolerance on the tension standard deviation and maximum (the target).
const TOLERANCE: Real = 5e-3;
/// Relative tolerance on the standard deviation of the wave-induced tension T − T_still: the
/// static-position field leaves out the change of the waves over a point's displacement δ
/// from its static position, a relative error k δ per component; at the fairlead (surge
/// amplitude 2 m) and the peak wavenumber k_p = 0.040 rad/m that is 8 %, less along the line
/// (its nodes move less), so 10 % (and twice that on the waveform).
const WAVE_PART_TOLERANCE: Real = 0.1;

fn oc3(waves: bool, method: WaveKinematicsMethod, duration: Real) -> Model {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/oc3_surge.toml");
    let mut model = hawser_io::scenario::load(&path).unwrap().model;
    model.settings.duration = duration;
    model.settings.time_step = TimeStep::Fixed(0.002);
    model.settings.output_interval = 0.1;
    for l in &mut model.lines {
        l.mass_matrix = hawser::model::MassMatrix::Lumped;
    }
    if waves {
        let tp = 10.0;
        let spec = WaveSpec {
            sea: SeaState::Irregular(IrregularSea {
                spectrum: Spectrum::Jonswap {
                    significant_height: 6.0,
                    peak_period: tp,
                    peak_enhancement: 3.3,
                },
                direction: 0.0,
                spreading: None,
                seed: 1,
                components: 200,
                frequency_range: (2.0 * PI * 0.5 / tp, 2.0 * PI * 5.0 / tp),
            }),
            ramp_time: 2.0 * tp,
            stretching: Stretching::Wheeler,
        };
        let env = &mut model.environment;
        env.waves = Waves::new(&spec, env.depth, env.gravity).unwrap();
        env.wave_kinematics = method;
    }
    model
}

/// Fairlead tension (end B node force) of every line at every output [N].
struct FairTen(Vec<[Real; 3]>);

impl Observer for FairTen {
    fn sample(
        &mut self,
        view: &hawser::session::View<'_>,
    ) -> Result<(), hawser::session::ObserverError> {
        let (system, ws) = (view.system, view.workspace);
        let f = |line| Channel::EndNodeForce { line, end_b: true }.value(system, ws);
        self.0.push([f(0), f(1), f(2)]);
        Ok(())
    }
}

fn run(model: &Model) -> (Vec<[Real; 3]>, Option<usize>) {
    let system = System::new(model).unwrap();
    let y0 = solve(&system, None, &StaticOptions::default())
        .unwrap()
        .state;
    let mut sim = Simulation::new(&system, &model.settings, y0).unwrap();
    let mut rec = FairTen(Vec::new());
    sim.run(model.settings.duration, &mut rec).unwrap();
    let bytes = sim
        .workspace()
        .wave_points
        .tables()
        .map(|t| t.memory_bytes());
    (rec.0, bytes)
}

/// (standard deviation, maximum) [N] of line `l` over the first `n` samples.
fn stats(v: &[[Real; 3]], l: usize, n: usize) -> (Real, Real) {
    let x: Vec<Real> = v[..n].iter().map(|s| s[l]).collect();
    let mean = x.iter().sum::<Real>() / n as Real;
    let var = x.iter().map(|a| (a - mean).powi(2)).sum::<Real>() / n as Real;
    (
        var.sqrt(),
        x.iter().cloned().fold(Real::NEG_INFINITY, Real::max),
    )
}

/// Runs still water, direct summation and static-position kinematics for `duration` [s];
/// prints and checks the statistics over the first `windows` [s] of the record: the target
/// on the tension itself, and the wave-induced part ΔT = T − T_still, which on OC3 is small
/// (the fairleads are 70 m deep) and so the sharper test of the field.
fn compare(duration: Real, windows: &[Real]) {
    let interval = |m: &Model| match m.environment.waves.field() {
        Some(f) => WaveKinematicsMethod::default_sample_interval(f),
        None => 1.0,
    };
    let probe = oc3(true, WaveKinematicsMethod::Direct, duration);
    let h = interval(&probe);
    let (still, _) = run(&oc3(false, WaveKinematicsMethod::Direct, duration));
    let (direct, _) = run(&probe);
    let (tabled, bytes) = run(&oc3(
        true,
        WaveKinematicsMethod::StaticPosition { sample_interval: h },
        duration,
    ));
    // The same seed gives the same bits: a second run of the same model.
    let (again, _) = run(&oc3(
        true,
        WaveKinematicsMethod::StaticPosition { sample_interval: h },
        duration,
    ));
    assert!(
        again
            .iter()
            .zip(&tabled)
            .all(|(a, b)| a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())),
        "two runs of the same sea differ"
    );
    eprintln!(
        "sample interval {h:.4} s; cache {} bytes ({} per point of 120)",
        bytes.unwrap(),
        bytes.unwrap() / 120
    );
    for &w in windows {
        let n = (w / 0.1).round() as usize + 1;
        for l in 0..3 {
            let (s0, m0) = stats(&still, l, n);
            let (sd, md) = stats(&direct, l, n);
            let (st, mt) = stats(&tabled, l, n);
            let (es, em) = ((st - sd) / sd, (mt - md) / md);
            // The wave-induced part.
            let dd: Vec<[Real; 3]> = direct
                .iter()
                .zip(&still)
                .map(|(a, b)| [a[l] - b[l]; 3])
                .collect();
            let dt: Vec<[Real; 3]> = tabled
                .iter()
                .zip(&still)
                .map(|(a, b)| [a[l] - b[l]; 3])
                .collect();
            let (wd, _) = stats(&dd, 0, n);
            let (wt, _) = stats(&dt, 0, n);
            let peak_d = dd[..n].iter().map(|x| x[0].abs()).fold(0.0, Real::max);
            let peak_t = dt[..n].iter().map(|x| x[0].abs()).fold(0.0, Real::max);
            let rms = (dd[..n]
                .iter()
                .zip(&dt[..n])
                .map(|(a, b)| (a[0] - b[0]).powi(2))
                .sum::<Real>()
                / n as Real)
                .sqrt();
            eprintln!(
                "{w} s, line {}: std still {s0:.1} N, direct {sd:.1} N, static {st:.1} N \
                 ({:+.5} %); max still {m0:.1} N, direct {md:.1} N, static {mt:.1} N ({:+.5} %); \
                 wave part ΔT: std direct {wd:.1} N, static {wt:.1} N ({:+.2} %), peak |ΔT| \
                 {peak_d:.1} N vs {peak_t:.1} N ({:+.2} %), rms difference {rms:.1} N ({:.2} % of its std)",
                l + 1,
                es * 100.0,
                em * 100.0,
                (wt - wd) / wd * 100.0,
                (peak_t - peak_d) / peak_d * 100.0,
                rms / wd * 100.0
            );
            assert!(es.abs() < TOLERANCE, "line {} std {es:+.2e}", l + 1);
            assert!(em.abs() < TOLERANCE, "line {} max {em:+.2e}", l + 1);
            // The wave-induced tension: its std within WAVE_PART_TOLERANCE, its waveform
            // within twice that (rms of the difference over the std).
            assert!(
                ((wt - wd) / wd).abs() < WAVE_PART_TOLERANCE,
                "line {} ΔT std",
                l + 1
            );
            assert!(
                rms / wd < 2.0 * WAVE_PART_TOLERANCE,
                "line {} ΔT waveform",
                l + 1
            );
        }
    }
}

#[test]
fn oc3_jonswap_static_position_within_half_percent_60_s() {
    compare(60.0, &[60.0]);
}

/// The 600 s record of the target (about 20 min of CPU for direct summation); its first 60 s
/// are the test above, bit for bit.
#[test]
#[ignore]
fn oc3_jonswap_static_position_within_half_percent_600_s() {
    compare(600.0, &[60.0, 600.0]);
}
