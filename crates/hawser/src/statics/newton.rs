//! Newton–Raphson statics on the block-structured Jacobian.
//!
//! The unknowns are the positions in the state vector (interior line nodes and free points);
//! velocities are zero. The residual is the net static force on every unknown node [N], from
//! the same force code as the dynamics. The Jacobian is formed by finite differences of that
//! code with three colours per line (a node only influences its two neighbours), so it costs
//! nine line evaluations per iteration ([`crate::linearise::force_jacobian`], shared with the
//! linearisation of modal analysis), and it is solved with the dynamics' coupled
//! block-tridiagonal solver.

use super::catenary;
use super::dynamic_relaxation;
use crate::error::StaticsError;
use crate::linearise::{Difference, Variable, force_jacobian, line_forces_at_rest};
use crate::math::{Mat3, Real, Vec3, get3, set3};
use crate::system::{System, Workspace};

/// Options of the static solver.
#[derive(Clone, Debug)]
pub struct StaticOptions {
    /// Newton iterations per load step.
    pub max_iterations: usize,
    /// Convergence tolerance on the largest nodal force imbalance, relative to the system's
    /// weight scale [-].
    pub relative_tolerance: Real,
    /// Seed lines with the elastic catenary (true) or straight lines (false).
    pub catenary_seed: bool,
    /// Keep an iteration log in [`StaticSolution::log`] (each Newton iteration's residual,
    /// shift and step; each change of method). The core prints nothing: a host or the CLI
    /// (`hawser statics --trace`) shows it.
    pub trace: bool,
}

impl Default for StaticOptions {
    fn default() -> Self {
        Self {
            max_iterations: 100,
            relative_tolerance: 1e-9,
            catenary_seed: true,
            trace: false,
        }
    }
}

/// A static equilibrium.
#[derive(Clone, Debug)]
pub struct StaticSolution {
    /// State vector (positions at equilibrium, zero velocities).
    pub state: Vec<Real>,
    /// Newton iterations used in all.
    pub iterations: usize,
    /// Largest nodal force imbalance [N].
    pub residual: Real,
    /// Method that converged.
    pub method: &'static str,
    /// The iteration log, one line per event, when [`StaticOptions::trace`] was set (else
    /// empty).
    pub log: Vec<String>,
}

/// The iteration log of a static solve ([`StaticOptions::trace`]).
#[derive(Clone, Debug, Default)]
pub(crate) struct Trace {
    on: bool,
    lines: Vec<String>,
}

impl Trace {
    pub(crate) fn new(on: bool) -> Self {
        Self {
            on,
            lines: Vec::new(),
        }
    }

    /// Records the line `f` makes, when tracing (the text is not built otherwise).
    pub(crate) fn push(&mut self, f: impl FnOnce() -> String) {
        if self.on {
            self.lines.push(f());
        }
    }

    pub(crate) fn into_lines(self) -> Vec<String> {
        self.lines
    }
}

/// Force scale [N] of the system: total weight magnitude of lines and points plus point loads.
fn force_scale(system: &System) -> Real {
    let g = system.environment.gravity.max(1e-3);
    let mut s = 0.0;
    for l in &system.lines {
        for &k in &l.mesh.element_section {
            let sec = &l.mesh.sections[k];
            s += sec.line_type.mass_per_length * g * sec.element_length;
        }
    }
    for p in &system.points {
        if let crate::model::PointKind::Free { mass, force, .. } = &p.kind {
            s += mass * g + force.norm();
        }
    }
    s.max(1e-9)
}

/// The convergence tolerance [N] in force at the current iterate: the weight-based `tol`, or
/// 1e-10 of the largest element tension in the workspace when that is larger (a pretensioned
/// or current-loaded line in zero gravity has forces far above its weight, and round-off in
/// its nodal balance scales with its tension).
pub(super) fn effective_tolerance(tol: Real, ws: &Workspace) -> Real {
    let tension = ws
        .lines
        .iter()
        .flat_map(|l| l.elements.tension.iter())
        .fold(0.0, |m: Real, t| m.max(t.abs()));
    tol.max(1e-10 * tension)
}

/// Static residual: the net force [N] on every position unknown, stored at that unknown's
/// index in the state layout (velocity entries are left at zero). Returns the largest entry
/// magnitude and its index.
pub fn residual(
    system: &System,
    y: &[Real],
    current_factor: Real,
    ws: &mut Workspace,
    out: &mut [Real],
) -> (Real, usize) {
    out.iter_mut().for_each(|x| *x = 0.0);
    line_forces_at_rest(system, y, current_factor, false, ws);
    for (li, l) in system.lines.iter().enumerate() {
        let lw = &ws.lines[li];
        let o = system.layout.line_offset[li];
        let n = l.vectors() - 1;
        for i in 1..n {
            set3(&mut out[o..], i - 1, &lw.force[i]);
        }
        // A clamp takes the normal part of its tangent's residual (its reaction moment).
        for (j, d) in l.clamped() {
            let f = lw.force[j];
            set3(&mut out[o..], j - 1, &(d * f.dot(&d)));
        }
        for (p, node) in [(l.end_a, 0), (l.end_b, n)] {
            if let Some(o) = system.layout.point_offset[p] {
                let f = get3(&out[o..], 0) + lw.force[node];
                set3(&mut out[o..], 0, &f);
            }
        }
    }
    for &p in &system.free_points {
        let o = system.layout.point_offset[p].expect("free point");
        let (f, _) = system.point_own_load(p, &ws.points[p], 0.0, current_factor);
        let f = get3(&out[o..], 0) + f;
        set3(&mut out[o..], 0, &f);
    }
    let mut worst = (0.0, 0);
    for (i, r) in out.iter().enumerate() {
        if !(r.abs() <= worst.0) {
            worst = (
                if r.is_finite() {
                    r.abs()
                } else {
                    Real::INFINITY
                },
                i,
            );
        }
    }
    worst
}

/// Seeds the lines of `y` with elastic catenaries between their current end positions. `dg`
/// lines take the L2 projection of their hermite twin's seed ([`System::statics_twin`],
/// [`System::state_from_twin`] without refinement).
pub fn catenary_seed(system: &System, y: &mut [Real], ws: &mut Workspace) {
    if system.has_dg_lines() {
        // A dg line's state is modal: seed its hermite twin and project the cubic shape.
        let twin = system.statics_twin();
        let mut y_twin = twin.straight_state();
        for (p, off) in system.layout.point_offset.iter().enumerate() {
            if let (Some(o), Some(ot)) = (off, twin.layout.point_offset[p]) {
                y_twin[ot..ot + 6].copy_from_slice(&y[*o..o + 6]);
            }
        }
        catenary_seed(&twin, &mut y_twin, &mut twin.workspace());
        y.copy_from_slice(&system.state_from_twin(&twin, &y_twin, false));
        system.point_kinematics(0.0, y, ws);
        return;
    }
    system.point_kinematics(0.0, y, ws);
    let env = &system.environment;
    for (li, l) in system.lines.iter().enumerate() {
        let n = l.mesh.elements();
        let length = l.mesh.length();
        let (mut weight, mut ea) = (0.0, 0.0);
        for &k in &l.mesh.element_section {
            let s = &l.mesh.sections[k];
            weight += (s.line_type.mass_per_length - env.water_density * s.area)
                * env.gravity
                * s.element_length;
            ea += s.element_length / s.law.stiffness.max_tangent();
        }
        let w = weight / length;
        let ea = length / ea;
        let pa = ws.points[l.end_a].position;
        let pb = ws.points[l.end_b].position;
        // Hang from the lower end for a sinking line, from the upper one for a buoyant line.
        let (lo, hi, reversed) = if (w >= 0.0) == (pa.z <= pb.z) {
            (pa, pb, false)
        } else {
            (pb, pa, true)
        };
        let d = hi - lo;
        let horizontal = Vec3::new(d.x, d.y, 0.0);
        let span = horizontal.norm();
        let height = d.z * w.signum();
        let on_bed = env.depth.is_finite()
            && w > 0.0
            && (lo.z - env.seabed_z()).abs() < 1e-3 * length.max(1.0);
        let dir = if span > 0.0 {
            horizontal / span
        } else {
            Vec3::x()
        };
        let cat = if w.abs() > 0.0 {
            catenary::solve(span, height, length, w.abs(), ea, on_bed)
        } else {
            None
        };
        let o = system.layout.line_offset[li];
        let shape: Vec<Vec3> = (0..=n)
            .map(|i| {
                let s_a = l.mesh.arc_length(i);
                let s = if reversed { length - s_a } else { s_a };
                match (&cat, i) {
                    (_, 0) => pa,
                    (_, i) if i == n => pb,
                    (Some(c), _) => {
                        let (x, z) = c.position(s);
                        lo + dir * x + Vec3::z() * (z * w.signum())
                    }
                    (None, _) => pa + (pb - pa) * (s_a / length),
                }
            })
            .collect();
        l.set_node_shape(&shape, &mut y[o..]);
    }
}

/// Solves J Δ = −R in place of the workspace blocks; `shift` adds −shift·I to every diagonal
/// block (a positive stiffness that regularises slack cables). Writes Δ into `delta`.
fn newton_step(
    system: &System,
    r: &[Real],
    shift: Real,
    ws: &mut Workspace,
    delta: &mut [Real],
) -> bool {
    for (li, l) in system.lines.iter().enumerate() {
        let n = l.vectors() - 1;
        let o = system.layout.line_offset[li];
        let b = &mut ws.blocks[li];
        // The same stiffness per metre of motion at every vector: a tangent's shift is l² μ.
        for i in 0..=n {
            b.diag[i] -= Mat3::identity() * (shift * l.length_scale(i).powi(2));
        }
        for i in 1..n {
            b.x[i] = -get3(&r[o..], i - 1);
        }
        l.apply_clamps(b);
        // End rows: a known end does not move; a free end's residual goes in once, with its
        // point, below.
        b.x[0] = Vec3::zeros();
        b.x[n] = Vec3::zeros();
    }
    for (f, &p) in system.free_points.iter().enumerate() {
        let o = system.layout.point_offset[p].expect("free point");
        ws.coupled.point_diag[f] -= Mat3::identity() * shift;
        ws.coupled.point_x[f] = -get3(&r[o..], 0);
    }
    // The coupled solver adds every line end's diagonal and right-hand side into its point;
    // the point rows already hold the full residual, so the ends contribute no extra rhs.
    if ws.coupled.solve(&mut ws.blocks).is_err() {
        return false;
    }
    delta.iter_mut().for_each(|d| *d = 0.0);
    for (li, l) in system.lines.iter().enumerate() {
        let o = system.layout.line_offset[li];
        for i in 1..l.vectors() - 1 {
            set3(&mut delta[o..], i - 1, &ws.blocks[li].x[i]);
        }
    }
    for (f, &p) in system.free_points.iter().enumerate() {
        let o = system.layout.point_offset[p].expect("free point");
        set3(&mut delta[o..], 0, &ws.coupled.point_x[f]);
    }
    delta.iter().all(|d| d.is_finite())
}

/// Newton iterations at a fixed load factor, with a Levenberg–Marquardt shift: the Jacobian's
/// diagonal blocks get −μI (a positive stiffness μ [N/m] at every node), μ grows tenfold when
/// a step fails to lower the residual and shrinks tenfold when one succeeds. This handles the
/// zero transverse stiffness of unloaded cables (straight seeds, slack spans). A short
/// backtracking search and a cap on the largest nodal move guard each step.
/// Returns (converged, iterations, residual).
fn newton(
    system: &System,
    y: &mut [Real],
    current_factor: Real,
    tol: Real,
    max_iter: usize,
    ws: &mut Workspace,
    trace: &mut Trace,
) -> (bool, usize, Real) {
    let len = y.len();
    let mut r = vec![0.0; len];
    let mut trial_r = vec![0.0; len];
    let mut delta = vec![0.0; len];
    let mut trial = vec![0.0; len];
    let max_step = system
        .lines
        .iter()
        .map(|l| l.mesh.length())
        .fold(0.0, Real::max)
        * 0.2;
    // Convergence is judged on the largest nodal imbalance; steps are accepted on the 2-norm,
    // which a shifted Newton step is guaranteed to lower for a positive-definite stiffness
    // (d‖R‖²/dα = −2 Rᵀ K (K + μI)⁻¹ R < 0), unlike the max-norm.
    let two_norm = |r: &[Real]| r.iter().map(|x| x * x).sum::<Real>().sqrt();
    let (mut norm, _) = residual(system, y, current_factor, ws, &mut r);
    let mut merit = two_norm(&r);
    let mut mu: Real = 0.0;
    for it in 0..max_iter {
        let tol = effective_tolerance(tol, ws);
        if norm <= tol {
            return (true, it, norm);
        }
        force_jacobian(
            system,
            y,
            Variable::Position,
            Difference::Forward,
            current_factor,
            ws,
        );
        let scale = ws
            .blocks
            .iter()
            .flat_map(|b| b.diag.iter())
            .map(|m| m.abs().max())
            .fold(0.0, Real::max)
            .max(1e-12);
        let mut applied = 0.0;
        let mut accepted = false;
        for _ in 0..16 {
            let solved = newton_step(system, &r, mu - applied, ws, &mut delta);
            applied = mu;
            if !solved {
                trace.push(|| format!("newton {it}: singular with mu {mu:.2e}"));
                mu = (mu * 10.0).max(1e-9 * scale);
                continue;
            }
            let big = (0..len / 3)
                .map(|i| get3(&delta, i).norm())
                .fold(0.0, Real::max);
            let mut alpha = if big > max_step && max_step > 0.0 {
                max_step / big
            } else {
                1.0
            };
            for _ in 0..4 {
                for i in 0..len {
                    trial[i] = y[i] + alpha * delta[i];
                }
                let (tn, _) = residual(system, &trial, current_factor, ws, &mut trial_r);
                let tm = two_norm(&trial_r);
                if tn.is_finite() && tm < merit {
                    y.copy_from_slice(&trial);
                    r.copy_from_slice(&trial_r);
                    trace.push(|| {
                        format!(
                            "newton {it}: |R| {norm:.3e} -> {tn:.3e} N (tolerance {tol:.1e} N), \
                             mu {mu:.2e}, alpha {alpha:.2e}"
                        )
                    });
                    norm = tn;
                    merit = tm;
                    accepted = true;
                    break;
                }
                alpha *= 0.5;
            }
            if accepted {
                mu = if mu > 1e-9 * scale { mu * 0.1 } else { 0.0 };
                break;
            }
            trace.push(|| {
                format!(
                    "newton {it}: rejected step with mu {mu:.2e} (|R| {norm:.3e} N, largest \
                     move {big:.3e} m)"
                )
            });
            mu = (mu * 10.0).max(1e-6 * scale);
        }
        if !accepted {
            return (norm <= effective_tolerance(tol, ws), it + 1, norm);
        }
    }
    (norm <= effective_tolerance(tol, ws), max_iter, norm)
}

/// Groups of points joined by lines that contain no fixed or prescribed point: they have no
/// static equilibrium under a net weight, buoyancy, point force or current drag.
fn check_supported(system: &System) -> Result<(), StaticsError> {
    let n = system.points.len();
    let mut parent: Vec<usize> = (0..n).collect();
    fn find(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    for l in &system.lines {
        let (a, b) = (find(&mut parent, l.end_a), find(&mut parent, l.end_b));
        parent[a] = b;
    }
    let env = &system.environment;
    let g = env.gravity;
    let roots: Vec<usize> = (0..n).map(|i| find(&mut parent, i)).collect();
    let mut anchored = vec![false; n];
    for (i, p) in system.points.iter().enumerate() {
        if p.free_index.is_none() {
            anchored[roots[i]] = true;
        }
    }
    for root in 0..n {
        if anchored[root] || roots[root] != root {
            continue;
        }
        // Net static force on the group: weights, buoyancy (at the initial positions) and
        // point forces; a current would also push it away.
        let mut net = Vec3::zeros();
        let mut names = Vec::new();
        for (i, p) in system.points.iter().enumerate() {
            if roots[i] != root {
                continue;
            }
            names.push(format!("`{}`", p.name));
            if let crate::model::PointKind::Free {
                mass,
                volume,
                force,
                ..
            } = &p.kind
            {
                net += force - Vec3::z() * (mass * g);
                if p.position.z < 0.0 {
                    net.z += env.water_density * volume * g;
                }
            }
        }
        for l in &system.lines {
            if roots[l.end_a] != root {
                continue;
            }
            for &k in &l.mesh.element_section {
                let s = &l.mesh.sections[k];
                net.z -= (s.line_type.mass_per_length - env.water_density * s.area)
                    * g
                    * s.element_length;
            }
        }
        // The statics is solved at t = 0, where ramped waves are still calm.
        let drifting = !env.is_still_at(0.0) || system.tow_velocity != Vec3::zeros();
        if net.norm() > 1e-9 * force_scale(system) || drifting {
            return Err(StaticsError::Unsupported {
                points: names.join(", "),
                net_force: net.norm(),
                what: if drifting {
                    "and a current, the waves or the tow push them".to_string()
                } else {
                    "weight, buoyancy and point forces".to_string()
                },
            });
        }
    }
    Ok(())
}

/// Finds the static equilibrium of the system with prescribed points at their t = 0
/// positions, starting from `initial` (or a catenary seed when `None`). A system with `dg`
/// lines or free bodies is solved on its twin ([`System::statics_twin`]: `hermite` lines,
/// bodies held at their initial pose) from a catenary seed (`initial` is not used) and carried
/// over by [`System::state_from_twin`]: free bodies start at their initial pose, at rest, so
/// give them a pose near their equilibrium.
///
/// A steady tow ([`System::tow_velocity`] V ≠ 0) is solved in the frame moving with the
/// vessel: every load is evaluated with every material point moving at V (drag on u − V,
/// seabed friction against V), prescribed points, bodies and obstacles at their t = 0 places,
/// and the returned state moves at V: line nodes, free points and free bodies (line tangents
/// and body rotations at rest), so that a run started from it carries on steadily.
pub fn solve(
    system: &System,
    initial: Option<&[Real]>,
    options: &StaticOptions,
) -> Result<StaticSolution, StaticsError> {
    let mut sol = solve_at_rest(system, initial, options)?;
    if system.tow_velocity != Vec3::zeros() {
        set_tow_velocities(system, &mut sol.state);
    }
    Ok(sol)
}

/// Writes the steady tow's velocities into `y`: [`System::tow_velocity`] for every line node
/// (zero for `hermite` tangents), free point and free body (zero angular velocity); with a zero
/// tow velocity, everything at rest.
pub fn set_tow_velocities(system: &System, y: &mut [Real]) {
    let v = system.tow_velocity;
    for (li, l) in system.lines.iter().enumerate() {
        if l.dg().is_some() {
            continue;
        }
        let o = system.layout.line_offset[li];
        let m = system.layout.line_interior[li];
        for j in 1..l.vectors() - 1 {
            let x = if l.is_tangent(j) { Vec3::zeros() } else { v };
            set3(&mut y[o + 3 * m..], j - 1, &x);
        }
    }
    for &p in &system.free_points {
        let o = system.layout.point_offset[p].expect("free point");
        set3(&mut y[o..], 1, &v);
    }
    for &b in &system.free_bodies {
        let o = system.layout.body_offset[b].expect("free body");
        let mut k = crate::bodies::read_state(&y[o..o + crate::bodies::STATE_LEN]);
        k.velocity = v;
        k.angular_velocity = Vec3::zeros();
        crate::bodies::write_state(&k, &mut y[o..o + crate::bodies::STATE_LEN]);
    }
}

/// [`solve`] with every velocity of the returned state zero.
fn solve_at_rest(
    system: &System,
    initial: Option<&[Real]>,
    options: &StaticOptions,
) -> Result<StaticSolution, StaticsError> {
    if !system.free_bodies.is_empty() {
        return super::bodies::solve_with_bodies(system, options);
    }
    if system.needs_statics_twin() {
        // dg lines or free bodies: solve the twin (hermite lines, bodies held), then carry
        // the state over (System::state_from_twin).
        let twin = system.statics_twin();
        let sol = solve(&twin, None, options)?;
        return Ok(StaticSolution {
            state: system.state_from_twin(&twin, &sol.state, true),
            iterations: sol.iterations,
            residual: sol.residual,
            method: if system.has_dg_lines() {
                "hermite twin projected onto dg"
            } else {
                "newton with the bodies held"
            },
            log: sol.log,
        });
    }
    check_supported(system)?;
    let mut ws = system.workspace();
    let mut y = match initial {
        Some(y0) => y0.to_vec(),
        None => system.straight_state(),
    };
    if initial.is_none() && options.catenary_seed {
        catenary_seed(system, &mut y, &mut ws);
    }
    // Zero velocities.
    zero_velocities(system, &mut y);
    let tol = options.relative_tolerance * force_scale(system);
    let seed = y.clone();
    let mut trace = Trace::new(options.trace);
    let max_iter = options.max_iterations;
    let (ok, it, res) = newton(system, &mut y, 1.0, tol, max_iter, &mut ws, &mut trace);
    if ok {
        return Ok(StaticSolution {
            state: y,
            iterations: it,
            residual: res,
            method: "newton",
            log: trace.into_lines(),
        });
    }
    trace.push(|| {
        format!(
            "newton failed after {it} iterations (residual {res:.3e} N, tolerance {tol:.3e} N): \
             load continuation on the current and point loads"
        )
    });
    // Load continuation on the current and point loads from the seed.
    let mut total = it;
    y.copy_from_slice(&seed);
    let mut lambda: Real = 0.0;
    let mut step: Real = 0.25;
    let mut cont_ok = true;
    while lambda < 1.0 {
        let target = (lambda + step).min(1.0);
        let mut trial = y.clone();
        trace.push(|| format!("load continuation: load factor {target:.4}"));
        let (ok, it, _) = newton(
            system, &mut trial, target, tol, max_iter, &mut ws, &mut trace,
        );
        total += it;
        if ok {
            y = trial;
            lambda = target;
            step *= 1.5;
        } else {
            step *= 0.25;
            if step < 1e-3 {
                cont_ok = false;
                break;
            }
        }
    }
    if cont_ok {
        let (_, _, res) = newton(system, &mut y, 1.0, tol, max_iter, &mut ws, &mut trace);
        return Ok(StaticSolution {
            state: y,
            iterations: total,
            residual: res,
            method: "newton with load continuation",
            log: trace.into_lines(),
        });
    }
    // Dynamic relaxation, then Newton to polish.
    let mut r = vec![0.0; y.len()];
    let (newton_res, worst) = residual(system, &seed, 1.0, &mut ws, &mut r);
    let location = system.locate(worst);
    y.copy_from_slice(&seed);
    trace.push(|| "load continuation failed: dynamic relaxation from the seed".to_string());
    let dr_res = dynamic_relaxation::relax(system, &mut y, tol, &mut ws);
    trace.push(|| format!("dynamic relaxation: residual {dr_res:.3e} N; newton to polish"));
    let (ok, it, res) = newton(system, &mut y, 1.0, tol, max_iter, &mut ws, &mut trace);
    if ok || dr_res <= effective_tolerance(tol, &ws) {
        return Ok(StaticSolution {
            state: y,
            iterations: total + it,
            residual: res.min(dr_res),
            method: "dynamic relaxation",
            log: trace.into_lines(),
        });
    }
    Err(StaticsError::NotConverged {
        iterations: total,
        residual: newton_res,
        tolerance: tol,
        location: format!("{} node {}", location.object, location.node),
        relaxation_residual: dr_res,
        hint: "check that every free point is held by a line or is neutrally supported, that lines are long \
               enough to reach between their ends, and that points start near their equilibrium"
            .into(),
    })
}

/// Sets every velocity entry of the state to zero.
pub fn zero_velocities(system: &System, y: &mut [Real]) {
    for (o, m) in system.layout.blocks() {
        y[o + 3 * m..o + 6 * m].iter_mut().for_each(|v| *v = 0.0);
    }
}

/// Evaluates the static forces at `y` into `ws` (zero velocities, prescribed points at their
/// t = 0 positions) so that [`System::end_force`] and [`System::node_tension`] give the static
/// end forces and tensions. Returns the largest residual [N].
///
/// With `dg` lines the forces are the dynamics' own at rest ([`System::rhs`] at t = 0): the
/// end forces are the flux tractions, and the residual is the largest of the free points'
/// net forces and the dg elements' mean momentum rates times their lengths [N].
pub fn evaluate(system: &System, y: &[Real], ws: &mut Workspace) -> Real {
    if system.has_dg_lines() {
        let mut rate = vec![0.0; y.len()];
        if system.rhs(0.0, y, &mut rate, ws).is_err() {
            return Real::INFINITY;
        }
        let mut norm: Real = 0.0;
        for (li, l) in system.lines.iter().enumerate() {
            if let Some(dg) = l.dg() {
                let o = system.layout.line_offset[li];
                for (e, el) in dg.elements.iter().enumerate() {
                    let m3 = 3 * dg.section(e).basis.modes();
                    let v = o + el.state + m3;
                    norm = norm.max(crate::math::get3(&rate[v..], 0).norm() * el.length);
                }
            }
        }
        for &p in &system.free_points {
            let o = system.layout.point_offset[p].expect("free point");
            let (_, mass) = system.point_own_load(p, &ws.points[p], 0.0, 1.0);
            norm = norm.max((mass * crate::math::get3(&rate[o..], 1)).norm());
        }
        return norm;
    }
    let mut r = vec![0.0; y.len()];
    let (norm, _) = residual(system, y, 1.0, ws, &mut r);
    for b in ws.blocks.iter_mut() {
        b.clear();
        b.x.iter_mut().for_each(|x| *x = Vec3::zeros());
    }
    norm
}
