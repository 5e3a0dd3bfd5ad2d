//! Axial constitutive law of a cable: tension from strain and strain rate.

use crate::math::Real;

/// Elastic part of the axial law.
#[derive(Clone, Debug, PartialEq)]
pub enum AxialStiffness {
    /// Linear: T = EA·ε, with EA [N].
    Linear(Real),
    /// Piecewise-linear tension–strain table (strain [-], tension [N]), strictly increasing
    /// strain starting at 0 with tension 0; extrapolated with the last slope.
    Table {
        /// Strain values [-].
        strain: Vec<Real>,
        /// Tension at each strain [N].
        tension: Vec<Real>,
    },
}

impl AxialStiffness {
    /// Elastic tension [N] at strain ε ≥ 0, and the tangent stiffness dT/dε [N].
    #[inline]
    pub fn tension_and_tangent(&self, strain: Real) -> (Real, Real) {
        match self {
            AxialStiffness::Linear(ea) => (ea * strain, *ea),
            AxialStiffness::Table {
                strain: e,
                tension: t,
            } => {
                let n = e.len();
                let k = e.partition_point(|&ek| ek <= strain).clamp(1, n - 1);
                let slope = (t[k] - t[k - 1]) / (e[k] - e[k - 1]);
                (t[k - 1] + slope * (strain - e[k - 1]), slope)
            }
        }
    }

    /// Largest tangent stiffness dT/dε [N] over the law (sets the axial wave speed).
    pub fn max_tangent(&self) -> Real {
        match self {
            AxialStiffness::Linear(ea) => *ea,
            AxialStiffness::Table {
                strain: e,
                tension: t,
            } => e
                .windows(2)
                .zip(t.windows(2))
                .map(|(e, t)| (t[1] - t[0]) / (e[1] - e[0]))
                .fold(0.0, Real::max),
        }
    }
}

/// Axial visco-elastic law of a line type (DG paper eq. 22):
/// T(ε, ε̇) = T_e(max(ε, 0)) + c·ε̇ when the cable carries no compression,
/// T(ε, ε̇) = T_e(ε) + c·ε̇ when it does (linear law only, extended to ε < 0).
#[derive(Clone, Debug, PartialEq)]
pub struct AxialLaw {
    /// Elastic part.
    pub stiffness: AxialStiffness,
    /// Axial damping coefficient c [N·s] multiplying the strain rate ε̇ [1/s].
    pub damping: Real,
    /// Whether the cable carries compression (rods, umbilicals with bending stiffness).
    pub compression: bool,
}

impl AxialLaw {
    /// Elastic strain energy per unit unstretched length ∫₀^ε T_e(e) de [J/m] of an axial law
    /// (zero in compression unless the law carries it; a table integrates exactly piecewise).
    pub fn strain_energy_density(&self, strain: Real) -> Real {
        let law = self;
        if !(strain > 0.0) {
            return if law.compression {
                0.5 * law.stiffness.max_tangent() * strain * strain
            } else {
                0.0
            };
        }
        match &law.stiffness {
            AxialStiffness::Linear(ea) => 0.5 * ea * strain * strain,
            AxialStiffness::Table { strain: e, .. } => {
                // Trapezoids between the table's breakpoints below ε, then up to ε.
                let mut w = 0.0;
                let mut prev = 0.0;
                for &ek in e.iter().skip(1).take_while(|&&ek| ek < strain) {
                    w += 0.5
                        * (law.stiffness.tension_and_tangent(prev).0
                            + law.stiffness.tension_and_tangent(ek).0)
                        * (ek - prev);
                    prev = ek;
                }
                w + 0.5
                    * (law.stiffness.tension_and_tangent(prev).0
                        + law.stiffness.tension_and_tangent(strain).0)
                    * (strain - prev)
            }
        }
    }

    /// Tension T [N] from strain ε [-] and strain rate ε̇ [1/s] (DG paper eq. 22).
    ///
    /// The damping term acts whatever the strain, as in eq. 22.
    #[inline(always)]
    pub fn tension(&self, strain: Real, strain_rate: Real) -> Real {
        let elastic = if strain > 0.0 {
            self.stiffness.tension_and_tangent(strain).0
        } else if self.compression {
            match &self.stiffness {
                AxialStiffness::Linear(ea) => ea * strain,
                AxialStiffness::Table { .. } => self.stiffness.max_tangent() * strain,
            }
        } else {
            0.0
        };
        elastic + self.damping * strain_rate
    }
}

/// Axial damping of a line type before it is resolved for an element length.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AxialDamping {
    /// Coefficient c [N·s] multiplying the strain rate.
    Coefficient(Real),
    /// Fraction ζ of the critical damping of a segment's axial mode (MoorDyn's `BA = -ζ`),
    /// see [`damping_from_ratio`].
    Ratio(Real),
}

impl AxialDamping {
    /// The coefficient c [N·s] for elements of unstretched length `l0` [m].
    pub fn coefficient(&self, l0: Real, stiffness: &AxialStiffness, mass_per_length: Real) -> Real {
        match *self {
            AxialDamping::Coefficient(c) => c,
            AxialDamping::Ratio(z) => {
                damping_from_ratio(z, l0, stiffness.max_tangent(), mass_per_length)
            }
        }
    }
}

/// Axial damping coefficient c [N·s] for a damping ratio ζ of a segment's axial mode,
/// MoorDyn's convention (`BA = -ζ`): c = ζ · l · √(EA·γ0) for a segment of unstretched length
/// l [m], axial stiffness EA [N] and mass per length γ0 [kg/m].
pub fn damping_from_ratio(
    ratio: Real,
    segment_length: Real,
    ea: Real,
    mass_per_length: Real,
) -> Real {
    ratio * segment_length * (ea * mass_per_length).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn bilinear_law_has_no_compression() {
        let law = AxialLaw {
            stiffness: AxialStiffness::Linear(100.0),
            damping: 2.0,
            compression: false,
        };
        assert_eq!(law.tension(0.01, 0.0), 1.0);
        assert_eq!(law.tension(-0.01, 0.0), 0.0);
        assert_eq!(law.tension(0.01, 0.5), 2.0);
        let law = AxialLaw {
            compression: true,
            ..law
        };
        assert_eq!(law.tension(-0.01, 0.0), -1.0);
    }
    #[test]
    fn table_interpolates_and_extrapolates() {
        let s = AxialStiffness::Table {
            strain: vec![0.0, 0.01, 0.02],
            tension: vec![0.0, 100.0, 300.0],
        };
        assert_eq!(s.tension_and_tangent(0.005), (50.0, 10000.0));
        let (t, k) = s.tension_and_tangent(0.03);
        assert!((t - 500.0).abs() < 1e-9 && k == 20000.0);
        assert_eq!(s.max_tangent(), 20000.0);
    }
}
