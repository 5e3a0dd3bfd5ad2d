//! Vibration cases: a mass on an elastic line against rod theory, the taut-string transverse
//! frequency, and bending frequencies of a tensioned pinned–pinned beam.

use super::*;
use crate::statics::{StaticOptions, solve};
use std::f64::consts::{PI, TAU};

/// The hanging mass: a 100 kg point mass in a vacuum at the end of a 10 m line (γ0 = 1 kg/m,
/// EA = 1e6 N) fixed at z = 20 m, gravity on.
pub mod hanging {
    use crate::math::Real;
    /// Line length [m].
    pub const LENGTH: Real = 10.0;
    /// Elements.
    pub const ELEMENTS: usize = 20;
    /// Mass per length [kg/m].
    pub const GAMMA: Real = 1.0;
    /// Axial stiffness [N].
    pub const EA: Real = 1.0e6;
    /// The hanging mass [kg].
    pub const MASS: Real = 100.0;
    /// Gravity [m/s²].
    pub const G: Real = 9.80665;
    /// Height of the fixed top [m].
    pub const TOP: Real = 20.0;
}

/// The hanging-mass model with `formulation`, `mass_matrix` and an extra downward force
/// `pull` [N] on the mass.
pub fn hanging_mass_model(formulation: Formulation, mass_matrix: MassMatrix, pull: Real) -> Model {
    use hanging::*;
    let top = Vec3::new(0.0, 0.0, TOP);
    let mut mass = free("mass", top - Vec3::new(0.0, 0.0, LENGTH), MASS, 0.0);
    if let PointKind::Free { force, .. } = &mut mass.kind {
        *force = Vec3::new(0.0, 0.0, -pull);
    }
    let mut model = single_line(
        dry_line_type(0.02, GAMMA, EA),
        LENGTH,
        ELEMENTS,
        (fixed("top", top), mass),
        formulation,
        mass_matrix,
    );
    model.environment = vacuum_environment(G);
    model
}

/// Root of β tan β = μ in (0, π/2) by bisection: the fundamental of the rod with an end mass
/// is ω = β c/L, μ = γ0 L/m, c = √(EA/γ0).
pub fn rod_beta(mu: Real) -> Real {
    let (mut lo, mut hi) = (0.0, std::f64::consts::FRAC_PI_2 - 1e-12);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid * mid.tan() < mu {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// A hanging-mass run.
#[derive(Clone, Debug)]
pub struct HangingMassRun {
    /// Measured period [s].
    pub period: Real,
    /// Rod theory's period 2π L/(β c) [s].
    pub rod: Real,
    /// Rayleigh's period 2π √((m + γ0 L/3) L/EA) [s].
    pub rayleigh: Real,
    /// Sample times [s] and the mass's height minus its equilibrium height [m].
    pub time: Vec<Real>,
    /// Height of the mass above its equilibrium [m].
    pub height: Vec<Real>,
}

/// Period of the hanging mass displaced `amplitude` [m] downward and released.
///
/// The displacement is formulation-neutral: the static equilibrium under an extra pull
/// F = EA a/L on the mass, which adds the uniform tension F and so stretches the line by
/// F L/EA = a, linearly in s (the shape of the fundamental for a light line). Because the law
/// is linear and the line stays taut (checked: a/L below half the static strain m g/EA), the
/// motion about equilibrium is linear and gravity drops out: it is a rod u(s, t) with
/// γ0 ü = EA u'', u(0) = 0, m ü(L) = −EA u'(L), whose fundamental is ω = β c/L with
/// β tan β = μ = γ0 L/m, c = √(EA/γ0). Rayleigh's spring k = EA/L with m + γ0 L/3 is short of
/// it by μ²/90 ≈ 1.1e-4.
///
/// Step 1e-4 s: the axial element frequency √(EA/L0/(γ0 L0/4)) = 4000 rad/s (lumped; √3 more
/// consistent) gives ω dt ≤ 0.7, stable, and RK4's phase error at the 31 rad/s fundamental is
/// (ω dt)⁴/120 ≈ 1e-12; a formulation with faster element modes takes 0.8 of its stability
/// limit if that is smaller. Runs for `duration` [s] (4 s: about 20 periods).
pub fn hanging_mass_period(
    formulation: Formulation,
    mass_matrix: MassMatrix,
    amplitude: Real,
    duration: Real,
    scheme: Scheme,
) -> Result<HangingMassRun, CaseError> {
    use hanging::*;
    if !(amplitude / LENGTH < 0.5 * MASS * G / EA) {
        return Err(CaseError::Failed(
            "the amplitude would slacken the line".into(),
        ));
    }
    let options = StaticOptions::default();
    let rest_model = hanging_mass_model(formulation, mass_matrix, 0.0);
    let rest = assemble(&rest_model)?;
    let z_eq = point_state(&rest, &solve(&rest, None, &options)?.state, 1)
        .0
        .z;
    let pulled = assemble(&hanging_mass_model(
        formulation,
        mass_matrix,
        EA * amplitude / LENGTH,
    ))?;
    let y = solve(&pulled, None, &options)?.state;
    let dt = rk4_step(&rest, 1.0e-4, 0.8);
    let steps = (duration / dt).round() as usize;
    let settings = fixed_step_settings(dt, scheme);
    let mut sim = session_from(&rest_model, settings, y)?;
    let mut height = Vec::with_capacity(steps);
    for _ in 0..steps {
        sim.step()?;
        height.push(point_state(&rest, sim.state(), 1).0.z - z_eq);
    }
    let crossings = upward_crossings(&height, 0.0, dt);
    if crossings.len() < 15 {
        return Err(CaseError::Failed(format!(
            "{} upward crossings of the equilibrium, 15 needed",
            crossings.len()
        )));
    }
    let mu = GAMMA * LENGTH / MASS;
    Ok(HangingMassRun {
        period: mean_period(&crossings),
        rod: TAU * LENGTH / (rod_beta(mu) * (EA / GAMMA).sqrt()),
        rayleigh: TAU * ((MASS + GAMMA * LENGTH / 3.0) * LENGTH / EA).sqrt(),
        time: (1..=steps).map(|k| k as Real * dt).collect(),
        height,
    })
}

/// Mass on an elastic line: period against rod theory and Rayleigh, over about 20 periods.
///
/// Tolerances: 5e-5 against the rod — the FE discretisation error of the fundamental is
/// O((β/N)²), measured +2.2e-5 lumped, < 1e-6 consistent for `fe` at 20 elements, and the
/// period measurement (crossing interpolation, higher axial modes riding on the signal) adds
/// ~1e-7; 5e-5 is 1/300 of the line-mass effect (the bare mass's period is 1.6 % shorter).
/// Against Rayleigh: its own model error μ²/90 = 1.1e-4 plus the above, 1.6e-4.
///
/// Generalized-α at the same step lengthens the period by about (ωh)²/12 = 8e-7 at the
/// 31 rad/s fundamental (docs/implicit.md: second order, the trapezoidal rule's phase error
/// plus a fraction for ρ∞ = 0.8) and damps the element modes RK4 keeps: the same tolerances
/// hold with a margin of 60.
pub fn hanging_mass(
    f: Formulation,
    _fidelity: Fidelity,
    scheme: Scheme,
) -> Result<Findings, CaseError> {
    let run = hanging_mass_period(f, MassMatrix::Consistent, 2.0e-3, 4.0, scheme)?;
    let head = run.time.partition_point(|&t| t <= 0.5);
    let (t, _) = thin(&run.time[..head], &run.height[..head], 500);
    let (tm, z) = thin(&run.time[..head], &run.height[..head], 80);
    Ok(Findings {
        checks: vec![
            Check::new(
                "period vs rod theory",
                "s",
                run.rod,
                run.period,
                Tolerance::Relative(5e-5),
            ),
            Check::new(
                "period vs Rayleigh (m + γ0 L/3)",
                "s",
                run.rayleigh,
                run.period,
                Tolerance::Relative(1.1e-4 + 5e-5),
            ),
        ],
        plots: vec![Plot {
            name: "height".into(),
            title: "Mass on an elastic line: height above equilibrium".into(),
            x_label: "t [s]".into(),
            y_label: "z − z_eq [m]".into(),
            log: false,
            series: vec![
                Series {
                    label: "rod theory (fundamental)".into(),
                    x: t.clone(),
                    y: t.iter()
                        .map(|&ti| -2.0e-3 * (TAU * ti / run.rod).cos())
                        .collect(),
                    markers: false,
                },
                Series {
                    label: "hawser".into(),
                    x: tm,
                    y: z,
                    markers: true,
                },
            ],
        }],
    })
}

/// A taut string in vacuum and zero gravity: unstretched length `l0` [m], γ0 `gamma` [kg/m],
/// EA `ea` [N], `elements` elements, stretched by `strain` between fixed points along x at
/// z = 10 m (tension EA·strain).
pub fn taut_string_model(
    formulation: Formulation,
    mass_matrix: MassMatrix,
    (l0, gamma, ea, strain): (Real, Real, Real, Real),
    elements: usize,
) -> Model {
    let span = l0 * (1.0 + strain);
    let mut model = single_line(
        dry_line_type(0.01, gamma, ea),
        l0,
        elements,
        (
            fixed("A", Vec3::new(0.0, 0.0, 10.0)),
            fixed("B", Vec3::new(span, 0.0, 10.0)),
        ),
        formulation,
        mass_matrix,
    );
    model.environment = vacuum_environment(0.0);
    model
}

/// The string of the case: 10 m, 1 kg/m, EA 1e5 N, 1 % strain (T = 1000 N).
const STRING: (Real, Real, Real, Real) = (10.0, 1.0, 1.0e5, 0.01);

/// A measured free vibration.
#[derive(Clone, Debug)]
pub struct StringRun {
    /// Measured frequency [Hz].
    pub frequency: Real,
    /// Closed-form frequency [Hz].
    pub exact: Real,
    /// Sample times [s].
    pub time: Vec<Real>,
    /// Transverse displacement of the probe node [m].
    pub displacement: Vec<Real>,
}

/// Releases line 0 of `model` (straight along x between fixed ends, stretched) from the
/// transverse shape `amplitude`·sin(nπ s/L0) in y at rest and measures the frequency of the
/// node at s = L0/(2n) from its upward zero crossings, over `duration` [s] in steps of `dt`
/// (or 0.8 of the stability limit if smaller; `None`: the automatic step).
fn transverse_vibration(
    model: &Model,
    mode: usize,
    amplitude: Real,
    dt: Option<Real>,
    duration: Real,
    scheme: Scheme,
) -> Result<(Real, Vec<Real>, Vec<Real>), CaseError> {
    let system = assemble(model)?;
    let (l0, n) = (model.lines[0].length(), model.lines[0].elements());
    let mut y = system.straight_state();
    let (a, b) = (model.points[0].position, model.points[1].position);
    let k = mode as Real * PI / l0;
    system.set_line_shape(&mut y, 0, |s| {
        let along = a + (b - a) * (s / l0);
        (
            along + Vec3::new(0.0, amplitude * (k * s).sin(), 0.0),
            Vec3::zeros(),
        )
    });
    let settings = match dt {
        Some(dt) => fixed_step_settings(rk4_step(&system, dt, 0.8), scheme),
        None => Settings {
            output_interval: 1e-3,
            initial_condition: InitialCondition::AsDefined,
            scheme,
            ..Default::default()
        },
    };
    let mut sim = session_from(model, settings, y)?;
    let probe = n / (2 * mode);
    let mut time = Vec::new();
    let mut displacement = Vec::new();
    while sim.time() < duration - 0.5 * sim.step_size() {
        sim.step()?;
        let ws = sim.view()?.workspace;
        displacement.push(node_position(&system, ws, 0, probe).y);
        time.push(sim.time());
    }
    // From the sample times: an adaptive scheme's steps differ in length.
    let crossings = upward_crossings_at(&time, &displacement, 0.0);
    if crossings.len() < 3 {
        return Err(CaseError::Failed(format!(
            "{} upward crossings, 3 needed",
            crossings.len()
        )));
    }
    Ok((1.0 / mean_period(&crossings), time, displacement))
}

/// Fundamental transverse frequency of the taut string of the case (10 m, 1 kg/m, EA 1e5 N,
/// 1 % strain) with `elements` elements, f1 = 1/(2 L) √(T/μ) with L the stretched length and
/// μ = γ0/(1 + ε) the mass per stretched length, i.e. 1/(2 L0) √(T/(γ0 (1 + ε))).
///
/// Released from a sine of amplitude 1e-5 L0: the tension change it causes, ~EA (π A/L)²/4,
/// shifts the frequency by ~1e-8 relative, far below the O(1e-4) mesh errors. Step
/// 2.5e-4 s (stability limit 1.3 ms at N = 32 lumped, 0.74 ms consistent; RK4's phase error
/// at the 10 rad/s fundamental (ω dt)⁴/120 ≈ 5e-11; 0.8 of the stability limit if that is
/// smaller), 2.6 s: about four periods.
pub fn taut_string_frequency(
    formulation: Formulation,
    mass_matrix: MassMatrix,
    elements: usize,
    scheme: Scheme,
) -> Result<StringRun, CaseError> {
    let (l0, gamma, ea, strain) = STRING;
    let model = taut_string_model(formulation, mass_matrix, STRING, elements);
    let (frequency, time, displacement) = transverse_vibration(
        &model,
        1,
        1.0e-5 * l0,
        Some(2.5e-4),
        10_400.0 * 2.5e-4,
        scheme,
    )?;
    Ok(StringRun {
        frequency,
        exact: 1.0 / (2.0 * l0) * (ea * strain / (gamma * (1.0 + strain))).sqrt(),
        time,
        displacement,
    })
}

/// Taut-string fundamental frequency at N = 32 (and 64 in the full suite).
///
/// Tolerance 2.5 π²/(24 N²) relative: the leading discretisation error of linear elements
/// (−π²/(24 N²) lumped, + consistent; the `fe` tests pin it to within 5 %) with a margin for
/// the next term; higher-order formulations are well inside. Generalized-α at the same
/// 2.5e-4 s step adds a period error of about (ωh)²/12 = 5e-7 at the 10 rad/s fundamental,
/// 1/1000 of the tolerance at N = 64.
pub fn taut_string(
    f: Formulation,
    fidelity: Fidelity,
    scheme: Scheme,
) -> Result<Findings, CaseError> {
    let meshes: &[usize] = match fidelity {
        Fidelity::Quick => &[32],
        Fidelity::Full => &[32, 64],
    };
    let mut checks = Vec::new();
    let mut plots = Vec::new();
    for &n in meshes {
        let run = taut_string_frequency(f, MassMatrix::Consistent, n, scheme)?;
        checks.push(Check::new(
            format!("fundamental frequency, N = {n}"),
            "Hz",
            run.exact,
            run.frequency,
            Tolerance::Relative(2.5 * PI * PI / (24.0 * (n * n) as Real)),
        ));
        if plots.is_empty() {
            let a = run.displacement.iter().copied().fold(0.0, Real::max);
            let (t, _) = thin(&run.time, &run.displacement, 400);
            let (tm, y) = thin(&run.time, &run.displacement, 100);
            plots.push(Plot {
                name: "midspan".into(),
                title: format!("Taut string, N = {n}: mid-span displacement"),
                x_label: "t [s]".into(),
                y_label: "y [m]".into(),
                log: false,
                series: vec![
                    Series {
                        label: "closed form f1".into(),
                        x: t.clone(),
                        y: t.iter()
                            .map(|&ti| a * (TAU * run.exact * ti).cos())
                            .collect(),
                        markers: false,
                    },
                    Series {
                        label: "hawser".into(),
                        x: tm,
                        y,
                        markers: true,
                    },
                ],
            });
        }
    }
    Ok(Findings { checks, plots })
}

/// Bending frequencies of a tensioned pinned–pinned beam (formulations with bending).
///
/// 10 m, γ0 1 kg/m, EA 1e6 N at strain 1e-4 (T = 100 N), EI 100 N·m², 10 elements, ends on
/// fixed points (pins: no moment). Modes n = 1, 2 have the closed form
/// ω_n = (nπ/L) √((EI (nπ/L)² + T)/γ0), bending 9 % and 28 % of ω_n², so a formulation that
/// dropped EI misses by 4 % and 15 %. Each mode is released from sin(nπ s/L) of amplitude
/// 1e-3 m and measured over about four periods at the automatic step. Tolerance 0.5 %
/// relative: cubic elements' frequency error is O(h⁴), ~1e-4 here; the margin covers the
/// span change of ε L (1e-4, in L) and the measurement.
///
/// With generalized-α the automatic step is the adaptive controller's at the default
/// tolerance (docs/implicit.md), and steps land on the 1 ms output times, so h ≤ 1 ms: at
/// mode 2 (ω = 7.4 rad/s) ωh ≤ 7.4e-3 and the scheme's period error (ωh)²/12 ≤ 5e-6, 1/1000
/// of the tolerance.
///
/// And the DG paper's vibrating cantilever ([`cantilever_frequencies`]).
pub fn beam_bending(
    f: Formulation,
    _fidelity: Fidelity,
    scheme: Scheme,
) -> Result<Findings, CaseError> {
    if !has_bending(f) {
        return Err(CaseError::NotAvailable(format!(
            "{} has no bending stiffness (SPEC §3)",
            formulation_name(f)
        )));
    }
    let (l0, gamma, ea, strain, ei) = (10.0, 1.0, 1.0e6, 1.0e-4, 100.0);
    let mut model = taut_string_model(f, MassMatrix::Consistent, (l0, gamma, ea, strain), 10);
    model.line_types[0].bending_stiffness = ei;
    let tension = ea * strain;
    let mut checks = Vec::new();
    for mode in [1usize, 2] {
        let k = mode as Real * PI / l0;
        let exact = k * ((ei * k * k + tension) / gamma).sqrt() / TAU;
        let (frequency, _, _) =
            transverse_vibration(&model, mode, 1e-3, None, 4.2 / exact, scheme)?;
        checks.push(Check::new(
            format!("bending mode {mode} frequency"),
            "Hz",
            exact,
            frequency,
            Tolerance::Relative(5e-3),
        ));
    }
    checks.extend(cantilever_frequencies(f)?);
    Ok(Findings {
        checks,
        plots: vec![],
    })
}

/// The DG paper's vibrating cantilever (§4.2; SPEC §7): L = 100 m, γ0 = 10 kg/m,
/// EI = 0.1 MN·m², EA = 0.1 MN, clamped horizontally at a fixed point (end A, `clamp`), free
/// at end B (a massless free point), no gravity. Natural frequencies from the linearised
/// stiffness and mass at the straight state (the same force and mass code as the dynamics):
/// ω_n = (β_n L)² √(EI/(γ0 L⁴)) with β_n L = 1.875104, 4.694091, 7.854757 (eqs. 41–45), each in
/// both transverse planes. 16 elements, as the paper's N = 16. Tolerance 0.5 % (the issue's
/// for the DG periods); the cubic elements' error is O(h⁴), about 1e-6 on the first mode.
pub fn cantilever_frequencies(f: Formulation) -> Result<Vec<Check>, CaseError> {
    use crate::linearise::{LinearisationOptions, linearise};
    let (length, gamma, ei, ea) = (100.0, 10.0, 1.0e5, 1.0e5);
    let mut lt = dry_line_type(0.1, gamma, ea);
    lt.bending_stiffness = ei;
    let mut model = single_line(
        lt,
        length,
        16,
        (
            fixed("wall", Vec3::zeros()),
            free("tip", Vec3::new(length, 0.0, 0.0), 0.0, 0.0),
        ),
        f,
        MassMatrix::Consistent,
    );
    model.environment = vacuum_environment(0.0);
    model.lines[0].clamp[0] = Some(Vec3::x());
    // A dg line's modes are its hermite twin's (analysis::modes::modal_twin); the DG paper's
    // periods are also measured in time on the dg line itself by tests/dg_cantilever.rs.
    let twin = crate::analysis::modes::modal_twin(&model);
    let system = assemble(twin.as_ref().unwrap_or(&model))?;
    let y = system.straight_state();
    let omega = linearise(&system, &y, LinearisationOptions::default())
        .angular_frequencies()
        .map_err(|e| CaseError::Failed(format!("eigen solve: {e}")))?;
    // The clamp's constrained directions (Q x = 0, each matrix keeping its own diagonal
    // scale there) add two eigenvalues ω² = K_jj/M_jj, an element-scale frequency far above
    // the bending modes compared here; the lowest six are the three modes in two planes.
    let scale = (ei / (gamma * length.powi(4))).sqrt();
    Ok([1.875_104_069, 4.694_091_133, 7.854_757_438]
        .iter()
        .enumerate()
        .map(|(n, beta)| {
            let exact = beta * beta * scale / TAU;
            let computed = 0.5 * (omega[2 * n] + omega[2 * n + 1]) / TAU;
            Check::new(
                format!("cantilever mode {} frequency", n + 1),
                "Hz",
                exact,
                computed,
                Tolerance::Relative(5e-3),
            )
        })
        .collect())
}
