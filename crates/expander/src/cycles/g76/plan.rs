//! Planning a G76: the depth of every pass (§4.2) and the moves of each pass (§4.3).

use super::error::{G76Error, G76ErrorKind};
use super::*;
use crate::cycles::Move;
use crate::Motion;

/// The depth (radius, from the crest) of every pass, rough passes then the m passes at k
/// (§4.2). Checks the values that do not depend on the start point.
pub(crate) fn passes(p: &G76Params) -> Result<Vec<f64>, G76Error> {
    use G76ErrorKind as K;
    let at = &p.at;
    if !p.k.is_finite() || p.k <= 0.0 {
        return Err(G76Error::new(K::Height { k: p.k }, at.k));
    }
    if !p.dd.is_finite() || p.dd <= 0.0 {
        return Err(G76Error::new(K::FirstDepth { dd: p.dd }, at.dd));
    }
    if !p.lead.is_finite() || p.lead <= 0.0 {
        return Err(G76Error::new(K::Lead { lead: p.lead }, at.lead));
    }
    if !p.dmin.is_finite() || p.dmin < 0.0 {
        return Err(G76Error::new(K::MinDepth { dmin: p.dmin }, at.dmin));
    }
    if !p.d.is_finite() || p.d < 0.0 || p.d >= p.k {
        return Err(G76Error::new(K::Allowance { d: p.d, k: p.k }, at.d));
    }
    if p.m == 0 {
        return Err(G76Error::new(K::NoFinishingPass, at.m));
    }
    let m = p.m as usize;
    let target = p.k - p.d;
    let mut out = Vec::new();
    let mut prev = 0.0;
    for n in 1.. {
        if out.len() + m >= MAX_PASSES {
            return Err(G76Error::new(
                K::TooManyPasses {
                    estimate: estimate(p, target),
                },
                at.dd,
            ));
        }
        let nf = f64::from(n);
        let mut h = match p.law {
            DepthLaw::ConstantAmount => p.dd * nf.sqrt(),
            DepthLaw::ConstantDepth => p.dd * nf,
        };
        if h - prev < p.dmin {
            h = prev + p.dmin;
        }
        if h >= target - EPS {
            out.push(target);
            break;
        }
        out.push(h);
        prev = h;
    }
    out.extend(std::iter::repeat_n(p.k, m));
    Ok(out)
}

/// About how many passes the words ask for (for the message only).
fn estimate(p: &G76Params, target: f64) -> f64 {
    let by_dd = match p.law {
        DepthLaw::ConstantAmount => (target / p.dd).powi(2),
        DepthLaw::ConstantDepth => target / p.dd,
    };
    let by_min = if p.dmin > 0.0 {
        target / p.dmin
    } else {
        f64::INFINITY
    };
    by_dd.min(by_min).ceil() + f64::from(p.m)
}

/// A thread move to `to`.
fn thread(to: Pt) -> Move {
    let mut m = Move::feed(to);
    m.motion = Motion::Thread;
    m
}

/// The moves of the whole cycle from the start point `start` (G54 frame), §4.3: five (four
/// without a chamfer) per pass, in the order of [`passes`].
pub(crate) fn moves(start: Pt, p: &G76Params) -> Result<Vec<Move>, G76Error> {
    use G76ErrorKind as K;
    let depths = passes(p)?;
    let at = &p.at;
    let theta = p.chamfer_angle;
    if !theta.is_finite() || theta <= 0.0 || theta >= 90.0 {
        return Err(G76Error::new(K::ChamferAngle { angle: theta }, at.chamfer));
    }
    // Z travel and the side of A (the shift and the chamfer point toward A).
    let dz = start.z - p.end.z;
    let travel = dz.abs();
    if travel < EPS {
        return Err(G76Error::new(K::NoZTravel, at.z));
    }
    let zeta = dz.signum();
    let gamma = p.chamfer_leads * p.lead;
    if gamma > 0.0 && gamma >= travel - EPS {
        return Err(G76Error::new(
            K::ChamferTooLong { gamma, travel },
            at.chamfer,
        ));
    }
    // Radial travel: non-zero, or OD and ID cannot be told apart. HUST also requires it to
    // be larger than the pull-out's radial size [S19]; FANUC, GSK and Haas run a pull-out
    // that climbs past the start X, then rapid back to it (docs/field-rules.md §9).
    let half_u = p.end.r - start.r;
    let pull_out = gamma * theta.to_radians().tan();
    if half_u.abs() <= EPS {
        return Err(G76Error::new(K::NoRadialTravel, at.x));
    }
    if p.i != 0.0 && p.i.signum() != half_u.signum() && p.i.abs() > half_u.abs() + EPS {
        return Err(G76Error::new(K::Taper { i: p.i, half_u }, at.i));
    }
    // σ: +1 OD (the start point is outside the end point), −1 ID.
    let sigma = if start.r > p.end.r { 1.0 } else { -1.0 };
    let tan_half = (p.a / 2.0).to_radians().tan();
    let mut out = Vec::with_capacity(depths.len() * 5);
    for (n, h) in depths.iter().enumerate() {
        let t = p.k - h;
        let side = match p.edges {
            Edges::One => 1.0,
            Edges::Alternating if n % 2 == 0 => 1.0,
            Edges::Alternating => -1.0,
        };
        let s = zeta * side * t * tan_half;
        let r_end = p.end.r + sigma * t;
        let z_end = p.end.z + s;
        out.push(Move::rapid(Pt::new(start.z + s, r_end + p.i))); // ① to the pass start
        if gamma > 0.0 {
            let r_c = r_end + p.i * gamma / travel; // on the taper, γ before the end
            out.push(thread(Pt::new(z_end + zeta * gamma, r_c))); // ② thread
            out.push(thread(Pt::new(z_end, r_end + sigma * pull_out))); // ③ chamfer
        } else {
            out.push(thread(Pt::new(z_end, r_end))); // ② thread to the end
        }
        out.push(Move::rapid(Pt::new(z_end, start.r))); // ④ out in X
        out.push(Move::rapid(start)); // ⑤ back in Z
    }
    Ok(out)
}

/// Advice that does not stop the program: a first depth larger than the whole thread height
/// (P and Q of the second block swapped?). The pass law caps it at k − d (§4.2).
pub(crate) fn first_depth_exceeds_height(p: &G76Params) -> bool {
    p.dd > p.k
}
