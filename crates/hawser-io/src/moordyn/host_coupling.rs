//! A deck loaded for a host program: MoorDyn's `Coupled`/`Vessel` points are the host's to
//! move, so a library that couples hawser into a host (the C ABI, the MoorDyn-compatible
//! library, the Python session) makes them [`PointKind::Coupled`] instead of the prescribed
//! points a standalone run gives them.

use crate::scenario::{InputFormat, LoadedScenario};
use hawser::model::{Motion, PointKind};

/// Makes the coupled points of a loaded MoorDyn deck [`PointKind::Coupled`], at their deck
/// positions, and returns their indices in model order. A deck's only prescribed points are
/// its `Coupled`/`Vessel` points held at their deck positions ([`Motion::Fixed`]); a deck
/// driven by a vessel-motion file, and a TOML scenario (which says `type = "coupled"` itself),
/// are left as they are.
pub fn couple_deck_points(loaded: &mut LoadedScenario) -> Vec<usize> {
    if loaded.format != InputFormat::MoorDyn {
        return Vec::new();
    }
    let mut coupled = Vec::new();
    for (i, p) in loaded.model.points.iter_mut().enumerate() {
        if let PointKind::Prescribed(Motion::Fixed { position }) = p.kind {
            p.position = position;
            p.kind = PointKind::Coupled;
            coupled.push(i);
        }
    }
    coupled
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    #[test]
    fn oc3_fairleads_become_coupled_at_their_deck_positions() {
        let path =
            Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/moordyn/oc3_lines.txt");
        let (mut loaded, _) =
            crate::input::load_input(&path, &Default::default()).expect("oc3 deck");
        let coupled = couple_deck_points(&mut loaded);
        let names: Vec<&str> = coupled
            .iter()
            .map(|&i| loaded.model.points[i].name.as_str())
            .collect();
        assert_eq!(names, ["P4", "P5", "P6"]);
        assert_eq!(loaded.model.points[coupled[0]].position.x, 5.2);
        assert_eq!(loaded.model.points[coupled[2]].position.y, -4.5);
        assert!(
            loaded
                .model
                .points
                .iter()
                .all(|p| !matches!(p.kind, PointKind::Prescribed(_)))
        );
        // Done once, a second call finds nothing left to couple.
        assert!(couple_deck_points(&mut loaded).is_empty());
    }
}
