//! The passes of `LinuxCNC`'s G76 and their moves, as `convert_threading_cycle` and
//! `threading_pass` (`interp_convert.cc`) make them (docs/linuxcnc-g76.md, "Passes").

use super::Params;
use crate::cycles::Move;
use crate::{Motion, Pt};

/// The depth of every pass below the drive line (radius, mm): |I| + J·n^(1/R) for
/// n = 1, 2, … while it is less than |I| + K, then H + 1 passes at |I| + K.
pub(crate) fn depths(p: &Params) -> Vec<f64> {
    let peak = p.i.abs();
    let full = p.k + peak;
    let mut out = Vec::new();
    let mut pass = 1.0_f64;
    let mut depth = peak + p.j;
    while depth < full {
        out.push(depth);
        pass += 1.0;
        depth = peak + p.j * pass.powf(1.0 / p.degression);
    }
    out.extend(std::iter::repeat_n(full, p.spring as usize + 1));
    out
}

/// The cycle's moves from the drive line's start `start` (G54 frame, radius) in
/// program units `unit` (mm per unit: the thread moves carry their lead as a feed).
pub(crate) fn moves(start: Pt, p: &Params, unit: f64) -> Vec<Move> {
    let pass = Pass::new(start, p, unit);
    let mut out = Vec::new();
    for depth in depths(p) {
        pass.cut(depth, &mut out);
    }
    // the end of the drive line (or the X of the block)
    out.push(Move::rapid(Pt::new(p.end_z, p.end_x.unwrap_or(start.r))));
    out
}

/// What every pass shares: `threading_pass`'s arguments.
struct Pass {
    /// The drive line's X (radius) and start Z.
    safe_x: f64,
    start_z: f64,
    /// +1 inside (I > 0, `boring`), −1 outside: the side a depth is taken to.
    side: f64,
    /// |I| + K: the depth of the last passes, and how far each pass retracts.
    end_depth: f64,
    /// |I|: the thread peak below the drive line.
    peak: f64,
    /// K: the full thread height.
    height: f64,
    /// tan of the compound angle, negative when the thread runs toward +Z.
    tan_q: f64,
    /// The Z every pass ends at, before its shift: Z + K·tan Q.
    target_z: f64,
    /// E toward the thread's end (negative when it runs toward +Z); 0 without a taper.
    taper: f64,
    entry: bool,
    exit: bool,
    /// Thread leads, mm per revolution along each move's dominant axis: the straight
    /// thread, the radial entry move (`LinuxCNC` syncs it at the taper pitch along the path),
    /// and the tapers.
    lead: f64,
    radial_lead: f64,
    taper_lead: f64,
    unit: f64,
}

impl Pass {
    fn new(start: Pt, p: &Params, unit: f64) -> Self {
        let toward_plus = p.end_z > start.z;
        let q = p.compound.to_radians();
        let tan_q = if toward_plus { -q.tan() } else { q.tan() };
        // LinuxCNC syncs a taper at P·hypot(E, K)/E along its path: P along Z per revolution
        let taper_pitch = if p.taper > 0.0 {
            p.pitch * p.taper.hypot(p.k) / p.taper
        } else {
            p.pitch
        };
        let taper_lead = if p.taper > 0.0 {
            p.pitch * p.taper.max(p.k) / p.taper
        } else {
            p.pitch
        };
        Self {
            safe_x: start.r,
            start_z: start.z,
            side: if p.i > 0.0 { 1.0 } else { -1.0 },
            end_depth: p.k + p.i.abs(),
            peak: p.i.abs(),
            height: p.k,
            tan_q,
            target_z: p.end_z + p.k * tan_q,
            taper: if toward_plus { -p.taper } else { p.taper },
            entry: p.taper > 0.0 && p.entry_taper,
            exit: p.taper > 0.0 && p.exit_taper,
            lead: p.pitch,
            radial_lead: taper_pitch,
            taper_lead,
            unit,
        }
    }

    /// The X `depth` below (outside) or above (bore) the drive line.
    fn x(&self, depth: f64) -> f64 {
        self.safe_x + self.side * depth
    }

    /// A thread move to `to` at `lead` mm per revolution (the feed of the move, in
    /// program units, is the lead: the interpreter takes a cycle thread's lead from it).
    fn thread(&self, to: Pt, lead: f64) -> Move {
        Move {
            motion: Motion::Thread,
            feed: Some(lead / self.unit),
            ..Move::feed(to)
        }
    }

    /// One pass at `depth`: back, in (or in and the entry taper), over (and the exit
    /// taper), out.
    fn cut(&self, depth: f64, out: &mut Vec<Move>) {
        let zoff = (depth - self.peak) * self.tan_q;
        let z0 = self.start_z - zoff;
        let z1 = self.target_z - zoff;
        let retract = self.x(depth - self.end_depth);
        out.push(Move::rapid(Pt::new(z0, retract))); // back
        if self.entry {
            out.push(self.thread(Pt::new(z0, self.x(depth - self.height)), self.radial_lead)); // in
            out.push(self.thread(Pt::new(z0 - self.taper, self.x(depth)), self.taper_lead));
        // angled in
        } else {
            out.push(Move::rapid(Pt::new(z0, self.x(depth)))); // in
        }
        if self.exit {
            out.push(self.thread(Pt::new(z1 + self.taper, self.x(depth)), self.lead)); // over
            out.push(self.thread(Pt::new(z1, self.x(depth - self.height)), self.taper_lead));
        // angled out
        } else {
            out.push(self.thread(Pt::new(z1, self.x(depth)), self.lead)); // over
        }
        out.push(Move::rapid(Pt::new(z1, retract))); // out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An M33×1.5-like outside thread: peak 0.5 below the drive line, J0.1, K0.9, R2, Q30, H1.
    fn example() -> Params {
        Params {
            pitch: 1.5,
            end_z: -20.0,
            end_x: None,
            i: -0.5,
            j: 0.1,
            k: 0.9,
            degression: 2.0,
            compound: 30.0,
            spring: 1,
            taper: 0.0,
            entry_taper: false,
            exit_taper: false,
        }
    }

    #[test]
    fn depths_follow_j_times_the_rth_root_of_n_then_spring_passes() {
        // J·√n: 0.1, 0.1414, 0.1732, …, √80·0.1 = 0.8944 < 0.9; √81·0.1 = 0.9 is not < 0.9
        let d = depths(&example());
        assert_eq!(d.len(), 80 + 2);
        assert!((d[0] - 0.6).abs() < 1e-12);
        assert!((d[1] - (0.5 + 0.1 * 2f64.sqrt())).abs() < 1e-12);
        assert!((d[79] - (0.5 + 0.1 * 80f64.sqrt())).abs() < 1e-12);
        assert_eq!(&d[80..], &[1.4, 1.4]);
        // R1: constant 0.1 steps, 0.1 … 0.8 (0.9 is not less than K), then one at K
        let r1 = Params {
            degression: 1.0,
            spring: 0,
            ..example()
        };
        let d = depths(&r1);
        assert_eq!(d.len(), 9);
        assert!((d[7] - 1.3).abs() < 1e-12 && d[8] == 1.4, "{d:?}");
    }

    #[test]
    fn a_pass_goes_back_in_over_and_out_shifted_along_the_compound_angle() {
        let p = example();
        let start = Pt::new(5.0, 16.0);
        let m = moves(start, &p, 1.0);
        let t = 30f64.to_radians().tan();
        // pass 1 at depth 0.6: zoff = 0.1·tan30; retract 0.8 above the drive line
        let zoff = 0.1 * t;
        assert_eq!(m[0].to, Pt::new(5.0 - zoff, 16.8));
        assert_eq!(m[0].motion, Motion::Rapid);
        assert_eq!(m[1].to, Pt::new(5.0 - zoff, 15.4));
        assert_eq!(m[2].motion, Motion::Thread);
        assert!((m[2].to.z - (-20.0 + 0.9 * t - zoff)).abs() < 1e-12);
        assert_eq!(m[2].feed, Some(1.5));
        assert_eq!(m[3].to.r, 16.8);
        // the last pass ends at Z-20 at the full depth, then the drive line's end
        let n = m.len();
        assert!((m[n - 3].to.z + 20.0).abs() < 1e-12 && (m[n - 3].to.r - 14.6).abs() < 1e-12);
        assert_eq!(m[n - 1].to, Pt::new(-20.0, 16.0));
    }

    #[test]
    fn tapers_run_at_the_taper_pitch_and_end_on_the_peak() {
        let p = Params {
            taper: 0.45,
            entry_taper: true,
            exit_taper: true,
            compound: 0.0,
            ..example()
        };
        let m = moves(Pt::new(5.0, 16.0), &p, 1.0);
        // back, in (radial, synced), angled in, over, angled out, out
        let kinds: Vec<Motion> = m[..6].iter().map(|m| m.motion).collect();
        use Motion::{Rapid as R, Thread as T};
        assert_eq!(kinds, [R, T, T, T, T, R]);
        // in to the depth less K (0.6 − 0.9 below the drive line: 0.3 above), then down
        // to the depth over E; X dominates (K > E): the lead along X is P·K/E = 3
        assert_eq!(m[1].to, Pt::new(5.0, 16.3));
        assert_eq!(m[2].to, Pt::new(4.55, 15.4));
        assert!((m[2].feed.unwrap() - 3.0).abs() < 1e-12);
        assert!((m[1].feed.unwrap() - 1.5 * 0.45f64.hypot(0.9) / 0.45).abs() < 1e-12);
        assert_eq!(m[3].to, Pt::new(-19.55, 15.4));
        assert_eq!(m[4].to, Pt::new(-20.0, 16.3));
    }

    #[test]
    fn a_bore_goes_up_and_a_thread_toward_plus_z_shifts_the_other_way() {
        let p = Params {
            i: 0.5,
            end_z: 30.0,
            ..example()
        };
        let m = moves(Pt::new(5.0, 10.0), &p, 1.0);
        let zoff = -0.1 * 30f64.to_radians().tan();
        assert_eq!(m[0].to, Pt::new(5.0 - zoff, 9.2));
        assert_eq!(m[1].to, Pt::new(5.0 - zoff, 10.6));
    }
}
