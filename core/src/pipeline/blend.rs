//! The recommended heading: the bank's, averaged with two simple experts' where they agree
//! with it. Estimators whose errors differ in kind are averaged, with a guard: the bank's
//! road model is wrong where the road is not as modelled; Table-III HDR's fixed-rate
//! heuristic cannot acquire a bias it did not start near, and follows a slow change the bank
//! lags; x-io Fusion's offset follows any slow rate within 3 deg/s, a bias and a long curve
//! alike. Over each block the heading moves by the mean of the bank's move and the move of
//! every expert whose implied bias differs from the bank's by less than `blend_sigmas` of the
//! bank's bias uncertainty, grown between stops as a bias walk of `blend_walk_dps_per_sqrt_s`
//! since the last stop (there the bank's sigma rests on road evidence it counts as white
//! over 10 s, so it is too narrow to reject an expert on); by the bank's alone when none
//! does (an expert diverging, or the bank correcting its heading at a stop). The experts
//! start after the lead-in, at the first block where the bank knows its bias to better than
//! one of HDR's own correction steps (Table III's i_c, 0.0422 deg/s: HDR's static bias eps0
//! is a standstill's, known that well), from the bank's bias then; before, the bank's alone.
//! Until the first stop, where the road alone may never take the bank there (no lead-in, no
//! speed), they start once HDR could acquire what is left: three sigma within its straight
//! threshold theta_w (0.188 deg/s).
//! Once the experts have started the bank's settled bias (the bias less its warm-up term) has
//! no cause to move far between stops, the bias's own evidence: while it is more than
//! `blend_move_dps` from where the last stop (or the experts' start) left it, the bank is
//! reading long bends that filled its road window as straight road, and the heading moves
//! by HDR's move alone, whose threshold about its own estimate calls a bend a turn. HDR's
//! bias is then held within the guard of the span between the bank's bias and the bank's
//! bias at that anchor, so the blend stays as bounded as the bank. Where the anchor is and
//! when a move is released: `fallback.rs`.
//! After a lead-in that shows a turn-on bias (an uncalibrated gyro), the bank's move counts
//! for less in that mean the longer it has been since the last stop: weight 1 / (1 + rho t /
//! `BANK_DECAY_S`), t since the last stop block, rho the turn-on bias the lead-in showed over
//! `warm_sigma_dps` (at most 1), the warm-up prior's rho without its variance term. At a stop the bank knows the
//! bias best; on an open road after it, its bias rests on the road evidence HDR reads too,
//! and a drifting gyro is followed better by the experts' fast tracking than by the bank's
//! likelihood-weighed walks. A calibrated gyro (rho near 0) or a log without a lead-in keeps
//! weight 1.
//! The stream and the batch path blend alike, block for block. Beyond the paper, like the
//! bank.

use super::fallback::Fallback;
use super::filter::PipelineOutput;
use crate::error::Result;
use crate::hdr::{Hdr, HdrParams};
use crate::peers::FusionOffset;

/// After a lead-in with a turn-on bias of `warm_sigma_dps` or more, the time since the last
/// stop at which the bank's move counts half as much as it does at the stop, s. Chosen on
/// the training populations among 150 and 300 (sixty-fourth session, docs/pipeline.md).
const BANK_DECAY_S: f64 = 300.0;

/// Whether a bias known to `sigma_dps` is within Table-III HDR's reach: three sigma within
/// its straight threshold theta_w, so its heuristic could acquire what is left.
pub(super) fn within_hdr_reach(sigma_dps: f64) -> bool {
    3.0 * sigma_dps < HdrParams::table_iii().theta_w_dps
}

/// The experts on the blocks once started, and their headings at the last block.
#[cfg_attr(feature = "snapshot", derive(serde::Serialize, serde::Deserialize))]
#[derive(Debug, Clone)]
struct Experts {
    hdr: Hdr,
    hdr_deg: f64,
    /// Fusion's algorithm on the 1 s blocks, as on a 1 Hz gyro (its 5 s timeout is 5 blocks).
    fusion: FusionOffset,
    /// How fast the bank's weight decays after a stop, rho / `BANK_DECAY_S` (1/s).
    decay_per_s: f64,
}

/// The blend beside a bank.
#[cfg_attr(feature = "snapshot", derive(serde::Serialize, serde::Deserialize))]
#[derive(Debug, Clone, Default)]
pub struct Blend {
    sigmas: f64,
    walk_dps_per_sqrt_s: f64,
    /// The last block with stop evidence, or the experts' first, s.
    last_stop_s: f64,
    experts: Option<Experts>,
    /// The last block's end time and the bank's heading then.
    last: Option<(f64, f64)>,
    /// What the blend has added to the bank's heading so far, deg.
    offset_deg: f64,
    /// The bank has had stop evidence since the lead-in (the experts then wait for i_c).
    seen_stop: bool,
    fallback: Fallback,
    /// The turn-on bias at which the bank's weight decays fully (`warm_sigma_dps`); 0 = never.
    decay_bias_dps: f64,
}

impl Blend {
    /// `sigmas`: the guard, `blend_sigmas` (0: the bank's output as it is); `walk`: how it
    /// grows between stops, `blend_walk_dps_per_sqrt_s`.
    pub fn new(sigmas: f64, walk_dps_per_sqrt_s: f64) -> Self {
        Blend { sigmas, walk_dps_per_sqrt_s, ..Default::default() }
    }

    /// The blend the pipeline's settings ask for (causal, smoothed and streamed alike).
    pub fn of(p: &super::PipelineParams) -> Self {
        Self { fallback: Fallback::of(p), decay_bias_dps: p.warm_sigma_dps, ..Self::new(p.blend_sigmas, p.blend_walk_dps_per_sqrt_s) }
    }

    /// One block (end time, mean raw rate) and the bank's output on it: the output with the
    /// blended heading and the bias it integrated. `after_lead_in`: the block is past the lead-in;
    /// `settled_dps`: the bank's settled bias before the block (not finite: no fallback);
    /// `quiet`: the gyro's standstill noise is within the stop's setting (`Pipeline::quiet`).
    pub fn update(
        &mut self,
        after_lead_in: bool,
        time_s: f64,
        rate_dps: f64,
        bank: PipelineOutput,
        settled_dps: f64,
        quiet: bool,
    ) -> Result<PipelineOutput> {
        self.fallback.lead_in_seen |= !after_lead_in && bank.stop;
        if !(self.sigmas > 0.0 && after_lead_in) {
            return Ok(bank);
        }
        let table_iii = HdrParams::table_iii();
        self.seen_stop |= bank.stop;
        let sigma = bank.bias_sigma_dps;
        let known = sigma < table_iii.i_c_dps || (!self.seen_stop && within_hdr_reach(sigma));
        if self.experts.is_none() && !known {
            return Ok(bank);
        }
        let e = match self.experts.as_mut() {
            Some(e) => e,
            None => {
                self.last_stop_s = time_s;
                let hdr = Hdr::new(table_iii, bank.bias_dps)?;
                let rho = if self.fallback.lead_in_seen && self.decay_bias_dps > 0.0 {
                    bank.bias_dps.abs().min(self.decay_bias_dps) / self.decay_bias_dps
                } else {
                    0.0
                };
                let fusion = FusionOffset::starting_at(1, bank.bias_dps);
                self.experts.insert(Experts { hdr, hdr_deg: 0.0, fusion, decay_per_s: rho / BANK_DECAY_S })
            }
        };
        let hdr_deg = e.hdr.update(time_s, rate_dps)?.heading_deg;
        let fusion_rate_dps = e.fusion.update(rate_dps);
        if bank.stop {
            self.last_stop_s = time_s;
        }
        let since_stop_s = time_s - self.last_stop_s;
        let guard_dps = self.sigmas * libm::sqrt(bank.bias_sigma_dps.powi(2) + self.walk_dps_per_sqrt_s.powi(2) * since_stop_s);
        let moved_from = self.fallback.moved(time_s, settled_dps, bank.bias_dps, bank.stop, quiet);
        let mut out = bank;
        if let Some((t, bank_deg)) = self.last {
            let dt = time_s - t;
            let bank_move_deg = bank.heading_deg - bank_deg;
            let hdr_move_deg = hdr_deg - e.hdr_deg;
            let bank_w = 1.0 / (1.0 + e.decay_per_s * since_stop_s);
            let (mut sum_deg, mut n) = (bank_w * bank_move_deg, bank_w);
            for move_deg in [hdr_move_deg, fusion_rate_dps * dt] {
                // How far the two moved apart over the block: (the bank's bias less the
                // expert's, as each integrated it) x dt.
                if dt > 0.0 && ((move_deg - bank_move_deg) / dt).abs() < guard_dps {
                    (sum_deg, n) = (sum_deg + move_deg, n + 1.0);
                }
            }
            // A settled bias on the move is a bend read as road: HDR's move alone, held
            // (module doc).
            let gain_deg = match moved_from {
                Some(anchor) => {
                    let b = bank.bias_dps;
                    let (lo, hi) = (b.min(anchor) - guard_dps, b.max(anchor) + guard_dps);
                    ((hdr_move_deg - bank_move_deg) / dt).max(b - hi).min(b - lo) * dt
                }
                None => sum_deg / n - bank_move_deg,
            };
            if gain_deg != 0.0 {
                self.offset_deg += gain_deg;
                out.bias_dps -= gain_deg / dt;
            }
        }
        e.hdr_deg = hdr_deg;
        self.last = Some((time_s, bank.heading_deg));
        out.heading_deg += self.offset_deg;
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bank(heading_deg: f64, bias_sigma_dps: f64) -> PipelineOutput {
        PipelineOutput { heading_deg, bias_dps: 0.0, bias_sigma_dps, heading_sigma_deg: 0.0, stop: false, straight: false, reopened: false }
    }

    /// HDR's move over the next block, from a copy of the blend's HDR.
    fn hdr_move(b: &Blend, time_s: f64, rate_dps: f64) -> f64 {
        let e = b.experts.clone().unwrap();
        let mut hdr = e.hdr;
        hdr.update(time_s, rate_dps).unwrap().heading_deg - e.hdr_deg
    }

    #[test]
    fn agreeing_moves_are_averaged_and_a_diverging_expert_is_left_out() {
        let mut b = Blend::new(2.0, 0.0);
        // In the lead-in, with the blend off, or after a stop while the bank's bias is less
        // sure than one of HDR's steps (0.0422 deg/s): the bank's output as it is, and no
        // expert started.
        assert_eq!(b.update(false, 0.0, 0.0, bank(0.3, 0.03), 0.0, false).unwrap(), bank(0.3, 0.03));
        assert_eq!(Blend::new(0.0, 0.0).update(true, 0.0, 0.0, bank(0.3, 0.03), 0.0, false).unwrap(), bank(0.3, 0.03));
        let stop = PipelineOutput { stop: true, ..bank(0.3, 0.05) };
        assert_eq!(b.update(true, 0.0, 0.0, stop, 0.0, false).unwrap(), stop);
        assert!(b.experts.is_none());
        // The experts start from the bank's bias (0); their first block moves nothing.
        assert_eq!(b.update(true, 1.0, 0.0, bank(0.0, 0.04), 0.0, false).unwrap(), bank(0.0, 0.04));
        // On a rate of 0, Fusion's move is 0 (offset 0, and it adapts only after 5 blocks
        // within 3 deg/s); HDR's moves only by its controller, at most i_c per block.
        let m = hdr_move(&b, 2.0, 0.0);
        assert!(m.abs() <= 0.0422 + 1e-12, "{m}");
        // The bank moves 0.03 deg: Fusion 0.03 deg/s apart, HDR at most 0.0722, both within
        // 2 x 0.04: the heading moves by the mean of the three moves, the bias is the bank's
        // less what that adds per second.
        let o = b.update(true, 2.0, 0.0, bank(0.03, 0.04), 0.0, false).unwrap();
        let gain = (0.03 + m + 0.0) / 3.0 - 0.03;
        assert!((o.heading_deg - (0.03 + gain)).abs() < 1e-12, "{} against {}", o.heading_deg, 0.03 + gain);
        assert!((o.bias_dps + gain).abs() < 1e-12, "{}", o.bias_dps);
        // Fusion's offset put at 0.5 deg/s: a move of -0.5 deg on a rate of 0, far from the
        // bank's; the bank moves HDR's move + 0.07 (within 0.08): the mean of the two.
        b.experts.as_mut().unwrap().fusion = FusionOffset::starting_at(1, 0.5);
        let m = hdr_move(&b, 3.0, 0.0);
        let bank_deg = 0.03 + m + 0.07;
        let o = b.update(true, 3.0, 0.0, bank(bank_deg, 0.04), 0.0, false).unwrap();
        let gain2 = (m + 0.07 + m) / 2.0 - (m + 0.07);
        assert!((o.heading_deg - (bank_deg + gain + gain2)).abs() < 1e-12, "{} against {}", o.heading_deg, bank_deg + gain + gain2);
        // The bank moves 0.3 deg, 0.17 deg/s or more from HDR (at most 3 i_c) and 0.8 from
        // Fusion: the bank's move alone, the offset kept, the bias the bank's.
        let m = hdr_move(&b, 4.0, 0.0);
        assert!(m.abs() <= 3.0 * 0.0422 + 1e-12, "{m}");
        let o = b.update(true, 4.0, 0.0, bank(bank_deg + 0.3, 0.04), 0.0, false).unwrap();
        assert!((o.heading_deg - (bank_deg + 0.3 + gain + gain2)).abs() < 1e-12 && o.bias_dps == 0.0);
    }

    /// Before any stop the experts start once three of the bank's sigma fit within HDR's
    /// straight threshold theta_w (0.564 deg/s): 3 x 0.19 = 0.57, not yet; 3 x 0.18 = 0.54,
    /// started. After a stop they wait for i_c: 0.05 does not start them.
    #[test]
    fn before_a_stop_the_experts_start_once_hdr_could_acquire_the_rest() {
        let mut b = Blend::new(2.0, 0.0);
        b.update(true, 1.0, 0.0, bank(0.0, 0.19), 0.0, false).unwrap();
        assert!(b.experts.is_none());
        b.update(true, 2.0, 0.0, bank(0.0, 0.18), 0.0, false).unwrap();
        assert!(b.experts.is_some());
        let mut s = Blend::new(2.0, 0.0);
        s.update(true, 1.0, 0.0, PipelineOutput { stop: true, ..bank(0.0, 0.05) }, 0.0, false).unwrap();
        s.update(true, 2.0, 0.0, bank(0.0, 0.05), 0.0, false).unwrap();
        assert!(s.experts.is_none());
    }

    /// Between stops the guard grows as the walk since the last stop: Fusion's offset 0.5
    /// deg/s from the bank's bias is beyond 2 x 0.04 at once, within 2 sqrt(0.04^2 + 0.01^2
    /// x 2500) = 1.0 after 2500 s without a stop, and beyond again a block after a stop.
    #[test]
    fn the_guard_grows_between_stops_and_closes_at_one() {
        let started = |walk: f64| {
            let mut b = Blend::new(2.0, walk);
            b.update(true, 1.0, 0.0, bank(0.0, 0.04), 0.0, false).unwrap();
            b.experts.as_mut().unwrap().fusion = FusionOffset::starting_at(1, 0.5);
            b
        };
        // 2500 s later: HDR has moved at most i_c per second; Fusion -0.5 deg/s x 2500 s.
        let (mut narrow, mut grown) = (started(0.0), started(0.01));
        let m = hdr_move(&grown, 2501.0, 0.0);
        assert!(m.abs() <= 0.0422 * 2500.0 + 1e-9, "{m}");
        let o = narrow.update(true, 2501.0, 0.0, bank(0.0, 0.04), 0.0, false).unwrap();
        assert!((o.heading_deg - m / 2.0).abs() < 1e-9, "{} against {}", o.heading_deg, m / 2.0);
        let o = grown.update(true, 2501.0, 0.0, bank(0.0, 0.04), 0.0, false).unwrap();
        assert!((o.heading_deg - (m - 1250.0) / 3.0).abs() < 1e-9, "{} against {}", o.heading_deg, (m - 1250.0) / 3.0);
        // A stop block at 2502 s closes it: at 2503 s Fusion (still -0.5 deg/s: within 3 deg/s
        // for 3 blocks, short of its 5 s timeout) is out, HDR in.
        let stop = PipelineOutput { stop: true, ..bank(0.0, 0.04) };
        let before = grown.update(true, 2502.0, 0.0, stop, 0.0, false).unwrap().heading_deg;
        let m = hdr_move(&grown, 2503.0, 0.0);
        let o = grown.update(true, 2503.0, 0.0, bank(0.0, 0.04), 0.0, false).unwrap();
        assert!((o.heading_deg - before - m / 2.0).abs() < 1e-9, "{} against {}", o.heading_deg - before, m / 2.0);
    }

    /// After a lead-in whose turn-on bias is 0.15 deg/s (rho = 0.15 / 0.3 = 0.5), 600 s
    /// after the last stop the bank's move counts 1 / (1 + 0.5 x 600 / 300) = 1/2 in the mean;
    /// at 0.6 deg/s (rho capped at 1) 1/3; without a lead-in, or with the decay off, 1. The
    /// experts start at the bias, so on its rate Fusion moves 0 and HDR by its controller, m.
    #[test]
    fn the_banks_weight_decays_after_a_stop_on_a_gyro_whose_lead_in_shows_a_bias() {
        for (bias, lead_in, decay_bias, w) in
            [(0.15, true, 0.3, 0.5), (0.6, true, 0.3, 1.0 / 3.0), (0.15, false, 0.3, 1.0), (0.15, true, 0.0, 1.0)]
        {
            let mut b = Blend { decay_bias_dps: decay_bias, ..Blend::new(2.0, 0.0) };
            let at = |heading_deg| PipelineOutput { bias_dps: bias, ..bank(heading_deg, 0.04) };
            b.update(false, 0.0, bias, PipelineOutput { stop: lead_in, ..at(0.0) }, bias, false).unwrap();
            b.update(true, 1.0, bias, at(0.0), bias, false).unwrap();
            // 600 s on the bias's rate: the bank moves 0.6 deg (0.001 deg/s from Fusion's 0,
            // within the guard).
            let m = hdr_move(&b, 601.0, bias);
            let o = b.update(true, 601.0, bias, at(0.6), bias, false).unwrap();
            let want = (w * 0.6 + m) / (w + 2.0);
            assert!((o.heading_deg - want).abs() < 1e-9, "bias {bias}, lead-in {lead_in}: {} against {want}", o.heading_deg);
        }
    }

    /// Once the experts have started, the bank's settled bias 0.5 deg/s from its anchor (0,
    /// beyond 0.3): the heading moves by HDR's move alone, its bias held within the guard
    /// (2 x 0.04, no walk) of the span between the bank's bias (0.5) and its anchor's (0),
    /// with or without a stop in the lead-in. With the fallback off the bank moves alone.
    #[test]
    fn a_settled_bias_on_the_move_takes_hdrs_move_held_near_the_bank() {
        let started = |move_dps: f64, lead_in_stop: bool| {
            let fallback = Fallback { move_dps, release_s: 60.0, ..Default::default() };
            let mut b = Blend { fallback, ..Blend::new(2.0, 0.0) };
            b.update(false, 0.0, 0.0, PipelineOutput { stop: lead_in_stop, ..bank(0.0, 0.04) }, 0.0, false).unwrap();
            b.update(true, 1.0, 0.0, bank(0.0, 0.04), 0.0, false).unwrap();
            b
        };
        // The bank took 0.5 deg/s as bias over the block: it moved -0.5 deg.
        let dragged = PipelineOutput { bias_dps: 0.5, ..bank(-0.5, 0.04) };
        for lead_in_stop in [true, false] {
            let mut b = started(0.3, lead_in_stop);
            let m = hdr_move(&b, 2.0, 0.0);
            assert!(m.abs() <= 0.0422 + 1e-12, "{m}");
            let o = b.update(true, 2.0, 0.0, dragged, 0.5, false).unwrap();
            assert!((o.heading_deg - m).abs() < 1e-12 && (o.bias_dps + m).abs() < 1e-12, "{o:?} against HDR's {m}");
        }
        let mut b = started(0.3, true);
        b.update(true, 2.0, 0.0, dragged, 0.5, false).unwrap();
        // The anchor stays while the fallback acts, and restarts after a stop.
        assert_eq!(b.fallback.anchor_dps, Some((0.0, 0.0)));
        b.update(true, 3.0, 0.0, PipelineOutput { stop: true, ..dragged }, 0.5, false).unwrap();
        assert_eq!(b.fallback.anchor_dps, None);
        b.update(true, 4.0, 0.0, dragged, 0.5, false).unwrap();
        assert_eq!(b.fallback.anchor_dps, Some((0.5, 0.5)));
        // HDR at -2 deg/s: its bias is held at the span's edge, 0 - 0.08.
        let mut b = started(0.3, true);
        let e = b.experts.as_mut().unwrap();
        e.hdr = Hdr::new(HdrParams::table_iii(), -2.0).unwrap();
        e.hdr_deg = e.hdr.update(1.0, 0.0).unwrap().heading_deg;
        assert!(hdr_move(&b, 2.0, 0.0) > 1.9);
        let o = b.update(true, 2.0, 0.0, dragged, 0.5, false).unwrap();
        assert!((o.bias_dps + 0.08).abs() < 1e-12 && (o.heading_deg - 0.08).abs() < 1e-12, "{o:?}");
        // HDR and Fusion (0 deg/s) both beyond the guard: the bank's move alone.
        let o = started(0.0, true).update(true, 2.0, 0.0, dragged, 0.5, false).unwrap();
        assert_eq!(o, dragged, "the fallback off");
    }
}
