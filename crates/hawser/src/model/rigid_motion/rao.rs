//! RAO motion: the vessel response to the environment's waves from a table of RAOs.

use super::*;

/// Displacement RAOs of a vessel: for each wave frequency and heading, the complex response
/// per unit wave amplitude of surge, sway, heave [m/m] and roll, pitch, yaw [rad/m], in the
/// vessel's axes about its origin (the RAO origin, also the phase origin).
///
/// Convention (docs/motions.md): a wave component η = a cos(ωt − k·x_ref − φ) at the RAO
/// origin x_ref produces the response ξ_k = a |RAO_k| cos(ωt − k·x_ref − φ − lag_k): the
/// phase is a **lag** behind the wave crest at the RAO origin. The heading is the direction of
/// propagation relative to the vessel x axis, positive toward the vessel's +y (port): 0 =
/// following seas (waves travelling from stern to bow), 90° = waves travelling toward port.
/// Stored as complex numbers H = |RAO| e^{−i lag}, so that ξ = a Re[H e^{i(ωt − k·x_ref − φ)}].
///
/// Interpolation: linear in the angular frequency and in the heading, of the real and
/// imaginary parts of H (not of amplitude and phase, which would need phase unwrapping).
/// Headings are periodic: the table's headings are taken modulo 360° and a heading between the
/// last and the first (+360°) is interpolated across the gap, so give the full circle (hawser
/// applies no port–starboard symmetry). Frequencies below the lowest tabulated one take the
/// lowest one's RAO (long waves: the responses tend to finite limits, e.g. heave → 1); above
/// the highest one the response is zero (short waves do not move a vessel).
#[derive(Clone, Debug, PartialEq)]
pub struct RaoTable {
    /// Angular frequencies [rad/s], strictly increasing.
    frequencies: Vec<Real>,
    /// Headings [rad] in [0, 2π), strictly increasing.
    headings: Vec<Real>,
    /// H per (frequency, heading), frequency-major: [re, im] for surge, sway, heave, roll,
    /// pitch, yaw.
    values: Vec<[[Real; 2]; 6]>,
}

impl RaoTable {
    /// A table from angular `frequencies` [rad/s] (strictly increasing, > 0), `headings` [rad]
    /// (any order; distinct modulo 2π, except that a heading repeated modulo 2π with the same
    /// RAOs — 0° and 360°, −180° and 180° — is dropped), and per (frequency, heading),
    /// frequency-major, the amplitudes (surge, sway, heave [m/m]; roll, pitch, yaw [rad/m]) and
    /// phase lags [rad] of the six DOFs.
    pub fn new(
        frequencies: Vec<Real>,
        headings: &[Real],
        amplitudes: &[[Real; 6]],
        phases: &[[Real; 6]],
    ) -> Result<Self, ModelError> {
        let (nf, nh) = (frequencies.len(), headings.len());
        check(
            nf >= 1 && nh >= 1 && amplitudes.len() == nf * nh && phases.len() == nf * nh,
            "RAO table",
            "needs at least one frequency and one heading, and one row per frequency and heading",
        )?;
        check(
            frequencies.iter().all(|w| w.is_finite() && *w > 0.0)
                && frequencies.windows(2).all(|w| w[1] > w[0]),
            "RAO table",
            "the frequencies must be > 0 and strictly increasing",
        )?;
        check(
            headings.iter().all(|h| h.is_finite())
                && amplitudes
                    .iter()
                    .chain(phases)
                    .flatten()
                    .all(|x| x.is_finite()),
            "RAO table",
            "headings, amplitudes and phases must be finite",
        )?;
        // Headings in [0, 2π), sorted, duplicates merged.
        let mut order: Vec<(Real, usize)> = headings
            .iter()
            .enumerate()
            .map(|(j, h)| {
                let mut w = h.rem_euclid(TAU);
                if w >= TAU - 1e-12 {
                    w = 0.0;
                }
                (w, j)
            })
            .collect();
        order.sort_by(|a, b| a.0.total_cmp(&b.0));
        let complex = |f: usize, j: usize| -> [[Real; 2]; 6] {
            let mut h = [[0.0; 2]; 6];
            for d in 0..6 {
                let (s, c) = phases[f * nh + j][d].sin_cos();
                let a = amplitudes[f * nh + j][d];
                h[d] = [a * c, -a * s];
            }
            h
        };
        let mut kept: Vec<(Real, usize)> = Vec::with_capacity(nh);
        for &(w, j) in &order {
            if let Some(&(w0, j0)) = kept.last()
                && (w - w0).abs() < 1e-9
            {
                let same = (0..nf).all(|f| {
                    let (a, b) = (complex(f, j), complex(f, j0));
                    a.iter()
                        .flatten()
                        .zip(b.iter().flatten())
                        .all(|(x, y)| (x - y).abs() <= 1e-9 * (1.0 + x.abs()))
                });
                if !same {
                    return Err(invalid(
                        "RAO table",
                        format!(
                            "headings {:.6}° and {:.6}° are the same direction but have \
                             different RAOs",
                            headings[j0].to_degrees(),
                            headings[j].to_degrees()
                        ),
                    ));
                }
                continue;
            }
            kept.push((w, j));
        }
        let mut values = Vec::with_capacity(nf * kept.len());
        for f in 0..nf {
            for &(_, j) in &kept {
                values.push(complex(f, j));
            }
        }
        Ok(Self {
            frequencies,
            headings: kept.iter().map(|k| k.0).collect(),
            values,
        })
    }

    /// Angular frequencies [rad/s].
    pub fn frequencies(&self) -> &[Real] {
        &self.frequencies
    }

    /// Headings [rad] in [0, 2π).
    pub fn headings(&self) -> &[Real] {
        &self.headings
    }

    /// Frequency bracket (index, weight of the next) of ω [rad/s]; `None` above the table.
    fn frequency_bracket(&self, omega: Real) -> Option<(usize, Real)> {
        let f = &self.frequencies;
        let n = f.len();
        if omega > f[n - 1] {
            return None;
        }
        if omega <= f[0] || n == 1 {
            return Some((0, 0.0));
        }
        let i = f.partition_point(|&w| w <= omega).clamp(1, n - 1) - 1;
        Some((i, (omega - f[i]) / (f[i + 1] - f[i])))
    }

    /// Heading bracket of β [rad]: (index j, index of the next, weight of the next, the
    /// bracket's width [rad]; 0 with a single heading).
    #[inline]
    fn heading_bracket(&self, beta: Real) -> (usize, usize, Real, Real) {
        let h = &self.headings;
        let n = h.len();
        if n == 1 {
            return (0, 0, 0.0, 0.0);
        }
        let b = beta.rem_euclid(TAU);
        let i = h.partition_point(|&x| x <= b);
        if i == 0 || i == n {
            // Across the gap from the last heading to the first + 2π.
            let width = h[0] + TAU - h[n - 1];
            let from_last = (b - h[n - 1]).rem_euclid(TAU);
            return (n - 1, 0, from_last / width, width);
        }
        let width = h[i] - h[i - 1];
        (i - 1, i, (b - h[i - 1]) / width, width)
    }

    /// The complex RAOs H [m/m or rad/m] of the six DOFs at ω [rad/s] and heading β [rad]
    /// (interpolated as the type's documentation says).
    pub fn at(&self, omega: Real, heading: Real) -> [[Real; 2]; 6] {
        match self.frequency_bracket(omega) {
            None => [[0.0; 2]; 6],
            Some((i, wf)) => self.interpolate(i, wf, heading).0,
        }
    }

    /// H and dH/dβ [per rad] at frequency bracket (i, wf) and heading β [rad].
    #[inline]
    fn interpolate(&self, i: usize, wf: Real, beta: Real) -> ([[Real; 2]; 6], [[Real; 2]; 6]) {
        let nh = self.headings.len();
        let (j0, j1, wh, width) = self.heading_bracket(beta);
        let i1 = (i + 1).min(self.frequencies.len() - 1);
        let (a, b, c, d) = (
            &self.values[i * nh + j0],
            &self.values[i * nh + j1],
            &self.values[i1 * nh + j0],
            &self.values[i1 * nh + j1],
        );
        let mut h = [[0.0; 2]; 6];
        let mut dh = [[0.0; 2]; 6];
        for k in 0..6 {
            for p in 0..2 {
                let lo = a[k][p] + wh * (b[k][p] - a[k][p]);
                let hi = c[k][p] + wh * (d[k][p] - c[k][p]);
                h[k][p] = lo + wf * (hi - lo);
                if width > 0.0 {
                    let slope_lo = b[k][p] - a[k][p];
                    let slope_hi = d[k][p] - c[k][p];
                    dh[k][p] = (slope_lo + wf * (slope_hi - slope_lo)) / width;
                }
            }
        }
        (h, dh)
    }
}

/// One wave component as the RAO motion needs it.
#[derive(Clone, Debug, PartialEq)]
struct RaoWave {
    amplitude: Real,
    omega: Real,
    kx: Real,
    ky: Real,
    phase: Real,
    direction: Real,
    /// Frequency bracket in the RAO table.
    bracket: (usize, Real),
}

/// Wave-frequency motion of a vessel from displacement RAOs ([`RaoTable`]), driven by the same
/// wave field as the lines, superposed on a mean motion (fixed, constant velocity or a
/// manoeuvre).
///
/// With the sea's components (a_j, ω_j, k_j, β_j, φ_j) and θ_j = k_j·x̄(t) − ω_j t + φ_j the
/// wave phase at the vessel's **mean** position x̄(t), the response of DOF k is
///
///   ξ_k(t) = r(t) Σ_j a_j Re[H_k(ω_j, β_j − ψ̄(t)) e^{−iθ_j}]
///          = r(t) Σ_j a_j |H_k| cos(ω_j t − k_j·x̄ − φ_j − lag_k),
///
/// r the sea's build-up ramp ([`crate::physics::waves::WaveSpec::ramp_time`]) and ψ̄ the mean
/// heading (the yaw of the mean orientation). Taking the phase at the moving mean position
/// gives a moving vessel the encounter frequency ω_j − k_j·v̄ in its response; the RAO itself
/// is taken at the wave's absolute frequency ω_j (the table is assumed to be for the vessel's
/// speed). Derivatives are exact: with E = e^{−iθ}, dθ/dt = k·v̄ − ω, d²θ/dt² = k·ā and
/// dH/dt = −(∂H/∂β) dψ̄/dt (the heading interpolation is linear, so ∂²H/∂β² = 0 inside a
/// bracket), ξ̇ = a Re[Ḣ E + H Ė], ξ̈ = a Re[Ḧ E + 2 Ḣ Ė + H Ë]. The mean heading rate is the
/// mean angular velocity's z component (exact for mean motions without roll and pitch).
///
/// Surge, sway and heave are displacements of the origin along the mean body axes; roll, pitch
/// and yaw are Euler angles R_e = R_z(ξ6) R_y(ξ5) R_x(ξ4) relative to the mean orientation R̄:
/// R = R̄ R_e, and with ρ = R̄ d the kinematics compose as those of a body moving in a moving
/// frame: v = v̄ + ω̄ × ρ + R̄ ḋ, a = ā + α̅ × ρ + ω̄ × (ω̄ × ρ) + 2 ω̄ × R̄ ḋ + R̄ d̈,
/// ω = ω̄ + R̄ ω_e, dω/dt = α̅ + R̄ α_e + ω̄ × R̄ ω_e.
#[derive(Clone, Debug, PartialEq)]
pub struct RaoMotion {
    mean: RigidMotion,
    table: RaoTable,
    waves: Vec<RaoWave>,
    ramp_time: Real,
}

impl RaoMotion {
    /// The RAO motion of a vessel with displacement RAOs `table` in the sea `waves` (the one
    /// built for the environment: a clone of its components is kept), on the `mean` motion. A
    /// calm sea leaves the vessel on its mean motion.
    pub fn new(table: RaoTable, waves: &Waves, mean: RigidMotion) -> Result<Self, ModelError> {
        if matches!(mean, RigidMotion::Rao(_)) {
            return Err(invalid(
                "RAO motion",
                "the mean motion cannot itself be an RAO motion",
            ));
        }
        let (components, ramp_time) = match waves.field() {
            Some(f) => (f.components(), f.spec().ramp_time),
            None => (&[][..], 0.0),
        };
        let waves = components
            .iter()
            .filter_map(|c| {
                table
                    .frequency_bracket(c.angular_frequency())
                    .map(|bracket| {
                        let (s, co) = c.direction().sin_cos();
                        RaoWave {
                            amplitude: c.amplitude(),
                            omega: c.angular_frequency(),
                            kx: c.wavenumber() * co,
                            ky: c.wavenumber() * s,
                            phase: c.phase(),
                            direction: c.direction(),
                            bracket,
                        }
                    })
            })
            .collect();
        Ok(Self {
            mean,
            table,
            waves,
            ramp_time,
        })
    }

    /// The mean motion.
    pub fn mean(&self) -> &RigidMotion {
        &self.mean
    }

    /// The RAO table.
    pub fn table(&self) -> &RaoTable {
        &self.table
    }

    /// The wave-frequency responses at t [s]: [surge, sway, heave (m), roll, pitch, yaw (rad)]
    /// in the mean body axes, their rates and second derivatives, with the mean kinematics.
    pub fn responses(&self, t: Real) -> ([Real; 6], [Real; 6], [Real; 6], RigidKinematics) {
        let m = self.mean.kinematics(t);
        let mut xi = [0.0; 6];
        let mut xid = [0.0; 6];
        let mut xidd = [0.0; 6];
        let (r, dr, ddr) = ramp(t, self.ramp_time);
        if r == 0.0 && dr == 0.0 || self.waves.is_empty() {
            return (xi, xid, xidd, m);
        }
        let (_, _, psi) = m.orientation.euler_angles();
        let (psi_d, psi_dd) = (m.angular_velocity.z, m.angular_acceleration.z);
        let (x, v, a) = (m.position, m.velocity, m.acceleration);
        for w in &self.waves {
            let theta = w.kx * x.x + w.ky * x.y - w.omega * t + w.phase;
            let theta_d = w.kx * v.x + w.ky * v.y - w.omega;
            let theta_dd = w.kx * a.x + w.ky * a.y;
            let (s, c) = theta.sin_cos();
            // E = e^{−iθ}, Ė = −i θ̇ E, Ë = (−i θ̈ − θ̇²) E.
            let e = [c, -s];
            let ed = [theta_d * e[1], -theta_d * e[0]];
            let edd = [
                theta_dd * e[1] - theta_d * theta_d * e[0],
                -theta_dd * e[0] - theta_d * theta_d * e[1],
            ];
            let (h, dh) = self
                .table
                .interpolate(w.bracket.0, w.bracket.1, w.direction - psi);
            for k in 0..6 {
                let hd = [-dh[k][0] * psi_d, -dh[k][1] * psi_d];
                let hdd = [-dh[k][0] * psi_dd, -dh[k][1] * psi_dd];
                let re = |p: [Real; 2], q: [Real; 2]| p[0] * q[0] - p[1] * q[1];
                xi[k] += w.amplitude * re(h[k], e);
                xid[k] += w.amplitude * (re(hd, e) + re(h[k], ed));
                xidd[k] += w.amplitude * (re(hdd, e) + 2.0 * re(hd, ed) + re(h[k], edd));
            }
        }
        for k in 0..6 {
            xidd[k] = r * xidd[k] + 2.0 * dr * xid[k] + ddr * xi[k];
            xid[k] = r * xid[k] + dr * xi[k];
            xi[k] *= r;
        }
        (xi, xid, xidd, m)
    }

    /// Kinematics at time t [s].
    pub fn kinematics(&self, t: Real) -> RigidKinematics {
        let (xi, xid, xidd, m) = self.responses(t);
        let rm = m.orientation;
        let rho = rm * Vec3::new(xi[0], xi[1], xi[2]);
        let rel_v = rm * Vec3::new(xid[0], xid[1], xid[2]);
        let rel_a = rm * Vec3::new(xidd[0], xidd[1], xidd[2]);
        let (w, al) = (m.angular_velocity, m.angular_acceleration);
        let (qe, we, ae) = euler_kinematics(
            [xi[3], xi[4], xi[5]],
            [xid[3], xid[4], xid[5]],
            [xidd[3], xidd[4], xidd[5]],
        );
        let we_g = rm * we;
        RigidKinematics {
            position: m.position + rho,
            orientation: rm * qe,
            velocity: m.velocity + w.cross(&rho) + rel_v,
            angular_velocity: w + we_g,
            acceleration: m.acceleration
                + al.cross(&rho)
                + w.cross(&w.cross(&rho))
                + 2.0 * w.cross(&rel_v)
                + rel_a,
            angular_acceleration: al + rm * ae + w.cross(&we_g),
        }
    }
}
