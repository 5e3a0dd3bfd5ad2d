//! Shared builders of the `dg` tests.
#![allow(dead_code)]

use hawser::formulation::dg::*;
use hawser::math::{Real, Vec3};
use hawser::model::LineType;
use hawser::physics::environment::Environment;
use hawser::physics::hydrodynamics::DragModel;
use hawser::physics::material::{AxialDamping, AxialStiffness};

/// A line type without fluid loading: γ0 [kg/m], EA [N], EI [N·m²], carrying compression.
pub fn beam_type(gamma: Real, ea: Real, ei: Real) -> LineType {
    LineType {
        name: "beam".into(),
        diameter: 0.01,
        mass_per_length: gamma,
        axial_stiffness: AxialStiffness::Linear(ea),
        axial_damping: AxialDamping::Coefficient(0.0),
        compression: true,
        bending_stiffness: ei,
        bending_damping: 0.0,
        drag: DragModel::Morison {
            normal: 0.0,
            tangential: 0.0,
        },
        normal_added_mass: 0.0,
        tangential_added_mass: 0.0,
    }
}

/// No gravity, no fluid loading at z ≥ 0.
pub fn vacuum() -> Environment {
    Environment {
        gravity: 0.0,
        ..Default::default()
    }
}

/// A single-section line.
pub fn single(
    t: LineType,
    length: Real,
    elements: usize,
    order: usize,
    ends: [EndCondition; 2],
) -> DgLine {
    DgLine::new(
        &[DgSectionSpec {
            line_type: t,
            length,
            elements,
            order,
        }],
        ends,
    )
}

/// Ends at rest at `a` and `b`, clamped (when clamped) along +x.
pub fn fixed_ends(a: Vec3, b: Vec3) -> [EndState; 2] {
    [EndState::fixed(a, Vec3::x()), EndState::fixed(b, Vec3::x())]
}

/// Time at which `f` first crosses `level` going up, linearly interpolated between samples.
pub fn crossing(times: &[Real], values: &[Real], level: Real) -> Option<Real> {
    for k in 1..values.len() {
        if values[k - 1] < level && values[k] >= level {
            let w = (level - values[k - 1]) / (values[k] - values[k - 1]);
            return Some(times[k - 1] + w * (times[k] - times[k - 1]));
        }
    }
    None
}
