//! Line strength: the largest effective tension along each section of a line against its
//! line type's minimum breaking load (MBL) and permissible tension MBL / SF, and where along
//! the line it occurs. The elastic-link paper lists the permissible tension at each point of
//! a line among a model's inputs and the maximum loads for a strength check among its
//! outputs; this is that check, on node tensions ([`crate::session::LineSample::tension`]).

use crate::formulation::Mesh;
use crate::math::Real;
use crate::system::{System, Workspace};

/// The strength check of one section of a line.
#[derive(Clone, Debug, PartialEq)]
pub struct SectionStrength {
    /// Section index along the line (0 at end A).
    pub section: usize,
    /// Name of the section's line type.
    pub line_type: String,
    /// Unstretched arc length of the section's first node from end A [m].
    pub start: Real,
    /// Unstretched arc length of its last node [m].
    pub end: Real,
    /// Minimum breaking load of the line type [N], if given.
    pub minimum_breaking_load: Option<Real>,
    /// Design safety factor of the line type [-], if given.
    pub design_safety_factor: Option<Real>,
    /// Largest effective tension at the section's nodes [N] (a node on the boundary of two
    /// sections counts for both).
    pub max_tension: Real,
    /// Unstretched arc length of the node carrying it [m].
    pub at: Real,
    /// That node's index (0 at end A).
    pub node: usize,
}

impl SectionStrength {
    /// Utilisation T_max / MBL [-]; `None` without an MBL.
    pub fn utilisation(&self) -> Option<Real> {
        self.minimum_breaking_load.map(|mbl| self.max_tension / mbl)
    }

    /// Permissible tension MBL / SF [N] (MBL without a safety factor).
    pub fn permissible_tension(&self) -> Option<Real> {
        self.minimum_breaking_load
            .map(|mbl| mbl / self.design_safety_factor.unwrap_or(1.0))
    }

    /// Design utilisation T_max / (MBL / SF) [-]; `None` without an MBL or a safety factor.
    pub fn design_utilisation(&self) -> Option<Real> {
        self.design_safety_factor?;
        self.permissible_tension().map(|p| self.max_tension / p)
    }

    /// The utilisation that decides: against the permissible tension when a safety factor
    /// is given, against the MBL otherwise.
    pub fn governing_utilisation(&self) -> Option<Real> {
        self.design_utilisation().or(self.utilisation())
    }
}

/// The strength check of every section of a line from its node tensions `tension` [N] at
/// unstretched arc lengths `arc_length` [m] (nodes 0 … N of `mesh`, whose elements give the
/// sections).
pub fn section_strength(
    mesh: &Mesh,
    arc_length: &[Real],
    tension: &[Real],
) -> Vec<SectionStrength> {
    let n = mesh.elements();
    assert!(arc_length.len() == n + 1 && tension.len() == n + 1);
    mesh.sections
        .iter()
        .enumerate()
        .filter_map(|(s, props)| {
            // Nodes i touching an element of section s: elements i − 1 and i.
            let nodes = (0..=n).filter(|&i| {
                (i > 0 && mesh.element_section[i - 1] == s)
                    || (i < n && mesh.element_section[i] == s)
            });
            let (first, last, worst) =
                nodes.fold(None, |acc: Option<(usize, usize, usize)>, i| {
                    Some(match acc {
                        None => (i, i, i),
                        Some((f, _, w)) => (f, i, if tension[i] > tension[w] { i } else { w }),
                    })
                })?;
            let t = &props.line_type;
            Some(SectionStrength {
                section: s,
                line_type: t.name.clone(),
                start: arc_length[first],
                end: arc_length[last],
                minimum_breaking_load: t.minimum_breaking_load,
                design_safety_factor: t.design_safety_factor,
                max_tension: tension[worst],
                at: arc_length[worst],
                node: worst,
            })
        })
        .collect()
}

/// The section with the largest governing utilisation
/// ([`SectionStrength::governing_utilisation`]); `None` when no section has an MBL.
pub fn worst_section(sections: &[SectionStrength]) -> Option<&SectionStrength> {
    sections
        .iter()
        .filter(|s| s.governing_utilisation().is_some())
        .max_by(|a, b| {
            a.governing_utilisation()
                .partial_cmp(&b.governing_utilisation())
                .unwrap_or(std::cmp::Ordering::Equal)
        })
}

/// The strength check of line `line` in the state evaluated in `ws` (a static equilibrium,
/// or one sample of a run): its node tensions along its current mesh.
pub fn line_strength(system: &System, ws: &Workspace, line: usize) -> Vec<SectionStrength> {
    let mesh = system.line_mesh(ws, line);
    let nodes = system.lines[line].nodes();
    // `+ 0.0` turns the −0 the mesh may give at end A into 0, as `LineSample` does.
    let arc: Vec<Real> = (0..nodes).map(|i| mesh.arc_length(i) + 0.0).collect();
    let tension: Vec<Real> = (0..nodes)
        .map(|i| system.node_tension(ws, line, i))
        .collect();
    section_strength(mesh, &arc, &tension)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::verification::line_type;

    /// Two sections: 3 elements of a strong type, 2 of a weak one with a safety factor. The
    /// boundary node 3 counts for both; each section's worst node and its utilisations.
    #[test]
    fn sections_share_their_boundary_node() {
        let mut strong = line_type(0.1, 50.0, 1e9);
        strong.name = "chain".into();
        strong.minimum_breaking_load = Some(1000.0);
        let mut weak = line_type(0.05, 10.0, 1e8);
        weak.name = "rope".into();
        weak.minimum_breaking_load = Some(400.0);
        weak.design_safety_factor = Some(2.0);
        let mesh = Mesh::new(&[(strong, 30.0, 3), (weak, 20.0, 2)]);
        let arc = [0.0, 10.0, 20.0, 30.0, 40.0, 50.0];
        let tension = [500.0, 450.0, 400.0, 350.0, 300.0, 250.0];
        let s = section_strength(&mesh, &arc, &tension);
        assert_eq!(s.len(), 2);
        assert_eq!(
            (s[0].start, s[0].end, s[0].at, s[0].node),
            (0.0, 30.0, 0.0, 0)
        );
        assert_eq!(s[0].utilisation(), Some(0.5));
        assert_eq!(s[0].design_utilisation(), None);
        assert_eq!(
            (s[1].start, s[1].end, s[1].at, s[1].max_tension),
            (30.0, 50.0, 30.0, 350.0)
        );
        assert_eq!(s[1].utilisation(), Some(350.0 / 400.0));
        assert_eq!(s[1].permissible_tension(), Some(200.0));
        assert_eq!(s[1].design_utilisation(), Some(1.75));
        assert_eq!(worst_section(&s).map(|w| w.section), Some(1));
    }
}
