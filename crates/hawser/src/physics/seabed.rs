//! The seabed: its shape ([`Bathymetry`]: flat, a plane of any slope, or a grid of heights
//! interpolated bilinearly) and the contact of cables, points and bodies with it (DG paper
//! eqs. 15–16, applied along the bed's local normal; docs/seabed.md).

use crate::math::{Real, Vec3};

/// The shape of the seabed, z up. The environment's `depth` places the flat bed and the
/// plane; a grid carries its own heights.
#[derive(Clone, Debug, PartialEq, Default)]
pub enum Bathymetry {
    /// The plane z = −depth (no seabed when the depth is infinite).
    #[default]
    Flat,
    /// The plane through (0, 0, −depth) with gradient (∂z/∂x, ∂z/∂y) [-]:
    /// z = −depth + g_x x + g_y y.
    Plane {
        /// (∂z/∂x, ∂z/∂y) of the bed [-]: its rise per metre along x and along y.
        gradient: [Real; 2],
    },
    /// Heights on a rectilinear grid, interpolated bilinearly ([`SeabedGrid`]).
    Grid(SeabedGrid),
}

/// The seabed under one horizontal position.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BedPoint {
    /// Height z of the bed [m].
    pub z: Real,
    /// Upward unit normal of the bed [-] (of the interpolating surface's tangent plane).
    pub normal: Vec3,
}

impl BedPoint {
    /// The bed at height `z` [m] with gradient (∂z/∂x, ∂z/∂y) = (`gx`, `gy`) [-]: normal
    /// (−g_x, −g_y, 1)/√(1 + g_x² + g_y²).
    #[inline]
    pub fn with_gradient(z: Real, gx: Real, gy: Real) -> Self {
        let n = Vec3::new(-gx, -gy, 1.0);
        Self {
            z,
            normal: n / n.norm(),
        }
    }

    /// Depth [m] of `position` below the bed's tangent plane, measured along the normal:
    /// (z_bed − z) n_z; ≤ 0 above the bed. Exact for a plane.
    #[inline]
    pub fn penetration(&self, position: &Vec3) -> Real {
        (self.z - position.z) * self.normal.z
    }
}

/// Seabed heights z [m] at the nodes of a rectilinear grid (x_i, y_j), interpolated
/// bilinearly within each cell; beyond the grid the height of the nearest edge is held
/// (MoorDyn's `SeafloorFile` rule), so the bed is level there across the edge.
#[derive(Clone, Debug, PartialEq)]
pub struct SeabedGrid {
    x: Vec<Real>,
    y: Vec<Real>,
    z: Vec<Real>,
    highest: Real,
    mean: Real,
}

impl SeabedGrid {
    /// The grid of heights `z` [m] at nodes `x` × `y` [m], `z[j · x.len() + i]` at
    /// (x_i, y_j). `x` and `y` strictly increasing (one value: the bed is constant along that
    /// axis), every number finite. The error says what is wrong.
    pub fn new(x: Vec<Real>, y: Vec<Real>, z: Vec<Real>) -> Result<Self, String> {
        for (axis, v) in [("x", &x), ("y", &y)] {
            if v.is_empty() {
                return Err(format!("the grid has no {axis} values"));
            }
            if let Some(k) = v.iter().position(|a| !a.is_finite()) {
                return Err(format!("{axis} value {} is not finite", k + 1));
            }
            if let Some(k) = v.windows(2).position(|w| !(w[1] > w[0])) {
                return Err(format!(
                    "the {axis} values must increase strictly: {} is followed by {}",
                    v[k],
                    v[k + 1]
                ));
            }
        }
        if z.len() != x.len() * y.len() {
            return Err(format!(
                "{} heights for a grid of {} × {} nodes",
                z.len(),
                x.len(),
                y.len()
            ));
        }
        if let Some(k) = z.iter().position(|a| !a.is_finite()) {
            return Err(format!(
                "the height at x = {}, y = {} is not finite",
                x[k % x.len()],
                y[k / x.len()]
            ));
        }
        let highest = z.iter().copied().fold(Real::NEG_INFINITY, Real::max);
        let mean = z.iter().sum::<Real>() / z.len() as Real;
        Ok(Self {
            x,
            y,
            z,
            highest,
            mean,
        })
    }

    /// Grid x values [m].
    pub fn x(&self) -> &[Real] {
        &self.x
    }

    /// Grid y values [m].
    pub fn y(&self) -> &[Real] {
        &self.y
    }

    /// Heights [m], `z[j · x.len() + i]` at (x_i, y_j).
    pub fn heights(&self) -> &[Real] {
        &self.z
    }

    /// The highest node [m].
    pub fn highest(&self) -> Real {
        self.highest
    }

    /// The mean of the node heights [m] (MoorDyn's "average depth", negated).
    pub fn mean(&self) -> Real {
        self.mean
    }

    /// Height z [m] and gradient (∂z/∂x, ∂z/∂y) [-] of the bilinear surface at (px, py).
    /// On a cell edge the gradient is the one of the cell above it; beyond the grid the
    /// component across the edge is zero.
    #[inline]
    pub fn height(&self, px: Real, py: Real) -> (Real, Real, Real) {
        let (i, fx, dx) = cell(&self.x, px);
        let (j, fy, dy) = cell(&self.y, py);
        let nx = self.x.len();
        let (i1, j1) = ((i + 1).min(nx - 1), (j + 1).min(self.y.len() - 1));
        let z00 = self.z[j * nx + i];
        let z10 = self.z[j * nx + i1];
        let z01 = self.z[j1 * nx + i];
        let z11 = self.z[j1 * nx + i1];
        let low = z00 + (z10 - z00) * fx;
        let high = z01 + (z11 - z01) * fx;
        let z = low + (high - low) * fy;
        let gx = ((z10 - z00) * (1.0 - fy) + (z11 - z01) * fy) * dx;
        let gy = (high - low) * dy;
        (z, gx, gy)
    }
}

/// The cell of a strictly increasing axis `xs` holding `x`: (lower node index i, fraction f in
/// [0, 1] from x_i to x_{i+1}, 1/(x_{i+1} − x_i) or 0 outside the axis and for one node).
#[inline]
fn cell(xs: &[Real], x: Real) -> (usize, Real, Real) {
    let n = xs.len();
    if n < 2 || x <= xs[0] {
        return (0, 0.0, 0.0);
    }
    if x >= xs[n - 1] {
        return (n - 2, 1.0, 0.0);
    }
    let k = xs.partition_point(|&v| v <= x).clamp(1, n - 1);
    let inv = 1.0 / (xs[k] - xs[k - 1]);
    (k - 1, (x - xs[k - 1]) * inv, inv)
}

impl Bathymetry {
    /// The bed under (x, y) [m] for a flat or plane bed through (0, 0, −`depth`).
    #[inline]
    pub fn at(&self, depth: Real, x: Real, y: Real) -> BedPoint {
        match self {
            Bathymetry::Flat => BedPoint {
                z: -depth,
                normal: Vec3::z(),
            },
            Bathymetry::Plane { gradient: [gx, gy] } => {
                BedPoint::with_gradient(-depth + gx * x + gy * y, *gx, *gy)
            }
            Bathymetry::Grid(g) => {
                let (z, gx, gy) = g.height(x, y);
                BedPoint::with_gradient(z, gx, gy)
            }
        }
    }

    /// The highest point of the bed [m] (+∞ for a sloping plane): nothing above it touches.
    pub fn top(&self, depth: Real) -> Real {
        match self {
            Bathymetry::Flat => -depth,
            Bathymetry::Plane { gradient } if gradient == &[0.0, 0.0] => -depth,
            Bathymetry::Plane { .. } => Real::INFINITY,
            Bathymetry::Grid(g) => g.highest(),
        }
    }
}

/// Seabed contact parameters: a vertical bilinear spring–damper and sliding friction.
#[derive(Clone, Debug, PartialEq)]
pub struct Seabed {
    /// Ground stiffness K_g per unit contact area [Pa/m = N/m³] (DG paper eq. 15).
    pub stiffness: Real,
    /// Damping of the vertical contact.
    pub damping: ContactDamping,
    /// Dynamic friction coefficient μ [-] (DG paper eq. 16).
    pub friction_coefficient: Real,
    /// Sliding speed v_μ [m/s] over which friction builds up (DG paper eq. 16).
    pub friction_velocity: Real,
    /// How friction grows with the sliding speed.
    pub friction_law: FrictionLaw,
}

/// How seabed friction grows with the sliding speed |v| up to its limit μ·N.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FrictionLaw {
    /// μ N tanh(π|v|/v_μ), with N the cable's net weight per length (DG paper eq. 16).
    Tanh,
    /// MoorDyn's law (`Line::getStateDeriv`, v2.7): a node's friction force is μ·c·|v|, or
    /// μ·|F_z| with F_z the node's vertical contact force once μ·c·|v| exceeds
    /// `static_scale`·μ·|F_z|. `damping` c [N·s/m] is per node (MoorDyn's `FricDamp`), so
    /// the law depends on the mesh as MoorDyn's does.
    Viscous {
        /// c [N·s/m] per node (`FricDamp`).
        damping: Real,
        /// Ratio of static to dynamic friction (`StatDynFricScale`).
        static_scale: Real,
    },
}

impl Default for Seabed {
    /// 3 MPa/m, ζ = 1, no friction, v_μ = 0.01 m/s: a firm, frictionless bed (MoorDyn's kBot
    /// default order of magnitude) that a user tunes to the soil.
    fn default() -> Self {
        Self {
            stiffness: 3.0e6,
            damping: ContactDamping::Ratio(1.0),
            friction_coefficient: 0.0,
            friction_velocity: 0.01,
            friction_law: FrictionLaw::Tanh,
        }
    }
}

/// Damping of the vertical seabed contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ContactDamping {
    /// Damping ratio ζ [-] of the contact spring with the cable's own mass: c = 2ζ√(K_g d γ0)
    /// per unit length (DG paper eq. 15); 1 is critical.
    Ratio(Real),
    /// Damping per unit contact area c_A [Pa·s/m]: c = c_A·d per unit length (MoorDyn's
    /// `cBot`).
    PerArea(Real),
}

impl Seabed {
    /// Vertical contact damping per unit length [N·s/m²] of a cable of `diameter` [m] and
    /// `mass_per_length` [kg/m].
    #[inline]
    pub fn damping_per_length(&self, diameter: Real, mass_per_length: Real) -> Real {
        match self.damping {
            ContactDamping::Ratio(zeta) => {
                2.0 * zeta * (self.stiffness * diameter * mass_per_length).sqrt()
            }
            ContactDamping::PerArea(c) => c * diameter,
        }
    }

    /// Vertical contact damping [N·s/m] of a body resting on `area` [m²] with spring
    /// stiffness `stiffness` [N/m] and mass `mass` [kg].
    pub fn damping_of_area(&self, area: Real, stiffness: Real, mass: Real) -> Real {
        match self.damping {
            ContactDamping::Ratio(zeta) => 2.0 * zeta * (stiffness * mass).sqrt(),
            ContactDamping::PerArea(c) => c * area,
        }
    }

    /// Magnitude of the friction force [N, or N/m per length] at sliding `speed` [m/s] under
    /// the normal load `normal` [N or N/m], for a node (or body) carrying `node_length` [m]
    /// of cable (1 for a body: the result is then a force).
    #[inline]
    pub fn friction(&self, speed: Real, normal: Real, node_length: Real) -> Real {
        let mu = self.friction_coefficient;
        match self.friction_law {
            FrictionLaw::Tanh => {
                mu * normal * (std::f64::consts::PI * speed / self.friction_velocity).tanh()
            }
            FrictionLaw::Viscous {
                damping,
                static_scale,
            } => {
                let limit = mu * normal;
                let viscous = mu * damping * speed / node_length;
                if viscous > static_scale * limit {
                    limit
                } else {
                    viscous
                }
            }
        }
    }

    /// Largest slope d(friction)/d(speed) [N·s/m per m of cable] at rest, for the stable step.
    pub fn friction_slope(&self, normal: Real, node_length: Real) -> Real {
        let mu = self.friction_coefficient;
        match self.friction_law {
            FrictionLaw::Tanh => mu * normal * std::f64::consts::PI / self.friction_velocity,
            FrictionLaw::Viscous { damping, .. } => mu * damping / node_length,
        }
    }

    /// Contact force per unit unstretched length [N/m] on a cable point at `position` [m]
    /// moving with `velocity` [m/s], over the bed `bed` (DG paper eqs. 15–16 along the bed's
    /// normal n).
    ///
    /// Normal (eq. 15): √(1+ε) (K_g d δ − c v·n) n with δ = (z_bed − z) n_z > 0 the depth
    /// below the bed's tangent plane and c from [`Seabed::damping_per_length`]
    /// (2ζ √(K_g d γ0), or c_A·d).
    /// Tangential (eq. 16): −√(1+ε) μ tanh(π|v_t|/v_μ) v̂_t · max(−w·n, 0), with v_t = v −
    /// (v·n) n the sliding velocity in the bed's tangent plane and w·n = w_z n_z the net weight
    /// per length pressing on the bed (w_z negative when the cable sinks), so friction opposes
    /// sliding; or MoorDyn's law on the normal contact force ([`FrictionLaw`]). On a flat bed
    /// n = ẑ and these are the paper's vertical and horizontal forces. `node_length` [m] is the
    /// length of cable the node carries (half of each adjacent element).
    #[inline]
    #[allow(clippy::too_many_arguments)]
    pub fn contact_force(
        &self,
        bed: &BedPoint,
        position: &Vec3,
        velocity: &Vec3,
        diameter: Real,
        mass_per_length: Real,
        stretch: Real,
        net_weight_z: Real,
        node_length: Real,
    ) -> Vec3 {
        self.contact_force_with(
            bed,
            position,
            velocity,
            diameter,
            stretch.max(0.0).sqrt(),
            self.damping_per_length(diameter, mass_per_length),
            net_weight_z,
            node_length,
        )
    }

    /// [`Seabed::contact_force`] with √(1+ε) `root` and the damping per unit length
    /// `damping` [N·s/m²] ([`Seabed::damping_per_length`]) given: a line's element loop
    /// has the first already and computes the second once per line type.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    pub fn contact_force_with(
        &self,
        bed: &BedPoint,
        position: &Vec3,
        velocity: &Vec3,
        diameter: Real,
        root: Real,
        damping: Real,
        net_weight_z: Real,
        node_length: Real,
    ) -> Vec3 {
        let penetration = bed.penetration(position);
        if penetration <= 0.0 {
            return Vec3::zeros();
        }
        let n = bed.normal;
        let kd = self.stiffness * diameter;
        let vn = velocity.dot(&n);
        let fn_ = root * (kd * penetration - damping * vn);
        let mut f = n * fn_;
        let normal = match self.friction_law {
            FrictionLaw::Tanh => -net_weight_z * n.z,
            FrictionLaw::Viscous { .. } => fn_.abs() / root.max(Real::MIN_POSITIVE),
        };
        if self.friction_coefficient > 0.0 && normal > 0.0 {
            let vt = velocity - n * vn;
            let speed = vt.norm();
            if speed > 0.0 {
                f -= vt * (root * self.friction(speed, normal, node_length) / speed);
            }
        }
        f
    }
}
