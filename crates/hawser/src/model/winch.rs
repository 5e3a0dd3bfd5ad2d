//! Winches: a line whose unstretched length changes on a schedule (docs/winches.md).
//!
//! The schedule is a list of stages, each a duration and a payout rate, as a winch is driven
//! stage by stage in OrcaFlex ("specified payout rate"): a positive rate pays out (the line
//! lengthens), a negative one hauls in. The line's own length is its length at t = 0, L(0);
//! before t = 0 (in the statics) and after the last stage the winch holds. At the start of
//! every stage, and at the end of the last, the rate goes from the previous stage's rate
//! (0 before the first) to the new one over `ramp_time` T_r with a half-cosine,
//!
//!   L̇(τ) = r_p + (r − r_p) h(τ),  h(τ) = ½ (1 − cos(π τ / T_r)),  0 ≤ τ ≤ T_r,
//!
//! τ the time since the stage started, so L̈ = (r − r_p) (π / 2T_r) sin(π τ / T_r) is
//! continuous and starts and ends at 0. A stage of duration D then pays out
//! r D − (r − r_p) T_r / 2 (the ramp loses half of the change in rate over T_r).

use crate::math::Real;

/// Which end of its line a winch is at. The winch tension is the tension at that end.
pub type WinchEnd = super::End;

/// One stage of a winch schedule.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WinchStage {
    /// Duration [s] (> 0).
    pub duration: Real,
    /// Payout rate [m/s] of unstretched line: > 0 pays out, < 0 hauls in.
    pub payout_rate: Real,
}

/// A winch on a line: the schedule of its unstretched length L(t) (see the module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct Winch {
    /// The line end the winch is at.
    pub end: WinchEnd,
    /// Stages from t = 0, one after the other.
    pub stages: Vec<WinchStage>,
    /// Time T_r [s] over which the rate changes at the start of each stage (0: at once);
    /// no longer than any stage that changes the rate.
    pub ramp_time: Real,
    /// Shortest unstretched length the schedule may reach [m] (≥ 0; the length must also
    /// stay > 0).
    pub minimum_length: Real,
}

/// L(t) of a winch: payout since t = 0 and its rates.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct WinchState {
    /// Unstretched line paid out since t = 0, L(t) − L(0) [m].
    pub payout: Real,
    /// Payout rate L̇ [m/s].
    pub rate: Real,
    /// Payout acceleration L̈ [m/s²].
    pub acceleration: Real,
}

impl Winch {
    /// A winch at `end` paying out at `rate` [m/s] from `start` for `duration` [s] (holding
    /// before and after), with ramps of `ramp_time` [s].
    pub fn constant_rate(
        end: WinchEnd,
        start: Real,
        duration: Real,
        rate: Real,
        ramp_time: Real,
    ) -> Self {
        let mut stages = Vec::new();
        if start > 0.0 {
            stages.push(WinchStage {
                duration: start,
                payout_rate: 0.0,
            });
        }
        stages.push(WinchStage {
            duration,
            payout_rate: rate,
        });
        Self {
            end,
            stages,
            ramp_time,
            minimum_length: 0.0,
        }
    }

    /// Whether the winch is at end B.
    pub fn at_end_b(&self) -> bool {
        self.end == WinchEnd::B
    }

    /// Payout, rate and acceleration at time `t` [s] (closed form; no allocation).
    pub fn state(&self, t: Real) -> WinchState {
        let mut start = 0.0;
        let mut payout = 0.0;
        let mut previous = 0.0;
        if t <= 0.0 {
            return WinchState::default();
        }
        // The stages, then a final hold (rate 0, no end).
        let last = self.stages.len();
        for k in 0..=last {
            let (duration, rate) = match self.stages.get(k) {
                Some(s) => (s.duration, s.payout_rate),
                None => (Real::INFINITY, 0.0),
            };
            let tau = t - start;
            if tau < duration {
                let (p, r, a) = self.within(previous, rate, tau);
                return WinchState {
                    payout: payout + p,
                    rate: r,
                    acceleration: a,
                };
            }
            payout += self.within(previous, rate, duration).0;
            start += duration;
            previous = rate;
        }
        unreachable!("the final hold has no end")
    }

    /// Payout [m], rate [m/s] and acceleration [m/s²] at τ [s] into a stage of rate `rate`
    /// after a stage of rate `previous` (τ no more than the stage's duration).
    fn within(&self, previous: Real, rate: Real, tau: Real) -> (Real, Real, Real) {
        let tr = self.ramp_time;
        let change = rate - previous;
        if tr > 0.0 && tau < tr {
            let w = std::f64::consts::PI / tr;
            let (s, c) = (w * tau).sin_cos();
            let payout = previous * tau + change * (0.5 * tau - 0.5 * s / w);
            (
                payout,
                previous + change * 0.5 * (1.0 - c),
                change * 0.5 * w * s,
            )
        } else {
            let ramp = tr.min(tau.max(0.0));
            // Through the ramp (previous·T_r + change·T_r/2), then at the stage's rate.
            let payout = previous * ramp + change * 0.5 * ramp + rate * (tau - ramp);
            (payout, rate, 0.0)
        }
    }

    /// Time [s] when the schedule ends (the last stage's end plus its final ramp).
    pub fn end_time(&self) -> Real {
        self.stages.iter().map(|s| s.duration).sum::<Real>() + self.ramp_time
    }

    /// The extremes of the payout over all time: (smallest payout [m], time [s]) and
    /// (largest payout [m], time [s]). L(t) is monotone where the rate keeps its sign, so
    /// the extremes are at the stage boundaries, the ends of the ramps, or where a ramp's
    /// rate crosses zero (h(τ*) = −r_p / (r − r_p)).
    pub fn payout_range(&self) -> ((Real, Real), (Real, Real)) {
        let mut lo = (0.0, 0.0);
        let mut hi = (0.0, 0.0);
        let mut consider = |t: Real| {
            let p = self.state(t).payout;
            if p < lo.0 {
                lo = (p, t);
            }
            if p > hi.0 {
                hi = (p, t);
            }
        };
        let mut start = 0.0;
        let mut previous = 0.0;
        let tr = self.ramp_time;
        for k in 0..=self.stages.len() {
            let (duration, rate) = match self.stages.get(k) {
                Some(s) => (s.duration, s.payout_rate),
                None => (tr, 0.0),
            };
            consider(start);
            consider(start + tr.min(duration));
            consider(start + duration);
            let change = rate - previous;
            if tr > 0.0 && change != 0.0 {
                let h = -previous / change;
                if h > 0.0 && h < 1.0 {
                    consider(start + tr / std::f64::consts::PI * (1.0 - 2.0 * h).acos());
                }
            }
            start += duration;
            previous = rate;
        }
        (lo, hi)
    }

    /// The first stage that changes the rate and is shorter than the ramp (whose rate would
    /// jump at its end), if any. A stage at the rate of the one before needs no ramp.
    pub fn short_ramped_stage(&self) -> Option<(usize, &WinchStage)> {
        let mut previous = 0.0;
        for (k, s) in self.stages.iter().enumerate() {
            if s.duration < self.ramp_time && s.payout_rate != previous {
                return Some((k, s));
            }
            previous = s.payout_rate;
        }
        None
    }

    /// Checks the schedule for a line of unstretched length `length` [m] at t = 0: finite
    /// positive durations, finite rates, a ramp no longer than any stage, and L(t) above the
    /// minimum length (and above 0) at all times. The error says why, with the numbers.
    pub fn check(&self, length: Real) -> Result<(), String> {
        if self.stages.is_empty() {
            return Err("has no stages: give at least one (duration, payout_rate)".into());
        }
        for (k, s) in self.stages.iter().enumerate() {
            if !(s.duration > 0.0 && s.duration.is_finite()) {
                return Err(format!(
                    "stage {k}: duration {} s must be finite and > 0",
                    s.duration
                ));
            }
            if !s.payout_rate.is_finite() {
                return Err(format!("stage {k}: payout_rate must be finite (m/s)"));
            }
        }
        if !(self.ramp_time >= 0.0 && self.ramp_time.is_finite()) {
            return Err(format!("ramp_time {} s must be ≥ 0", self.ramp_time));
        }
        if let Some((k, s)) = self.short_ramped_stage() {
            return Err(format!(
                "ramp_time {} s is longer than stage {k} ({} s), which changes the rate: each \
                 ramp must end within its stage",
                self.ramp_time, s.duration
            ));
        }
        if !(self.minimum_length >= 0.0 && self.minimum_length.is_finite()) {
            return Err(format!(
                "minimum_length {} m must be ≥ 0",
                self.minimum_length
            ));
        }
        let ((low, at), _) = self.payout_range();
        let shortest = length + low;
        if !(shortest > self.minimum_length) || !(shortest > 0.0) {
            return Err(format!(
                "hauls the line in to {shortest:.6} m at t = {at:.3} s (from {length} m), \
                 not above the minimum length {} m",
                self.minimum_length
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn schedule() -> Winch {
        Winch {
            end: WinchEnd::A,
            stages: vec![
                WinchStage {
                    duration: 4.0,
                    payout_rate: 0.5,
                },
                WinchStage {
                    duration: 6.0,
                    payout_rate: -0.8,
                },
            ],
            ramp_time: 2.0,
            minimum_length: 0.0,
        }
    }

    /// The payout is the integral of the rate and the rate the integral of the acceleration
    /// (Simpson's rule on 2000 intervals per piece between ramp ends, where the jerk jumps:
    /// error ~1e-13 for these smooth pieces),
    /// and stage payouts follow r D − (r − r_p) T_r / 2.
    #[test]
    fn payout_rate_and_acceleration_are_consistent() {
        let w = schedule();
        let simpson = |f: &dyn Fn(Real) -> Real, a: Real, b: Real| {
            let n = 2000;
            let h = (b - a) / n as Real;
            (0..=n)
                .map(|i| {
                    let c = if i == 0 || i == n {
                        1.0
                    } else if i % 2 == 1 {
                        4.0
                    } else {
                        2.0
                    };
                    c * f(a + i as Real * h)
                })
                .sum::<Real>()
                * h
                / 3.0
        };
        for (a, b) in [
            (0.0, 2.0),
            (2.0, 4.0),
            (4.0, 6.0),
            (6.0, 10.0),
            (10.0, 12.0),
            (12.0, 13.0),
        ] {
            let dp = w.state(b).payout - w.state(a).payout;
            let int = simpson(&|t| w.state(t).rate, a, b);
            assert!((dp - int).abs() < 1e-11, "{a}..{b}: {dp} vs {int}");
            let dr = w.state(b).rate - w.state(a).rate;
            let int = simpson(&|t| w.state(t).acceleration, a, b);
            assert!((dr - int).abs() < 1e-11, "{a}..{b}: {dr} vs {int}");
        }
        // r D − (r − r_p) T_r / 2 per stage, then the final ramp to rest.
        let s0 = 0.5 * 4.0 - 0.5 * 2.0 / 2.0;
        let s1 = -0.8 * 6.0 - (-0.8 - 0.5) * 2.0 / 2.0;
        let tail = -0.8 * 2.0 / 2.0;
        assert!((w.state(4.0).payout - s0).abs() < 1e-14);
        assert!((w.state(10.0).payout - s0 - s1).abs() < 1e-13);
        assert!((w.state(100.0).payout - s0 - s1 - tail).abs() < 1e-13);
        assert_eq!(w.state(100.0).rate, 0.0);
        assert_eq!(w.state(-1.0), WinchState::default());
    }

    /// The extremes found from the boundaries and zero crossings match a dense scan (step h =
    /// 1e-4 s: at a smooth extreme the scan misses by at most ½ max|L̈| h² ≈ 5e-9 m).
    #[test]
    fn payout_range_matches_a_scan() {
        let w = schedule();
        let ((lo, _), (hi, at_hi)) = w.payout_range();
        let (mut slo, mut shi) = (0.0 as Real, 0.0 as Real);
        for i in 0..=200_000 {
            let p = w.state(i as Real * 1e-4).payout;
            slo = slo.min(p);
            shi = shi.max(p);
        }
        assert!(
            (lo - slo).abs() < 1e-8 && (hi - shi).abs() < 1e-8 && lo <= slo && hi >= shi,
            "{lo} {slo} {hi} {shi}"
        );
        // The largest payout is where the second stage's ramp crosses zero rate.
        assert!(at_hi > 4.0 && at_hi < 6.0);
        assert!(w.check(10.0).is_ok());
        assert!(w.check(1.0).unwrap_err().contains("hauls the line in"));
    }
}
