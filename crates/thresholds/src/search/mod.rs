//! How a threshold search chooses the impact speeds it integrates.
//!
//! Along the impact speed the outcomes come in the order sticking < double collision < bouncing;
//! each transition is searched on its own predicate (`Transition`: "not sticking" for the
//! onset of double collisions, "bouncing" for V_stick) from one shared set of classified speeds
//! (`Seen`). Every round integrates two impact speeds, on two threads when asked; the speeds
//! depend only on the outcomes seen, so the result does not depend on the threads.
//!
//! Collisions are integrated on a ladder of solver tolerances (`ladder`): while a bracket is
//! wide, a coarse collision classifies a speed as well as a tight one; the final brackets of both
//! transitions are made of collisions at the search's own tolerance only.
//!
//! The search has three stages:
//! 1. `bracket`: a sticking speed below and a bouncing speed above, on the coarsest rung,
//!    starting just below V_stick,JKR or around a [`hints::Hint`] from a neighbouring sweep point;
//! 2. `v_out`: V_stick as a zero of V_out (coarse secant steps, then full-tolerance pairs that
//!    close its bracket), then `onset`: the onset of double collisions, a jump of the outcome,
//!    by trisection;
//! 3. the result rule of [`crate::stick`]: V_stick is the zero of V_out between the ends of its
//!    final bracket, the onset the centre of its final bracket.
//!
//! A collision close to two collisions of the same rung starts at its rebound, interpolated from
//! theirs (`restarts`).

mod bracket;
pub mod hints;
pub(crate) mod ladder;
mod onset;
mod restarts;
mod v_out;

use crate::{SearchOptions, ThresholdsError};
use contact::Contact;
use dynamics::{Collider, Outcome, Rebound};
use greenwood::CrackLaw;
use v_out::StickState;

/// The most collisions one search integrates before it gives up with
/// [`ThresholdsError::NotConverged`]: a safeguard against a search that stops narrowing its
/// brackets; searches take 20-100 (`StickingThresholds::collisions`).
pub const MAX_COLLISIONS: usize = 1000;

/// One classified impact speed.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Seen {
    /// Impact speed (m/s).
    pub(crate) v: f64,
    /// Its outcome.
    pub(crate) outcome: Outcome,
    /// V_out (m/s).
    pub(crate) v_out: f64,
    /// The rung of the tolerance ladder it was integrated on ([`ladder::LADDER`]`.len()` is the
    /// search's own solver settings).
    pub(crate) rung: usize,
    /// Its state where delta first returned to zero, if it did.
    pub(crate) rebound: Option<Rebound>,
}

#[cfg(test)]
impl Seen {
    /// A full-tolerance collision at `v` (m/s) with `outcome` and `v_out` (m/s), for the unit
    /// tests of the pure helpers.
    pub(crate) fn at(v: f64, outcome: Outcome, v_out: f64) -> Seen {
        Seen {
            v,
            outcome,
            v_out,
            rung: ladder::LADDER.len(),
            rebound: None,
        }
    }
}

/// A transition between two classes of outcomes: the fastest speed below it and the slowest
/// above it seen so far.
pub(crate) type Bracket = (Option<Seen>, Option<Seen>);

/// The two transitions along V_in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Transition {
    /// Sticking -> double collision: above it nothing sticks.
    DoubleOnset,
    /// Double collision -> bouncing (V_stick): above it everything bounces.
    Stick,
}

impl Transition {
    /// Whether `outcome` lies above the transition.
    fn is_above(self, outcome: Outcome) -> bool {
        match self {
            Transition::DoubleOnset => outcome != Outcome::Sticking,
            Transition::Stick => outcome == Outcome::Bouncing,
        }
    }
}

/// The rank of an outcome along V_in.
fn rank(o: Outcome) -> u8 {
    match o {
        Outcome::Sticking => 0,
        Outcome::DoubleCollision => 1,
        Outcome::Bouncing => 2,
    }
}

/// The two speeds that cut `[lo, hi]` in thirds, on `rung`.
fn trisect(lo: f64, hi: f64, rung: usize) -> Vec<(f64, usize)> {
    let third = (hi - lo) / 3.0;
    vec![(lo + third, rung), (lo + 2.0 * third, rung)]
}

/// Whether a finer classification `q` overrules `p`: the same speed integrated again more
/// finely, or a finer outcome that contradicts `p`'s (outcomes come in the order sticking,
/// double, bouncing along V_in).
fn overrules(q: &Seen, p: &Seen) -> bool {
    q.rung > p.rung
        && ((q.v == p.v)
            || (q.v > p.v && rank(q.outcome) < rank(p.outcome))
            || (q.v < p.v && rank(q.outcome) > rank(p.outcome)))
}

/// The speeds of `seen`, each by its finest classification, without the coarse ones that a finer
/// one overrules.
fn trusted(seen: &[Seen]) -> Vec<Seen> {
    seen.iter()
        .filter(|p| !seen.iter().any(|q| overrules(q, p)))
        .copied()
        .collect()
}

/// The coarsest rung a search may still use: a rung whose outcomes finer ones contradicted
/// [`MAX_CONTRADICTIONS`] times is off by more than its shift here (near the no-bouncing cliff
/// the onset moves by 3e-3 at rtol 1e-5), and every later round runs on a finer one.
fn min_rung(seen: &[Seen]) -> usize {
    let contradicted = |p: &&Seen| seen.iter().any(|q| q.v != p.v && overrules(q, p));
    (0..ladder::LADDER.len())
        .rev()
        .find(|&r| {
            seen.iter()
                .filter(|p| p.rung == r)
                .filter(contradicted)
                .count()
                >= MAX_CONTRADICTIONS
        })
        .map_or(0, |r| r + 1)
}

/// Contradicted outcomes of one rung after which a search stops using it ([`min_rung`]): one or
/// two happen where a transition lies within a rung's shift of a trial speed, which the final
/// full-tolerance collisions set right.
const MAX_CONTRADICTIONS: usize = 3;

/// The bracket of `transition` among `points`: the slowest above it, and the fastest below it
/// that is slower than that.
fn bracket_of<'p>(
    points: impl Iterator<Item = &'p Seen> + Clone,
    transition: Transition,
) -> Bracket {
    let hi = points
        .clone()
        .filter(|p| transition.is_above(p.outcome))
        .min_by(|a, b| a.v.total_cmp(&b.v))
        .copied();
    let lo = points
        .filter(|p| !transition.is_above(p.outcome) && hi.is_none_or(|h| p.v < h.v))
        .max_by(|a, b| a.v.total_cmp(&b.v))
        .copied();
    (lo, hi)
}

/// One threshold search: colliders for each rung, its settings, and every classified speed.
pub(crate) struct Search<'a> {
    /// One collider a rung of [`ladder::LADDER`], then one with the search's own solver settings.
    colliders: Vec<Collider>,
    opts: &'a SearchOptions,
    /// V_stick,JKR of the contact (m/s).
    pub(crate) v_jkr: f64,
    /// Highest speed searched (m/s).
    pub(crate) v_max: f64,
    /// Every speed integrated, in order.
    pub(crate) seen: Vec<Seen>,
    /// Solver steps over all collisions.
    pub(crate) steps: usize,
    /// The state of the V_stick stage.
    stick: StickState,
}

impl<'a> Search<'a> {
    /// A search of `contact` with `law` at `t_vis` (s, > 0), with the settings `opts` (valid).
    pub(crate) fn new(
        contact: &Contact,
        law: &CrackLaw,
        t_vis: f64,
        opts: &'a SearchOptions,
    ) -> Result<Self, ThresholdsError> {
        let v_jkr = contact.v_stick_jkr();
        Ok(Search {
            colliders: ladder::colliders(contact, law, t_vis, &opts.solver)?,
            opts,
            v_jkr,
            v_max: opts.v_max_for(v_jkr),
            seen: Vec::new(),
            steps: 0,
            stick: StickState::default(),
        })
    }

    /// The relaxation time searched (s).
    pub(crate) fn t_vis(&self) -> f64 {
        self.colliders[0].t_vis()
    }

    /// Runs the three stages: the first bracket, then V_stick, then the onset, each to the
    /// tolerance on full-tolerance collisions, two speeds a round (both cores busy).
    pub(crate) fn run(&mut self) -> Result<(), ThresholdsError> {
        self.bracket_stage()?;
        loop {
            let jobs = self.stick_jobs()?;
            if jobs.is_empty() {
                break;
            }
            self.round(&jobs)?;
        }
        loop {
            let jobs = self.onset_jobs();
            if jobs.is_empty() {
                return Ok(());
            }
            self.round(&jobs)?;
        }
    }

    /// The final bracket of `transition`: its two ends at the search's own tolerance; `None`
    /// where the outcomes above it were never seen (nothing bounced, or everything stuck, up
    /// to `v_max`).
    pub(crate) fn final_bracket(&self, transition: Transition) -> Option<(Seen, Seen)> {
        if !self.has(transition) {
            return None;
        }
        match self.tight_bracket(transition) {
            (Some(lo), Some(hi)) => Some((lo, hi)),
            _ => None,
        }
    }

    /// Integrates impact speeds, each on its rung, two at a time (concurrently when asked).
    fn round(&mut self, jobs: &[(f64, usize)]) -> Result<(), ThresholdsError> {
        if self.seen.len() >= MAX_COLLISIONS {
            return Err(ThresholdsError::NotConverged {
                t_vis: self.t_vis(),
                collisions: self.seen.len(),
            });
        }
        let jobs: Vec<(f64, usize, Option<Rebound>)> = jobs
            .iter()
            .map(|&(v, rung)| (v, rung, self.restart_from(v, rung)))
            .collect();
        let one = |(v, rung, from): (f64, usize, Option<Rebound>)| {
            let collider = &self.colliders[rung];
            match from {
                Some(r) => collider.collide_from(v, &r),
                None => collider.collide(v),
            }
            .map(|c| (v, rung, c))
        };
        let results = match jobs.as_slice() {
            [a, b] if self.opts.parallel => {
                let (x, y) = rayon::join(|| one(*a), || one(*b));
                vec![x, y]
            }
            _ => jobs.iter().map(|j| one(*j)).collect(),
        };
        for r in results {
            let (v, rung, c) = r?;
            self.steps += c.steps;
            self.seen.push(Seen {
                v,
                outcome: c.outcome,
                v_out: c.v_out,
                rung,
                rebound: c.rebound,
            });
        }
        Ok(())
    }

    /// The bracket of `transition` from every trusted speed.
    fn bracket(&self, transition: Transition) -> Bracket {
        self.bracket_from(0, transition)
    }

    /// The bracket of `transition` from the trusted speeds integrated on `rung` or finer.
    fn bracket_from(&self, rung: usize, transition: Transition) -> Bracket {
        let mut trusted = trusted(&self.seen);
        trusted.retain(|p| p.rung >= rung);
        bracket_of(trusted.iter(), transition)
    }

    /// The bracket of `transition` from full-tolerance collisions only.
    fn tight_bracket(&self, transition: Transition) -> Bracket {
        let tight = self.tight();
        bracket_of(self.seen.iter().filter(|p| p.rung == tight), transition)
    }

    /// Whether any speed seen lies above `transition`.
    fn has(&self, transition: Transition) -> bool {
        self.seen.iter().any(|p| transition.is_above(p.outcome))
    }

    /// Whether any speed seen sticks.
    fn has_sticking(&self) -> bool {
        self.seen.iter().any(|p| p.outcome == Outcome::Sticking)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn on(rung: usize, (v, outcome): (f64, Outcome)) -> Seen {
        Seen {
            rung,
            ..Seen::at(v, outcome, 0.0)
        }
    }

    /// A coarse "bouncing" at 1.0 below a full-tolerance double collision at 1.1 contradicts the
    /// order of outcomes and is dropped; so is a coarse speed integrated again more finely.
    #[test]
    fn finer_collisions_overrule_coarse_ones() {
        let (stick, double, bounce) = (
            Outcome::Sticking,
            Outcome::DoubleCollision,
            Outcome::Bouncing,
        );
        let pts = [
            on(0, (1.0, bounce)),
            on(3, (1.1, double)),
            on(0, (1.2, bounce)),
            on(3, (1.2, bounce)),
            on(0, (0.9, stick)),
        ];
        let kept: Vec<(f64, usize)> = trusted(&pts).iter().map(|p| (p.v, p.rung)).collect();
        assert_eq!(kept, [(1.1, 3), (1.2, 3), (0.9, 0)]);
    }

    /// A rung whose outcomes three finer collisions contradicted is not used again (the coarse
    /// "double collisions" at 106.0-106.3 m/s that rtol 1e-7 found sticking, near the cliff of
    /// 1.5 um CO2 grains at T_vis = 2.2e-10 s, had kept a search from closing); one or two
    /// contradictions are allowed.
    #[test]
    fn a_rung_contradicted_three_times_is_dropped() {
        let (stick, double) = (Outcome::Sticking, Outcome::DoubleCollision);
        let mut pts = vec![on(1, (106.1, double)), on(2, (106.15, stick))];
        assert_eq!(min_rung(&pts), 0);
        pts.extend([on(1, (106.2, double)), on(2, (106.25, stick))]);
        assert_eq!(min_rung(&pts), 0);
        pts.extend([on(1, (106.3, double)), on(2, (106.35, stick))]);
        assert_eq!(min_rung(&pts), 2);
    }

    /// Each transition's bracket: the slowest speed above it and the fastest below that.
    #[test]
    fn brackets_of_both_transitions() {
        let outcomes = [
            (0.9, Outcome::Sticking),
            (1.0, Outcome::DoubleCollision),
            (1.1, Outcome::DoubleCollision),
            (1.3, Outcome::Bouncing),
            (1.2, Outcome::Bouncing),
        ];
        let pts = outcomes.map(|p| on(3, p));
        let ends = |(lo, hi): Bracket| (lo.map(|p| p.v), hi.map(|p| p.v));
        assert_eq!(
            ends(bracket_of(pts.iter(), Transition::DoubleOnset)),
            (Some(0.9), Some(1.0))
        );
        assert_eq!(
            ends(bracket_of(pts.iter(), Transition::Stick)),
            (Some(1.1), Some(1.2))
        );
        let t = trisect(1.0, 1.3, 2);
        assert!((t[0].0 - 1.1).abs() < 1e-15 && (t[1].0 - 1.2).abs() < 1e-15);
        assert_eq!((t[0].1, t[1].1), (2, 2));
    }
}
