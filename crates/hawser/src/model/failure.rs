//! Line failure: a line end that releases from its attachment during a run (a mooring line
//! parting at its fairlead, a shackle breaking at an anchor, a tether cut on purpose), as
//! MoorDyn's FAILURE section and OrcaFlex's line "release" do.
//!
//! **What happens at a release.** The end stops being owned by its attachment and is owned
//! instead by a free point of its own: a massless, dimensionless point (no mass, volume, drag
//! or force of its own) that takes the attachment's position and velocity at the release and
//! from then on moves with the line end. By the rule that an attachment gathers its line ends'
//! force and mass (MoorDyn's), that point's motion is the line's end node's: (m_end) a =
//! F_end, with the end node's mass, added mass, weight, buoyancy and drag as the line's
//! formulation lumps them at its end. The attachment loses the line's end force from that
//! instant (its reaction from that line is zero), and whatever the attachment holds (a free
//! point, a free body) moves on under the lines that remain. MoorDyn 2 does the same: its
//! failure detaches the lines from the point or rod end and attaches them to a new free point
//! at the same place and velocity (docs/moordyn.md).
//!
//! **When.** At the first step end where the run's time reaches [`LineFailure::time`], or
//! where the end's tension (the magnitude of the force the line exerts on its attachment,
//! the `L.end_b.tension` channel) reaches [`LineFailure::tension`], whichever comes first; or
//! when a host calls [`crate::Session::release`]. The check is made between steps, so a
//! release lands on a step end: within one step of the given time, and at the first step end
//! whose tension is at or above the threshold (the step before was below it).

use super::{End, Formulation, LineEnd, Model};
use crate::math::Real;

/// A line end that may release from its attachment during a run (module doc), with any
/// further line ends at the same attachment that release with it and stay joined.
///
/// **Joined ends** ([`LineFailure::joined`]): MoorDyn's FAILURE row that lists several lines
/// detaches all their ends from the point and attaches them to one new free point at the
/// point's place and velocity (MoorDyn2.cpp `detachLines`), so they stay joined to each
/// other. Here every end of a failure moves onto the failure's one reserved free point; its
/// equation gathers all their end masses and forces, so the lines move on as one chain
/// through a massless joint.
#[derive(Clone, Debug, PartialEq)]
pub struct LineFailure {
    /// Index into [`Model::lines`].
    pub line: usize,
    /// Which end releases.
    pub end: End,
    /// Further line ends (line index, end) that release at the same instant onto the same
    /// free point: all on the attachment of (`line`, `end`). Empty for a single end.
    pub joined: Vec<(usize, End)>,
    /// Release at a time [s] (the first step end at or after it); `None`: no time trigger.
    pub time: Option<Real>,
    /// Release when the tension at the end reaches this value [N] (a breaking load);
    /// `None`: no tension trigger. With joined ends the tension is the magnitude of the
    /// vector sum of all the failure's end forces on the attachment, |Σ F_end| [N]: the
    /// force the attachment loses at the release. With neither trigger the end releases only on the host's
    /// call ([`crate::Session::release`]).
    pub tension: Option<Real>,
}

impl LineFailure {
    /// Every end of the failure, (line index, end): the first, then the joined ones.
    pub fn ends(&self) -> impl Iterator<Item = (usize, End)> + '_ {
        std::iter::once((self.line, self.end)).chain(self.joined.iter().copied())
    }

    /// The attachment of the failing end (the point the end releases from).
    pub fn attachment(&self, model: &Model) -> usize {
        let LineEnd::Point(p) = model.lines[self.line].ends()[self.end.index()];
        p
    }

    /// Checks the failure `k` of `model`: (what, why) when it is wrong.
    pub(super) fn check(&self, model: &Model, k: usize) -> Result<(), (String, String)> {
        let Some(line) = model.lines.get(self.line) else {
            return Err((
                format!("failure #{k}"),
                "refers to a line that does not exist".into(),
            ));
        };
        let what = |key: &str| {
            format!(
                "failure #{k} (line {}, end {}){key}",
                line.name,
                self.end.name()
            )
        };
        if line.formulation == Formulation::Dg {
            return Err((
                what(""),
                "is on a `dg` line, whose end conditions are built into its flux (DG paper \
                 Table 1): use `formulation = \"fe\"` or `\"hermite\"` for a line that fails"
                    .into(),
            ));
        }
        if line.clamp[self.end.index()].is_some() {
            return Err((
                what(""),
                "is a clamped end: only a pinned end can release (remove its clamp)".into(),
            ));
        }
        if let Some(t) = self.time
            && !(t >= 0.0 && t.is_finite())
        {
            return Err((what(".time"), format!("is {t} s; must be ≥ 0 s and finite")));
        }
        if let Some(t) = self.tension
            && !(t > 0.0 && t.is_finite())
        {
            return Err((
                what(".tension"),
                format!("is {t} N; must be > 0 N and finite"),
            ));
        }
        let attachment = self.attachment(model);
        for (j, &(li, end)) in self.joined.iter().enumerate() {
            let joined = |why: String| Err((what(&format!(".joined[{j}]")), why));
            let Some(other) = model.lines.get(li) else {
                return joined("refers to a line that does not exist".into());
            };
            let LineEnd::Point(p) = other.ends()[end.index()];
            if p != attachment {
                return joined(format!(
                    "is end {} of line {}, at point {}, not at the failure's point {}: the \
                     ends that release together must share their attachment",
                    end.name(),
                    other.name,
                    model.points[p].name,
                    model.points[attachment].name
                ));
            }
            if other.formulation == Formulation::Dg {
                return joined(format!(
                    "is on line {}, a `dg` line, whose end conditions are built into its flux",
                    other.name
                ));
            }
            if other.clamp[end.index()].is_some() {
                return joined(format!(
                    "is end {} of line {}, a clamped end: only a pinned end can release",
                    end.name(),
                    other.name
                ));
            }
        }
        let mine: Vec<(usize, End)> = self.ends().collect();
        for (i, e) in mine.iter().enumerate() {
            if mine[..i].contains(e)
                || model.failures[..k]
                    .iter()
                    .any(|o| o.ends().any(|x| x == *e))
            {
                return Err((
                    what(""),
                    format!(
                        "names end {} of line {}, which already has a failure (one failure \
                         per line end)",
                        e.1.name(),
                        model.lines[e.0].name
                    ),
                ));
            }
        }
        Ok(())
    }
}
