//! Results analysis: output channels, running statistics, slack intervals and snap events;
//! natural modes about the static state ([`modes`]) and the resonance report ([`resonance`]);
//! the independent steady-towing reference ([`steady_cable`]); design statistics
//! ([`statistics`]), range graphs of tension along each line ([`range_graph`]) and the
//! strength check against the breaking load ([`strength`]).

pub mod channels;
pub mod modes;
pub mod obstacles;
pub mod range_graph;
pub mod resonance;
pub mod statistics;
pub mod steady_cable;
pub mod strength;

use crate::math::Real;

pub use channels::{
    BODY_LINE_LOAD, BODY_MOTION, BODY_VELOCITY, Channel, Object, OutputChannel, relative_position,
    stretched_length, unstretched_length,
};

/// Running statistics of one channel (Welford).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RunningStats {
    /// Samples.
    pub count: u64,
    /// Minimum.
    pub min: Real,
    /// Maximum.
    pub max: Real,
    mean: Real,
    m2: Real,
}

impl Default for RunningStats {
    fn default() -> Self {
        Self {
            count: 0,
            min: Real::INFINITY,
            max: Real::NEG_INFINITY,
            mean: 0.0,
            m2: 0.0,
        }
    }
}

impl RunningStats {
    /// Adds a sample.
    pub fn push(&mut self, x: Real) {
        self.count += 1;
        self.min = self.min.min(x);
        self.max = self.max.max(x);
        let d = x - self.mean;
        self.mean += d / self.count as Real;
        self.m2 += d * (x - self.mean);
    }
    /// Mean.
    pub fn mean(&self) -> Real {
        self.mean
    }
    /// Population standard deviation.
    pub fn std(&self) -> Real {
        if self.count > 0 {
            (self.m2 / self.count as Real).sqrt()
        } else {
            0.0
        }
    }
}

impl RunningStats {
    /// Saves the statistics exactly (a checkpoint of a writer).
    pub fn encode(&self, e: &mut crate::session::Encoder) {
        e.u64(self.count);
        for x in [self.min, self.max, self.mean, self.m2] {
            e.f64(x);
        }
    }

    /// Statistics saved by [`RunningStats::encode`].
    pub fn decode(d: &mut crate::session::Decoder) -> Result<Self, crate::SimulationError> {
        Ok(Self {
            count: d.u64()?,
            min: d.f64()?,
            max: d.f64()?,
            mean: d.f64()?,
            m2: d.f64()?,
        })
    }
}

/// An interval during which some element of a line was slack (strain ≤ 0).
#[derive(Clone, Debug, PartialEq)]
pub struct SlackInterval {
    /// Start [s] (first sample found slack).
    pub start: Real,
    /// End [s] (first sample found taut again; the run's end if still slack).
    pub end: Real,
    /// Smallest strain seen in the interval [-].
    pub min_strain: Real,
}

/// A snap: a line going from slack to taut, and the tension peak that follows.
#[derive(Clone, Debug, PartialEq)]
pub struct SnapEvent {
    /// Time of the slack → taut transition [s].
    pub time: Real,
    /// Time of the peak [s].
    pub peak_time: Real,
    /// Peak element tension [N].
    pub peak_tension: Real,
    /// Unstretched arc length of the peak's element midpoint from end A [m].
    pub location: Real,
    /// Mean rate of rise from the transition to the peak [N/s].
    pub rise_rate: Real,
}

/// Detects slack intervals and snap events on one line from samples of its element tensions
/// and strains.
#[derive(Clone, Debug, Default)]
pub struct SlackSnapDetector {
    slack: Option<SlackInterval>,
    /// Closed slack intervals.
    pub intervals: Vec<SlackInterval>,
    /// Snap events.
    pub snaps: Vec<SnapEvent>,
    pending: Option<(SnapEvent, Real)>,
}

fn put_slack(e: &mut crate::session::Encoder, s: &SlackInterval) {
    for x in [s.start, s.end, s.min_strain] {
        e.f64(x);
    }
}

fn get_slack(d: &mut crate::session::Decoder) -> Result<SlackInterval, crate::SimulationError> {
    Ok(SlackInterval {
        start: d.f64()?,
        end: d.f64()?,
        min_strain: d.f64()?,
    })
}

fn put_snap(e: &mut crate::session::Encoder, s: &SnapEvent) {
    for x in [s.time, s.peak_time, s.peak_tension, s.location, s.rise_rate] {
        e.f64(x);
    }
}

fn get_snap(d: &mut crate::session::Decoder) -> Result<SnapEvent, crate::SimulationError> {
    Ok(SnapEvent {
        time: d.f64()?,
        peak_time: d.f64()?,
        peak_tension: d.f64()?,
        location: d.f64()?,
        rise_rate: d.f64()?,
    })
}

impl SlackSnapDetector {
    /// Saves the detector exactly, open interval and pending event included.
    pub fn encode(&self, e: &mut crate::session::Encoder) {
        e.bool(self.slack.is_some());
        if let Some(s) = &self.slack {
            put_slack(e, s);
        }
        e.u64(self.intervals.len() as u64);
        self.intervals.iter().for_each(|s| put_slack(e, s));
        e.u64(self.snaps.len() as u64);
        self.snaps.iter().for_each(|s| put_snap(e, s));
        e.bool(self.pending.is_some());
        if let Some((s, t)) = &self.pending {
            put_snap(e, s);
            e.f64(*t);
        }
    }

    /// A detector saved by [`SlackSnapDetector::encode`].
    pub fn decode(d: &mut crate::session::Decoder) -> Result<Self, crate::SimulationError> {
        let slack = if d.bool()? { Some(get_slack(d)?) } else { None };
        let n = d.u64()?;
        let intervals = (0..n).map(|_| get_slack(d)).collect::<Result<_, _>>()?;
        let n = d.u64()?;
        let snaps = (0..n).map(|_| get_snap(d)).collect::<Result<_, _>>()?;
        let pending = if d.bool()? {
            Some((get_snap(d)?, d.f64()?))
        } else {
            None
        };
        Ok(Self {
            slack,
            intervals,
            snaps,
            pending,
        })
    }

    /// Processes one sample. `arc_mid` gives the arc length of element e's midpoint.
    pub fn push(
        &mut self,
        time: Real,
        tension: &[Real],
        strain: &[Real],
        arc_mid: impl Fn(usize) -> Real,
    ) {
        let min_strain = strain.iter().copied().fold(Real::INFINITY, Real::min);
        let (emax, tmax) =
            tension
                .iter()
                .copied()
                .enumerate()
                .fold(
                    (0, Real::NEG_INFINITY),
                    |a, (i, t)| if t > a.1 { (i, t) } else { a },
                );
        let slack_now = min_strain <= 0.0;
        if slack_now {
            if let Some((ev, _)) = self.pending.take() {
                self.snaps.push(ev);
            }
            match &mut self.slack {
                Some(s) => s.min_strain = s.min_strain.min(min_strain),
                None => {
                    self.slack = Some(SlackInterval {
                        start: time,
                        end: time,
                        min_strain,
                    })
                }
            }
        } else {
            if let Some(mut s) = self.slack.take() {
                s.end = time;
                self.intervals.push(s);
                self.pending = Some((
                    SnapEvent {
                        time,
                        peak_time: time,
                        peak_tension: tmax,
                        location: arc_mid(emax),
                        rise_rate: 0.0,
                    },
                    tmax,
                ));
            } else if let Some((ev, start_tension)) = &mut self.pending {
                if tmax > ev.peak_tension {
                    ev.peak_tension = tmax;
                    ev.peak_time = time;
                    ev.location = arc_mid(emax);
                    ev.rise_rate =
                        (tmax - *start_tension) / (time - ev.time).max(Real::MIN_POSITIVE);
                } else {
                    // The tension has passed its peak: the event is complete.
                    let (ev, _) = self.pending.take().expect("pending");
                    self.snaps.push(ev);
                }
            }
        }
    }

    /// Closes open intervals and events at the end of a run.
    pub fn finish(&mut self, time: Real) {
        if let Some(mut s) = self.slack.take() {
            s.end = time;
            self.intervals.push(s);
        }
        if let Some((ev, _)) = self.pending.take() {
            self.snaps.push(ev);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn stats_match_direct_formulas() {
        let xs = [1.0, 4.0, -2.0, 7.5];
        let mut s = RunningStats::default();
        xs.iter().for_each(|&x| s.push(x));
        let mean = xs.iter().sum::<f64>() / 4.0;
        let std = (xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / 4.0).sqrt();
        assert!((s.mean() - mean).abs() < 1e-14 && (s.std() - std).abs() < 1e-14);
        assert_eq!((s.min, s.max), (-2.0, 7.5));
    }
    #[test]
    fn snap_after_slack_is_detected_with_its_peak() {
        let mut d = SlackSnapDetector::default();
        let samples = [
            (0.0, 10.0, 0.01),
            (0.1, 0.0, -0.01),
            (0.2, 0.0, -0.02),
            (0.3, 50.0, 0.02),
            (0.4, 80.0, 0.03),
            (0.5, 20.0, 0.01),
        ];
        for (t, ten, st) in samples {
            d.push(t, &[ten], &[st], |_| 1.0);
        }
        d.finish(0.5);
        assert_eq!(d.intervals.len(), 1);
        assert_eq!((d.intervals[0].start, d.intervals[0].end), (0.1, 0.3));
        assert_eq!(d.snaps.len(), 1);
        assert_eq!(d.snaps[0].peak_tension, 80.0);
        assert_eq!(d.snaps[0].peak_time, 0.4);
        assert!((d.snaps[0].rise_rate - 300.0).abs() < 1e-9);
    }
}
